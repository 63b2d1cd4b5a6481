/* Area-based contacts of polygons with polygons, discs and wall segments (seed 004 §3). */
#ifndef PL_CONTACT_POLYGON_H
#define PL_CONTACT_POLYGON_H
#include "dem/world_internal.h"

/* Evaluates pair p (kind PL_PAIR_POLY_DISC, PL_PAIR_POLY_POLY or PL_PAIR_POLY_SEGMENT).
 * Uses w->verts_world for the current outlines. Sets p->touching, p->fn, p->ft, p->point,
 * p->normal, p->overlap; updates the history p->fs and p->area_prev (reset when not touching);
 * adds the forces and moments into w->force / w->torque (a gets -F, b gets +F where F is the
 * force on b), and the dissipated energy into w->e_damped / w->e_friction.
 * Also returns the effective normal stiffness of the contact (N/m) for time-step estimates,
 * or 0 when not touching. */
double pl__contact_polygon(pl_world *w, pl_pair *p, const pl_pair_params *pp, double dt);
#endif
