/* Helpers shared by the physics tests: small worlds built through the public API. */
#ifndef PL_TEST_PHYSICS_COMMON_H
#define PL_TEST_PHYSICS_COMMON_H
#include "porelab/world.h"
#include <math.h>
#include <stdio.h>

static inline int add_material(pl_world *w, const char *name, double density, double kn, double ks, double mu,
                               double cn, double cs) {
    pl_material_def m = pl_default_material_def();
    m.name = name;
    m.density = density;
    m.kn = kn;
    m.ks = ks;
    m.friction = mu;
    m.cn = cn;
    m.cs = cs;
    return pl_world_add_material(w, &m);
}

static inline int add_disc(pl_world *w, int mat, double x, double y, double r) {
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_DISC;
    b.material = mat;
    b.position = (pl_vec2){x, y};
    b.radius = r;
    return pl_world_add_body(w, &b);
}

static inline int add_wall(pl_world *w, int mat, double x0, double y0, double x1, double y1) {
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_SEGMENT;
    b.motion = PL_MOTION_FIXED;
    b.material = mat;
    b.a = (pl_vec2){x0, y0};
    b.b = (pl_vec2){x1, y1};
    return pl_world_add_body(w, &b);
}

static inline pl_body_info body(const pl_world *w, int i) {
    pl_body_info b;
    pl_world_body_info(w, i, &b);
    return b;
}

/* Contact force on body b from body a (a < b or not), summed over their contact; 0 if none. */
static inline pl_vec2 contact_force_on(const pl_world *w, int on, int from) {
    pl_contact_info c[256];
    const int n = pl_world_copy_contacts(w, c, 256);
    for (int k = 0; k < n; k++) {
        const pl_vec2 t = {-c[k].normal.y, c[k].normal.x};
        const pl_vec2 F = {c[k].fn * c[k].normal.x + c[k].ft * t.x, c[k].fn * c[k].normal.y + c[k].ft * t.y};
        if (c[k].b == on && c[k].a == from) return F;
        if (c[k].a == on && c[k].b == from) return (pl_vec2){-F.x, -F.y};
    }
    return (pl_vec2){0, 0};
}
#endif
