/* State images (restart files): the whole state of a world as bytes, written and read by the
 * host (the engine opens no file). Format version 1, every number in the byte order of the
 * machine that wrote it (the layout hash covers the byte order, so another order is refused):
 *
 *   header (72 bytes)
 *     0  char[8]  magic "PLSTATE\0"
 *     8  u32      format version (PL_STATE_VERSION)
 *    12  u32      number of sections
 *    16  u64      layout hash: sizes and offsets of everything the grains section holds
 *                 (pl__grains_layout) and the names and order of the built-in model classes
 *    24  i32 x 6  bodies, outline vertices, neighbour pairs, materials, attached models, flags
 *    48  f64      time, s
 *    56  i64      step
 *    64  u64      FNV-1a checksum (pl_hash_bytes) of bytes 0..63
 *   then each section:
 *         char[16] tag ("grains" or "model"), NUL-padded
 *         u64      payload length
 *         u64      FNV-1a checksum of the payload
 *         payload
 *
 *   "grains" (world/snapshot.c, pl__grains_save): the world's scalars, every state array of
 *            the snapshot's list (SPECS) as a counted array (u64 count, u64 element size,
 *            bytes), the broadphase split.
 *   "model"  one per attached model, in attachment order: its class name as a counted array
 *            of chars, then what the class's save function writes (a model starts with a
 *            layout word of its own: fluid/darcy/darcy_snapshot.c).
 *
 * Loading checks the header, the layout and the counts, then every section's length and
 * checksum, before anything of the world changes; then the models are loaded (a model the
 * world lacks is created, one the file lacks is detached, as pl_world_restore does) and last
 * the grain store. */
#include "world/image_internal.h"
#include "core/alloc.h"
#include "world/state_image.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PL_STATE_VERSION 1u
#define HEADER_BYTES 72
#define SECTION_HEAD 32
static const char MAGIC[8] = {'P', 'L', 'S', 'T', 'A', 'T', 'E', '\0'};

static uint64_t layout_hash(void) {
    uint64_t h = pl__grains_layout(PL_HASH_SEED);
    for (int k = 0; k < pl__model_class_count(); k++)
        h = pl_hash_bytes(h, pl__model_class_at(k)->name, strlen(pl__model_class_at(k)->name) + 1);
    return h;
}

typedef struct header {
    uint32_t version, sections;
    uint64_t layout;
    int32_t counts[6];
    double time;
    int64_t step;
} header;

static void put_header(unsigned char *p, const header *h) {
    memcpy(p, MAGIC, 8);
    memcpy(p + 8, &h->version, 4);
    memcpy(p + 12, &h->sections, 4);
    memcpy(p + 16, &h->layout, 8);
    memcpy(p + 24, h->counts, 24);
    memcpy(p + 48, &h->time, 8);
    memcpy(p + 56, &h->step, 8);
    const uint64_t sum = pl_hash_bytes(PL_HASH_SEED, p, 64);
    memcpy(p + 64, &sum, 8);
}

/* Starts a section: its head with the length and checksum left to finish_section. */
static pl_status begin_section(pl_image *img, const char *tag, size_t *at) {
    char t[16] = {0};
    strncpy(t, tag, sizeof t - 1);
    const uint64_t zero[2] = {0, 0};
    *at = img->len;
    pl_status st = pl__image_put(img, t, sizeof t);
    return st == PL_OK ? pl__image_put(img, zero, sizeof zero) : st;
}

static void finish_section(pl_image *img, size_t at) {
    const uint64_t len = img->len - at - SECTION_HEAD;
    const uint64_t sum = pl_hash_bytes(PL_HASH_SEED, img->data + at + SECTION_HEAD, (size_t)len);
    memcpy(img->data + at + 16, &len, 8);
    memcpy(img->data + at + 24, &sum, 8);
}

/* Messages of a const world: the message buffer is not state (a save changes nothing else). */
#define SAVE_ERROR(w, st, ...) pl__error((pl_world *)(w), st, __VA_ARGS__)

