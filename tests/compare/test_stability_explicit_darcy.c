/* Stability sweep of the explicit Darcy update (seed 000 §3.9.2, eq. 3.18): h += dt M^-1 (f - K h)
 * with the lumped storage matrix M is stable for dt < 2 / lambda_max(M^-1 K); the engine bounds
 * lambda_max with Gershgorin circles (pl_fl_explicit_dt_limit, darcy_solve.c) and sub-steps at
 * FLUID_EXPLICIT_SAFETY (<= 1, the parameter table refuses more) times that bound. This test
 * drives the kernel past it: on the pressure-wave rod of tests/fluid/wave_rod.h (40 cells,
 * D = S = 1, head 1 at x = 0) it sets the safety factor to r = 0.5 ... 1.5 directly and advances
 * to t = 0.05 s. The maximum principle bounds the exact head by [0, 1]; measured: max |h|.
 * Failure: max |h| > 2. Checks: every r <= 1 (the computed limit) is stable, and the first
 * failure lies within a factor 2 above it (Gershgorin's bound is safe, not needlessly small;
 * measured: between 1.45 and 1.48 on this rod).
 * With an output folder as argument it also draws stability_explicit_darcy.png there
 * (docs/compare/, docs/compare.md). */
#include "harness.h"
#include "fluid/darcy/darcy_internal.h"
#include "fluid/darcy/darcy_world.h"
#include "fluid/wave_rod.h"
#include "render/charts.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

#define NR 15
static const double R[NR] = {0.5, 0.8, 0.9, 1.0, 1.05, 1.1, 1.2, 1.3, 1.35, 1.4, 1.45, 1.48, 1.5, 2.0, 3.0};
static double measure[NR];
static int failed[NR];
static double limit_s;
static const char *out_dir;

static double sweep_one(double r) {
    pl_world *w = wave_rod(40, 2, 0);
    if (pl_world_fluid_advance(w, 1e-4) != PL_OK) return NAN; /* builds the system */
    struct pl_fluid *f = pl__darcy(w);
    limit_s = pl_fl_explicit_dt_limit(f);
    f->par.explicit_safety = r; /* past the table's range on purpose */
    double hmax = 0;
    for (int k = 0; k < 50 && isfinite(hmax) && hmax < 1e6; k++) {
        if (pl_fl_advance(f, 1e-3) != PL_OK) return NAN;
        for (int j = 0; j < f->mesh.nn; j++) hmax = fmax(hmax, fabs(f->head[j]));
    }
    pl_world_destroy(&w);
    return hmax;
}

static int sweep(void) {
    double first_fail = INFINITY;
    for (int i = 0; i < NR; i++) {
        measure[i] = sweep_one(R[i]);
        failed[i] = !(measure[i] <= 2);
        if (failed[i] && R[i] < first_fail) first_fail = R[i];
        printf("  sub-step / computed limit %.3f: max |h| = %.4g %s\n", R[i], measure[i], failed[i] ? "FAILED" : "stable");
    }
    printf("computed limit %.4g s; first failure at %.3g x the computed limit\n", limit_s, first_fail);
    for (int i = 0; i < NR; i++)
        if (R[i] <= 1.0) ENSURE(!failed[i]);
    ENSURE(first_fail > 1.0 && first_fail <= 2.0);
    if (out_dir) {
        double y[NR], lx[2] = {1, 1}, ly[2] = {0.3, 1e7}, fx[2] = {first_fail, first_fail};
        for (int i = 0; i < NR; i++) y[i] = fmin(fmax(measure[i], 0.3), 1e7);
        char fname[96];
        snprintf(fname, sizeof fname, "measured failure (%.3g \u00d7 limit)", first_fail);
        pl_chart_series s[3] = {
            {"largest |head| (m); exact solution \u2264 1 m", R, y, NR, PL_SERIES_LINE_POINTS, {0.12, 0.47, 0.71, 1}, 2},
            {"computed limit (Gershgorin bound)", lx, ly, 2, PL_SERIES_DASHED, {0, 0, 0, 1}, 1.5},
            {fname, fx, ly, 2, PL_SERIES_LINE, {0.84, 0.15, 0.16, 1}, 2}};
        pl_chart_def d = pl_default_chart_def();
        d.title = "Explicit Darcy update (Klosek 1997 eq. 3.18), 40-cell rod";
        d.xlabel = "sub-step #gDt / computed limit (1)";
        d.ylabel = "largest |head| up to t = 0.05 s (m)";
        d.series = s;
        d.series_count = 3;
        d.logy = 1;
        d.xmin = 0.45;
        d.xmax = 3.1;
        d.ymin = 0.3;
        d.ymax = 1e7;
        d.legend = 3;
        d.width = 900;
        d.height = 620;
        char path[1024], err[256];
        snprintf(path, sizeof path, "%s/stability_explicit_darcy.png", out_dir);
        ENSURE(pl_chart_write(path, &d, err, sizeof err) == 0);
    }
    return 0;
}

int main(int argc, char **argv) {
    out_dir = argc > 1 ? argv[1] : NULL;
    RUN(sweep);
    return pl_test_report();
}
