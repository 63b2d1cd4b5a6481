/* Benchmark of the boundary-element Stokes model (not a test; docs/stokes.md "Cost"):
 *   1. error against CPU time for several element counts per particle
 *      - seed 003 §4.4.1, the fixed cylinder in Poiseuille flow (k = 0.2): T/(μU) against the
 *        finest run of the set (every boundary refined in proportion);
 *      - seed 003 §5.1, the disc between walls: its resistance K from one solve against Faxén's
 *        series (Happel & Brenner 7-5.9; 16.533 μ at k = 0.2);
 *   2. cost per coupled grain step with 3, 20, 50 and 100 discs (16 elements each) in a fixed
 *      box, and the dense LU's growth with the boundary nodes (the 400-disc cost extrapolated
 *      from the fitted power, with the memory the dense matrix would need);
 *   3. the §5.1 disc falling between walls with the hydrostatic and the Darcy models beside the
 *      boundary elements: fall velocity after 0.03 s and CPU per step.
 *     bench_stokes [OUT_DIR]   CSV OUT_DIR/bench_stokes.csv; with PLplot the chart
 *                              OUT_DIR/stokes_error_cpu.png */
#include "porelab/darcy.h"
#include "porelab/fluid.h"
#include "porelab/hydrostatic.h"
#include "porelab/stokes.h"
#include "porelab/world.h"
#include "stokes/stokes_cases.h"
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <string.h>
#if PL_STOKES_CHART
#include <plplot.h>
#endif

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

#define NCYL 4
#define NDISC 5

#if PL_STOKES_CHART
static void chart(const char *dir, double c1[], double e1[], int n1, double c2[], double e2[], int n2) {
    char path[512];
    snprintf(path, sizeof path, "%s/stokes_error_cpu.png", dir);
    plsdev("pngcairo");
    plsfnam(path);
    plsetopt("geometry", "760x520");
    plscolbg(255, 255, 255);
    plinit();
    plscol0(1, 0, 0, 0);
    plscol0(9, 31, 78, 156);
    plscol0(3, 155, 34, 38);
    double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
    double lx1[NCYL], ly1[NCYL], lx2[NDISC], ly2[NDISC];
    for (int k = 0; k < n1; k++) {
        lx1[k] = log10(c1[k]);
        ly1[k] = log10(e1[k]);
    }
    for (int k = 0; k < n2; k++) {
        lx2[k] = log10(c2[k]);
        ly2[k] = log10(e2[k]);
    }
    for (int k = 0; k < n1; k++) {
        xmin = fmin(xmin, lx1[k]);
        xmax = fmax(xmax, lx1[k]);
        ymin = fmin(ymin, ly1[k]);
        ymax = fmax(ymax, ly1[k]);
    }
    for (int k = 0; k < n2; k++) {
        xmin = fmin(xmin, lx2[k]);
        xmax = fmax(xmax, lx2[k]);
        ymin = fmin(ymin, ly2[k]);
        ymax = fmax(ymax, ly2[k]);
    }
    plcol0(1);
    plenv(floor(xmin), ceil(xmax), floor(ymin), ceil(ymax), 0, 30);
    pllab("CPU time per solve (s)", "relative error of the drag",
          "Boundary-element Stokes: error against CPU time");
    plcol0(9);
    plline(n1, lx1, ly1);
    plpoin(n1, lx1, ly1, 4);
    plcol0(3);
    plline(n2, lx2, ly2);
    plpoin(n2, lx2, ly2, 4);
    const char *names[2] = {"4.4.1 cylinder in Poiseuille flow (vs finest)", "5.1 disc between walls (vs Faxen)"};
    int opt[2] = {PL_LEGEND_LINE, PL_LEGEND_LINE};
    int tc[2] = {1, 1}, sty[2] = {1, 1}, colors[2] = {9, 3}, sc[2] = {9, 3}, sn[2] = {1, 1};
    double wid[2] = {1, 1}, ss[2] = {1, 1};
    const char *sym[2] = {"#(728)", "#(728)"};
    double lw, lh;
    pllegend(&lw, &lh, 0, PL_POSITION_RIGHT | PL_POSITION_TOP | PL_POSITION_INSIDE, 0.02, 0.02, 0.1, 0, 1, 1, 0, 0, 2,
             opt, 1.0, 0.8, 2.0, 0.0, tc, names, NULL, NULL, NULL, NULL, colors, sty, wid, sc, ss, sn, sym);
    plend();
    printf("wrote %s\n", path);
}
#endif

