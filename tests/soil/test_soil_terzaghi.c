/* Terzaghi one-dimensional consolidation, solver alone (docs/soil.md §4). A grain-free column
 * of height H, drained at the top (pressure head 0), impermeable elsewhere, with a prescribed
 * compressible skeleton: its constrained compressibility m_v enters as the skeleton part of
 * the specific storage, FLUID_STORAGE = m_v rho_f g, and FLUID_CONSOLIDATION adds the fluid's
 * n rho_f g / K_f, so that
 *     c_v = D / (rho_f g (m_v + n / K_f))      (D hydraulic conductivity, m/s)
 * At t = 0 a load is applied undrained: uniform excess pressure u0. The average degree of
 * consolidation U = 1 - (mean u) / u0 is compared with Terzaghi's series (single drainage,
 * drainage path H; Terzaghi 1925; e.g. Craig's Soil Mechanics §7.6, eq. 7.22):
 *     U(T_v) = 1 - sum_m 2/M^2 exp(-M^2 T_v),  M = (2m + 1) pi / 2,  T_v = c_v t / H^2.
 * Required: |U_FE - U| <= 0.01 U at T_v = 0.1, 0.2, 0.5 (the solver-alone tolerance).
 * The test also checks the isochrone u(z, t) at mid-depth against the series
 *     u/u0 = sum_m 2/M sin(M Z) exp(-M^2 T_v), Z = depth / H,
 * and fails when the fluid's storage is left out (FLUID_CONSOLIDATION 0 with the same
 * FLUID_STORAGE gives a c_v larger by (m_v + n/K_f)/m_v = 2: U off by far more than 1%). */
#include "harness.h"
#include "porelab/fluid.h"
#include "porelab/soil.h"
#include "porelab/world.h"
#include <stdio.h>

#define PI 3.141592653589793
#define H 1.0
#define WD 0.05

static double U_series(double Tv) {
    double s = 0;
    for (int m = 0; m < 200; m++) {
        double M = (2 * m + 1) * PI / 2;
        s += 2 / (M * M) * exp(-M * M * Tv);
    }
    return 1 - s;
}

static double u_series(double Z, double Tv) {
    double s = 0;
    for (int m = 0; m < 400; m++) {
        double M = (2 * m + 1) * PI / 2;
        s += 2 / M * sin(M * Z) * exp(-M * M * Tv);
    }
    return s;
}

/* cons: FLUID_CONSOLIDATION; returns the worst relative error of U over the three T_v. */
static double run(int cons, int verbose, double *iso_err) {
    const double rho = 1000, g = 9.80665; /* gravity off: heads convert with standard gravity */
    const double D = 1e-3, mv = 1e-6, Kf = 1e6 * 0.99; /* n / K_f = m_v for n = 0.99 (no grains) */
    const double u0 = 1e4;
    pl_world_def wd = pl_default_world_def();
    pl_world *w = pl_world_create(&wd);
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){WD, 0};
    q.corners[2] = (pl_vec2){WD, H};
    q.corners[3] = (pl_vec2){0, H};
    q.ndivx = 1;
    q.ndivy = 80;
    pl_world_add_fluid_quad(w, &q);
    pl_world_add_fluid_bc(w, (pl_vec2){0, H}, (pl_vec2){WD, H}, 0);
    const char *names[] = {"GRAVITY_Y", "FLUIDS_ON", "FLUID_PERM", "FLUID_PERM_HIGH", "FLUID_STORAGE",
                           "FLUID_CONSOLIDATION", "FLUID_BULK_MODULUS", "FLUID_DRAG", "FLUID_METHOD"};
    const double vals[] = {0, 1, 0, D, mv * rho * g, cons, Kf, 0, 1};
    for (int k = 0; k < 9; k++)
        if (pl_world_set_flag(w, names[k], vals[k]) != PL_OK) fprintf(stderr, "%s\n", pl_world_last_error(w));
    pl_world_fluid_set_pressure_head(w, u0 / (rho * g));
    const double cv = D / (rho * g * (mv + 0.99 / Kf));
    const double T[3] = {0.1, 0.2, 0.5};
    const int nsteps = 2000; /* Crank-Nicolson steps up to T_v = 0.5 */
    const double dt = 0.5 * H * H / cv / nsteps;
    double worst = 0, t = 0;
    int next = 0;
    *iso_err = 0;
    for (int s = 1; s <= nsteps && next < 3; s++) {
        if (pl_world_fluid_advance(w, dt) != PL_OK) {
            fprintf(stderr, "%s\n", pl_world_last_error(w));
            return 1e9;
        }
        t += dt;
        double Tv = cv * t / (H * H);
        if (Tv >= T[next] - 1e-12) {
            pl_soil_region r;
            pl_world_soil_region(w, (pl_vec2){0, 0}, (pl_vec2){WD, H}, &r);
            double U = 1 - r.u_excess / u0, Ua = U_series(Tv);
            double rel = fabs(U - Ua) / Ua;
            if (rel > worst) worst = rel;
            double p;
            pl_world_prepare(w); /* queries read only: build first */
            pl_world_fluid_pressure_at(w, (pl_vec2){WD / 2, H / 2}, &p, NULL);
            double ia = u_series(0.5, Tv);
            double ie = fabs(p / u0 - ia);
            if (ie > *iso_err) *iso_err = ie;
            if (verbose)
                fprintf(stderr, "  T_v = %.3f: U = %.5f, Terzaghi %.5f (%.3f%%); u(mid-depth)/u0 = %.5f, series %.5f\n", Tv,
                        U, Ua, 100 * rel, p / u0, ia);
            next++;
        }
    }
    pl_world_destroy(&w);
    return worst;
}

static int test_terzaghi_solver(void) {
    double iso;
    double worst = run(1, 1, &iso);
    fprintf(stderr, "  worst relative error of U: %.4f%%; isochrone at mid-depth: %.2e u0\n", 100 * worst, iso);
    pl_validation("soil.terzaghi", "consolidation, grain-free column with a prescribed skeleton",
                  "Terzaghi U(T_v) at T_v = 0.1, 0.2, 0.5 (Craig §7.6)", "1 %",
                  "%.4f %%; mid-depth isochrone %.1e u₀", 100 * worst, iso);
    ENSURE(worst <= 0.01);
    ENSURE(iso <= 0.01);
    return 0;
}

static int test_without_fluid_storage_fails(void) {
    double iso;
    double worst = run(0, 0, &iso);
    fprintf(stderr, "  FLUID_CONSOLIDATION 0 (fluid compressibility ignored): worst error of U %.1f%%\n", 100 * worst);
    pl_validation("soil.terzaghi_no_storage", "same with FLUID_CONSOLIDATION 0 (no fluid storage)", "must miss Terzaghi",
                  "> 5 %", "misses by %.1f %%", 100 * worst);
    ENSURE(worst > 0.05);
    return 0;
}

int main(void) {
    RUN(test_terzaghi_solver);
    RUN(test_without_fluid_storage_fails);
    return pl_test_report();
}
