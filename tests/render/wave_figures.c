/* Seed 000 (Klosek 1997) Figs. 4-10 to 4-12: the fluid pressure wave, finite elements against
 * the analytic solution phi = phi0 erfc(x / 2 sqrt(t)) at t = 0.001, 0.005 and 0.010 s, for
 * meshes of 4, 8, 16, 32 and 64 elements along x (the thesis's runs). The rod is the one of
 * tests/bench/fluid_charts.c (unit square-ish strip [0, 1] x [0, 0.1], head 1 at x = 0 and 0
 * at x = 1, permeability and storage 1, no gravity: eq. 4.1 with all constants 1), stepped
 * with the implicit (backward Euler) method at dt = 1e-6 s. One chart per time, drawn with
 * porelab's charts (PLplot), like the thesis's three figures.
 *   wave_figures OUTDIR     writes OUTDIR/klosek1997-fig4-{10,11,12}-wave.png
 * Run by tools/figures.sh. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "charts.h"
#include "drawlist.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include "fluid/wave_rod.h"

static pl_world *rod(int n) { return wave_rod(n, 0, 0); }

enum { MAXN = 64 + 1 };

/* Head along the bottom edge y = 0 (nodes created in order of x). */
static int profile(pl_world *w, double *x, double *h) {
    pl_world_prepare(w); /* queries read only: build first */
    int nn = pl_world_fluid_node_count(w);
    pl_vec2 *xy = malloc(sizeof(pl_vec2) * (size_t)nn);
    double *hd = malloc(sizeof(double) * (size_t)nn);
    int m = 0;
    if (xy && hd) {
        pl_world_prepare(w); /* queries read only: build first */
        pl_world_fluid_copy_nodes(w, xy, nn);
        pl_world_prepare(w); /* queries read only: build first */
        pl_world_fluid_copy_node_field(w, PL_FLUID_HEAD, hd, nn);
        for (int i = 0; i < nn && m < MAXN; i++)
            if (fabs(xy[i].y) < 1e-12) {
                x[m] = xy[i].x;
                h[m] = hd[i];
                m++;
            }
    }
    free(xy);
    free(hd);
    return m;
}

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";
    const int ns[5] = {4, 8, 16, 32, 64};
    const double times[3] = {0.001, 0.005, 0.010};
    const char *fig[3] = {"4-10", "4-11", "4-12"};
    static double X[5][3][MAXN], H[5][3][MAXN];
    int M[5][3];
    for (int k = 0; k < 5; k++) {
        pl_world *w = rod(ns[k]);
        const double dt = 1e-6;
        long step = 0;
        for (int ti = 0; ti < 3; ti++) {
            long target = lround(times[ti] / dt);
            for (; step < target; step++) pl_world_fluid_advance(w, dt);
            M[k][ti] = profile(w, X[k][ti], H[k][ti]);
        }
        pl_world_destroy(&w);
    }
    /* analytic curve, and the largest nodal error of the finest mesh for the title */
    enum { NA = 241 };
    double xa[NA], ya[NA];
    const pl_rgba colors[5] = {pl_rgb_hex(0xC44E52), pl_rgb_hex(0xDD8452), pl_rgb_hex(0x55A868),
                               pl_rgb_hex(0x4C72B0), pl_rgb_hex(0x8172B2)};
    char names[5][32];
    for (int ti = 0; ti < 3; ti++) {
        double t = times[ti];
        for (int i = 0; i < NA; i++) {
            xa[i] = 0.3 * i / (NA - 1);
            ya[i] = erfc(xa[i] / (2.0 * sqrt(t)));
        }
        pl_chart_series s[6];
        s[0] = (pl_chart_series){"analytic: erfc(x / 2\xe2\x88\x9at)", xa, ya, NA, PL_SERIES_DASHED,
                                 pl_rgb(0, 0, 0), 2.5};
        double emax = 0.0;
        for (int k = 0; k < 5; k++) {
            snprintf(names[k], sizeof names[k], "%d elements", ns[k]);
            s[k + 1] = (pl_chart_series){names[k], X[k][ti], H[k][ti], M[k][ti],
                                         k < 2 ? PL_SERIES_LINE_POINTS : PL_SERIES_LINE,
                                         colors[k], 1.8};
            if (k == 4)
                for (int i = 0; i < M[k][ti]; i++)
                    emax = fmax(emax, fabs(H[k][ti][i] - erfc(X[k][ti][i] / (2.0 * sqrt(t)))));
        }
        char title[160], path[1024], err[512];
        snprintf(title, sizeof title,
                 "Seed 000 Fig. %s: pressure wave at t = %.3f s (64 elements: max error %.4f)",
                 fig[ti], t, emax);
        pl_chart_def def = pl_default_chart_def();
        def.width = 900;
        def.height = 560;
        def.title = title;
        def.xlabel = "x (distance from the loaded end)";
        def.ylabel = "head \xcf\x86 / \xcf\x86\xe2\x82\x80";
        def.series = s;
        def.series_count = 6;
        def.xmin = 0.0;
        def.xmax = 0.3;
        def.ymin = 0.0;
        def.ymax = 1.02;
        def.legend = 1;
        snprintf(path, sizeof path, "%s/klosek1997-fig%s-wave.png", dir, fig[ti]);
        if (pl_chart_write(path, &def, err, sizeof err)) {
            fprintf(stderr, "wave_figures: %s\n", err);
            return 1;
        }
        printf("wrote %s  (t = %.3f s, 64 elements: largest nodal error %.4f)\n", path, t, emax);
    }
    return 0;
}
