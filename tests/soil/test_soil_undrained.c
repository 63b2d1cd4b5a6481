/* Undrained loading of a sealed saturated sample (Skempton's B) and the drained limit
 * (docs/soil.md §4).
 *
 * A box of discs under a heavy rigid piston (a polygon that displaces water) is saturated;
 * the fluid mesh covers the sample and the piston, with a head line above the piston.
 * 1. Drained (conductivity 1 m/s): a load step dF on the piston; the settlement gives the
 *    skeleton's constrained modulus M = d(sigma) / d(eps).
 * 2. Undrained: the sample sealed (no head line; the mesh ends inside the piston), gravity
 *    off, conductivity 1e-2 m/s inside so that the pressure equalises within the sample
 *    (c_v ~ 30 m^2/s), K_f = 100 M: the same load step. Theory (Skempton 1954; for incompressible grains in 1D loading):
 *        B = du / d(sigma) = 1 / (1 + n M / K_f)  ~ 0.997 for n ~ 0.2.
 *    Required: the mean excess pore pressure in the sample carries >= 90% of the added total
 *    stress (the criterion), and the settlement is < 10% of the drained one.
 *    With FLUID_CONSOLIDATION 0 the pressure does not respond (B = 0): checked, so the test
 *    fails when the coupling breaks.
 * 3. Drained limit: with a conductivity of 1e5 m/s and grains moving (the load step), the pore
 *    pressure stays hydrostatic to 1e-6 of the hydrostatic pressure at the floor. */
#include "harness.h"
#include "soil_common.h"
#include <math.h>
#include <string.h>

#define BW 0.05
#define NG 64

typedef struct result { double settle, du, dsig, n, M, hyd_dev, p_floor; } result;

static int g_lag; /* FLUID_POROSITY_TIMESTEPS of the runs (0: pieces cut at every solve) */

static double piston_y(soil_box *b) {
    pl_body_info bi;
    pl_world_body_info(b->w, b->piston, &bi);
    return bi.position.y;
}

/* cons: FLUID_CONSOLIDATION; D conductivity during the load step; Kf bulk modulus; dt grain
   step during the load step; drained: head line (pressure head 0) at the mesh top and gravity
   on, otherwise a sealed sample without gravity (the piston load holds the packing). */
