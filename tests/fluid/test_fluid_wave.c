/* Fluid pressure wave (seed 000 §4.3, Appendix C.3, Figs. 4-10 to 4-12): S dh/dt = K d2h/dx2
 * with S = K = 1 on 0 <= x <= 1, h(0, t) = phi0, h(1, t) = 0, h(x, 0) = 0.
 * Reference: phi0 erfc(x / (2 sqrt(t))) (eq. 4.2, semi-infinite rod; at t <= 0.01 the far end
 * changes it by less than erfc(5) = 1.5e-12), and the finite-domain Fourier series
 * phi0 (1 - x) - sum 2 phi0 / (n pi) sin(n pi x) exp(-n^2 pi^2 t) at later times (Carslaw &
 * Jaeger, Conduction of Heat in Solids, §3.4). Meshes of 4, 8, 16, 32, 64 cells along x; the
 * maximum nodal error must fall with every refinement; the observed order is printed.
 * Explicit (thesis §3.9.2, sub-stepped below its computed limit) against implicit. */
#include "harness.h"
#include "fluid/darcy/darcy_world.h"
#include "fluid/darcy/darcy_internal.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include "fluid/wave_rod.h"
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

static int g_mass = 0; /* FLUID_MASS: 0 lumped, 1 consistent */

static pl_world *rod(int n, int method) { return wave_rod(n, method, g_mass); }

static double series(double x, double t) {
    double s = 1 - x;
    for (int n = 1; n < 2000; n++) {
        double term = 2 / (n * 3.141592653589793) * sin(n * 3.141592653589793 * x) * exp(-n * n * 9.869604401089358 * t);
        s -= term;
        if (n * n * 9.87 * t > 60) break;
    }
    return s;
}

static double max_error(pl_world *w, double t, int use_series) {
    int nn = pl_world_fluid_node_count(w);
    pl_vec2 *xy = malloc(sizeof(pl_vec2) * nn);
    double *h = malloc(sizeof(double) * nn);
    pl_world_fluid_copy_nodes(w, xy, nn);
    pl_world_fluid_copy_node_field(w, PL_FLUID_HEAD, h, nn);
    double err = 0;
    for (int i = 0; i < nn; i++) {
        double ref = use_series ? series(xy[i].x, t) : erfc(xy[i].x / (2 * sqrt(t)));
        err = fmax(err, fabs(h[i] - ref));
    }
    free(xy);
    free(h);
    return err;
}

static int erfc_convergence(double min_order) {
    const int ns[5] = {4, 8, 16, 32, 64};
    const double times[3] = {0.001, 0.005, 0.010};
    double err[3][5];
    const double dt = 1e-6; /* backward Euler: time error well below the spatial error */
    for (int k = 0; k < 5; k++) {
        pl_world *w = rod(ns[k], 0);
        double t = 0;
        int ti = 0;
        while (ti < 3) {
            if (pl_world_fluid_advance(w, dt) != PL_OK) {
                fprintf(stderr, "%s\n", pl_world_last_error(w));
                return 1;
            }
            t += dt;
            if (fabs(t - times[ti]) < 0.5 * dt) err[ti++][k] = max_error(w, t, 0);
        }
        pl_world_destroy(&w);
    }
    fprintf(stderr, "  max nodal error against phi0 erfc(x / 2 sqrt(t)) (backward Euler, dt = 1e-6, %s mass):\n",
            g_mass ? "consistent" : "lumped");
    fprintf(stderr, "  %-8s %-11s %-11s %-11s %-11s %-11s\n", "t", "N=4", "8", "16", "32", "64");
    for (int ti = 0; ti < 3; ti++) {
        fprintf(stderr, "  %-8g", times[ti]);
        for (int k = 0; k < 5; k++) fprintf(stderr, " %-11.3e", err[ti][k]);
        fprintf(stderr, "\n  %-8s %-11s", "order", "");
        for (int k = 1; k < 5; k++) fprintf(stderr, " %-11.2f", log2(err[ti][k - 1] / err[ti][k]));
        fprintf(stderr, "\n");
    }
    for (int ti = 0; ti < 3; ti++)
        for (int k = 1; k < 5; k++) ENSURE(err[ti][k] < err[ti][k - 1]);
    /* on the resolved meshes: observed order (P1, max norm at the nodes) */
    ENSURE(log2(err[2][3] / err[2][4]) > min_order);
    ENSURE(err[2][4] < 1e-3);
    return 0;
}

/* Lumped storage (default): smaller errors, order about 1.5 in the max norm on these meshes
   (the centre nodes carry a different lumped mass); consistent storage: order 2. */
