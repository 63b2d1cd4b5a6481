/* Fields derived from the nodal total head: pressure p = rho_f g (h - z), head gradients and
 * Darcy velocities per element (eq. 3.19, exact for linear elements instead of the finite
 * differences of eq. 3.20), and interpolation at any point (eqs. 3.21-3.23) through the
 * point-location grid (§3.13.1). */
#include "fluid/darcy/darcy_internal.h"
#include <math.h>

double pl_fl_z(const struct pl_fluid *f, pl_vec2 p) {
    if (f->par.gravity.x == 0 && f->par.gravity.y == 0) return 0;
    return f->par.up.x * p.x + f->par.up.y * p.y;
}

double pl_fl_node_pressure(const struct pl_fluid *f, int node) {
    return f->par.density * f->par.g * (f->head[node] - pl_fl_z(f, f->mesh.xy[node]));
}

void pl_fl_update_gradients(struct pl_fluid *f) {
    const pl_mesh *m = &f->mesh;
    for (int e = 0; e < m->ne; e++) {
        const int32_t *v = &m->tri[3 * e];
        const double *bc = &m->bc[6 * e];
        double inv2A = 1.0 / (2 * m->area[e]);
        double h0 = f->head[v[0]], h1 = f->head[v[1]], h2 = f->head[v[2]];
        f->grad[2 * e] = (bc[0] * h0 + bc[1] * h1 + bc[2] * h2) * inv2A;
        f->grad[2 * e + 1] = (bc[3] * h0 + bc[4] * h1 + bc[5] * h2) * inv2A;
    }
}

int pl_fl_pressure_at(const struct pl_fluid *f, pl_vec2 p, double *pressure, double *head) {
    int e = pl_mesh_locate(&f->mesh, p);
    if (e < 0) {
        if (pressure) *pressure = 0;
        if (head) *head = NAN;
        return -1;
    }
    double l[3];
    pl_mesh_barycentric(&f->mesh, e, p, l);
    const int32_t *v = &f->mesh.tri[3 * e];
    double h = l[0] * f->head[v[0]] + l[1] * f->head[v[1]] + l[2] * f->head[v[2]];
    if (head) *head = h;
    if (pressure) *pressure = f->par.density * f->par.g * (h - pl_fl_z(f, p));
    return e;
}
