/* The models attached to a world: the registry of built-in classes, attachment, the grain view
 * handed to models, and the per-step call of every model (advance, then loads into the
 * external-force column, which is added to the dynamic bodies before the motion laws run). */
#include "core/alloc.h"
#include "core/assert.h"
#include "world/world_layer.h"
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Built-in classes, in a fixed order: the flag table takes their flag rows in this order. */
static const pl_model_class *const CLASSES[] = {&pl_darcy_class, &pl_hydrostatic_class, &pl_stokes_class,
                                               &pl_navier_stokes_class, &pl_solid_class};
#define NCLASSES ((int)(sizeof CLASSES / sizeof CLASSES[0]))

int pl__model_class_count(void) { return NCLASSES; }
const pl_model_class *pl__model_class_at(int i) { return PL_CHECK(i >= 0 && i < NCLASSES) ? CLASSES[i] : NULL; }
const pl_model_class *pl__model_class_named(const char *name) {
    for (int i = 0; name && i < NCLASSES; i++)
        if (strcmp(CLASSES[i]->name, name) == 0) return CLASSES[i];
    return NULL;
}

void *pl__world_model(const pl_world *w, const pl_model_class *cls) {
    for (int k = 0; k < w->model_n; k++)
        if (w->models[k].cls == cls) return w->models[k].self;
    return NULL;
}

pl_status pl__world_attach(pl_world *w, const pl_model_class *cls, void *self) {
    if (pl__world_model(w, cls))
        return pl__error(w, PL_ERR_STATE, "%s: the world already has this model attached", cls->name);
    if (w->model_n == w->model_cap) {
        const int nc = w->model_cap ? 2 * w->model_cap : 4;
        pl_model_slot *p = pl_realloc(w->models, (size_t)nc * sizeof *p);
        if (!p) return pl__error(w, PL_ERR_NOMEM, "%s: out of memory attaching the model", cls->name);
        w->models = p;
        w->model_cap = nc;
    }
    w->models[w->model_n++] = (pl_model_slot){cls, self};
    return PL_OK;
}

void pl__world_detach(pl_world *w, const pl_model_class *cls) {
    for (int k = 0; k < w->model_n; k++) {
        if (w->models[k].cls != cls) continue;
        cls->destroy(w->models[k].self);
        memmove(&w->models[k], &w->models[k + 1], (size_t)(w->model_n - k - 1) * sizeof *w->models);
        w->model_n--;
        return;
    }
    PL_ASSERT(0 && "detach: the model is not attached to this world");
}

void pl__models_destroy(pl_world *w) {
    for (int k = w->model_n - 1; k >= 0; k--) w->models[k].cls->destroy(w->models[k].self);
    pl_free(w->models);
    w->models = NULL;
    w->model_n = w->model_cap = 0;
}

pl_status pl__world_error(const pl_world *w, pl_status s, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(w->error, PL_ERR_LEN, fmt, ap);
    va_end(ap);
    return s;
}

double pl__world_time(const pl_world *w) { return w->time; }
const pl_file_writer *pl__world_file_writer(const pl_world *w) { return &w->writer; }

void pl_world_set_file_writer(pl_world *w, const pl_file_writer *fw) {
    if (fw) w->writer = *fw;
    else w->writer = (pl_file_writer){NULL, NULL};
}
pl_vec2 pl__world_gravity(const pl_world *w) { return w->def.gravity; }

int pl__world_body_acceleration(const pl_world *w, int body, double t, pl_vec2 *acc) {
    if (body < 0 || body >= w->n || w->motion[body] != PL_MOTION_PRESCRIBED) return 0;
    return pl__law_acceleration(&w->law[body], t, acc);
}

pl_grain_view pl__world_grains(const pl_world *w) {
    pl_grain_view g;
    g.n = w->n;
    g.shape = w->shape;
    g.motion = w->motion;
    g.pos = w->pos;
    g.vel = w->vel;
    g.angle = w->angle;
    g.omega = w->omega;
    g.radius = w->radius;
    g.area = w->area;
    g.mass = w->mass;
    g.vert_offset = w->vert_offset;
    g.vert_count = w->vert_count;
    g.verts = w->verts_world;
    g.wants_load = w->wants_load;
    g.time = w->time;
    g.gravity = w->def.gravity;
    return g;
}

