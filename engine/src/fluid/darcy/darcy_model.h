/* The Darcy model's class functions (darcy_model.c), gathered into pl_darcy_class in
 * darcy_params.c next to the parameter table. */
#ifndef PL_DARCY_MODEL_H
#define PL_DARCY_MODEL_H
#include "world/model.h"

struct pl_fluid;
struct pl_fluid *pl__darcy_new(void);
void *pl__darcy_create(void);
pl_status pl__darcy_advance(void *self, pl_world *w, const pl_grain_view *g, double dt);
pl_status pl__darcy_loads(void *self, pl_world *w, const pl_grain_view *g, double dt, pl_vec2 *force, double *moment);
uint64_t pl__darcy_hash(const void *self, uint64_t h);
void *pl__darcy_snapshot(const void *self, size_t *bytes);
pl_status pl__darcy_restore(void *self, pl_world *w, const void *snap);
void pl__darcy_snapshot_free(void *snap);
double pl__darcy_cost(const void *self, long *calls);
void pl__darcy_destroy(void *self);
#endif
