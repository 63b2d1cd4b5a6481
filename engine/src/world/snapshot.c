/* Snapshots of the world's state (for rewinding and restarts). A snapshot keeps a shallow copy
 * of the world struct (all scalars) and deep copies of every array that carries state. On
 * restore the live world keeps its own buffers and capacities; only their contents and the
 * scalars are taken from the snapshot. The broadphase's grid/large split is kept too (it sets
 * the skin and so the rebuild times); its other buffers are scratch. Each attached model
 * captures its own state through its class (snapshot/restore of world/model.h). */
#include "core/alloc.h"
#include "world/world_layer.h"
#include <stdlib.h>
#include <string.h>

/* Every state array: its field, element size and element count in a given world. */
typedef struct array_spec {
    size_t offset, elem;
    int count_kind; /* 0: n bodies, 1: verts_n, 2: pair_n, 3: materials, 4: materials^2, 5: flags */
} array_spec;

#define A(field, kind) {offsetof(pl_world, field), sizeof(*((pl_world *)0)->field), kind}
static const array_spec SPECS[] = {
    A(pos, 0), A(vel, 0), A(force, 0), A(angle, 0), A(omega, 0), A(torque, 0), A(mass, 0),
    A(inv_mass, 0), A(inertia, 0), A(inv_inertia, 0), A(radius, 0), A(area, 0), A(shape, 0),
    A(motion, 0), A(material, 0), A(user_id, 0), A(law, 0), A(load, 0), A(load_moment, 0),
    A(tally, 0), A(x0, 0), A(vert_offset, 0), A(vert_count, 0), A(pos_at_build, 0),
    A(angle_at_build, 0), A(verts_local, 1), A(verts_world, 1), A(pairs, 2), A(materials, 3),
    A(pair_params, 4), A(pair_overrides, 4), A(flag_values, 5),
};
#undef A
#define NSPECS ((int)(sizeof SPECS / sizeof SPECS[0]))

struct pl_snapshot {
    pl_world w;          /* scalars; its pointer fields are not used */
    void *data[NSPECS];  /* deep copies */
    uint8_t *is_large;   /* broadphase split (NULL when the world was never classified) */
    int32_t *large_list;
    pl_model_slot *models; /* the attached models' own snapshots (self = the copy) */
    int model_n;
    size_t bytes;
};

static size_t count_of(const pl_world *w, int kind) {
    switch (kind) {
    case 0: return (size_t)w->n;
    case 1: return (size_t)w->verts_n;
    case 2: return (size_t)w->pair_n;
    case 3: return (size_t)w->material_count;
    case 4: return (size_t)w->material_count * (size_t)w->material_count;
    default: return (size_t)pl_flag_count();
    }
}

static void **field_ptr(pl_world *w, const array_spec *s) { return (void **)((char *)w + s->offset); }

void pl_snapshot_destroy(pl_snapshot **sp) {
    if (!sp || !*sp) return;
    for (int k = 0; k < NSPECS; k++) pl_free((*sp)->data[k]);
    pl_free((*sp)->is_large);
    pl_free((*sp)->large_list);
    for (int k = 0; k < (*sp)->model_n; k++) (*sp)->models[k].cls->snapshot_free((*sp)->models[k].self);
    pl_free((*sp)->models);
    pl_free(*sp);
    *sp = NULL;
}

pl_snapshot *pl_world_snapshot(pl_world *w) {
    pl_snapshot *s = pl_calloc(1, sizeof *s);
    if (!s) return NULL;
    s->w = *w;
    s->bytes = sizeof *s;
    if (w->model_n > 0) {
        s->models = pl_calloc((size_t)w->model_n, sizeof *s->models);
        if (!s->models) {
            pl_snapshot_destroy(&s);
            pl__error(w, PL_ERR_NOMEM, "snapshot: out of memory");
            return NULL;
        }
        for (int k = 0; k < w->model_n; k++) {
            size_t mb = 0;
            void *copy = w->models[k].cls->snapshot(w->models[k].self, &mb);
            if (!copy) {
                pl_snapshot_destroy(&s);
                pl__error(w, PL_ERR_NOMEM, "snapshot: out of memory for the %s model's state", w->models[k].cls->name);
                return NULL;
            }
            s->models[s->model_n++] = (pl_model_slot){w->models[k].cls, copy};
            s->bytes += mb;
        }
    }
    for (int k = 0; k < NSPECS; k++) {
        const size_t bytes = count_of(w, SPECS[k].count_kind) * SPECS[k].elem;
        if (bytes == 0) continue;
        s->data[k] = pl_malloc(bytes);
        if (!s->data[k]) {
            pl_snapshot_destroy(&s);
            pl__error(w, PL_ERR_NOMEM, "snapshot: out of memory");
            return NULL;
        }
        memcpy(s->data[k], *field_ptr(w, &SPECS[k]), bytes);
        s->bytes += bytes;
    }
    /* the grid/large split decides the skin and the rebuild times: keep it as it is */
    if (w->class_cap >= w->n && w->n > 0 && w->is_large) {
        s->is_large = pl_malloc((size_t)w->n);
        s->large_list = pl_malloc((size_t)(w->large_n > 0 ? w->large_n : 1) * sizeof *s->large_list);
        if (!s->is_large || !s->large_list) {
            pl_snapshot_destroy(&s);
            pl__error(w, PL_ERR_NOMEM, "snapshot: out of memory");
            return NULL;
        }
        memcpy(s->is_large, w->is_large, (size_t)w->n);
        memcpy(s->large_list, w->large_list, (size_t)w->large_n * sizeof *s->large_list);
        s->bytes += (size_t)w->n + (size_t)w->large_n * sizeof *s->large_list;
    }
    return s;
}

