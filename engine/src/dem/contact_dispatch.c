/* Narrow phase: evaluates every neighbour pair with the law of its shape pair. */
#include "dem/contact_disc.h"
#include "dem/contact_polygon.h"

void pl__compute_contact_forces(pl_world *w, double dt) {
    w->worst_overlap_ratio = 0;
    w->e_shear_prev = w->e_shear;
    w->e_shear = 0;
    w->worst_a = w->worst_b = -1;
    const pl_pair_params *params = w->pair_params;
    for (int k = 0; k < w->pair_n; k++) {
        pl_pair *p = &w->pairs[k];
        const pl_pair_params *pp = &params[p->params];
        switch (p->kind) {
        case PL_PAIR_DISC_DISC: pl__contact_disc_disc(w, p, pp, dt); break;
        case PL_PAIR_DISC_SEGMENT: pl__contact_disc_segment(w, p, pp, dt); break;
        case PL_PAIR_POLY_DISC:
        case PL_PAIR_POLY_POLY:
        case PL_PAIR_POLY_SEGMENT: pl__contact_polygon(w, p, pp, dt); break;
        default: break;
        }
    }
}
