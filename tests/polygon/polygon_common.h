/* Helpers for the polygon physics tests: small worlds built through the public API. */
#ifndef PL_TEST_POLYGON_COMMON_H
#define PL_TEST_POLYGON_COMMON_H
#include "porelab/shapes.h"
#include "porelab/world.h"
#include "physics/common.h"
#include <math.h>
#include <stdio.h>

#define PI 3.14159265358979323846

static inline int poly_material(pl_world *w, const char *name, double density, double kn, double mu,
                                double restitution) {
    pl_material_def m = pl_default_material_def();
    m.name = name;
    m.density = density;
    m.kn = kn;
    m.friction = mu;
    m.restitution = restitution;
    return pl_world_add_material(w, &m);
}

static inline int poly_add(pl_world *w, int mat, const pl_vec2 *v, int n, pl_motion_type motion) {
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_POLYGON;
    b.motion = motion;
    b.material = mat;
    b.vertices = v;
    b.vertex_count = n;
    const int id = pl_world_add_body(w, &b);
    if (id < 0) fprintf(stderr, "add polygon: %s\n", pl_world_last_error(w));
    return id;
}

static inline int poly_add_box(pl_world *w, int mat, double cx, double cy, double width, double height,
                               double angle, pl_motion_type motion) {
    pl_vec2 v[4];
    pl_shape_rectangle((pl_vec2){cx, cy}, width, height, angle, v, 4, NULL, 0);
    return poly_add(w, mat, v, 4, motion);
}

/* Discs, walls and body queries: the physics tests' helpers (tests/physics/common.h). */
static inline int poly_add_disc(pl_world *w, int mat, double x, double y, double r) { return add_disc(w, mat, x, y, r); }

static inline int poly_add_wall(pl_world *w, int mat, double x0, double y0, double x1, double y1) {
    return add_wall(w, mat, x0, y0, x1, y1);
}

static inline pl_body_info poly_body(const pl_world *w, int i) { return body(w, i); }

/* Contact between bodies i and j after the last step (0 when none). */
static inline int poly_contact(const pl_world *w, int i, int j, pl_contact_info *out) {
    pl_contact_info c[512];
    const int n = pl_world_copy_contacts(w, c, 512);
    for (int k = 0; k < n; k++)
        if ((c[k].a == i && c[k].b == j) || (c[k].a == j && c[k].b == i)) {
            *out = c[k];
            return 1;
        }
    return 0;
}

/* Steps and reports an unexpected stop. */
static inline int poly_run(pl_world *w, int steps) {
    const pl_status s = pl_world_step(w, steps);
    if (s != PL_OK) fprintf(stderr, "step failed: %s\n", pl_world_last_error(w));
    return s == PL_OK;
}
#endif