pl_status pl_world_restore(pl_world *w, const pl_snapshot *s) {
    const pl_world *o = &s->w;
    if (o->n != w->n || o->verts_n != w->verts_n || o->material_count != w->material_count)
        return pl__error(w, PL_ERR_ARG,
                         "restore: the snapshot is of a world with %d bodies, %d outline vertices and %d materials; "
                         "this one has %d, %d and %d",
                         o->n, o->verts_n, o->material_count, w->n, w->verts_n, w->material_count);
    /* the models first: they may fail (out of memory) before anything of the grains changed.
       A model attached after the snapshot was taken goes; one the snapshot has and the world
       lost comes back. */
    for (int k = 0; k < s->model_n; k++) {
        const pl_model_class *cls = s->models[k].cls;
        void *self = pl__world_model(w, cls);
        if (!self) {
            self = cls->create();
            if (!self) return pl__error(w, PL_ERR_NOMEM, "restore: out of memory for the %s model", cls->name);
            pl_status st = pl__world_attach(w, cls, self);
            if (st != PL_OK) {
                cls->destroy(self);
                return st;
            }
        }
        pl_status st = cls->restore(self, w, s->models[k].self);
        if (st != PL_OK) return st;
    }
    for (int k = w->model_n - 1; k >= 0; k--) {
        int kept = 0;
        for (int j = 0; j < s->model_n; j++) kept |= s->models[j].cls == w->models[k].cls;
        if (!kept) pl__world_detach(w, w->models[k].cls);
    }
    if (s->is_large && w->class_cap < w->n) {
        uint8_t *a = pl_realloc(w->is_large, (size_t)w->n);
        if (a) w->is_large = a;
        int32_t *b = pl_realloc(w->large_list, (size_t)w->n * sizeof *b);
        if (b) w->large_list = b;
        if (!a || !b) return pl__error(w, PL_ERR_NOMEM, "restore: out of memory");
        w->class_cap = w->n;
    }
    if (o->pair_n > w->pair_cap) {
        pl_pair *p = pl_realloc(w->pairs, (size_t)o->pair_n * sizeof *p);
        if (!p) return pl__error(w, PL_ERR_NOMEM, "restore: out of memory");
        w->pairs = p;
        w->pair_cap = o->pair_n;
    }
    pl_world live = *w;
    *w = *o;
    /* keep the live buffers, capacities, scratch and attachments */
    for (int k = 0; k < NSPECS; k++) *field_ptr(w, &SPECS[k]) = *field_ptr(&live, &SPECS[k]);
    w->cap = live.cap;
    w->material_cap = live.material_cap;
    w->verts_cap = live.verts_cap;
    w->pair_cap = live.pair_cap;
    w->pairs_scratch = live.pairs_scratch;
    w->pair_scratch_cap = live.pair_scratch_cap;
    w->is_large = live.is_large;
    w->large_list = live.large_list;
    w->class_cap = live.class_cap;
    w->cand = live.cand;
    w->cand_cap = live.cand_cap;
    w->cell_start = live.cell_start;
    w->cell_items = live.cell_items;
    w->body_cell = live.body_cell;
    w->cursor = live.cursor;
    w->cell_cap = live.cell_cap;
    w->cell_items_cap = live.cell_items_cap;
    w->body_cell_cap = live.body_cell_cap;
    w->cursor_cap = live.cursor_cap;
    w->models = live.models;
    w->model_n = live.model_n;
    w->model_cap = live.model_cap;
    w->ext_force = live.ext_force;
    w->ext_moment = live.ext_moment;
    w->wants_load = live.wants_load;
    w->ext_cap = live.ext_cap;
    memcpy(w->error, live.error, sizeof w->error);
    for (int k = 0; k < NSPECS; k++) {
        const size_t bytes = count_of(o, SPECS[k].count_kind) * SPECS[k].elem;
        if (bytes) memcpy(*field_ptr(w, &SPECS[k]), s->data[k], bytes);
    }
    for (int m = 0; m < w->material_count; m++) w->materials[m].def.name = w->materials[m].name;
    if (s->is_large) {
        memcpy(w->is_large, s->is_large, (size_t)w->n);
        memcpy(w->large_list, s->large_list, (size_t)o->large_n * sizeof *w->large_list);
    } else {
        w->classify_dirty = 1; /* the snapshot's world had not classified its bodies yet either */
    }
    return PL_OK;
}

double pl_snapshot_time(const pl_snapshot *s) { return s->w.time; }
size_t pl_snapshot_bytes(const pl_snapshot *s) { return s->bytes; }
