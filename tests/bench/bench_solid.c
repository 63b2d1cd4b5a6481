/* Benchmark of the solid kernels (not a test): element-steps per second of the explicit step
 * (internal forces, stress update, pressure, central differences) for about 10k and 100k
 * linear triangles, plain against FIC (explicit and semi-implicit pressure), and Q1/P0 on
 * the same number of quadrilaterals' worth of elements. Elastic steel block, clamped at the
 * bottom, initial velocity field, small strain. Prints a table and writes
 * bench_solid.csv (formulation, elements, steps, seconds, element_steps_per_s).
 *   build/tests/bench_solid [steps]        (default 200) */
#define _POSIX_C_SOURCE 200809L
#include "solid/fic/solid_internal.h"
#include "solid/fic/solid_mesh.h"
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv) {
    const int steps = argc > 1 ? atoi(argv[1]) : 200;
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
            pl_sf_destroy(s);
        }
    if (csv) fclose(csv);
    return 0;
}
