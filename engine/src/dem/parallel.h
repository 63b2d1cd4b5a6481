/* Threaded contact loop (parallel.c): per-pair result slots and their gathering per body. */
#ifndef PL_DEM_PARALLEL_H
#define PL_DEM_PARALLEL_H
#include "dem/contact_out.h"

/* One slot per pair for this step, and the body -> pairs lists for the current pair list
   (rebuilt after a neighbour-list rebuild). NULL when out of memory. */
pl_contact_add *pl__parallel_slots(pl_world *w, uint16_t **flag, pl_contact_sum **sum);
/* Adds every slot with a flag to its two bodies, per body in pair order, through the world's
   task hook. */
void pl__parallel_gather(pl_world *w, const pl_contact_add *out, const uint16_t *flag);
void pl__parallel_free(pl_world *w);
#endif
