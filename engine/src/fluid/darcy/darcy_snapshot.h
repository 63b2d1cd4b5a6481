/* Snapshots of the pore-fluid model (darcy_snapshot.c), the class's snapshot, restore
 * and hash functions (darcy_model.c). */
#ifndef PL_FLUID_SNAPSHOT_H
#define PL_FLUID_SNAPSHOT_H
#include "world/model.h"
#include <stddef.h>
#include <stdint.h>

struct pl_fluid;
typedef struct pl_fl_snapshot pl_fl_snapshot;

/* Copies every piece of fluid state that influences later steps or queries; NULL when out of
   memory. *bytes receives the memory held. */
pl_fl_snapshot *pl__fluid_snapshot(const struct pl_fluid *f, size_t *bytes);
/* Puts the snapshot's fluid state into f, the model of w; remeshes or
   rebuilds the boundary conditions first when w's quads or lines differ from the snapshot's.
   The numeric factorization is dropped and redone at the next solve (same matrix, same
   analysis: bit-identical factors). */
pl_status pl__fluid_restore(pl_world *w, struct pl_fluid *f, const pl_fl_snapshot *z);
void pl__fluid_snapshot_free(pl_fl_snapshot **z);
/* Folds the fluid state (heads, permeabilities, solid areas, consolidation reference and
   source, reused forces, update phase) into a state hash. */
uint64_t pl__fluid_hash(const struct pl_fluid *f, uint64_t h);
#endif
