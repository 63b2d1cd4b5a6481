/* The world layer's own declarations (engine/src/world): the model registry and slots, flags,
 * the state hash of the grain store. Only world/ includes this. */
#ifndef PL_WORLD_LAYER_H
#define PL_WORLD_LAYER_H

#include "dem/world_internal.h"
#include "world/model.h"

#define PL_MAX_MODEL_CLASSES 8

/* One attached model. */
typedef struct pl_model_slot {
    const pl_model_class *cls;
    void *self;
} pl_model_slot;

/* The registry of model classes built into the engine, in a fixed order (flag table order). */
int pl__model_class_count(void);
const pl_model_class *pl__model_class_at(int i);
const pl_model_class *pl__model_class_named(const char *name);

/* Flags (world/flags.c) */
void pl__flags_init(pl_world *w);
int pl__flag_block_start(const pl_model_class *cls);

/* Models (world/models.c): advance every model, then fill the external-force column and add it
   to the dynamic bodies' forces (with the work done into e_external). */
pl_status pl__models_step(pl_world *w, double dt);
void pl__models_destroy(pl_world *w);
/* Destroys and removes the attached instance of cls (if any). */
void pl__world_detach(pl_world *w, const pl_model_class *cls);
uint64_t pl__models_hash(const pl_world *w, uint64_t h);
/* After pl__compute_dt: the models' critical steps into the report and the step (model_services.c). */
void pl__models_limit_dt(pl_world *w);
/* grows the external-force column to the body count (0 or PL_ERR_NOMEM) */
pl_status pl__ext_reserve(pl_world *w);

#endif
