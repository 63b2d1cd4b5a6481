/* Benchmark of the Darcy fluid update (seed 000 ch. 3; issue: Performance).
 * A 100 x 100-cell quad (1 m x 1 m, 40,000 triangles, 20,201 nodes) under upward flow with
 * 5,000 discs (FLUID_PERM = 1, exact porosity), moved slightly before every update so that
 * porosity, permeability and the factorization really change. Prints the time per update
 * split into porosity, assembly, factorization, solve and forces (pressure + drag on every
 * grain), and the same for a plain static P1 solve to compare with FreeFEM++
 * (tests/bench/run_freefem.sh). Writes a CSV line per measurement to bench_fluid.csv.
 *   bench_fluid [cells] [grains] [updates]      (defaults 100 5000 10) */
#define _POSIX_C_SOURCE 200809L
#include "porelab/fluid.h"
#include "porelab/world.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static double urand(void) {
    rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

int main(int argc, char **argv) {
    int cells = argc > 1 ? atoi(argv[1]) : 100;
    int grains = argc > 2 ? atoi(argv[2]) : 5000;
    int updates = argc > 3 ? atoi(argv[3]) : 10;
    pl_world_def wd = pl_default_world_def();
    pl_world *w = pl_world_create(&wd);
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){1, 0};
    q.corners[2] = (pl_vec2){1, 1};
    q.corners[3] = (pl_vec2){0, 1};
    q.ndivx = q.ndivy = cells;
    pl_world_add_fluid_quad(w, &q);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){1, 0}, 1.5);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 1}, (pl_vec2){1, 1}, 0);
    pl_world_set_flag(w, "FLUID_PERM", 1);
    pl_world_set_flag(w, "FLUID_STORAGE", 0); /* quasi-static: a full static solve per update */
    pl_material_def md = pl_default_material_def();
    md.name = "sand";
    md.density = 2650;
    md.kn = 1e6;
    pl_world_add_material(w, &md);
    int side = (int)ceil(sqrt((double)grains));
    double pitch = 1.0 / side, r = 0.42 * pitch;
    for (int k = 0; k < grains; k++) {
        pl_body_def b = pl_default_body_def();
        b.material = 0;
        b.motion = PL_MOTION_FIXED;
        b.shape = PL_SHAPE_DISC;
        b.radius = r * (0.8 + 0.2 * urand());
        b.position = (pl_vec2){(k % side + 0.5) * pitch, (k / side + 0.5) * pitch};
        if (pl_world_add_body(w, &b) < 0) {
            fprintf(stderr, "%s\n", pl_world_last_error(w));
            return 1;
        }
    }
    double t0 = now();
    if (pl_world_fluid_solve_static(w) != PL_OK) {
        fprintf(stderr, "%s\n", pl_world_last_error(w));
        return 1;
    }
    double t_first = now() - t0;
    pl_world_prepare(w); /* queries read only: build first */
    int nn = pl_world_fluid_node_count(w), ne = pl_world_fluid_triangle_count(w);
    pl_fluid_stats s0, s1;
    pl_world_fluid_stats(w, &s0);
    double t_forces = 0, t_total = 0;
    for (int u = 0; u < updates; u++) {
        for (int k = 0; k < grains; k++) { /* small moves: every element's porosity changes */
            pl_vec2 p = {(k % side + 0.5) * pitch + 0.05 * pitch * (urand() - 0.5),
                         (k / side + 0.5) * pitch + 0.05 * pitch * (urand() - 0.5)};
            pl_world_set_body_position(w, k, p, 0);
        }
        double a = now();
        if (pl_world_fluid_advance(w, 1e-3) != PL_OK) {
            fprintf(stderr, "%s\n", pl_world_last_error(w));
            return 1;
        }
        double b = now();
        pl_vec2 F;
        double M;
        pl_world_prepare(w); /* queries read only: build first */
        for (int k = 0; k < grains; k++) pl_world_fluid_body_force(w, k, &F, &M);
        double c = now();
        t_forces += c - b;
        t_total += c - a;
    }
    pl_world_fluid_stats(w, &s1);
    double n = updates;
    double tp = (s1.t_porosity - s0.t_porosity) / n, ta = (s1.t_assembly - s0.t_assembly) / n;
    double tf = (s1.t_factor - s0.t_factor) / n, ts = (s1.t_solve - s0.t_solve) / n, tF = t_forces / n;
    printf("porelab fluid update: %d x %d cells, %d nodes, %d triangles, %d grains, %d updates\n", cells, cells, nn, ne,
           grains, updates);
    printf("  first build (mesh, pattern, symbolic analysis, porosity, assembly, factor, solve): %.4f s\n", t_first);
    printf("  per update: porosity %.4f s, assembly %.4f s, factorization %.4f s, solve %.4f s, forces %.4f s, total %.4f s\n",
           tp, ta, tf, ts, tF, t_total / n);
    printf("  factorizations %ld, analyses %ld (symbolic analysis reused)\n", s1.factorizations - s0.factorizations,
           s1.analyses - s0.analyses);
    /* unchanged grains: refactorization and solve skipped */
    pl_world_fluid_stats(w, &s0);
    double a = now();
    pl_world_fluid_advance(w, 1e-3);
    double t_same = now() - a;
    pl_world_fluid_stats(w, &s1);
    printf("  update with nothing moved: %.4f s (factorizations %ld, solves skipped %ld)\n", t_same,
           s1.factorizations - s0.factorizations, s1.skipped - s0.skipped);
    pl_world_destroy(&w);

    /* plain static P1 problem on the same mesh for the FreeFEM++ comparison: uniform
       conductivity, heads 1 and 0 on two sides; assembly = element values into the fixed
       pattern; factor + solve; re-solve with the stored factor */
    w = pl_world_create(&wd);
    pl_world_add_fluid_quad(w, &q);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){1, 0}, 1);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 1}, (pl_vec2){1, 1}, 0);
    pl_world_set_flag(w, "GRAVITY_Y", 0);
    pl_world_set_flag(w, "FLUID_PERM", 0);
    pl_world_set_flag(w, "FLUID_STORAGE", 1);
    pl_world_set_flag(w, "FLUID_DRAG", 0);
    a = now();
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_node_count(w); /* mesh */
    double t_mesh = now() - a;
    pl_world_fluid_stats(w, &s0);
    a = now();
    pl_world_fluid_solve_static(w); /* pattern + analysis + assembly + factor + solve */
    double t_static = now() - a;
    pl_world_fluid_stats(w, &s1);
    double asm_ = s1.t_assembly - s0.t_assembly, fac = s1.t_factor - s0.t_factor, sol = s1.t_solve - s0.t_solve;
    /* re-solve: a transient step with the factor kept (same dt) */
    pl_world_fluid_advance(w, 1e-3);
    pl_world_fluid_stats(w, &s0);
    a = now();
    pl_world_fluid_advance(w, 1e-3);
    double t_resolve = now() - a;
    pl_world_fluid_stats(w, &s1);
    printf("static P1 solve (same mesh, %d nodes): mesh + pattern + symbolic analysis %.4f s, first solve %.4f s, assembly %.4f s, "
           "factor %.4f s, solve %.4f s, factor+solve %.4f s, re-solve %.4f s (factorizations %ld)\n",
           pl_world_fluid_node_count(w), t_mesh, t_static, asm_, fac, sol, fac + sol, t_resolve,
           s1.factorizations - s0.factorizations);
    printf("CSV nodes,triangles,grains,porosity,assembly,factor,solve,forces,setup,static_assembly,static_factor_solve,resolve\n");
    printf("CSV %d,%d,%d,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", nn, ne, grains, tp, ta, tf, ts, tF, t_mesh, asm_,
           fac + sol, t_resolve);
    pl_world_destroy(&w);
    return 0;
}
