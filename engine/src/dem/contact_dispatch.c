/* Narrow phase: evaluates every neighbour pair with the law of its shape pair. */
#include "dem/contact_disc.h"
#include "dem/contact_polygon.h"

void pl__compute_contact_forces(pl_world *w, double dt) {
    pl_disc_ctx c = {w->pos, w->vel, w->omega, w->radius, w->force, w->torque, w->tally, w->def.track_energy,
                     0, 0, 0, -1, -1};
    const pl_pair_params *params = w->pair_params;
    double e_poly = 0;
    w->worst_overlap_ratio = 0;
    for (int k = 0; k < w->pair_n; k++) {
        pl_pair *p = &w->pairs[k];
        const pl_pair_params *pp = &params[p->params];
        switch (p->kind) {
        case PL_PAIR_DISC_DISC: pl__contact_disc_disc(&c, p, pp, dt); break;
        case PL_PAIR_DISC_SEGMENT: pl__contact_disc_segment(&c, w, p, pp, dt); break;
        case PL_PAIR_POLY_DISC:
        case PL_PAIR_POLY_POLY:
        case PL_PAIR_POLY_SEGMENT:
            pl__contact_polygon(w, p, pp, dt);
            e_poly += p->touching ? p->elastic : 0;
            break;
        default: break;
        }
    }
    w->e_shear_prev = w->e_shear;
    w->e_shear = c.e_shear;
    w->e_elastic = c.e_normal + c.e_shear + e_poly;
    if (c.worst_ratio > w->worst_overlap_ratio) {
        w->worst_overlap_ratio = c.worst_ratio;
        w->worst_a = c.worst_a;
        w->worst_b = c.worst_b;
    }
}
