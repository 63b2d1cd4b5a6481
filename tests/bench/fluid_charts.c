/* Charts of the fluid validation (PLplot, PNG): FE against analytic pressure-wave profiles
 * like seed 000 Figs. 4-10 to 4-12, error against CPU time for explicit and implicit stepping,
 * and the porosity methods' accuracy against cost. Writes into the folder given (docs/img).
 *   fluid_charts docs/img */
#define _POSIX_C_SOURCE 200809L
#include "porelab/fluid.h"
#include "porelab/world.h"
#include "fluid/wave_rod.h"
#include <math.h>
#include <plplot.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double cpu(void) {
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static pl_world *rod(int n, int method) { return wave_rod(n, method, 0); }

/* Profile along y = 0: nodes on the bottom edge, sorted by x (they are created in order). */
static int profile(pl_world *w, double *x, double *h, int cap) {
    pl_world_prepare(w); /* queries read only: build first */
    int nn = pl_world_fluid_node_count(w);
    pl_vec2 *xy = malloc(sizeof(pl_vec2) * nn);
    double *hd = malloc(sizeof(double) * nn);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_nodes(w, xy, nn);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_node_field(w, PL_FLUID_HEAD, hd, nn);
    int m = 0;
    for (int i = 0; i < nn && m < cap; i++)
        if (fabs(xy[i].y) < 1e-12) { x[m] = xy[i].x; h[m] = hd[i]; m++; }
    free(xy);
    free(hd);
    return m;
}

static double max_error(pl_world *w, double t) {
    pl_world_prepare(w); /* queries read only: build first */
    int nn = pl_world_fluid_node_count(w);
    pl_vec2 *xy = malloc(sizeof(pl_vec2) * nn);
    double *hd = malloc(sizeof(double) * nn), e = 0;
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_nodes(w, xy, nn);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_node_field(w, PL_FLUID_HEAD, hd, nn);
    for (int i = 0; i < nn; i++) e = fmax(e, fabs(hd[i] - erfc(xy[i].x / (2 * sqrt(t)))));
    free(xy);
    free(hd);
    return e;
}

enum { INK = 1, GRID = 2, S0 = 3 }; /* cmap0 slots: ink, grid, series S0 .. S0 + 5 */

static void start(const char *dir, const char *name, int w, int h) {
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    plsdev("pngcairo");
    plsfnam(path);
    char geo[64];
    snprintf(geo, sizeof geo, "%dx%d", w, h);
    plsetopt("geometry", geo);
    plscolbg(255, 255, 255);
    plinit();
    /* the chart palette of app/render/charts.c: ink, light grid, series dark enough on white */
    plscol0(INK, 34, 34, 38);
    plscol0(GRID, 222, 222, 226);
    static const unsigned series[6] = {0x1F5FA8, 0xC8384B, 0x2E8B57, 0xE08E1B, 0x6B4C9A, 0x555555};
    for (int i = 0; i < 6; i++) plscol0(S0 + i, (int)(series[i] >> 16) & 255, (int)(series[i] >> 8) & 255, (int)series[i] & 255);
    printf("writing %s\n", path);
}

/* light grid at the major ticks, then the frame and its labels in ink */
static void frame(const char *xopt, const char *yopt) {
    plcol0(GRID);
    plwidth(1.0);
    plbox(strchr(xopt, 'l') ? "gl" : "g", 0, 0, strchr(yopt, 'l') ? "gl" : "g", 0, 0);
    plcol0(INK);
    plwidth(1.2);
    plbox(xopt, 0, 0, yopt, 0, 0);
}

