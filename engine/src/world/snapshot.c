/* Snapshots of the world's state (for rewinding and restarts). A snapshot keeps a shallow copy
 * of the world struct (all scalars) and deep copies of every array that carries state. On
 * restore the live world keeps its own buffers and capacities; only their contents and the
 * scalars are taken from the snapshot. The broadphase's grid/large split is kept too (it sets
 * the skin and so the rebuild times); its other buffers are scratch. Each attached model
 * captures its own state through its class (snapshot/restore of world/model.h). */
#include "core/alloc.h"
#include "world/world_layer.h"
#include "world/image_internal.h"
#include "world/state_image.h"
#include <stdlib.h>
#include <string.h>

/* Every state array: its field, element size and element count in a given world. */
typedef struct array_spec {
    size_t offset, elem;
    int count_kind; /* 0: n bodies, 1: verts_n, 2: pair_n, 3: materials, 4: materials^2, 5: flags,
                       6: bond_n, 7: bond_law_n, 8: thermal_n */
    const char *name; /* the field's name (state-image layout hash and messages) */
} array_spec;

#define A(field, kind) {offsetof(pl_world, field), sizeof(*((pl_world *)0)->field), kind, #field}
static const array_spec SPECS[] = {
    A(pos, 0), A(vel, 0), A(force, 0), A(angle, 0), A(omega, 0), A(torque, 0), A(mass, 0),
    A(inv_mass, 0), A(inertia, 0), A(inv_inertia, 0), A(radius, 0), A(area, 0), A(shape, 0),
    A(motion, 0), A(material, 0), A(user_id, 0), A(law, 0), A(load, 0), A(load_moment, 0),
    A(tally, 0), A(x0, 0), A(vert_offset, 0), A(vert_count, 0), A(pos_at_build, 0),
    A(angle_at_build, 0), A(verts_local, 1), A(verts_world, 1), A(pairs, 2), A(materials, 3),
    A(pair_params, 4), A(pair_overrides, 4), A(flag_values, 5),
    A(temperature, 0), A(heat, 0), A(wear, 0), A(removed_at, 0), A(temp_hold, 0), A(removed, 0),
    A(bonds, 6), A(bond_laws, 7), A(thermal, 8),
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
    case 6: return (size_t)w->bond_n;
    case 7: return (size_t)w->bond_law_n;
    case 8: return (size_t)w->thermal_n;
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

static pl_status restore_grains(pl_world *w, const pl_snapshot *s);

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
    return restore_grains(w, s);
}

static int grow_to(void **p, int *cap, int need, size_t elem) {
    if (need <= *cap) return 1;
    void *q = pl_realloc(*p, (size_t)need * elem);
    if (!q) return 0;
    *p = q;
    *cap = need;
    return 1;
}

