/* Helpers of the solid tests: a kernel solid from a gmsh mesh, dynamic relaxation to the static
 * state, nearest node. */
#ifndef PL_SOLID_TEST_UTIL_H
#define PL_SOLID_TEST_UTIL_H
#include "solid/fic/solid_internal.h"
#include "solid/fic/solid_mesh.h"
#include <math.h>
#include <stdio.h>

/* Steel: E = 200 GPa, nu = 0.3, rho = 7800 kg/m^3, in the given formulation. */
static inline pl_solid_def sf_steel(int form) {
    pl_solid_def d = pl_default_solid_def();
    d.young = 200e9;
    d.poisson = 0.3;
    d.density = 7800;
    d.formulation = form;
    return d;
}

static inline pl_sf *sf_from_quad(const pl_solid_def *d, pl_vec2 c0, pl_vec2 c1, pl_vec2 c2, pl_vec2 c3, int nx, int ny) {
    const pl_vec2 c[4] = {c0, c1, c2, c3};
    pl_sf_mesh m;
    char msg[320];
    if (pl_sf_mesh_quad(c, nx, ny, d->formulation == PL_SOLID_Q1P0, &m, msg, sizeof msg) != PL_OK) {
        fprintf(stderr, "%s\n", msg);
        return NULL;
    }
    pl_sf *s = pl_sf_create(d, &m, msg, sizeof msg);
    if (!s) fprintf(stderr, "%s\n", msg);
    pl_sf_mesh_free(&m);
    return s;
}

static inline pl_sf *sf_rect(const pl_solid_def *d, double x0, double y0, double x1, double y1, int nx, int ny) {
    return sf_from_quad(d, (pl_vec2){x0, y0}, (pl_vec2){x1, y0}, (pl_vec2){x1, y1}, (pl_vec2){x0, y1}, nx, ny);
}

static inline int sf_nearest(const pl_sf *s, double x, double y) {
    int best = 0;
    double bd = INFINITY;
    for (int i = 0; i < s->nn; i++) {
        const double d = hypot(s->X[2 * i] - x, s->X[2 * i + 1] - y);
        if (d < bd) bd = d, best = i;
    }
    return best;
}

/* Steps with damping until the watched displacement changes by less than rel over a window of
   `window` steps (or max_steps). Returns 0 on success, 1 on a step error. */
static inline int sf_relax(pl_sf *s, double dt, int node, int comp, double rel, int window, long max_steps) {
    double last = NAN;
    for (long k = 0; k < max_steps; k++) {
        if (pl_sf_step(s, dt, NULL) != PL_OK) {
            fprintf(stderr, "%s\n", s->err);
            return 1;
        }
        if ((k + 1) % window == 0) {
            const double u = s->x[2 * node + comp] - s->X[2 * node + comp];
            if (fabs(u - last) <= rel * fabs(u)) return 0;
            last = u;
        }
    }
    return 0;
}
#endif
