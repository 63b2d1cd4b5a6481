/* DEM throughput benchmark (not a test): particle-steps per second and contact evaluations
 * per second on one core, for settled packings of bidisperse discs, matching the LIGGGHTS
 * baseline in ../shared/bench/liggghts (5,978 discs of diameters 3.6 and 2.8 mm, half each,
 * density 2500, box 0.2 m wide, Young's modulus 5e8, Poisson 0.45, restitution 0.5,
 * friction 0.5, dt 2e-6, hooke with tangential history, settled for 0.8 s).
 *
 * LIGGGHTS' hooke model for the stiffness of a pair (its gran model hooke documentation):
 *   k_n = 16/15 sqrt(R*) Y* (15 m* V^2 / (16 sqrt(R*) Y*))^(1/5),  k_t = k_n,
 *   gamma_n = gamma_t = sqrt(4 m* k_n / (1 + (pi / ln e)^2)) = 2 zeta sqrt(m* k_n)
 * with Y* = Y / (2 (1 - nu^2)), 1/R* = 1/R1 + 1/R2, 1/m* = 1/m1 + 1/m2, V = 2 m/s, and masses
 * of discs of unit thickness (area x density). porelab uses the same k_n per pair of sizes
 * (material-pair overrides), k_s = k_n and the same damping ratio from e.
 *
 * Usage: bench_dem [--columns N] [--rows N] [--settle S] [--settle-dt DT] [--steps N] [--csv FILE] [--label L]
 *   --settle-dt settles with a larger step (the packing's critical step is about 5e-4 s) to
 *   prepare quickly; the measured steps always use dt = 2e-6 like LIGGGHTS.
 *   --no-energy turns off the exact dissipation tallies (LIGGGHTS computes none).
 *   --settle-damping A damps the settling fall (Rayleigh alpha, 1/s; 0 = none, the default);
 *   the measured steps are always undamped.
 *   --polygons uses random convex polygons (5-9 corners, half axes 1.4-1.8 mm, seed 004 §2.1)
 *   with the area-based contact law instead of discs, on the same lattice.
 *   --threads N computes the contacts on N threads (app/thread_pool.c, the pool of porelab run
 *   --threads; same state hash as without) and reports CPU and wall time; without it the
 *   contact loop is the serial one (no task hook).
 *   --hash prints the state hash after the measured steps (to compare thread counts).
 *   defaults reproduce the 5,978-disc packing (49 columns x 122 rows of the 4 mm lattice). */
#include "porelab/shapes.h"
#include "porelab/world.h"
#include "thread_pool.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double hooke_kn(double r1, double r2, double rho) {
    const double Y = 5e8, nu = 0.45, V = 2.0;
    const double ys = Y / (2 * (1 - nu * nu));
    const double rs = 1 / (1 / r1 + 1 / r2);
    const double m1 = rho * M_PI * r1 * r1, m2 = rho * M_PI * r2 * r2, ms = 1 / (1 / m1 + 1 / m2);
    return 16.0 / 15.0 * sqrt(rs) * ys * pow(15 * ms * V * V / (16 * sqrt(rs) * ys), 0.2);
}

/* CPU time of this (single-threaded) process: unlike wall time it does not count the time
   other processes take the core away, so runs on a busy machine stay comparable. */
static double cpu_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t rng_state = 32452843;
static double urand(void) {
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}