/* The grain store's part of a restore (also the last step of loading a state image). */
static pl_status restore_grains(pl_world *w, const pl_snapshot *s) {
    const pl_world *o = &s->w;
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
    /* bonds and their laws and the thermal table may have grown or shrunk since */
    if (!grow_to((void **)&w->bonds, &w->bond_cap, o->bond_n, sizeof *w->bonds) ||
        !grow_to((void **)&w->bond_laws, &w->bond_law_cap, o->bond_law_n, sizeof *w->bond_laws) ||
        !grow_to((void **)&w->thermal, &w->thermal_cap, o->thermal_n, sizeof *w->thermal))
        return pl__error(w, PL_ERR_NOMEM, "restore: out of memory");
    pl_world live = *w;
    *w = *o;
    /* keep the live buffers, capacities, scratch and attachments */
    for (int k = 0; k < NSPECS; k++) *field_ptr(w, &SPECS[k]) = *field_ptr(&live, &SPECS[k]);
    w->cap = live.cap;
    w->material_cap = live.material_cap;
    w->verts_cap = live.verts_cap;
    w->pair_cap = live.pair_cap;
    w->bond_cap = live.bond_cap;
    w->heat_step = live.heat_step;
    w->bond_law_cap = live.bond_law_cap;
    w->thermal_cap = live.thermal_cap;
    w->pairs_scratch = live.pairs_scratch;
    w->par = live.par; /* the threaded loop's buffers and the task hook stay the live ones */
    w->def.parallel_for = live.def.parallel_for;
    w->def.parallel_user = live.def.parallel_user;
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
    w->writer = live.writer;
    w->models = live.models;
    w->model_n = live.model_n;
    w->model_cap = live.model_cap;
    w->ext_force = live.ext_force;
    w->ext_moment = live.ext_moment;
    w->wants_load = live.wants_load;
    w->ext_cap = live.ext_cap;
    w->error = live.error;
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

/* ------------------------------------------------------------ state image: grains section */

pl_status pl__grains_restore(pl_world *w, const pl_snapshot *s) { return restore_grains(w, s); }

/* dt_report.limit_kind points at one of these string literals: the image keeps its index */
static const char *const LIMIT_KINDS[] = {"none", "translation", "rotation", "polygon face"};
#define NLIMIT ((int)(sizeof LIMIT_KINDS / sizeof LIMIT_KINDS[0]))

uint64_t pl__grains_layout(uint64_t h) {
    const uint32_t order = 0x01020304u; /* byte order */
    const uint64_t sizes[] = {sizeof(pl_world), sizeof(pl_pair), sizeof(pl_motion), sizeof(pl_material),
                              sizeof(pl_pair_params), sizeof(pl_pair_def), sizeof(pl_tally), sizeof(pl_vec2),
                              sizeof(pl_world_def), sizeof(pl_dt_report), sizeof(int), sizeof(long),
                              sizeof(void *), sizeof(double),
                              offsetof(pl_world, time), offsetof(pl_world, step), offsetof(pl_world, dt),
                              offsetof(pl_world, n), offsetof(pl_world, pair_n), offsetof(pl_world, large_n),
                              offsetof(pl_world, e_damped), offsetof(pl_world, dt_report),
                              offsetof(pl_world, flag_values), offsetof(pl_world, models)};
    h = pl_hash_bytes(h, &order, sizeof order);
    h = pl_hash_bytes(h, sizes, sizeof sizes);
    for (int k = 0; k < NSPECS; k++) {
        const uint64_t v[3] = {SPECS[k].offset, SPECS[k].elem, (uint64_t)SPECS[k].count_kind};
        h = pl_hash_bytes(h, v, sizeof v);
        h = pl_hash_bytes(h, SPECS[k].name, strlen(SPECS[k].name));
    }
    /* the flag values are an array over the flag table: its rows and their order */
    for (int k = 0; k < pl_flag_count(); k++) h = pl_hash_bytes(h, pl_flag_at(k)->name, strlen(pl_flag_at(k)->name) + 1);
    return h;
}

/* The scalars are written as one raw copy of struct pl_world (the same shallow copy an
   in-memory snapshot keeps) with every pointer nulled, the message, capacities and
   attachments cleared (a restore keeps the live ones), and dt_report.limit_kind (a pointer to
   a string literal) written apart as an index. */
pl_status pl__grains_save(const pl_world *w, pl_image *img) {
    pl_world c;
    memset(&c, 0, sizeof c);
    memcpy(&c, w, sizeof c);
    for (int k = 0; k < NSPECS; k++) *field_ptr(&c, &SPECS[k]) = NULL;
    c.pairs_scratch = NULL;
    c.par = NULL;
    c.def.parallel_for = NULL;
    c.def.parallel_user = NULL;
    c.is_large = NULL;
    c.large_list = NULL;
    c.cand = NULL;
    c.cell_start = c.cell_items = c.body_cell = c.cursor = NULL;
    c.ext_force = NULL;
    c.ext_moment = NULL;
    c.wants_load = NULL;
    c.models = NULL;
    c.cap = c.material_cap = c.verts_cap = c.pair_cap = c.pair_scratch_cap = c.class_cap = 0;
    c.bond_cap = c.bond_law_cap = c.thermal_cap = 0;
    c.heat_step = NULL;
    c.cand_cap = c.cell_cap = c.cell_items_cap = c.body_cell_cap = c.cursor_cap = 0;
    c.model_n = c.model_cap = c.ext_cap = 0;
    c.error = NULL;
    c.writer = (pl_file_writer){NULL, NULL};
    c.flag_values = NULL;
    int32_t kind = 0;
    for (int k = 0; k < NLIMIT; k++)
        if (w->dt_report.limit_kind && strcmp(w->dt_report.limit_kind, LIMIT_KINDS[k]) == 0) kind = k;
    c.dt_report.limit_kind = NULL;
    pl_status st = pl__image_put(img, &c, sizeof c);
    if (st == PL_OK) st = pl__image_put(img, &kind, sizeof kind);
    for (int k = 0; k < NSPECS && st == PL_OK; k++) {
        const size_t count = count_of(w, SPECS[k].count_kind);
        const void *data = *field_ptr((pl_world *)w, &SPECS[k]);
        if (SPECS[k].offset == offsetof(pl_world, materials) && count > 0) {
            /* without the name pointers (restore points them at the names again) */
            pl_material *m = pl_malloc(count * sizeof *m);
            if (!m) return PL_ERR_NOMEM;
            memcpy(m, data, count * sizeof *m);
            for (size_t i = 0; i < count; i++) m[i].def.name = NULL;
            st = pl__image_put_array(img, m, SPECS[k].elem, count);
            pl_free(m);
        } else {
            st = pl__image_put_array(img, data, SPECS[k].elem, count);
        }
    }
    /* the broadphase's grid/large split (see pl_world_snapshot) */
    const uint8_t has_large = w->class_cap >= w->n && w->n > 0 && w->is_large;
    if (st == PL_OK) st = pl__image_put(img, &has_large, 1);
    if (st == PL_OK && has_large) st = pl__image_put_array(img, w->is_large, 1, (size_t)w->n);
    if (st == PL_OK && has_large)
        st = pl__image_put_array(img, w->large_list, sizeof *w->large_list, (size_t)w->large_n);
    return st;
}

/* A counted array of `count` elements read into new memory (NULL for none); fails without
   allocating when the image has fewer bytes left than the array needs. */
static pl_status get_new_array(pl_image *img, void **out, size_t elem, size_t count) {
    *out = NULL;
    if (count > 0) {
        if (count > (SIZE_MAX - 16) / elem || 16 + elem * count > img->len - img->pos) return img->failed = 1, PL_ERR_IO;
        *out = pl_malloc(elem * count);
        if (!*out) return PL_ERR_NOMEM;
    }
    return pl__image_get_array(img, *out, elem, count);
}

pl_status pl__grains_decode(pl_world *w, pl_image *img, pl_snapshot **out) {
    *out = NULL;
    pl_snapshot *s = pl_calloc(1, sizeof *s);
    if (!s) return pl__error(w, PL_ERR_NOMEM, "load state: out of memory");
    int32_t kind = 0;
    if (pl__image_get(img, &s->w, sizeof s->w) != PL_OK || pl__image_get(img, &kind, sizeof kind) != PL_OK) {
        pl_free(s);
        return pl__error(w, PL_ERR_IO, "load state: the grains section ends inside the world's scalars");
    }
    pl_world *o = &s->w;
    o->error = NULL;
    o->writer = (pl_file_writer){NULL, NULL};
    o->dt_report.limit_kind = LIMIT_KINDS[kind >= 0 && kind < NLIMIT ? kind : 0];
    o->models = NULL;
    if (o->n != w->n || o->verts_n != w->verts_n || o->material_count != w->material_count) {
        const int on = o->n, ov = o->verts_n, om = o->material_count;
        pl_free(s);
        return pl__error(w, PL_ERR_STATE,
                         "load state: the file is of a world with %d bodies, %d outline vertices and %d materials; "
                         "this one has %d, %d and %d (load a state into the world its scene builds)",
                         on, ov, om, w->n, w->verts_n, w->material_count);
    }
    if (o->bond_n < 0 || o->bond_law_n < 0 || o->thermal_n < 0 || o->thermal_n > o->material_count) {
        pl_free(s);
        return pl__error(w, PL_ERR_IO, "load state: damaged grains section (bond or thermal counts)");
    }
    if (o->pair_n < 0 || o->large_n < 0 || o->large_n > o->n) {
        const int pn = o->pair_n, ln = o->large_n;
        pl_free(s);
        return pl__error(w, PL_ERR_IO, "load state: damaged grains section (%d pairs, %d large bodies)", pn, ln);
    }
    pl_status st = PL_OK;
    for (int k = 0; k < NSPECS && st == PL_OK; k++) {
        st = get_new_array(img, &s->data[k], SPECS[k].elem, count_of(o, SPECS[k].count_kind));
        if (st != PL_OK)
            pl__error(w, st, st == PL_ERR_NOMEM ? "load state: out of memory for the array '%s'"
                                                : "load state: the array '%s' of the grains section does not fit "
                                                  "(damaged or of another build)",
                      SPECS[k].name);
    }
    uint8_t has_large = 0;
    if (st == PL_OK && (st = pl__image_get(img, &has_large, 1)) != PL_OK)
        pl__error(w, st, "load state: the grains section ends before the broadphase split");
    if (st == PL_OK && has_large) {
        void *a = NULL, *b = NULL;
        st = get_new_array(img, &a, 1, (size_t)o->n);
        if (st == PL_OK) st = get_new_array(img, &b, sizeof *s->large_list, (size_t)o->large_n);
        s->is_large = a;
        s->large_list = b;
        if (st == PL_OK && !s->large_list) { /* large_n = 0: restore copies nothing but wants a buffer */
            s->large_list = pl_malloc(sizeof *s->large_list);
            if (!s->large_list) st = PL_ERR_NOMEM;
        }
        if (st != PL_OK) pl__error(w, st, "load state: the broadphase split of the grains section does not fit");
    }
    for (int k = 0; k < NSPECS && st == PL_OK; k++) {
        if (SPECS[k].offset != offsetof(pl_world, bonds)) continue;
        const pl_bond *b = s->data[k];
        for (int j = 0; j < o->bond_n && st == PL_OK; j++)
            if (b[j].a < 0 || b[j].b <= b[j].a || b[j].b >= o->n || b[j].law < 0 || b[j].law >= o->bond_law_n)
                st = pl__error(w, PL_ERR_IO, "load state: damaged bond %d in the grains section", j);
    }
    if (st == PL_OK && img->pos != img->len) {
        st = PL_ERR_IO;
        pl__error(w, st, "load state: %zu unread bytes at the end of the grains section (damaged or of another build)",
                  img->len - img->pos);
    }
    if (st != PL_OK) {
        pl_snapshot_destroy(&s);
        return st;
    }
    *out = s;
    return PL_OK;
}
