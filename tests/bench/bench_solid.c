/* Benchmark of the solid kernels (not a test): element-steps per second of the explicit step
 * (internal forces, stress update, pressure, central differences) for about 10k and 100k
 * linear triangles, plain against FIC (explicit and semi-implicit pressure), and Q1/P0 on
 * the same number of quadrilaterals' worth of elements. Elastic steel block, clamped at the
 * bottom, initial velocity field, small strain. Prints a table and writes
 * bench_solid.csv (formulation, elements, steps, seconds, element_steps_per_s).
 * Then the coupled cost of the cutting scene (scenes/solids/cutting.lua built in C: 15 x 7
 * lattice discs of sand in a box, the elasto-plastic FIC tool at 4 m/s) split into grains,
 * solid and grain-edge contact, per step, on one monotonic clock.
 *   build/tests/bench_solid [steps] [coupled_steps]   (defaults 200, 3000) */
#define _POSIX_C_SOURCE 200809L
#include "solid/fic/solid_internal.h"
#include "solid/fic/solid_mesh.h"
#include "porelab/world.h"
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The cutting scene of scenes/solids/cutting.lua: grains, then the tool; cost split. */
/* argv[3]: a Markdown file that receives both tables (docs/solids.md, "Cost", through
   tests/bench/run_all.sh solid) */
static FILE *table_md;

static int coupled(int steps) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, -9.81};
    wd.dt_safety = 0.3;
    pl_world *w = pl_world_create(&wd);
    pl_material_def md = pl_default_material_def();
    md.name = "sand";
    md.density = 2600;
    md.kn = 5e6;
    md.friction = 0.5;
    md.restitution = 0.3;
    const int sand = pl_world_add_material(w, &md);
    const pl_vec2 box[4][2] = {{{0, 0}, {0.12, 0}}, {{0.12, 0}, {0.12, 0.05}}, {{0.12, 0.05}, {0, 0.05}}, {{0, 0.05}, {0, 0}}};
    for (int k = 0; k < 4; k++) {
        pl_body_def b = pl_default_body_def();
        b.shape = PL_SHAPE_SEGMENT;
        b.motion = PL_MOTION_FIXED;
        b.material = sand;
        b.a = box[k][0];
        b.b = box[k][1];
        if (pl_world_add_body(w, &b) < 0) {
            fprintf(stderr, "%s\n", pl_world_last_error(w));
            return 1;
        }
    }
    int grains = 0;
    for (int j = 0; j < 7; j++)
        for (int i = 0; i < 29; i++) {
            pl_body_def b = pl_default_body_def();
            b.shape = PL_SHAPE_DISC;
            b.motion = PL_MOTION_DYNAMIC;
            b.material = sand;
            b.radius = 0.002;
            b.position = (pl_vec2){0.003 + 0.004 * i + (j % 2) * 0.002, 0.003 + 0.00346 * j};
            if (pl_world_add_body(w, &b) < 0) {
                fprintf(stderr, "%s\n", pl_world_last_error(w));
                return 1;
            }
            grains++;
        }
    pl_solid_def sd = pl_default_solid_def();
    sd.young = 2e9;
    sd.poisson = 0.3;
    sd.density = 7800;
    sd.yield_stress = 2e7;
    sd.hardening = 2e8;
    sd.large_strain = 1;
    sd.contact_stiffness = 5e6;
    sd.contact_damping = 20;
    sd.friction = 0.4;
    const pl_vec2 tool[4] = {{0.010, 0.024}, {0.020, 0.024}, {0.026, 0.050}, {0.016, 0.050}};
    if (pl_world_attach_solid(w, &sd) != PL_OK || pl_world_solid_polygon(w, tool, 4, 0.0015) < 0 ||
        pl_world_solid_velocity(w, 0.0, 0.045, 0.05, 0.051, 3, 4.0, 0.0) < 0) {
        fprintf(stderr, "%s\n", pl_world_last_error(w));
        return 1;
    }
    if (pl_world_step(w, 10) != PL_OK) {
        fprintf(stderr, "%s\n", pl_world_last_error(w));
        return 1;
    }
    double s0, c0, s1, c1;
    pl_world_solid_cost(w, &s0, &c0);
    const double t0 = now();
    if (pl_world_step(w, steps) != PL_OK) {
        fprintf(stderr, "%s\n", pl_world_last_error(w));
        return 1;
    }
    const double total = now() - t0;
    pl_world_solid_cost(w, &s1, &c1);
    const double fe = s1 - s0, ct = c1 - c0;
    if (table_md) {
        fprintf(table_md, "\nCoupled cost of the cutting scene built in C (%d grains, %d elasto-plastic triangles in updated "
                    "Lagrangian form), %d steps:\n\n",
                grains, pl_world_solid_element_count(w), steps);
        fprintf(table_md, "| part | ms per step | share |\n|---|---|---|\n");
        fprintf(table_md, "| grains (contacts, integration, guards) | %.3f | %.0f %% |\n", 1e3 * (total - fe - ct) / steps,
                100 * (total - fe - ct) / total);
        fprintf(table_md, "| solid (FIC pressure: S refactorised each step, stress update, forces) | %.3f | %.0f %% |\n",
                1e3 * fe / steps, 100 * fe / total);
        fprintf(table_md, "| grain–edge contact (search and forces) | %.3f | %.0f %% |\n", 1e3 * ct / steps, 100 * ct / total);
        fprintf(table_md, "| total | %.3f | |\n", 1e3 * total / steps);
    }
    printf("\ncutting scene (%d grains, %d triangles), %d steps: %.3g ms per step = grains %.3g ms (%.0f %%), "
           "solid %.3g ms (%.0f %%), contact %.3g ms (%.0f %%)\n",
           grains, pl_world_solid_element_count(w), steps, 1e3 * total / steps, 1e3 * (total - fe - ct) / steps,
           100 * (total - fe - ct) / total, 1e3 * fe / steps, 100 * fe / total, 1e3 * ct / steps, 100 * ct / total);
    pl_world_destroy(&w);
    return 0;
}

