/* Cundall-Strack contacts of discs with discs and with wall segments (seed 003 §2.2.4.2). */
#ifndef PL_CONTACT_DISC_H
#define PL_CONTACT_DISC_H
#include "dem/world_internal.h"

/* Both evaluate pair p, update its history and state, add forces and moments into
   w->force / w->torque and dissipated energy into the world's tallies. */
void pl__contact_disc_disc(pl_world *w, pl_pair *p, const pl_pair_params *pp, double dt);
void pl__contact_disc_segment(pl_world *w, pl_pair *p, const pl_pair_params *pp, double dt);
#endif
