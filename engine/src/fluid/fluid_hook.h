/* Hooks the world calls into the fluid module. Owned by the fluid module. */
#ifndef PL_FLUID_HOOK_H
#define PL_FLUID_HOOK_H
#include "dem/world_internal.h"

/* Called by pl_world_step once per DEM step, after contact forces and before integration,
 * only when w->fluid != NULL. Solves the fluid when due (FLUID_SOLVE_TIMESTEPS) and adds the
 * fluid force and moment on every body into w->force / w->torque (and the work done into
 * w->e_external). Returns PL_OK, or an error status with a message set through pl__error. */
pl_status pl__fluid_step(pl_world *w, double dt);

/* Frees the fluid model attached to a world (called by pl_world_destroy). */
void pl__fluid_free(struct pl_fluid *f);
#endif
