/* The interface between the world and the models attached to it (fluid and solid models).
 *
 * A model is a room of its own (engine/src/fluid/<model>/, engine/src/solid/...): it includes
 * this header and the public headers, never the grain engine (dem/) or another model. What it
 * sees of the grains is a read-only column view (pl_grain_view); what it gives back is an
 * external load per body, written into the world's external-force column before the motion
 * laws run. The world calls the functions of every attached model in a fixed order each step:
 *
 *     advance(dt)   (update the model's own state: solve when due)
 *     loads(dt)     (force and moment on every body the view marks)
 *
 * and, outside the step: save/load (the state image), hash (the state hash), snapshot/restore
 * (rewind), field (drawing), destroy. docs/architecture.md tells how to add a model. */
#ifndef PL_WORLD_MODEL_H
#define PL_WORLD_MODEL_H

#include "porelab/core.h"
#include "porelab/params.h"
#include <stddef.h>
#include <stdint.h>

typedef struct pl_world pl_world;

/* What a model sees of the grains (columns of the grain store, valid during one call). */
typedef struct pl_grain_view {
    int n;                       /* bodies */
    const uint8_t *shape;        /* pl_shape_type */
    const uint8_t *motion;       /* pl_motion_type */
    const pl_vec2 *pos, *vel;    /* centroid (m), velocity (m/s) */
    const double *angle, *omega; /* rad, rad/s */
    const double *radius;        /* disc radius or bounding radius, m */
    const double *area;          /* m^2 */
    const double *mass;          /* kg per m thickness */
    const int32_t *vert_offset, *vert_count;
    const pl_vec2 *verts;        /* world vertices of polygons and segments */
    const uint8_t *wants_load;   /* 1: the world uses this body's load (dynamic discs and
                                    polygons; servo walls that count the fluid's force) */
    double time;                 /* s, at the start of the step */
    pl_vec2 gravity;             /* m/s^2 */
} pl_grain_view;

/* A model's field for drawing: nodes, linear triangles (a P2 or boundary-element field is
   sampled onto linear sub-triangles by the model) and one value per node. */
typedef struct pl_field_sample {
    int nn, nt;
    const pl_vec2 *xy;
    const int32_t *tri;          /* 3 nt */
    const double *value;         /* nn */
} pl_field_sample;

/* Byte image writer/reader for restart files (world/image.c). */
typedef struct pl_image pl_image;

typedef struct pl_model_class {
    const char *name;            /* "darcy", "hydrostatic": unique, used in images and reports */
    const char *label;           /* one line for `porelab info` */
    /* the model's def: size, parameter table (name, unit, range, doc, MIMES flag) */
    size_t def_size;
    const pl_param *params;
    int nparams;
    /* A new, empty instance (restoring a snapshot into a world that has none); NULL when out of
       memory. */
    void *(*create)(void);
    /* Build what the queries read (meshes, boundary conditions, an initial solution) without
       advancing time; the world's explicit prepare step (pl_world_prepare). May be NULL. */
    pl_status (*prepare)(void *self, pl_world *w);
    /* Update the model's state over [t, t + dt] (solve when due). Errors set the world's
       message through pl__world_error and return its status. */
    pl_status (*advance)(void *self, pl_world *w, const pl_grain_view *g, double dt);
    /* Loads on the bodies g->wants_load marks: add into force[i], moment[i] (the world zeroed
       both). */
    pl_status (*loads)(void *self, pl_world *w, const pl_grain_view *g, double dt, pl_vec2 *force,
                       double *moment);
    /* State hash: fold the state that influences later steps into h. */
    uint64_t (*hash)(const void *self, uint64_t h);
    /* In-memory copy for rewind: returns an opaque copy (NULL when out of memory) and its size. */
    void *(*snapshot)(const void *self, size_t *bytes);
    pl_status (*restore)(void *self, pl_world *w, const void *snap);
    void (*snapshot_free)(void *snap);
    /* State image (restart files): write every piece of state; read it back into a model of
       the same scene (a fresh instance from create when the world has none). The world frames
       the output as one checksummed section (world/snapshot_file.c), so load only has to
       refuse what does not fit: start with a layout word of the model's own (a hash of the
       sizes of what it writes, as fluid/darcy/darcy_snapshot.c does), read counted arrays
       with pl__image_get_array after checking pl__image_left, and read the section to its end.
       NULL save: worlds with this model cannot be saved (PL_ERR_NOT_BUILT). */
    pl_status (*save)(const void *self, pl_image *img);
    pl_status (*load)(void *self, pl_world *w, pl_image *img);
    /* The model's field for drawing, sampled on linear triangles: quantity is a
       pl_fluid_node_field (PL_FLUID_PRESSURE, ...). Returns the node count (0: no such field) and
       sets *nt; writes xy, tri (3 per triangle) and value only when they fit in cap_nodes and
       cap_tris (call with 0 caps to size the buffers). Read-only. May be NULL. */
    int (*field)(const void *self, const pl_world *w, int quantity, pl_vec2 *xy, int32_t *tri, double *value,
                 int cap_nodes, int cap_tris, int *nt);
    /* Seconds of CPU spent per call of advance + loads so far (for `porelab info`), may be NULL. */
    double (*cost)(const void *self, long *calls);
    void (*destroy)(void *self);
    /* The model's critical time step, s (explicit models; the world's automatic step is
       dt_safety times the smallest of the grains' and the models'). May be NULL. */
    double (*critical_dt)(const void *self, const pl_world *w);
    /* Mechanical energy the model holds now and can give back to the grains (a solid's kinetic
       and elastic energy), J per m; the energy-surge guard counts it as supplied. May be NULL. */
    double (*stored_energy)(const void *self);
} pl_model_class;

