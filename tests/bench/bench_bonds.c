/* Bonded-rock benchmark (not a test): particle-steps per second of a hexagonal packing of
 * discs (radius 1 mm +- 5 %, overlapping by 0.1 % of a diameter, so every neighbour pair is a
 * touching contact), without bonds, with every neighbour pair bonded (brittle, strong enough
 * not to break), with heat (friction heat and conduction) and with heat and Archard wear.
 * The discs start with random velocities of 0.05 m/s so that contacts slide and bonds work.
 * CPU time of the process (one core). The extra time of heat and of wear is also given per
 * contact and step (ns: the added seconds over steps x touching contacts, bonds counted as
 * contacts where they conduct heat).
 *   bench_bonds [--discs N] [--steps S] [--csv FILE]     (default 5000 discs, 400 steps) */
#include "porelab/bonds.h"
#include "porelab/world.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double cpu_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static unsigned rng = 12345u;
static double urand(void) {
    rng = rng * 1664525u + 1013904223u;
    return (rng >> 8) / 16777216.0;
}

static pl_world *build(int n, int bonds, int heat, int wear) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, 0};
    pl_world *w = pl_world_create(&wd);
    pl_material_def m = pl_default_material_def();
    m.name = "rock";
    m.density = 2600;
    m.kn = 1e8;
    m.friction = 0.5;
    m.restitution = 0.5;
    const int mat = pl_world_add_material(w, &m);
    pl_bond_def L = pl_default_bond_def();
    L.kn = 1e8;
    L.rn = L.rt = 1e9;
    pl_world_set_bond_law(w, mat, mat, &L);
    const int nx = (int)sqrt((double)n);
    const double r = 1e-3, d = 2 * r * 0.999, h = d * sqrt(3) / 2;
    rng = 12345u;
    for (int k = 0; k < n; k++) {
        const int i = k % nx, j = k / nx;
        pl_body_def b = pl_default_body_def();
        b.material = mat;
        b.radius = r * (1 + 0.05 * (urand() - 0.5) * 0.02); /* tiny spread: all neighbours overlap */
        b.position = (pl_vec2){i * d + (j % 2) * 0.5 * d, j * h};
        b.velocity = (pl_vec2){0.05 * (urand() - 0.5), 0.05 * (urand() - 0.5)};
        pl_world_add_body(w, &b);
    }
    if (bonds) pl_world_bond_touching(w, 0);
    if (heat) {
        pl_thermal_def t = pl_default_thermal_def();
        t.conductivity = 3;
        t.wear = wear ? 1e-4 : 0;
        pl_world_set_thermal(w, mat, &t);
        pl_world_enable_heat(w, 1, 293.15);
        if (wear) pl_world_enable_wear(w, 1);
    }
    return w;
}

int main(int argc, char **argv) {
    int n = 5000, steps = 400;
    const char *csv = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--discs") && i + 1 < argc) n = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--steps") && i + 1 < argc) steps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
        else {
            fprintf(stderr, "usage: bench_bonds [--discs N] [--steps S] [--csv FILE]\n");
            return 2;
        }
    }
    static const char *const names[] = {"unbonded", "bonded", "bonded+heat", "bonded+heat+wear"};
    FILE *f = csv ? fopen(csv, "a") : NULL;
    double base = 0, sec_prev = 0;
    printf("%-18s %8s %8s %8s %14s %8s\n", "case", "discs", "bonds", "contacts", "particle-steps/s", "cost");
    for (int c = 0; c < 4; c++) {
        pl_world *w = build(n, c >= 1, c >= 2, c >= 3);
        if (pl_world_step(w, 10) != PL_OK) { /* warm-up: lists built, dt computed */
            fprintf(stderr, "bench_bonds: %s\n", pl_world_last_error(w));
            return 1;
        }
        const double t0 = cpu_now();
        if (pl_world_step(w, steps) != PL_OK) {
            fprintf(stderr, "bench_bonds: %s\n", pl_world_last_error(w));
            return 1;
        }
        const double sec = cpu_now() - t0, rate = (double)n * steps / sec;
        if (c == 0) base = rate;
        const int nc = pl_world_contact_count(w);
        printf("%-18s %8d %8d %8d %14.4g %7.2fx", names[c], n, pl_world_bond_count(w), nc, rate, base / rate);
        if (c >= 2) /* heat over bonded, wear over heat: ns per contact and step */
            printf("   %+.3g ns per contact-step", 1e9 * (sec - sec_prev) / ((double)steps * (nc > 0 ? nc : 1)));
        printf("\n");
        sec_prev = sec;
        if (f) fprintf(f, "%s,%d,%d,%d,%.6g\n", names[c], n, pl_world_bond_count(w), pl_world_contact_count(w), rate);
        pl_world_destroy(&w);
    }
    if (f) fclose(f);
    return 0;
}
