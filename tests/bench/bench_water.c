/* Benchmark: the cost per step of still water on the classroom buoyancy lab
 * (scenes/lab/buoyancy.lua: a 0.40 m tank, water 0.30 m deep, 3 blocks, 8 pebbles) with the
 * hydrostatic model (porelab/hydrostatic.h) and with the Darcy model the scene used before
 * (16 x 12 quad, head 0 on the top, FLUID_STORAGE 0, solved every 20 steps), against the same
 * scene dry, and with the hydrostatic model's moving level. The water's cost per step is the step time minus the dry step time.
 *   bench_water [steps] [repeats] [csv]      (defaults 20000 5 bench_water.csv)
 * Prints µs per step (fastest of the repeats) and the ratios; appends one CSV line per model. */
#define _POSIX_C_SOURCE 200809L
#include "porelab/fluid.h"
#include "porelab/hydrostatic.h"
#include "porelab/world.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { DRY = 0, HYDRO = 1, DARCY = 2, MOVING = 3, NMODELS = 4 };
static const char *const model_name[NMODELS] = {"dry", "hydrostatic", "darcy", "hydrostatic_moving_level"};

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int material(pl_world *w, const char *name, double rho) {
    pl_material_def md = pl_default_material_def();
    md.name = name;
    md.density = rho;
    md.kn = 2e5;
    md.friction = 0.4;
    md.restitution = 0.2;
    return pl_world_add_material(w, &md);
}

static pl_world *lab(int model) {
    const double W = 0.40, H = 0.30;
    pl_world_def wd = pl_default_world_def();
    wd.rayleigh_alpha = 4;
    pl_world *w = pl_world_create(&wd);
    const int tank = material(w, "tank", 2500);
    const int mats[3] = {material(w, "wood", 600), material(w, "ice", 920), material(w, "brick", 1900)};
    const int stone = material(w, "pebble", 2650);
    const pl_vec2 seg[3][2] = {{{-0.02, 0}, {W + 0.02, 0}}, {{0, 0}, {0, 0.42}}, {{W, 0}, {W, 0.42}}};
    for (int k = 0; k < 3; k++) {
        pl_body_def b = pl_default_body_def();
        b.shape = PL_SHAPE_SEGMENT;
        b.motion = PL_MOTION_FIXED;
        b.material = tank;
        b.a = seg[k][0];
        b.b = seg[k][1];
        pl_world_add_body(w, &b);
    }
    const double cx[3] = {0.08, 0.20, 0.32}, bw[3] = {0.07, 0.06, 0.06}, bh[3] = {0.04, 0.05, 0.04};
    for (int k = 0; k < 3; k++) {
        const pl_vec2 v[4] = {{cx[k] - bw[k] / 2, 0.36 - bh[k] / 2}, {cx[k] + bw[k] / 2, 0.36 - bh[k] / 2},
                              {cx[k] + bw[k] / 2, 0.36 + bh[k] / 2}, {cx[k] - bw[k] / 2, 0.36 + bh[k] / 2}};
        pl_body_def b = pl_default_body_def();
        b.shape = PL_SHAPE_POLYGON;
        b.material = mats[k];
        b.vertices = v;
        b.vertex_count = 4;
        pl_world_add_body(w, &b);
    }
    for (int i = 0; i < 8; i++) {
        pl_body_def b = pl_default_body_def();
        b.shape = PL_SHAPE_DISC;
        b.material = stone;
        b.radius = 0.012;
        b.position = (pl_vec2){0.03 + 0.045 * i, 0.02 + 0.01 * (i % 2)};
        pl_world_add_body(w, &b);
    }
    if (model == HYDRO || model == MOVING) {
        pl_hydrostatic_def h = pl_default_hydrostatic_def();
        h.x_min = 0;
        h.x_max = W;
        h.bottom = 0;
        h.level = H;
        h.moving_level = model == MOVING;
        pl_world_attach_hydrostatic(w, &h);
    } else if (model == DARCY) {
        pl_fluid_quad_def q = pl_default_fluid_quad_def();
        q.corners[0] = (pl_vec2){0, 0};
        q.corners[1] = (pl_vec2){W, 0};
        q.corners[2] = (pl_vec2){W, H};
        q.corners[3] = (pl_vec2){0, H};
        q.ndivx = 16;
        q.ndivy = 12;
        pl_world_add_fluid_quad(w, &q);
        pl_world_add_fluid_bc(w, (pl_vec2){0, H}, (pl_vec2){W, H}, 0);
        pl_world_set_flag(w, "FLUIDS_ON", 1);
        pl_world_set_flag(w, "FLUID_DENSITY", 1000);
        pl_world_set_flag(w, "FLUID_STORAGE", 0);
        pl_world_set_flag(w, "FLUID_SOLVE_TIMESTEPS", 20);
    }
    return w;
}

int main(int argc, char **argv) {
    const int steps = argc > 1 ? atoi(argv[1]) : 20000;
    const int repeats = argc > 2 ? atoi(argv[2]) : 5;
    const char *csv = argc > 3 ? argv[3] : "bench_water.csv";
    double us[NMODELS];
    for (int m = 0; m < NMODELS; m++) {
        double best = INFINITY;
        for (int r = 0; r < repeats; r++) {
            pl_world *w = lab(m);
            /* the first steps build the Darcy mesh and factorization: not timed */
            if (pl_world_step(w, 100) != PL_OK) {
                fprintf(stderr, "%s: %s\n", model_name[m], pl_world_last_error(w));
                return 1;
            }
            const double t0 = now();
            if (pl_world_step(w, steps) != PL_OK) {
                fprintf(stderr, "%s: %s\n", model_name[m], pl_world_last_error(w));
                return 1;
            }
            best = fmin(best, (now() - t0) / steps);
            pl_world_destroy(&w);
        }
        us[m] = 1e6 * best;
    }
    const double hyd = us[HYDRO] - us[DRY], dar = us[DARCY] - us[DRY];
    printf("buoyancy lab (14 bodies), %d steps, fastest of %d:\n", steps, repeats);
    printf("  dry          %8.3f us/step\n", us[DRY]);
    printf("  hydrostatic  %8.3f us/step   water %7.3f us/step\n", us[HYDRO], hyd);
    printf("  darcy        %8.3f us/step   water %7.3f us/step\n", us[DARCY], dar);
    printf("  hydrostatic, moving level %8.3f us/step   water %7.3f us/step\n", us[MOVING], us[MOVING] - us[DRY]);
    printf("  darcy / hydrostatic: %.1f x per step, %.1f x for the water alone\n", us[DARCY] / us[HYDRO],
           hyd > 0 ? dar / hyd : INFINITY);
    FILE *f = fopen(csv, "a");
    if (f) {
        for (int m = 0; m < NMODELS; m++)
            fprintf(f, "buoyancy_lab,%s,%d,%.4f,%.4f\n", model_name[m], steps, us[m], us[m] - us[DRY]);
        fclose(f);
    }
    return 0;
}