/* ---- world services for models (world/models.c) ---- */

/* The attached instance of a class, or NULL. */
void *pl__world_model(const pl_world *w, const pl_model_class *cls);
/* Attaches a new instance (the world owns it from now on and destroys it with cls->destroy). */
pl_status pl__world_attach(pl_world *w, const pl_model_class *cls, void *self);
/* The grain columns of the world now. */
pl_grain_view pl__world_grains(const pl_world *w);
/* Formats the world's last-error message and returns s. */
pl_status pl__world_error(const pl_world *w, pl_status s, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
double pl__world_time(const pl_world *w);
/* The host's file writer (porelab/core.h); the engine opens no files itself. */
const pl_file_writer *pl__world_file_writer(const pl_world *w);
pl_vec2 pl__world_gravity(const pl_world *w);
/* The world's flag values of a class with MIMES flags, in the order of its flag-carrying
   parameter rows: the one storage of that class's def (a flag and the typed def cannot differ).
   NULL for a class without flags. */
const double *pl__world_flag_values(const pl_world *w, const pl_model_class *cls);
/* Checks v (one value per flag-carrying row) against the rows and stores it; `what` names the
   call in the message. Nothing changes on error. */
pl_status pl__world_set_flag_values(pl_world *w, const pl_model_class *cls, const double *v, const char *what);
/* Acceleration of a prescribed body's law at time t (shaking-table frames); 0 if it has none. */
int pl__world_body_acceleration(const pl_world *w, int body, double t, pl_vec2 *acc);

/* Bodies whose bounding circle meets the box [lo, hi], ascending, from the grains' neighbour
   grid (world/model_services.c); writes up to cap indices and returns the count. */
int pl__world_bodies_near(const pl_world *w, pl_vec2 lo, pl_vec2 hi, int32_t *out, int cap);
/* The model's critical step changed (a part added): the world recomputes its step. */
void pl__world_invalidate_dt(pl_world *w);

/* ---- state images (world/image.c) ---- */
pl_status pl__image_put(pl_image *img, const void *data, size_t bytes);
pl_status pl__image_get(pl_image *img, void *data, size_t bytes);
/* arrays with their element count: put writes the count, get checks it against `count` */
pl_status pl__image_put_array(pl_image *img, const void *data, size_t elem, size_t count);
pl_status pl__image_get_array(pl_image *img, void *data, size_t elem, size_t count);
/* bytes not read yet (check a count against it before allocating for it) */
size_t pl__image_left(const pl_image *img);

/* The model classes built into this engine (world/models.c lists them). */
extern const pl_model_class pl_darcy_class;
extern const pl_model_class pl_hydrostatic_class;
extern const pl_model_class pl_navier_stokes_class;
extern const pl_model_class pl_stokes_class;
extern const pl_model_class pl_solid_class;

#endif
