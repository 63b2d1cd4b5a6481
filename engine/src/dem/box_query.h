/* Bodies near an axis-aligned box, read from the grain engine's own neighbour grid
 * (dem/neighbor.c); for the world's model service pl__world_bodies_near (world/model.h). */
#ifndef PL_DEM_BOX_QUERY_H
#define PL_DEM_BOX_QUERY_H

#include "dem/world_internal.h"

/* Indices (ascending) of the bodies whose bounding circle meets the box [lo, hi]; writes up to
   cap of them and returns how many there are. Uses the grid of the last neighbour build when it
   is current (every body within half the skin of where it was binned), else scans all bodies. */
int pl__bodies_in_box(const pl_world *w, pl_vec2 lo, pl_vec2 hi, int32_t *out, int cap);

#endif