static int run(int cons, double D, double Kf, double dt, int drained, result *r, int verbose) {
    memset(r, 0, sizeof *r);
    soil_box b = soil_make_box(BW, NG, 2e5, 0.3);
    pl_world *w = b.w;
    soil_flag(w, "RAYLEIGH_FACTOR", 40);
    soil_flag(w, "LOCAL_DAMPING", 0.3); /* quasi-static loading (seed 002 eqs. 24-29) */
    /* settle dry first (fast), then add the piston */
    if (soil_run_for(w, 0.3)) return 1;
    double top = soil_grain_top(&b);
    const double tp = 0.012, gap = 0.0004;
    pl_vec2 pv[4] = {{gap, top + 0.0002}, {BW - gap, top + 0.0002}, {BW - gap, top + 0.0002 + tp}, {gap, top + 0.0002 + tp}};
    pl_material_def md = pl_world_material(w, 1);
    (void)md;
    pl_body_def pd = pl_default_body_def();
    pd.shape = PL_SHAPE_POLYGON;
    pd.material = 1; /* frictionless wall material */
    pd.vertices = pv;
    pd.vertex_count = 4;
    b.piston = pl_world_add_body(w, &pd);
    const double F0 = 20; /* N/m */
    pl_world_set_body_load(w, b.piston, (pl_vec2){0, -F0}, 0);
    if (soil_run_for(w, 0.25)) return 1;
    /* saturate: the mesh covers the sample and ends inside the piston (a rigid body crossing
       the mesh boundary seals it and displaces water as it moves in) */
    if (!drained) {
        soil_flag(w, "GRAVITY_Y", 0);
        pl_world_set_body_load(w, b.piston, (pl_vec2){0, -F0 - 20}, 0); /* replaces the grains' weight */
        if (soil_run_for(w, 0.1)) return 1;
    }
    double ymesh = piston_y(&b);
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){BW, 0};
    q.corners[2] = (pl_vec2){BW, ymesh};
    q.corners[3] = (pl_vec2){0, ymesh};
    q.ndivx = 8;
    q.ndivy = (int)(ymesh / (BW / 8)) + 1;
    pl_world_add_fluid_quad(w, &q);
    if (drained) pl_world_add_fluid_bc(w, (pl_vec2){0, ymesh}, (pl_vec2){BW, ymesh}, 0);
    soil_flag(w, "FLUIDS_ON", 1);
    soil_flag(w, "FIRST_STEP_STATIC", drained);
    soil_flag(w, "FLUID_PERM", 0);
    soil_flag(w, "FLUID_PERM_HIGH", drained ? 1.0 : D);
    soil_flag(w, "FLUID_STORAGE", cons ? 0 : 1e-4);
    soil_flag(w, "FLUID_CONSOLIDATION", cons);
    soil_flag(w, "FLUID_BULK_MODULUS", Kf);
    soil_flag(w, "FLUID_POROSITY_TIMESTEPS", g_lag);
    if (soil_run_for(w, 0.1)) return 1;
    soil_flag(w, "FLUID_PERM_HIGH", D);
    /* the staggered coupling acts on a grain like a spring of stiffness ~ K_f / (n (1 - n)^2)
       (docs/soil.md §2): a stiff fluid needs a smaller grain step than the contacts alone */
    soil_flag(w, "DT", dt);
    if (soil_run_for(w, 0.01)) return 1;
    double y0 = piston_y(&b);
    double ytop0 = y0 - tp / 2;
    pl_vec2 lo = {0.002, 0.002}, hi = {BW - 0.002, ytop0 - 0.004};
    pl_soil_region r0;
    pl_world_soil_region(w, lo, hi, &r0);
    r->n = 1 - b.solid_area / (BW * ytop0);
    /* load step */
    const double dF = 40;
    pl_body_info pi0;
    pl_world_body_info(w, b.piston, &pi0);
    (void)pi0;
    double Fnow = drained ? F0 : F0 + 20;
    pl_world_set_body_load(w, b.piston, (pl_vec2){0, -Fnow - dF}, 0);
    r->hyd_dev = 0;
    double pf_h = 1000 * 9.81 * ymesh; /* hydrostatic pressure at the floor */
    r->p_floor = pf_h;
    double du_sum = 0, sig_sum = 0;
    int du_n = 0;
    for (int k = 0; k < 40; k++) {
        if (soil_run_for(w, 0.006)) return 1;
        if (k >= 20) { /* mean over the second half: the piston rings on the stiff water */
            pl_soil_region rk;
            pl_world_soil_region(w, lo, hi, &rk);
            du_sum += rk.u_excess - r0.u_excess;
            sig_sum += rk.eff[3];
            du_n++;
        }
        double p;
        for (int j = 0; j < 5 && drained; j++) {
            pl_vec2 x = {BW * (j + 0.5) / 5, 0.001 + j * 0.004};
            pl_world_prepare(w); /* queries read only: build first */
            pl_world_fluid_pressure_at(w, x, &p, NULL);
            double dev = fabs(p - 1000 * 9.81 * (ymesh - x.y)) / pf_h;
            if (dev > r->hyd_dev) r->hyd_dev = dev;
        }
    }
    pl_soil_region r1;
    pl_world_soil_region(w, lo, hi, &r1);
    r->settle = y0 - piston_y(&b);
    r->du = du_sum / du_n;
    r1.eff[3] = sig_sum / du_n;
    r->dsig = dF / (BW - 2 * gap);
    double eps = r->settle / ytop0;
    r->M = r->dsig / eps;
    if (verbose)
        fprintf(stderr,
                "  cons %d D %.1e K_f %.3g: n = %.3f, settlement %.3e m (strain %.2e), du = %.1f Pa of dsigma = %.1f Pa "
                "(B = %.4f); sigma'_yy %.1f -> %.1f Pa; max |p - p_hyd| / p_floor = %.2e\n",
                cons, D, Kf, r->n, r->settle, eps, r->du, r->dsig, r->du / r->dsig, r0.eff[3], r1.eff[3], r->hyd_dev);
    pl_world_destroy(&w);
    return 0;
}

