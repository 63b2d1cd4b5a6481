/* Helpers shared by darcy_world.c (API) and darcy_model.c (stepping). */
#ifndef PL_FLUID_WORLD_H
#define PL_FLUID_WORLD_H
#include "world/model.h"
#include "fluid/darcy/darcy_internal.h"

/* The world's Darcy model, or NULL. */
static inline struct pl_fluid *pl__darcy(const pl_world *w) { return (struct pl_fluid *)pl__world_model(w, &pl_darcy_class); }
void pl__fluid_read_params(pl_world *w, pl_fl_params *p);
pl_fl_bodies pl__fluid_world_bodies(const pl_world *w);
/* One fluid update: porosity, permeability, assembly, solve (static when is_static). */
pl_status pl__fluid_update(pl_world *w, double dt, int is_static);
void pl__fluid_free_state(struct pl_fluid *f);
/* Meshes and builds the system when the quads or lines changed (fluid_snapshot.c uses it to
   bring a world's mesh and boundary conditions to those of a snapshot). */
pl_status pl__fluid_ensure_built(pl_world *w);
#endif