pl_status pl_world_save_state(const pl_world *w, void **bytes, size_t *len) {
    if (!w || !bytes || !len) return PL_ERR_ARG;
    *bytes = NULL;
    *len = 0;
    for (int k = 0; k < w->model_n; k++)
        if (!w->models[k].cls->save)
            return SAVE_ERROR(w, PL_ERR_NOT_BUILT, "save state: the %s model cannot write its state to a file yet "
                                                   "(its class has no save function)",
                              w->models[k].cls->name);
    pl_image img = {0};
    header h = {PL_STATE_VERSION, (uint32_t)(1 + w->model_n), layout_hash(),
                {w->n, w->verts_n, w->pair_n, w->material_count, w->model_n, pl_flag_count()}, w->time, w->step};
    unsigned char head[HEADER_BYTES];
    put_header(head, &h);
    pl_status st = pl__image_put(&img, head, sizeof head);
    size_t at = 0;
    if (st == PL_OK) st = begin_section(&img, "grains", &at);
    if (st == PL_OK) st = pl__grains_save(w, &img);
    if (st == PL_OK) finish_section(&img, at);
    for (int k = 0; k < w->model_n && st == PL_OK; k++) {
        const pl_model_class *cls = w->models[k].cls;
        st = begin_section(&img, "model", &at);
        if (st == PL_OK) st = pl__image_put_array(&img, cls->name, 1, strlen(cls->name));
        if (st == PL_OK) st = cls->save(w->models[k].self, &img);
        if (st != PL_OK) {
            pl__image_free(&img);
            return SAVE_ERROR(w, st, "save state: the %s model could not write its state (%s)", cls->name,
                              st == PL_ERR_NOMEM ? "out of memory" : "inconsistent state");
        }
        finish_section(&img, at);
    }
    if (st != PL_OK || img.failed) {
        pl__image_free(&img);
        return SAVE_ERROR(w, PL_ERR_NOMEM, "save state: out of memory");
    }
    *bytes = img.data;
    *len = img.len;
    return PL_OK;
}

void pl_state_free(void *bytes) { pl_free(bytes); }

/* Checks the header; fills h. Messages go to err. */
static pl_status read_header(const unsigned char *p, size_t len, header *h, char *err, size_t errlen) {
    if (len < 12) {
        snprintf(err, errlen, "truncated: %zu bytes, a state file header takes %d", len, HEADER_BYTES);
        return PL_ERR_IO;
    }
    if (memcmp(p, MAGIC, 8) != 0) {
        snprintf(err, errlen, "not a porelab state file (it does not start with PLSTATE)");
        return PL_ERR_IO;
    }
    memcpy(&h->version, p + 8, 4);
    if (h->version != PL_STATE_VERSION) {
        snprintf(err, errlen,
                 "state file format version %u; this build of porelab reads version %u only (resume it "
                 "with the porelab that wrote it)",
                 h->version, PL_STATE_VERSION);
        return PL_ERR_STATE;
    }
    if (len < HEADER_BYTES) {
        snprintf(err, errlen, "truncated: %zu bytes, a state file header takes %d", len, HEADER_BYTES);
        return PL_ERR_IO;
    }
    uint64_t sum;
    memcpy(&sum, p + 64, 8);
    if (sum != pl_hash_bytes(PL_HASH_SEED, p, 64)) {
        snprintf(err, errlen, "damaged: the header fails its checksum");
        return PL_ERR_IO;
    }
    memcpy(&h->sections, p + 12, 4);
    memcpy(&h->layout, p + 16, 8);
    memcpy(h->counts, p + 24, 24);
    memcpy(&h->time, p + 48, 8);
    memcpy(&h->step, p + 56, 8);
    if (h->layout != layout_hash()) {
        snprintf(err, errlen,
                 "the file was written by a build of porelab with another state layout (layout hash "
                 "%016llx, this build %016llx): resume it with the build that wrote it",
                 (unsigned long long)h->layout, (unsigned long long)layout_hash());
        return PL_ERR_STATE;
    }
    return PL_OK;
}

pl_status pl_state_info_of(const void *bytes, size_t len, pl_state_info *out, char *err, size_t errlen) {
    header h;
    char e[512];
    if (!err) err = e, errlen = sizeof e;
    err[0] = '\0';
    if (!bytes || !out) {
        snprintf(err, errlen, "no bytes");
        return PL_ERR_ARG;
    }
    pl_status st = read_header(bytes, len, &h, err, errlen);
    if (st != PL_OK) return st;
    out->version = (int)h.version;
    out->time = h.time;
    out->step = h.step;
    out->bodies = h.counts[0];
    out->models = h.counts[4];
    return PL_OK;
}

typedef struct section {
    char tag[17];
    const unsigned char *data;
    size_t len;
} section;