pl_status pl__ext_reserve(pl_world *w) {
    if (w->ext_cap >= w->n && w->ext_force) return PL_OK;
    const int nc = w->n + 64;
    pl_vec2 *f = pl_realloc(w->ext_force, (size_t)nc * sizeof *f);
    if (f) w->ext_force = f;
    double *m = pl_realloc(w->ext_moment, (size_t)nc * sizeof *m);
    if (m) w->ext_moment = m;
    uint8_t *q = pl_realloc(w->wants_load, (size_t)nc);
    if (q) w->wants_load = q;
    if (!f || !m || !q) return pl__error(w, PL_ERR_NOMEM, "step: out of memory for the external-force column");
    for (int i = w->ext_cap; i < nc; i++) {
        w->ext_force[i] = (pl_vec2){0, 0};
        w->ext_moment[i] = 0;
        w->wants_load[i] = 0;
    }
    w->ext_cap = nc;
    return PL_OK;
}

pl_status pl__models_step(pl_world *w, double dt) {
    if (w->model_n == 0) return PL_OK;
    pl_status st = pl__ext_reserve(w);
    if (st != PL_OK) return st;
    for (int i = 0; i < w->n; i++) {
        const int dyn = w->motion[i] == PL_MOTION_DYNAMIC &&
                        (w->shape[i] == PL_SHAPE_DISC || w->shape[i] == PL_SHAPE_POLYGON);
        const int servo = w->motion[i] == PL_MOTION_PRESCRIBED && w->law[i].law == PL_LAW_SERVO &&
                          w->law[i].servo_fluid;
        w->wants_load[i] = (uint8_t)(dyn || servo);
        w->ext_force[i] = (pl_vec2){0, 0};
        w->ext_moment[i] = 0;
    }
    const pl_grain_view g = pl__world_grains(w);
    for (int k = 0; k < w->model_n; k++) {
        const pl_model_slot *m = &w->models[k];
        st = m->cls->advance(m->self, w, &g, dt);
        if (st != PL_OK) return st;
        st = m->cls->loads(m->self, w, &g, dt, w->ext_force, w->ext_moment);
        if (st != PL_OK) return st;
    }
    /* the loads act on the dynamic bodies (servo walls read theirs in their motion law); their
       work is tallied by the integrator with the mid-step velocity (dem/integrate.c) */
    for (int i = 0; i < w->n; i++) {
        if (w->motion[i] != PL_MOTION_DYNAMIC || !w->wants_load[i]) continue;
        w->force[i].x += w->ext_force[i].x;
        w->force[i].y += w->ext_force[i].y;
        w->torque[i] += w->ext_moment[i];
    }
    w->e_models = 0;
    for (int k = 0; k < w->model_n; k++)
        if (w->models[k].cls->stored_energy) w->e_models += w->models[k].cls->stored_energy(w->models[k].self);
    return PL_OK;
}

uint64_t pl__models_hash(const pl_world *w, uint64_t h) {
    for (int k = 0; k < w->model_n; k++) h = w->models[k].cls->hash(w->models[k].self, h);
    return h;
}

/* ------------------------------------------------------------ public listing */

int pl_world_model_count(const pl_world *w) { return w->model_n; }

const char *pl_world_model_name(const pl_world *w, int k) {
    return k >= 0 && k < w->model_n ? w->models[k].cls->name : NULL;
}

const char *pl_world_model_label(const pl_world *w, int k) {
    return k >= 0 && k < w->model_n ? w->models[k].cls->label : NULL;
}

double pl_world_model_cost(const pl_world *w, int k, long *calls) {
    if (calls) *calls = 0;
    if (k < 0 || k >= w->model_n || !w->models[k].cls->cost) return 0;
    return w->models[k].cls->cost(w->models[k].self, calls);
}

int pl_world_field_sample(const pl_world *w, int quantity, pl_vec2 *xy, int32_t *tri, double *value, int cap_nodes,
                          int cap_tris, int *nt) {
    *nt = 0;
    for (int k = 0; k < w->model_n; k++) {
        const pl_model_slot *m = &w->models[k];
        if (!m->cls->field) continue;
        const int nn = m->cls->field(m->self, w, quantity, xy, tri, value, cap_nodes, cap_tris, nt);
        if (nn > 0) return nn;
    }
    return 0;
}