static int test_erfc_convergence(void) {
    g_mass = 0;
    if (erfc_convergence(1.3)) return 1;
    g_mass = 1;
    int r = erfc_convergence(1.8);
    g_mass = 0;
    return r;
}

static int test_series_late(void) {
    /* later times on the finite rod: Crank-Nicolson, N = 64 */
    pl_world *w = rod(64, 1);
    double t = 0, dt = 1e-4;
    const double times[2] = {0.05, 0.2};
    int ti = 0;
    /* a few backward Euler steps damp the start-up oscillation of Crank-Nicolson (Rannacher) */
    pl_world_set_flag(w, "FLUID_METHOD", 0);
    for (int k = 0; k < 4; k++) { pl_world_fluid_advance(w, dt / 4); t += dt / 4; }
    pl_world_set_flag(w, "FLUID_METHOD", 1);
    while (ti < 2) {
        ENSURE(pl_world_fluid_advance(w, dt) == PL_OK);
        t += dt;
        if (fabs(t - times[ti]) < 0.5 * dt) {
            double e = max_error(w, t, 1);
            fprintf(stderr, "  t = %g: max error against the Fourier series %.3e (N = 64, Crank-Nicolson, dt = 1e-4)\n", t, e);
            ENSURE(e < 1e-3);
            ti++;
        }
    }
    pl_world_destroy(&w);
    return 0;
}

static int test_explicit_vs_implicit(void) {
    const int n = 32;
    const double T = 0.005, dt = 5e-4;
    double e_imp, e_exp, c_imp, c_exp;
    pl_world *w = rod(n, 0);
    double c0 = cpu();
    for (int k = 0; k < (int)(T / dt + 0.5); k++) ENSURE(pl_world_fluid_advance(w, dt) == PL_OK);
    c_imp = cpu() - c0;
    e_imp = max_error(w, T, 0);
    pl_world_destroy(&w);
    w = rod(n, 2);
    c0 = cpu();
    for (int k = 0; k < (int)(T / dt + 0.5); k++) ENSURE(pl_world_fluid_advance(w, dt) == PL_OK);
    c_exp = cpu() - c0;
    e_exp = max_error(w, T, 0);
    pl_fluid_stats st;
    pl_world_fluid_stats(w, &st);
    fprintf(stderr, "  N = %d, fluid step %g s to t = %g: implicit error %.3e (%.3f s CPU), explicit error %.3e (%.3f s CPU, "
                    "%d sub-steps per step, limit %.3e s)\n",
            n, dt, T, e_imp, c_imp, e_exp, c_exp, st.last_substeps, st.explicit_dt_limit);
    /* sub-steps as the limit demands */
    ENSURE(st.last_substeps == (int)ceil(dt / (0.9 * st.explicit_dt_limit)));
    ENSURE(st.last_substeps > 1);
    /* the explicit sub-steps are small: it is the more accurate in time here */
    ENSURE(e_exp < 0.01);
    ENSURE(e_imp < 0.05);
    /* the Gershgorin limit is safe: lambda_max(M^-1 K) by power iteration is below the bound */
    struct pl_fluid *f = pl__darcy(w);
    int nn = f->mesh.nn;
    double *x = malloc(sizeof(double) * nn), *y = malloc(sizeof(double) * nn);
    for (int i = 0; i < nn; i++) x[i] = f->sys.is_dir[i] ? 0 : ((i * 7919) % 13) - 6.0;
    double lam = 0;
    for (int it = 0; it < 3000; it++) {
        memset(y, 0, sizeof(double) * nn);
        for (int j = 0; j < nn; j++)
            for (int p = f->sys.colp[j]; p < f->sys.colp[j + 1]; p++) y[f->sys.rowi[p]] += f->sys.kval[p] * x[j];
        double nrm = 0;
        for (int i = 0; i < nn; i++) {
            y[i] = f->sys.is_dir[i] ? 0 : y[i] / f->sys.mlump[i];
            nrm += y[i] * y[i];
        }
        nrm = sqrt(nrm);
        double xn = 0;
        for (int i = 0; i < nn; i++) xn += x[i] * x[i];
        lam = nrm / sqrt(xn);
        for (int i = 0; i < nn; i++) x[i] = y[i] / nrm;
    }
    fprintf(stderr, "  stability: 2 / lambda_max = %.4e s (power iteration), Gershgorin limit %.4e s\n", 2 / lam,
            st.explicit_dt_limit);
    ENSURE(st.explicit_dt_limit <= 2 / lam * (1 + 1e-9));
    ENSURE(st.explicit_dt_limit > 0.3 * 2 / lam);
    free(x);
    free(y);
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(test_erfc_convergence);
    RUN(test_series_late);
    RUN(test_explicit_vs_implicit);
    return pl_test_report();
}