pl_status pl_world_load_state(pl_world *w, const void *bytes, size_t len) {
    if (!w) return PL_ERR_ARG;
    if (!bytes) return pl__error(w, PL_ERR_ARG, "load state: no bytes");
    const unsigned char *p = bytes;
    header h;
    char err[768];
    pl_status st = read_header(p, len, &h, err, sizeof err);
    if (st != PL_OK) return pl__error(w, st, "load state: %s", err);
    const int32_t *c = h.counts;
    if (c[0] != w->n || c[1] != w->verts_n || c[3] != w->material_count)
        return pl__error(w, PL_ERR_STATE,
                         "load state: the file is of a world with %d bodies, %d outline vertices and %d "
                         "materials; this one has %d, %d and %d (load a state into the world its scene builds)",
                         c[0], c[1], c[3], w->n, w->verts_n, w->material_count);
    if (c[5] != pl_flag_count() || c[4] < 0 || c[4] > PL_MAX_MODEL_CLASSES || h.sections != (uint32_t)(1 + c[4]))
        return pl__error(w, PL_ERR_IO, "load state: damaged header (%u sections, %d models, %d flags)", h.sections,
                         c[4], c[5]);
    /* every section: length and checksum first */
    section sec[1 + PL_MAX_MODEL_CLASSES];
    size_t pos = HEADER_BYTES;
    for (uint32_t k = 0; k < h.sections; k++) {
        if (len - pos < SECTION_HEAD)
            return pl__error(w, PL_ERR_IO, "load state: truncated: %zu bytes, section %u of %u should start at byte %zu",
                             len, k + 1, h.sections, pos);
        memcpy(sec[k].tag, p + pos, 16);
        sec[k].tag[16] = '\0';
        uint64_t slen, sum;
        memcpy(&slen, p + pos + 16, 8);
        memcpy(&sum, p + pos + 24, 8);
        pos += SECTION_HEAD;
        if (slen > len - pos)
            return pl__error(w, PL_ERR_IO,
                             "load state: truncated: section '%.16s' needs %llu bytes, the file has %zu left",
                             sec[k].tag, (unsigned long long)slen, len - pos);
        if (pl_hash_bytes(PL_HASH_SEED, p + pos, (size_t)slen) != sum)
            return pl__error(w, PL_ERR_IO, "load state: damaged: section '%.16s' fails its checksum", sec[k].tag);
        sec[k].data = p + pos;
        sec[k].len = (size_t)slen;
        pos += (size_t)slen;
        const char *want = k == 0 ? "grains" : "model";
        char padded[16] = {0};
        strncpy(padded, want, sizeof padded - 1);
        if (memcmp(sec[k].tag, padded, sizeof padded) != 0)
            return pl__error(w, PL_ERR_IO, "load state: section %u is '%.16s', expected '%s'", k + 1, sec[k].tag, want);
    }
    if (pos != len)
        return pl__error(w, PL_ERR_IO, "load state: damaged: %zu bytes after the last section", len - pos);
    /* the model classes: known to this build, each once */
    const pl_model_class *cls[PL_MAX_MODEL_CLASSES];
    pl_image mimg[PL_MAX_MODEL_CLASSES];
    for (int k = 0; k < c[4]; k++) {
        mimg[k] = (pl_image){(unsigned char *)sec[1 + k].data, sec[1 + k].len, sec[1 + k].len, 0, 0};
        uint64_t n = 0, e = 0;
        char name[64] = {0};
        if (pl__image_get(&mimg[k], &n, 8) != PL_OK || pl__image_get(&mimg[k], &e, 8) != PL_OK || e != 1 ||
            n >= sizeof name || pl__image_get(&mimg[k], name, (size_t)n) != PL_OK)
            return pl__error(w, PL_ERR_IO, "load state: damaged: model section %d has no class name", k + 1);
        cls[k] = pl__model_class_named(name);
        if (!cls[k])
            return pl__error(w, PL_ERR_STATE, "load state: the file has a '%s' model, which this build does not know",
                             name);
        if (!cls[k]->load)
            return pl__error(w, PL_ERR_NOT_BUILT, "load state: the %s model cannot read its state from a file yet",
                             name);
        for (int j = 0; j < k; j++)
            if (cls[j] == cls[k]) return pl__error(w, PL_ERR_IO, "load state: damaged: two %s model sections", name);
    }
    /* the grains section, decoded (not applied yet) */
    pl_image gimg = {(unsigned char *)sec[0].data, sec[0].len, sec[0].len, 0, 0};
    pl_snapshot *s = NULL;
    st = pl__grains_decode(w, &gimg, &s);
    if (st != PL_OK) return st;
    /* models: as pl_world_restore (attach what the file has and the world lacks, detach the rest) */
    for (int k = 0; k < c[4]; k++) {
        void *self = pl__world_model(w, cls[k]);
        if (!self) {
            self = cls[k]->create();
            if (!self) {
                pl_snapshot_destroy(&s);
                return pl__error(w, PL_ERR_NOMEM, "load state: out of memory for the %s model", cls[k]->name);
            }
            st = pl__world_attach(w, cls[k], self);
            if (st != PL_OK) {
                cls[k]->destroy(self);
                pl_snapshot_destroy(&s);
                return st;
            }
        }
        st = cls[k]->load(self, w, &mimg[k]);
        if (st == PL_OK && mimg[k].pos != mimg[k].len)
            st = pl__error(w, PL_ERR_IO, "load state: %zu unread bytes at the end of the %s model's section",
                           mimg[k].len - mimg[k].pos, cls[k]->name);
        if (st != PL_OK) {
            pl_snapshot_destroy(&s);
            char msg[PL_ERR_LEN];
            snprintf(msg, sizeof msg, "%s", w->error);
            return pl__error(w, st, "%s (the world is left partly loaded: build it again)", msg);
        }
    }
    for (int k = w->model_n - 1; k >= 0; k--) {
        int kept = 0;
        for (int j = 0; j < c[4]; j++) kept |= cls[j] == w->models[k].cls;
        if (!kept) pl__world_detach(w, w->models[k].cls);
    }
    st = pl__grains_restore(w, s);
    pl_snapshot_destroy(&s);
    return st;
}