/* a world with a closed box of four fixed walls (bottom, right, top, left) */
static pl_world *box(double x0, double x1, double y0, double y1, double g, double dt, double density) {
    pl_world_def wd = pl_default_world_def();
    wd.energy_surge_ratio = 1e12;
    wd.gravity = (pl_vec2){0, g};
    wd.dt = dt;
    pl_world *w = pl_world_create(&wd);
    pl_material_def md = pl_default_material_def();
    md.name = "grain";
    md.density = density;
    md.kn = 1e6;
    pl_world_add_material(w, &md);
    const double e = 0.1 * (x1 - x0);
    const pl_vec2 seg[4][2] = {{{x0 - e, y0}, {x1 + e, y0}},
                               {{x1, y0 - e}, {x1, y1 + e}},
                               {{x1 + e, y1}, {x0 - e, y1}},
                               {{x0, y1 + e}, {x0, y0 - e}}};
    for (int k = 0; k < 4; k++) {
        pl_body_def b = pl_default_body_def();
        b.shape = PL_SHAPE_SEGMENT;
        b.motion = PL_MOTION_FIXED;
        b.material = 0;
        b.a = seg[k][0];
        b.b = seg[k][1];
        pl_world_add_body(w, &b);
    }
    return w;
}

static int disc(pl_world *w, pl_vec2 c, double r) {
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_DISC;
    b.material = 0;
    b.position = c;
    b.radius = r;
    return pl_world_add_body(w, &b);
}

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";
    setvbuf(stdout, NULL, _IOLBF, 0);
    char path[512];
    snprintf(path, sizeof path, "%s/bench_stokes.csv", dir);
    FILE *csv = fopen(path, "w");
    if (!csv) {
        fprintf(stderr, "bench_stokes: cannot write %s\n", path);
        return 1;
    }
    fprintf(csv, "case,elements_per_particle,unknowns,cpu_s,value,rel_error\n");
    pl_sb_rules R;
    if (pl_sb_rules_init(&R) != PL_OK) return 1;

    /* 1a. §4.4.1 cylinder: walls 5, ends 2.5, disc 64/(2π) elements per unit length at s = 1 */
    const double sc[NCYL] = {0.25, 0.5, 1, 2}, sref = 3;
    double c1[NCYL], e1[NCYL], T1[NCYL];
    pl_sb_solver s;
    memset(&s, 0, sizeof s);
    const double Tref = sc_cylinder(&R, &s, 0.2, 15, (int)(150 * sref), (int)(25 * sref), (int)(64 * sref), 0, NULL);
    printf("4.4.1 cylinder, k = 0.2: reference (disc %d elements, walls %d) T/(mu U) = %.5f (Tan 24.20)\n",
           (int)(64 * sref), (int)(150 * sref), Tref);
    printf("  disc elements  unknowns  CPU per solve (s)  T/(mu U)   error vs finest\n");
    for (int i = 0; i < NCYL; i++) {
        pl_sb_solver_free(&s);
        memset(&s, 0, sizeof s);
        const double t0 = cpu();
        T1[i] = sc_cylinder(&R, &s, 0.2, 15, (int)(150 * sc[i]), (int)(25 * sc[i]), (int)(64 * sc[i]), 0, NULL);
        c1[i] = cpu() - t0;
        e1[i] = fabs(T1[i] / Tref - 1);
        printf("  %13d  %8d  %17.3f  %9.5f  %.2e\n", (int)(64 * sc[i]), s.n, c1[i], T1[i], e1[i]);
        fprintf(csv, "cylinder_4.4.1,%d,%d,%.6g,%.8g,%.6g\n", (int)(64 * sc[i]), s.n, c1[i], T1[i], e1[i]);
    }
    pl_sb_solver_free(&s);

    /* 1b. §5.1 disc: resistance from one world solve against Faxén */
    const int nd[NDISC] = {8, 16, 32, 64, 128};
    double c2[NDISC], e2[NDISC];
    const double Kf = 50 * sc_faxen(0.2);
    printf("5.1 disc between walls (r = 0.5 cm, 2b = 5 cm, 40 cm high, mu = 50 P): Faxen K = %.3f g/(cm s)\n", Kf);
    printf("  disc elements  unknowns  CPU per solve (s)  K/mu      error vs Faxen\n");
    for (int i = 0; i < NDISC; i++) {
        pl_world *w = box(-2.5, 2.5, -20, 20, -980, 5e-4, 2.0);
        const int d = disc(w, (pl_vec2){0, 0}, 0.5);
        pl_stokes_def sd = pl_default_stokes_def();
        sd.viscosity = 50;
        sd.density = 1;
        sd.disc_elements = nd[i];
        sd.wall_elements = 4;
        sd.element_length = 8.0 / nd[i];
        pl_world_attach_stokes(w, &sd);
        const double t0 = cpu();
        if (pl_world_stokes_solve(w) != PL_OK) {
            fprintf(stderr, "solve: %s\n", pl_world_last_error(w));
            return 1;
        }
        c2[i] = cpu() - t0;
        pl_stokes_body_result r;
        pl_world_stokes_body(w, d, &r);
        e2[i] = fabs(r.k_trans / Kf - 1);
        printf("  %13d  %8d  %17.3f  %8.4f  %.2e\n", nd[i], pl_world_stokes_unknowns(w), c2[i], r.k_trans / 50, e2[i]);
        fprintf(csv, "disc_5.1,%d,%d,%.6g,%.8g,%.6g\n", nd[i], pl_world_stokes_unknowns(w), c2[i], r.k_trans / 50, e2[i]);
        pl_world_destroy(&w);
    }