static int test_skempton_b(void) {
    result dr, un, off;
    ENSURE(run(1, 1.0, 1e9, 5e-5, 1, &dr, 1) == 0);
    double M = dr.M;
    double Kf = 100 * M;
    ENSURE(run(1, 1e-2, Kf, 5e-6, 0, &un, 1) == 0);
    double B = un.du / un.dsig;
    double B_th = 1 / (1 + dr.n * M / Kf);
    fprintf(stderr, "  drained modulus M = %.4g Pa; K_f = 100 M = %.4g Pa; B = %.4f (theory %.4f); undrained settlement %.2f%% of drained\n",
            M, Kf, B, B_th, 100 * un.settle / dr.settle);
    pl_validation("soil.undrained", "undrained loading of a sealed sample, K_f = 100 M", "Skempton B = 1/(1 + nM/K_f) ≈ 1",
                  "B ≥ 0.9; pieces cut every 20 steps within 2 %", "B = %.4f (theory %.4f)", B, B_th);
    ENSURE(B >= 0.9);
    ENSURE(B <= 1.05); /* the water cannot carry more than the load */
    ENSURE(un.settle < 0.1 * dr.settle);
    ENSURE(run(0, 1e-2, Kf, 5e-5, 0, &off, 1) == 0);
    fprintf(stderr, "  without the coupling (FLUID_CONSOLIDATION 0): B = %.4f\n", off.du / off.dsig);
    ENSURE(off.du / off.dsig < 0.1);
    return 0;
}

/* FLUID_POROSITY_TIMESTEPS = 20: the pieces of the grains in the elements are cut every 20
   grain steps and the source and forces use the last ones in between (docs/soil.md §2.5). The
   undrained response must be the same physics: B >= 0.9 and within 2% of the B with pieces cut
   at every solve, and the settlement still < 10% of the drained one. */
static int test_skempton_b_lagged_pieces(void) {
    result dr, un, un_lag;
    g_lag = 0;
    ENSURE(run(1, 1.0, 1e9, 5e-5, 1, &dr, 0) == 0);
    const double Kf = 100 * dr.M;
    ENSURE(run(1, 1e-2, Kf, 5e-6, 0, &un, 0) == 0);
    g_lag = 20;
    ENSURE(run(1, 1e-2, Kf, 5e-6, 0, &un_lag, 1) == 0);
    g_lag = 0;
    const double B = un.du / un.dsig, Bl = un_lag.du / un_lag.dsig;
    fprintf(stderr, "  B with pieces cut at every solve %.4f, every 20 grain steps %.4f (difference %.2f%%)\n", B, Bl,
            100 * fabs(Bl - B) / B);
    pl_validation("soil.undrained", "", "", "", "lagged pieces %.4f (%.2f %%)", Bl, 100 * fabs(Bl - B) / B);
    ENSURE(Bl >= 0.9);
    ENSURE(fabs(Bl - B) <= 0.02 * B);
    ENSURE(un_lag.settle < 0.1 * dr.settle);
    return 0;
}

static int test_drained_limit(void) {
    result dr;
    ENSURE(run(1, 1e5, 2.2e9, 5e-5, 1, &dr, 1) == 0);
    fprintf(stderr, "  drained limit: max |p - p_hydrostatic| / p_floor = %.2e while the sample settles %.2e m\n", dr.hyd_dev,
            dr.settle);
    pl_validation("soil.drained", "drained limit while grains move", "hydrostatic pressure unchanged", "1e-6 relative",
                  "%.1e", dr.hyd_dev);
    ENSURE(dr.settle > 1e-6);
    ENSURE(dr.hyd_dev <= 1e-6);
    return 0;
}

int main(void) {
    RUN(test_skempton_b);
    RUN(test_skempton_b_lagged_pieces);
    RUN(test_drained_limit);
    return pl_test_report();
}