static void wave_profiles(const char *dir) {
    const int ns[5] = {4, 8, 16, 32, 64};
    const double times[3] = {0.001, 0.005, 0.010};
    static double X[5][3][80], H[5][3][80];
    int M[5][3];
    for (int k = 0; k < 5; k++) {
        pl_world *w = rod(ns[k], 0);
        double t = 0, dt = 1e-6;
        int ti = 0;
        while (ti < 3) {
            pl_world_fluid_advance(w, dt);
            t += dt;
            if (fabs(t - times[ti]) < 0.5 * dt) { M[k][ti] = profile(w, X[k][ti], H[k][ti], 80); ti++; }
        }
        pl_world_destroy(&w);
    }
    start(dir, "fluid_wave_profiles.png", 1200, 420);
    plssub(3, 1);
    const int colors[5] = {S0, S0 + 1, S0 + 2, S0 + 3, S0 + 4};
    for (int ti = 0; ti < 3; ti++) {
        pladv(0);
        plvpor(0.23, 0.92, 0.16, 0.86); /* room for the head label left of the tick labels */
        plwind(0, 0.3, 0, 1.05);
        frame("bcnst", "bcnstv");
        char title[64];
        snprintf(title, sizeof title, "t = %g s", times[ti]);
        pllab("x (m)", "", title);
        plmtex("l", 4.2, 0.5, 0.5, "head (m)"); /* pllab's 5 character heights fall off a narrow panel */
        double xa[200], ya[200];
        for (int i = 0; i < 200; i++) { xa[i] = 0.3 * i / 199; ya[i] = erfc(xa[i] / (2 * sqrt(times[ti]))); }
        plcol0(INK);
        plwidth(2.5);
        pllsty(3);
        plline(200, xa, ya);
        pllsty(1);
        plwidth(1.6);
        for (int k = 0; k < 5; k++) {
            plcol0(colors[k]);
            plline(M[k][ti], X[k][ti], H[k][ti]);
        }
        if (ti == 0) { /* top right of the first panel: above every curve */
            const char *txt[6] = {"erfc (analytic)", "N = 4", "N = 8", "N = 16", "N = 32", "N = 64"};
            int opt[6], col[6], sty[6];
            double wid[6];
            for (int i = 0; i < 6; i++) { opt[i] = PL_LEGEND_LINE; col[i] = i ? colors[i - 1] : 1; sty[i] = i ? 1 : 3; wid[i] = i ? 1.6 : 2.5; }
            double lw, lh;
            int tc[6] = {1, 1, 1, 1, 1, 1};
            pllegend(&lw, &lh, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX,
                     PL_POSITION_RIGHT | PL_POSITION_TOP | PL_POSITION_INSIDE, 0.01, 0.01, 0.06, 0, GRID, 1, 0, 0, 6, opt,
                     0.6, 0.72, 1.5, 0.0, tc, (const char **)txt, NULL, NULL, NULL, NULL, col, sty, wid, NULL, NULL,
                     NULL, NULL);
        }
    }
    plend();
}

static void error_cpu(const char *dir) {
    const int ns[4] = {8, 16, 32, 64};
    const char *names[3] = {"backward Euler", "Crank-Nicolson", "explicit (sub-stepped)"};
    double E[3][4], C[3][4];
    const double T = 0.01, dt = 2.5e-4;
    FILE *csv = NULL;
    char path[512];
    snprintf(path, sizeof path, "%s/fluid_wave_error_cpu.csv", dir);
    csv = fopen(path, "w");
    if (csv) fprintf(csv, "method,N,fluid_dt,error,cpu_s\n");
    for (int m = 0; m < 3; m++)
        for (int k = 0; k < 4; k++) {
            double best = 1e300, err = 0;
            for (int rep = 0; rep < 3; rep++) {
                pl_world *w = rod(ns[k], m);
                double c0 = cpu();
                for (int s = 0; s < (int)(T / dt + 0.5); s++) pl_world_fluid_advance(w, dt);
                double c = cpu() - c0;
                err = max_error(w, T);
                best = fmin(best, c);
                pl_world_destroy(&w);
            }
            E[m][k] = err;
            C[m][k] = best;
            if (csv) fprintf(csv, "%s,%d,%g,%.6e,%.6e\n", names[m], ns[k], dt, err, best);
        }
    if (csv) fclose(csv);
    start(dir, "fluid_wave_error_cpu.png", 700, 500);
    double lx[4], ly[4], xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
    for (int m = 0; m < 3; m++)
        for (int k = 0; k < 4; k++) {
            xmin = fmin(xmin, log10(C[m][k])); xmax = fmax(xmax, log10(C[m][k]));
            ymin = fmin(ymin, log10(E[m][k])); ymax = fmax(ymax, log10(E[m][k]));
        }
    plcol0(INK);
    plenv(floor(xmin), ceil(xmax), floor(ymin), ceil(ymax), 0, 30);
    frame("bcnstl", "bcnstvl");
    pllab("CPU time (s)", "max head error at t = 0.01 s (m)", "Pressure wave: error against cost (N = 8 … 64, fluid step 2.5 × 10#u−4#d s)");
    const int colors[3] = {S0, S0 + 1, S0 + 2};
    for (int m = 0; m < 3; m++) {
        for (int k = 0; k < 4; k++) { lx[k] = log10(C[m][k]); ly[k] = log10(E[m][k]); }
        plcol0(colors[m]);
        plline(4, lx, ly);
        plpoin(4, lx, ly, 4);
    }
    int opt[3] = {PL_LEGEND_LINE, PL_LEGEND_LINE, PL_LEGEND_LINE};
    int tc[3] = {1, 1, 1}, sty[3] = {1, 1, 1};
    double wid[3] = {1, 1, 1};
    double lw, lh;
    pllegend(&lw, &lh, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX,
             PL_POSITION_RIGHT | PL_POSITION_TOP | PL_POSITION_INSIDE, 0.02, 0.02, 0.1, 0, GRID, 1, 0, 0, 3, opt, 0.8,
             0.8, 2.0, 0.0, tc, names, NULL, NULL, NULL, NULL, colors, sty, wid, NULL, NULL, NULL, NULL);
    plend();
}