int main(int argc, char **argv) {
    const int steps = argc > 1 ? atoi(argv[1]) : 200;
    if (argc > 3 && !(table_md = fopen(argv[3], "w"))) {
        fprintf(stderr, "bench_solid: cannot write the table file '%s' (argument 3)\n", argv[3]);
        return 1;
    }
    double rate_of[2][4];
    int ne_of[2][4];
    const int forms[4] = {PL_SOLID_PLAIN, PL_SOLID_FIC_EXPLICIT, PL_SOLID_FIC_SEMI_IMPLICIT, PL_SOLID_Q1P0};
    const char *names[4] = {"plain", "fic_explicit", "fic_semi_implicit", "q1p0"};
    const int sizes[2][2] = {{100, 50}, {316, 158}};
    FILE *csv = fopen("bench_solid.csv", "w");
    if (csv) fprintf(csv, "formulation,elements,steps,seconds,element_steps_per_s\n");
    printf("%-18s %9s %7s %9s %14s\n", "formulation", "elements", "steps", "seconds", "elem-steps/s");
    for (int z = 0; z < 2; z++)
        for (int f = 0; f < 4; f++) {
            pl_solid_def d = pl_default_solid_def();
            d.formulation = forms[f];
            d.fic_alpha = forms[f] == PL_SOLID_FIC_EXPLICIT ? 0.05 : 0.1;
            const int nx = forms[f] == PL_SOLID_Q1P0 ? sizes[z][0] * 2 : sizes[z][0];
            const pl_vec2 c[4] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
            pl_sf_mesh m;
            char msg[320];
            if (pl_sf_mesh_quad(c, nx, sizes[z][1], forms[f] == PL_SOLID_Q1P0, &m, msg, sizeof msg) != PL_OK) {
                fprintf(stderr, "%s\n", msg);
                return 1;
            }
            pl_sf *s = pl_sf_create(&d, &m, msg, sizeof msg);
            pl_sf_mesh_free(&m);
            if (!s) {
                fprintf(stderr, "%s\n", msg);
                return 1;
            }
            pl_sf_add_set(s, -1, -1e-9, 3, 1e-9, 3, 0, 0);
            for (int i = 0; i < s->nn; i++) s->v[2 * i] = 0.01 * s->X[2 * i + 1];
            const double dt = 0.5 * s->dt_crit;
            if (pl_sf_step(s, dt, NULL) != PL_OK) { /* first step: factorisation, excluded */
                fprintf(stderr, "%s\n", s->err);
                return 1;
            }
            const double t0 = now();
            for (int k = 0; k < steps; k++)
                if (pl_sf_step(s, dt, NULL) != PL_OK) {
                    fprintf(stderr, "%s\n", s->err);
                    return 1;
                }
            const double sec = now() - t0, rate = (double)s->ne * steps / sec;
            printf("%-18s %9d %7d %9.3f %14.3e\n", names[f], s->ne, steps, sec, rate);
            if (csv) fprintf(csv, "%s,%d,%d,%.6f,%.6e\n", names[f], s->ne, steps, sec, rate);
            rate_of[z][f] = rate;
            ne_of[z][f] = s->ne;
            pl_sf_destroy(s);
        }
    if (csv) fclose(csv);
    if (table_md) {
        fprintf(table_md, "Element-steps per second (one core, %d steps after the first; a plane-strain block sheared "
                    "from rest, small strain):\n\n", steps);
        fprintf(table_md, "| formulation | elements | element-steps/s | elements | element-steps/s |\n|---|---|---|---|---|\n");
        for (int f = 0; f < 4; f++)
            fprintf(table_md, "| %s | %d | %.3g | %d | %.3g |\n", names[f], ne_of[0][f], rate_of[0][f], ne_of[1][f], rate_of[1][f]);
    }
    const int rc = coupled(argc > 2 ? atoi(argv[2]) : 3000);
    if (table_md) fclose(table_md);
    return rc;
}
