/* Area-based contacts of polygons with polygons, discs and wall segments (seed 004 §3). */
#ifndef PL_CONTACT_POLYGON_H
#define PL_CONTACT_POLYGON_H
#include "dem/contact_out.h"

/* Evaluates pair p (kind PL_PAIR_POLY_DISC, PL_PAIR_POLY_POLY or PL_PAIR_POLY_SEGMENT).
 * Uses w->verts_world for the current outlines. Sets p->touching, p->fn, p->ft, p->point,
 * p->normal, p->overlap; updates the history p->fs and p->area_prev (reset when not touching);
 * puts the forces and moments (a gets -F, b gets +F where F is the force on b), the dissipated
 * energy (for w->e_damped / w->e_friction) and the overlap ratio into o (o->flags = 0 when not
 * touching); the caller adds them (contact_dispatch.c, parallel.c).
 * Also returns the effective normal stiffness of the contact (N/m) for time-step estimates,
 * or 0 when not touching. */
double pl__contact_polygon(const pl_world *w, pl_pair *p, const pl_pair_params *pp, double dt, pl_contact_out *o);
/* The area law's damping ratio zeta' for a pair whose restitution gives zeta (a flat contact
 * with the cutoff |F_da| <= F_el then rebounds with that restitution). */
double pl__polygon_cutoff_zeta(double zeta);
#endif