#if PL_STOKES_CHART
    chart(dir, c1, e1, NCYL, c2, e2, NDISC);
#endif

    /* 2. cost per coupled step: N discs r = 1 cm, 16 elements each, solid fraction about 0.2,
       placed on a jittered lattice (clearance at least 0.4 r) */
    const int NN[4] = {3, 20, 50, 100};
    double lnN[4], lnT[4];
    printf("cost per coupled step (16 elements per disc, fixed box, water):\n"
           "  discs  unknowns  CPU per step (s)\n");
    for (int q = 0; q < 4; q++) {
        const int N = NN[q];
        const double r = 0.01, side = sqrt(N * M_PI * r * r / 0.2);
        const int nx = (int)ceil(sqrt((double)N));
        const double pitch = side / nx;
        pl_world *w = box(0, side, 0, side, 0, 1e-4, 2650);
        srand(7);
        for (int k = 0; k < N; k++) {
            const double jx = (rand() / (double)RAND_MAX - 0.5) * (pitch - 2.4 * r);
            const double jy = (rand() / (double)RAND_MAX - 0.5) * (pitch - 2.4 * r);
            disc(w, (pl_vec2){(k % nx + 0.5) * pitch + jx, (k / nx + 0.5) * pitch + jy}, r);
        }
        pl_stokes_def sd = pl_default_stokes_def();
        sd.disc_elements = 16;
        sd.wall_elements = 4;
        sd.element_length = 2 * M_PI * r / 16;
        sd.check_stability = 1;
        pl_world_attach_stokes(w, &sd);
        pl_world_step(w, 1); /* first step: the container's factor */
        const int steps = N >= 50 ? 1 : 3;
        const double t0 = cpu();
        if (pl_world_step(w, steps) != PL_OK) {
            fprintf(stderr, "step: %s\n", pl_world_last_error(w));
            return 1;
        }
        const double t = (cpu() - t0) / steps;
        const int n = pl_world_stokes_unknowns(w);
        lnN[q] = log((double)n);
        lnT[q] = log(t);
        printf("  %5d  %8d  %16.3f\n", N, n, t);
        fprintf(csv, "step_cost,%d,%d,%.6g,%d,\n", 16, n, t, N);
        pl_world_destroy(&w);
    }
    const double p = (lnT[3] - lnT[2]) / (lnN[3] - lnN[2]);
    const double n400 = exp(lnN[3]) * 4.0; /* unknowns grow with the discs */
    const double t400 = exp(lnT[3]) * pow(4.0, p);
    printf("  growth between 50 and 100 discs: CPU ~ unknowns^%.2f; 400 discs (about %.0f unknowns): about %.0f s "
           "per step (extrapolated), dense matrix %.1f GB\n",
           p, n400, t400, n400 * n400 * 8 / 1e9);
    fprintf(csv, "step_cost_400_extrapolated,16,%.0f,%.6g,400,\n", n400, t400);

    /* 3. the §5.1 disc with the other fluid rungs: fall velocity after 0.03 s */
    printf("5.1 disc falling between walls, 60 steps of 0.5 ms (exact terminal velocity 0.9311 cm/s, Faxen):\n"
           "  model           v after 0.03 s (cm/s)  CPU per step (s)\n");
    for (int m = 0; m < 3; m++) {
        pl_world *w = box(-2.5, 2.5, -20, 20, -980, 5e-4, 2.0);
        const int d = disc(w, (pl_vec2){0, 0}, 0.5);
        pl_status st = PL_OK;
        const char *name = "";
        if (m == 0) {
            name = "stokes (BEM)";
            pl_stokes_def sd = pl_default_stokes_def();
            sd.viscosity = 50;
            sd.density = 1;
            sd.disc_elements = 32;
            sd.element_length = 0.25;
            st = pl_world_attach_stokes(w, &sd);
        } else if (m == 1) {
            name = "hydrostatic";
            pl_hydrostatic_def hd = pl_default_hydrostatic_def();
            hd.x_min = -2.5;
            hd.x_max = 2.5;
            hd.bottom = -20;
            hd.level = 20;
            hd.density = 1;
            st = pl_world_attach_hydrostatic(w, &hd);
        } else {
            name = "darcy";
            pl_fluid_quad_def q = pl_default_fluid_quad_def();
            q.corners[0] = (pl_vec2){-2.5, -20};
            q.corners[1] = (pl_vec2){2.5, -20};
            q.corners[2] = (pl_vec2){2.5, 20};
            q.corners[3] = (pl_vec2){-2.5, 20};
            q.ndivx = 5;
            q.ndivy = 40;
            if (pl_world_add_fluid_quad(w, &q) < 0) st = PL_ERR_ARG;
            pl_darcy_def dd = pl_default_darcy_def();
            dd.on = 1;
            dd.density = 1;
            dd.viscosity = 50;
            dd.perm_mode = 1;
            /* start from the static (hydrostatic) field: from zero pressure the water column
               first drains downwards through the grain and drags it faster than free fall
               (32 cm/s after 0.03 s instead of 14.7) */
            dd.first_step_static = 1;
            if (st == PL_OK) st = pl_world_set_darcy(w, &dd);
            if (st == PL_OK) pl_world_add_fluid_bc(w, (pl_vec2){-2.5, 20}, (pl_vec2){2.5, 20}, 0);
        }
        if (st == PL_OK) {
            const double t0 = cpu();
            st = pl_world_step(w, 60);
            const double t = (cpu() - t0) / 60;
            pl_body_info bi;
            pl_world_body_info(w, d, &bi);
            printf("  %-15s %21.4f  %16.2e\n", name, -bi.velocity.y, t);
            fprintf(csv, "rung_%s,,,%.6g,%.8g,\n", name, t, -bi.velocity.y);
        }
        if (st != PL_OK) printf("  %-15s refused: %s\n", name, pl_world_last_error(w));
        pl_world_destroy(&w);
    }
    fclose(csv);
    printf("wrote %s\n", path);
    return 0;
}
