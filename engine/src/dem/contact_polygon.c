/* Placeholder until the area-based polygon contact lands: polygons do not interact yet. */
#include "dem/contact_polygon.h"

double pl__contact_polygon(pl_world *w, pl_pair *p, const pl_pair_params *pp, double dt) {
    (void)w; (void)pp; (void)dt;
    p->touching = 0; p->fs = 0; p->fn = 0; p->ft = 0; p->area_prev = 0;
    return 0;
}
