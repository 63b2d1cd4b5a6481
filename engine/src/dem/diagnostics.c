/* Read-only diagnostics: energies, momentum, contacts, bounds and the state hash. */
#include "dem/world_internal.h"
#include <math.h>
#include <string.h>

/* Energies are reported at the time of the last force evaluation, t_n = t - dt, where the
   contact springs' elastic energy was measured. The central difference keeps velocities at
   half steps; the synchronous velocity v_n = (v_{n-1/2} + v_{n+1/2}) / 2 is recovered from the
   newest half-step velocity and the last acceleration, and positions are taken back one step,
   x_n = x_{n+1} - v_{n+1/2} dt. With all terms at the same instant the energy balance of the
   scheme is second order in dt. */
static int synced(const pl_world *w) { return w->step > 0 && w->dt > 0; }

double pl__kinetic_energy(const pl_world *w) {
    double e = 0;
    const double h = synced(w) ? 0.5 * w->dt : 0;
    const pl_vec2 g = w->def.gravity;
    const double C = w->def.global_c, Cr = w->def.global_c_rot, al = w->def.rayleigh_alpha;
    for (int i = 0; i < w->n; i++) {
        if (w->motion[i] != PL_MOTION_DYNAMIC || !(w->mass[i] > 0)) continue;
        const double m = w->mass[i], I = w->inertia[i];
        const double q = 1 - h * (C + al * m) / m;
        const pl_vec2 v = {(w->vel[i].x - h * (w->force[i].x / m + g.x)) / q,
                           (w->vel[i].y - h * (w->force[i].y / m + g.y)) / q};
        double om = w->omega[i];
        if (I > 0) om = (om - h * w->torque[i] / I) / (1 - h * (Cr + al * I) / I);
        e += 0.5 * m * (v.x * v.x + v.y * v.y) + 0.5 * I * om * om;
    }
    return e;
}

double pl__gravitational_energy(const pl_world *w) {
    double e = 0;
    const double dt = synced(w) ? w->dt : 0;
    for (int i = 0; i < w->n; i++)
        if (w->motion[i] == PL_MOTION_DYNAMIC) {
            const double x = w->pos[i].x - dt * w->vel[i].x, y = w->pos[i].y - dt * w->vel[i].y;
            e -= w->mass[i] * (w->def.gravity.x * x + w->def.gravity.y * y);
        }
    return e;
}

/* the loads' work tally runs to the half step t_n + dt/2 (dem/integrate.c): back to t_n */
double pl__external_work(const pl_world *w) { return w->e_external - (synced(w) ? w->e_ext_half : 0); }

double pl__elastic_energy(const pl_world *w) { return w->bond_n ? w->e_elastic + w->e_bond : w->e_elastic; }

pl_energy pl_world_energy(const pl_world *w) {
    pl_energy e;
    e.kinetic = pl__kinetic_energy(w);
    e.gravitational = pl__gravitational_energy(w);
    e.elastic = pl__elastic_energy(w);
    e.damped = w->e_damped;
    e.friction = w->e_friction;
    e.fracture = w->e_fracture;
    e.external = pl__external_work(w);
    e.balance = e.kinetic + e.gravitational + e.elastic + e.damped + e.friction + e.fracture - e.external -
                (w->energy_initialised ? w->e_initial : e.kinetic + e.gravitational + e.elastic + e.damped +
                                                            e.friction + e.fracture - e.external);
    return e;
}

pl_vec2 pl_world_momentum(const pl_world *w) {
    pl_vec2 p = {0, 0};
    for (int i = 0; i < w->n; i++)
        if (w->motion[i] == PL_MOTION_DYNAMIC) {
            p.x += w->mass[i] * w->vel[i].x;
            p.y += w->mass[i] * w->vel[i].y;
        }
    return p;
}

int pl_world_contact_count(const pl_world *w) {
    int c = 0;
    for (int k = 0; k < w->pair_n; k++) c += w->pairs[k].touching;
    return c;
}

int pl_world_copy_contacts(const pl_world *w, pl_contact_info *out, int cap) {
    int c = 0;
    for (int k = 0; k < w->pair_n && c < cap; k++) {
        const pl_pair *p = &w->pairs[k];
        if (!p->touching) continue;
        out[c].a = p->a;
        out[c].b = p->b;
        out[c].point = p->point;
        out[c].normal = p->normal;
        out[c].fn = p->fn;
        out[c].ft = p->ft;
        out[c].overlap = p->overlap;
        c++;
    }
    return c;
}

void pl_world_bounds(const pl_world *w, pl_vec2 *lo, pl_vec2 *hi) {
    pl_vec2 l = {INFINITY, INFINITY}, h = {-INFINITY, -INFINITY};
    for (int i = 0; i < w->n; i++) {
        if (w->removed[i]) continue; /* worn away or carved out (heat.c) */
        if (w->vert_count[i]) {
            const pl_vec2 *v = &w->verts_world[w->vert_offset[i]];
            for (int k = 0; k < w->vert_count[i]; k++) {
                l.x = fmin(l.x, v[k].x);
                l.y = fmin(l.y, v[k].y);
                h.x = fmax(h.x, v[k].x);
                h.y = fmax(h.y, v[k].y);
            }
        } else {
            l.x = fmin(l.x, w->pos[i].x - w->radius[i]);
            l.y = fmin(l.y, w->pos[i].y - w->radius[i]);
            h.x = fmax(h.x, w->pos[i].x + w->radius[i]);
            h.y = fmax(h.y, w->pos[i].y + w->radius[i]);
        }
    }
    if (!isfinite(l.x)) l = h = (pl_vec2){0, 0};
    *lo = l;
    *hi = h;
}

