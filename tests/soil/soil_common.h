/* Shared set-up of the soil tests: a box of discs (seed-fixed, deterministic) with a fluid
 * mesh over it. Units SI, 2D (per metre of thickness). */
#ifndef PL_SOIL_COMMON_H
#define PL_SOIL_COMMON_H
#include "porelab/fluid.h"
#include "porelab/soil.h"
#include "porelab/world.h"
#include <math.h>
#include <stdio.h>

#define SOIL_PI 3.141592653589793

typedef struct soil_box {
    pl_world *w;
    int floor_body, piston;
    int first_grain, ngrains;
    double solid_area;  /* grains only, m^2 */
    double width;
} soil_box;

static void soil_flag(pl_world *w, const char *name, double v) {
    if (pl_world_set_flag(w, name, v) != PL_OK) fprintf(stderr, "%s\n", pl_world_last_error(w));
}

/* Box [0, width] x [0, 2 height], ndisc discs of radius 2.0/2.6 mm (alternating) dropped
   from a loose grid; material kn, friction mu; grains rho_s = 2650. */
static soil_box soil_make_box(double width, int ndisc, double kn, double mu) {
    soil_box b = {0};
    pl_world_def wd = pl_default_world_def();
    b.w = pl_world_create(&wd);
    b.width = width;
    pl_material_def md = pl_default_material_def();
    md.name = "sand";
    md.density = 2650;
    md.kn = kn;
    md.friction = mu;
    md.restitution = 0.3;
    int sand = pl_world_add_material(b.w, &md);
    md.name = "wall";
    md.friction = 0;
    int wall = pl_world_add_material(b.w, &md);
    pl_body_def s = pl_default_body_def();
    s.shape = PL_SHAPE_SEGMENT;
    s.motion = PL_MOTION_FIXED;
    s.material = wall;
    s.a = (pl_vec2){-0.01, 0};
    s.b = (pl_vec2){width + 0.01, 0};
    b.floor_body = pl_world_add_body(b.w, &s);
    s.a = (pl_vec2){0, 0};
    s.b = (pl_vec2){0, 1.0};
    pl_world_add_body(b.w, &s);
    s.a = (pl_vec2){width, 0};
    s.b = (pl_vec2){width, 1.0};
    pl_world_add_body(b.w, &s);
    int ncol = (int)(width / 0.0052);
    b.first_grain = pl_world_body_count(b.w);
    for (int k = 0; k < ndisc; k++) {
        pl_body_def d = pl_default_body_def();
        d.shape = PL_SHAPE_DISC;
        d.material = sand;
        d.radius = (k % 2) ? 0.0026 : 0.0020;
        int row = k / ncol, col = k % ncol;
        d.position = (pl_vec2){0.0027 + col * (width - 0.0054) / (ncol - 1) + ((row % 2) ? 0.0004 : -0.0004),
                               0.004 + row * 0.0058};
        if (d.position.x < 0.0027) d.position.x = 0.0027;
        if (d.position.x > width - 0.0027) d.position.x = width - 0.0027;
        if (pl_world_add_body(b.w, &d) < 0) fprintf(stderr, "%s\n", pl_world_last_error(b.w));
        b.solid_area += SOIL_PI * d.radius * d.radius;
    }
    b.ngrains = ndisc;
    b.piston = -1;
    return b;
}

static double soil_grain_top(const soil_box *b) {
    double top = 0;
    for (int i = b->first_grain; i < b->first_grain + b->ngrains; i++) {
        pl_body_info bi;
        pl_world_body_info(b->w, i, &bi);
        top = fmax(top, bi.position.y + bi.radius);
    }
    return top;
}

/* Mean height of the tops of the grains in the highest layer (within 1.5 diameters of the top). */
static inline double soil_surface(const soil_box *b) {
    double top = soil_grain_top(b), s = 0;
    int n = 0;
    for (int i = b->first_grain; i < b->first_grain + b->ngrains; i++) {
        pl_body_info bi;
        pl_world_body_info(b->w, i, &bi);
        if (bi.position.y + bi.radius > top - 0.0035) { s += bi.position.y + bi.radius; n++; }
    }
    return n ? s / n : top;
}
/* Steps the world for a duration (s); returns 0 or 1 on error (message printed). */
static int soil_run_for(pl_world *w, double seconds) {
    double t_end = pl_world_time(w) + seconds;
    while (pl_world_time(w) < t_end - 1e-12) {
        double dt = pl_world_dt(w);
        int n = (int)ceil((t_end - pl_world_time(w)) / dt);
        if (n > 1000) n = 1000;
        if (n < 1) n = 1;
        if (pl_world_step(w, n) != PL_OK) {
            fprintf(stderr, "%s\n", pl_world_last_error(w));
            return 1;
        }
    }
    return 0;
}
#endif