/* Porosity: pixellation error and time against exact clipping on a packing. */
static void porosity_cost(const char *dir) {
    pl_world_def wd = pl_default_world_def();
    pl_world *w = pl_world_create(&wd);
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){1.2, 0};
    q.corners[2] = (pl_vec2){1.2, 0.8};
    q.corners[3] = (pl_vec2){0, 0.8};
    q.ndivx = 24;
    q.ndivy = 16;
    pl_world_add_fluid_quad(w, &q);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){1.2, 0}, 0.8);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0.8}, (pl_vec2){1.2, 0.8}, 0);
    pl_world_set_flag(w, "FLUID_PERM", 1);
    pl_material_def md = pl_default_material_def();
    md.name = "g";
    md.density = 2650;
    md.kn = 1e6;
    pl_world_add_material(w, &md);
    for (int j = 0; j < 28; j++)
        for (int i = 0; i < 44; i++) {
            pl_body_def b = pl_default_body_def();
            b.material = 0;
            b.motion = PL_MOTION_FIXED;
            b.shape = PL_SHAPE_DISC;
            b.position = (pl_vec2){0.02 + i * 0.026 + (j % 2) * 0.01, 0.02 + j * 0.026};
            b.radius = 0.009 + 0.003 * ((i * 7 + j * 3) % 4) / 3.0;
            pl_world_add_body(w, &b);
        }
    pl_world_fluid_solve_static(w);
    pl_world_prepare(w); /* queries read only: build first */
    int ne = pl_world_fluid_triangle_count(w);
    double *ex = malloc(sizeof(double) * ne), *px = malloc(sizeof(double) * ne);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_element_field(w, PL_FLUID_SOLID_AREA, ex, ne);
    pl_fluid_stats s0, s1;
    double t_exact = 1e300;
    for (int rep = 0; rep < 5; rep++) {
        pl_world_fluid_stats(w, &s0);
        pl_world_fluid_advance(w, 1e-3);
        pl_world_fluid_stats(w, &s1);
        t_exact = fmin(t_exact, s1.t_porosity - s0.t_porosity);
    }
    double err[6], tim[6];
    int res[6] = {2, 4, 8, 16, 32, 64};
    for (int k = 0; k < 6; k++) {
        pl_world_set_flag(w, "FLUID_POROSITY_METHOD", 1);
        pl_world_set_flag(w, "FLUID_PIXELS", res[k]);
        double best = 1e300;
        for (int rep = 0; rep < 3; rep++) {
            pl_world_fluid_stats(w, &s0);
            pl_world_fluid_advance(w, 1e-3);
            pl_world_fluid_stats(w, &s1);
            best = fmin(best, s1.t_porosity - s0.t_porosity);
        }
        pl_world_prepare(w); /* queries read only: build first */
        pl_world_fluid_copy_element_field(w, PL_FLUID_SOLID_AREA, px, ne);
        double e = 0, A = 0.96 / ne;
        for (int i = 0; i < ne; i++) e += fabs(px[i] - ex[i]);
        err[k] = e / (ne * A);
        tim[k] = best;
        printf("pixels %d: mean |error| / element area %.4e, %.4e s (exact %.4e s)\n", res[k], err[k], tim[k], t_exact);
    }
    start(dir, "fluid_porosity_cost.png", 700, 500);
    double lx[6], ly[6];
    for (int k = 0; k < 6; k++) { lx[k] = log10(tim[k]); ly[k] = log10(err[k]); }
    plcol0(INK);
    plenv(floor(fmin(lx[0], log10(t_exact))), ceil(lx[5]), -4, 0, 0, 30);
    frame("bcnstl", "bcnstvl");
    pllab("time per porosity update (s)", "mean |solid area error| / element area",
          "Porosity: pixellation (2 … 64 px) against exact clipping");
    plcol0(S0);
    plline(6, lx, ly);
    plpoin(6, lx, ly, 4);
    for (int k = 0; k < 6; k++) {
        /* right of its marker; a label that would run past the frame's right edge goes left of it */
        char lab[16];
        int left = lx[k] > ceil(lx[5]) - 0.35;
        snprintf(lab, sizeof lab, left ? "%d px  " : "  %d px", res[k]);
        plptex(lx[k], ly[k], 1, 0, left ? 1.0 : 0.0, lab);
    }
    double ex_x[2] = {log10(t_exact), log10(t_exact)}, ex_y[2] = {-4, 0};
    plcol0(S0 + 1);
    pllsty(2);
    plline(2, ex_x, ex_y);
    pllsty(1);
    plptex(log10(t_exact), -3.7, 1, 0, -0.05, "exact clipping (error 0)");
    plend();
    free(ex);
    free(px);
    pl_world_destroy(&w);
}

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";
    wave_profiles(dir);
    error_cpu(dir);
    porosity_cost(dir);
    return 0;
}