int main(int argc, char **argv) {
    int cols = 49, rows = 122, steps = 20000;
    double settle = 0.8, settle_dt = 2e-6;
    int track = 1, polygons = 0, threads = 0, hash = 0;
    double settle_alpha = 0;
    pl_rng rng;
    pl_rng_seed(&rng, 2020);
    pl_random_polygon_def pd = pl_default_random_polygon_def();
    pd.a_min = 0.0014; /* about the size of the discs: half axes 1.4-1.8 mm */
    pd.a_max = 0.0018;
    const char *csv = NULL, *label = "discs";
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--columns") && i + 1 < argc) cols = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--rows") && i + 1 < argc) rows = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--settle") && i + 1 < argc) settle = atof(argv[++i]);
        else if (!strcmp(argv[i], "--steps") && i + 1 < argc) steps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--settle-dt") && i + 1 < argc) settle_dt = atof(argv[++i]);
        else if (!strcmp(argv[i], "--no-energy")) track = 0;
        else if (!strcmp(argv[i], "--settle-damping") && i + 1 < argc) settle_alpha = atof(argv[++i]);
        else if (!strcmp(argv[i], "--polygons")) polygons = 1;
        else if (!strcmp(argv[i], "--hash")) hash = 1;
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) {
            if (pl_cli_threads("bench_dem", argv[++i], &threads) != 0) return 2;
        }
        else if (!strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
        else if (!strcmp(argv[i], "--label") && i + 1 < argc) label = argv[++i];
        else {
            fprintf(stderr, "usage: bench_dem [--columns N] [--rows N] [--settle S] [--settle-dt DT] [--settle-damping A] [--steps N] [--no-energy] [--polygons] [--threads N] [--hash] [--csv FILE] [--label L]\n");
            return 2;
        }
    }
    struct rusage ru0;
    getrusage(RUSAGE_SELF, &ru0); /* baseline before the world exists (libraries, heap) */
    const double rho = 2500, rl = 0.0018, rs = 0.0014, e = 0.5;
    const double bw = 0.004 * cols + 0.004, bh = 0.004 * rows + 0.01;
    pl_world_def d = pl_default_world_def();
    d.gravity = (pl_vec2){0, -9.81};
    d.dt = settle_dt;
    d.skin = 0.0004; /* LIGGGHTS: neighbor 0.0004 bin */
    pl_world *w = pl_world_create(&d);
    pl_material_def m = pl_default_material_def();
    m.density = rho;
    m.friction = 0.5;
    m.restitution = e;
    m.name = "large";
    m.kn = hooke_kn(rl, rl, rho);
    m.ks = m.kn;
    const int ml = pl_world_add_material(w, &m);
    m.name = "small";
    m.kn = hooke_kn(rs, rs, rho);
    m.ks = m.kn;
    const int ms = pl_world_add_material(w, &m);
    pl_pair_def p = pl_default_pair_def();
    p.kn = p.ks = hooke_kn(rl, rs, rho);
    pl_world_set_pair(w, ml, ms, &p);
    /* walls are flat: LIGGGHTS uses R* = R and m* = m of the particle against a wall */
    m.name = "wall";
    const int mw = pl_world_add_material(w, &m);
    p = pl_default_pair_def();
    p.kn = p.ks = hooke_kn(rl, 1e9, rho);
    pl_world_set_pair(w, mw, ml, &p);
    p.kn = p.ks = hooke_kn(rs, 1e9, rho);
    pl_world_set_pair(w, mw, ms, &p);
    pl_body_def wall = pl_default_body_def();
    wall.shape = PL_SHAPE_SEGMENT;
    wall.motion = PL_MOTION_FIXED;
    wall.material = mw;
    wall.a = (pl_vec2){0, 0}; wall.b = (pl_vec2){bw, 0};
    pl_world_add_body(w, &wall);
    wall.a = (pl_vec2){0, 0}; wall.b = (pl_vec2){0, bh};
    pl_world_add_body(w, &wall);
    wall.a = (pl_vec2){bw, 0}; wall.b = (pl_vec2){bw, bh};
    pl_world_add_body(w, &wall);
    pl_body_def b = pl_default_body_def();
    for (int j = 0; j < rows; j++)
        for (int i = 0; i < cols; i++) {
            const int large = urand() < 0.5;
            b.material = large ? ml : ms;
            b.radius = large ? rl : rs;
            b.position = (pl_vec2){0.004 + 0.004 * i + 0.0004 * (urand() - 0.5), 0.004 + 0.004 * j + 0.0004 * (urand() - 0.5)};
            if (polygons) {
                pl_vec2 v[PL_MAX_POLY_VERTICES];
                char err[128];
                b.shape = PL_SHAPE_POLYGON;
                b.vertex_count = pl_shape_random_polygon(&pd, &rng, b.position, v, PL_MAX_POLY_VERTICES, err, sizeof err);
                b.vertices = v;
                if (pl_world_add_body(w, &b) < 0) {
                    fprintf(stderr, "polygon: %s\n", pl_world_last_error(w));
                    return 1;
                }
                continue;
            }
            pl_world_add_body(w, &b);
        }
    const int n = pl_world_body_count(w) - 3;
    /* a tall column falling from the lattice hits its base hard: damp the fall while settling
       (Rayleigh alpha, 1/s; terminal speed g/alpha), then measure undamped like LIGGGHTS */
    pl_world_set_flag(w, "RAYLEIGH_FACTOR", settle_alpha);
    double t0 = now();
    const int nsettle = (int)(settle / settle_dt);
    for (int s = 0; s < nsettle; s += 10000) {
        if (pl_world_step(w, nsettle - s < 10000 ? nsettle - s : 10000) != PL_OK) {
            fprintf(stderr, "settling failed: %s\n", pl_world_last_error(w));
            return 1;
        }
    }
    const double tsettle = now() - t0;
    pl_world_set_flag(w, "RAYLEIGH_FACTOR", 0);
    pl_world_set_flag(w, "DT", 2e-6);
    pl_world_set_flag(w, "ENERGY_TRACKING", track);
    pl_world_step(w, 1);
    pl_thread_pool *pool = threads ? pl_thread_pool_create(threads) : NULL;
    if (threads && !pool) {
        fprintf(stderr, "bench_dem: cannot start %d threads\n", threads);
        return 1;
    }
    if (pool) pl_world_set_parallel_for(w, pl_thread_pool_parallel_for, pool);
    const int contacts0 = pl_world_contact_count(w);
    t0 = now();
    const double c0 = cpu_now();
    if (pl_world_step(w, steps) != PL_OK) {
        fprintf(stderr, "benchmark failed: %s\n", pl_world_last_error(w));
        return 1;
    }
    const double t = now() - t0, tc = cpu_now() - c0;
    if (hash) printf("state-hash: %016llx\n", (unsigned long long)pl_world_state_hash(w));
    pl_world_set_parallel_for(w, NULL, NULL);
    pl_thread_pool_destroy(&pool);
    const int contacts = pl_world_contact_count(w);
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    const double ps = (double)n * steps / tc;
    const double cs = 0.5 * (contacts0 + contacts) * steps / tc;
    printf("porelab %s: %d %s, %d contacts (%.2f per body), settle %.1f s simulated in %.1f s wall\n", label, n, polygons ? "polygons" : "discs", contacts,
           2.0 * contacts / n, settle, tsettle);
    printf("  %d steps in %.3f s CPU (%.3f s wall): %.3e particle-steps/s, %.3e contact evaluations/s (per CPU second), peak memory above the baseline %.0f bytes/particle\n",
           steps, tc, t, ps, cs, (ru.ru_maxrss - ru0.ru_maxrss) * 1024.0 / n);
    printf("  threads %d: %.3e particle-steps per wall second\n", threads ? threads : 1, (double)n * steps / t);
    if (csv) {
        FILE *f = fopen(csv, "a");
        if (f) {
            fprintf(f, "%s,%d,%d,%d,%.4f,%.4f,%.6e,%.6e,%.0f,%d,%.6e\n", label, n, contacts, steps, tc, t, ps, cs,
                    (ru.ru_maxrss - ru0.ru_maxrss) * 1024.0 / n, threads ? threads : 1, (double)n * steps / t);
            fclose(f);
        }
    }
    pl_world_destroy(&w);
    return 0;
}
