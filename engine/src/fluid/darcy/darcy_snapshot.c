/* Snapshots of the pore-fluid model, so that a world with a fluid can be rewound and stepped
 * again bit for bit (issue 7; docs/fluid.md §8). Every field of struct pl_fluid is one of:
 *
 *   input, captured:   quads (mesh input: a differing set remeshes on restore), lines (boundary
 *                      conditions, which hooks may clear and add at run time: a differing set
 *                      rebuilds the system on restore), perm_user (FLUID_PERM 2 values),
 *                      output file names
 *   state, captured:   head, head_prev, perm, perm_assembled, solid, voidr, porosity, grad;
 *                      the assembled matrices sys.kval/mval/mlump (kept while k_dirty = 0);
 *                      consolidation src, stor, stor_assembled, ref_pos/ref_ang (positions at
 *                      the last update: the next source is the displacement since then);
 *                      covers (cover, body_cover_start, cover_xyr: the disc force reuses them
 *                      while a disc has not moved); fcache (FLUID_FORCE_REUSE forces);
 *                      flags and counters mesh_dirty, bc_dirty, built, k_dirty, have_solution,
 *                      static_valid, initialised, refresh_pending (a query applied changed
 *                      lines: the next step still restarts the fluid), steps_since (the fluid
 *                      update's phase against the grain steps), geom_since (the phase of the
 *                      cuts, FLUID_POROSITY_TIMESTEPS), time_since, time, out_time,
 *                      src_active; the accelerating frame frame_body_plus1 (input) and
 *                      frame_acc (the drag between updates uses it); the resolved
 *                      parameters par and assembled_par (flags changed in between take effect
 *                      at the next update); output progress geometry_written,
 *                      pressures_started; statistics stats, t_source, last_src_abs
 *   derived, rebuilt:  mesh (a function of the quads), sys pattern, prescribed nodes and
 *                      CHOLMOD analysis (functions of mesh and lines), elem_bedge
 *   cache, dropped:    the numeric factor sys.L (factorised = 0: the next solve refactorizes
 *                      the same values with the same analysis, which gives the same factor
 *                      bit for bit; test_fluid_snapshot checks it through the state hash)
 *   scratch, live:     stamp/stamp_gen (only equality with the current generation matters),
 *                      pix_*, vbar, bchord, sys.work, sys.rhs/sol/wy/we, msg, capacities
 */
#include "core/alloc.h"
#include "fluid/darcy/darcy_snapshot.h"
#include "fluid/darcy/darcy_internal.h"
#include "fluid/darcy/darcy_world.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Scalar fields of struct pl_fluid that a snapshot copies one to one (same names in the
   snapshot): one list, so that capture and restore cannot drift apart. */
#define PL_FL_SNAPSHOT_SCALARS(X)                                                            \
    X(k_dirty) X(have_solution) X(static_valid) X(initialised) X(refresh_pending)            \
    X(steps_since) X(geom_since) X(time_since) X(time) X(out_time) X(par) X(assembled_par)                 \
    X(geometry_written) X(pressures_started) X(stats) X(src_active) X(t_source) X(last_src_abs)      \
    X(frame_body_plus1) X(frame_acc)

struct pl_fl_snapshot {
    /* scalars */
    int nq, nl;
    int mesh_dirty, bc_dirty, built;
    int nn, ne, nnz;            /* sizes of the mesh arrays below; nn = 0: no valid mesh */
    int k_dirty, have_solution, static_valid, initialised, refresh_pending;
    int64_t steps_since, geom_since;
    double time_since, time, out_time;
    pl_fl_params par, assembled_par;
    char geometry_file[256], pressures_file[256];
    int geometry_written, pressures_started;
    pl_fluid_stats stats;
    int src_active;
    double t_source, last_src_abs;
    int frame_body_plus1;
    pl_vec2 frame_acc;
    int ncover, cover_bodies, has_cover_start;
    int ref_n, fcache_n;
    int has_perm_user, has_cons;
    /* arrays */
    pl_mesh_quad *quads;
    pl_fl_line *lines;
    double *head, *head_prev, *perm, *perm_user, *perm_assembled, *solid, *voidr, *porosity, *grad;
    double *kval, *mval, *mlump;
    double *src, *stor, *stor_assembled;
    pl_vec2 *ref_pos;
    double *ref_ang;
    pl_fl_cover *cover;
    int32_t *body_cover_start;
    double *cover_xyr;
    double *fcache;
};

void pl__fluid_snapshot_free(pl_fl_snapshot **zp) {
    if (!zp || !*zp) return;
    pl_fl_snapshot *z = *zp;
    pl_free(z->quads); pl_free(z->lines);
    pl_free(z->head); pl_free(z->head_prev); pl_free(z->perm); pl_free(z->perm_user); pl_free(z->perm_assembled);
    pl_free(z->solid); pl_free(z->voidr); pl_free(z->porosity); pl_free(z->grad);
    pl_free(z->kval); pl_free(z->mval); pl_free(z->mlump);
    pl_free(z->src); pl_free(z->stor); pl_free(z->stor_assembled); pl_free(z->ref_pos); pl_free(z->ref_ang);
    pl_free(z->cover); pl_free(z->body_cover_start); pl_free(z->cover_xyr); pl_free(z->fcache);
    pl_free(z);
    *zp = NULL;
}

/* Copy of n bytes (NULL for none); counts the bytes and flags a failed allocation. */
static void *dup(const void *p, size_t n, size_t *bytes, int *fail) {
    if (!p || n == 0) return NULL;
    void *q = pl_malloc(n);
    if (!q) { *fail = 1; return NULL; }
    memcpy(q, p, n);
    *bytes += n;
    return q;
}

pl_fl_snapshot *pl__fluid_snapshot(const struct pl_fluid *f, size_t *bytes) {
    pl_fl_snapshot *z = pl_calloc(1, sizeof *z);
    if (!z) return NULL;
    size_t b = sizeof *z;
    int fail = 0;
    z->nq = f->nq;
    z->nl = f->nl;
    z->quads = dup(f->quads, sizeof(pl_mesh_quad) * (size_t)f->nq, &b, &fail);
    z->lines = dup(f->lines, sizeof(pl_fl_line) * (size_t)f->nl, &b, &fail);
    z->mesh_dirty = f->mesh_dirty;
    z->bc_dirty = f->bc_dirty;
    z->built = f->built;
    if (f->built && !f->mesh_dirty && f->head && f->sys.kval) {
        const size_t nn = (size_t)f->mesh.nn, ne = (size_t)f->mesh.ne, nnz = (size_t)f->sys.nnz;
        z->nn = f->mesh.nn;
        z->ne = f->mesh.ne;
        z->nnz = f->sys.nnz;
        z->head = dup(f->head, sizeof(double) * nn, &b, &fail);
        z->head_prev = dup(f->head_prev, sizeof(double) * nn, &b, &fail);
        z->perm = dup(f->perm, sizeof(double) * ne, &b, &fail);
        z->has_perm_user = f->perm_user != NULL;
        z->perm_user = dup(f->perm_user, sizeof(double) * ne, &b, &fail);
        z->perm_assembled = dup(f->perm_assembled, sizeof(double) * ne, &b, &fail);
        z->solid = dup(f->solid, sizeof(double) * ne, &b, &fail);
        z->voidr = dup(f->voidr, sizeof(double) * ne, &b, &fail);
        z->porosity = dup(f->porosity, sizeof(double) * ne, &b, &fail);
        z->grad = dup(f->grad, sizeof(double) * 2 * ne, &b, &fail);
        z->kval = dup(f->sys.kval, sizeof(double) * nnz, &b, &fail);
        z->mval = dup(f->sys.mval, sizeof(double) * nnz, &b, &fail);
        z->mlump = dup(f->sys.mlump, sizeof(double) * nn, &b, &fail);
        z->has_cons = f->src != NULL;
        if (f->src) {
            z->src = dup(f->src, sizeof(double) * nn, &b, &fail);
            z->stor = dup(f->stor, sizeof(double) * ne, &b, &fail);
            z->stor_assembled = dup(f->stor_assembled, sizeof(double) * ne, &b, &fail);
        }
        z->ncover = f->ncover;
        z->cover_bodies = f->cover_bodies;
        z->cover = dup(f->cover, sizeof(pl_fl_cover) * (size_t)f->ncover, &b, &fail);
        z->has_cover_start = f->body_cover_start != NULL;
        if (f->body_cover_start) {
            z->body_cover_start = dup(f->body_cover_start, sizeof(int32_t) * ((size_t)f->cover_bodies + 1), &b, &fail);
            z->cover_xyr = dup(f->cover_xyr, sizeof(double) * 3 * (size_t)f->cover_bodies, &b, &fail);
        }
    }
    /* the consolidation reference exists without the arrays above after a soil_reset */
    z->ref_n = f->ref_pos ? f->ref_n : 0;
    z->ref_pos = dup(f->ref_pos, sizeof(pl_vec2) * (size_t)z->ref_n, &b, &fail);
    z->ref_ang = dup(f->ref_ang, sizeof(double) * (size_t)z->ref_n, &b, &fail);
    z->fcache_n = f->fcache ? f->fcache_n : 0;
    z->fcache = dup(f->fcache, sizeof(double) * 3 * (size_t)z->fcache_n, &b, &fail);
#define PL_FL_CAPTURE(field) z->field = f->field;
    PL_FL_SNAPSHOT_SCALARS(PL_FL_CAPTURE)
#undef PL_FL_CAPTURE
    memcpy(z->geometry_file, f->geometry_file, sizeof z->geometry_file);
    memcpy(z->pressures_file, f->pressures_file, sizeof z->pressures_file);
    if (fail) {
        pl__fluid_snapshot_free(&z);
        return NULL;
    }
    if (bytes) *bytes = b;
    return z;
}

/* Grows *p to hold at least need elements of size elem (keeps the contents). */
static int grow(void **p, int *cap, int need, size_t elem) {
    if (need <= *cap && *p) return 1;
    int nc = need + 64;
    void *q = pl_realloc(*p, elem * (size_t)nc);
    if (!q) return 0;
    *p = q;
    *cap = nc;
    return 1;
}

/* The mesh is a function of the quads' corners and divisions (the ids and anisotropies do
   not change it); the prescribed nodes and flux loads a function of mesh and lines. */
static int same_quads(const struct pl_fluid *f, const pl_fl_snapshot *z) {
    if (f->nq != z->nq) return 0;
    for (int k = 0; k < f->nq; k++) {
        const pl_mesh_quad *a = &f->quads[k], *b = &z->quads[k];
        if (a->ndivx != b->ndivx || a->ndivy != b->ndivy) return 0;
        for (int c = 0; c < 4; c++)
            if (a->c[c].x != b->c[c].x || a->c[c].y != b->c[c].y) return 0;
    }
    return 1;
}

static int same_lines(const struct pl_fluid *f, const pl_fl_snapshot *z) {
    if (f->nl != z->nl) return 0;
    for (int k = 0; k < f->nl; k++) {
        const pl_fl_line *a = &f->lines[k], *b = &z->lines[k];
        if (a->a.x != b->a.x || a->a.y != b->a.y || a->b.x != b->b.x || a->b.y != b->b.y || a->value != b->value ||
            a->kind != b->kind)
            return 0;
    }
    return 1;
}

/* memcpy of n elements; nothing (and no null pointer handed to memcpy) when n = 0 */
#define COPY(dst, src, n)                                                    \
    do {                                                                     \
        if ((n) > 0) memcpy((dst), (src), sizeof(*(dst)) * (size_t)(n));    \
    } while (0)

pl_status pl__fluid_restore(pl_world *w, struct pl_fluid *f, const pl_fl_snapshot *z) {
    const int valid = z->nn > 0;
    const int live_mesh = f->built && !f->mesh_dirty && f->head && f->sys.kval;
    const int keep_mesh = valid && live_mesh && same_quads(f, z);
    const int keep_bcs = keep_mesh && !f->bc_dirty && !z->bc_dirty && same_lines(f, z);
    /* input: quads and lines */
    if (!grow((void **)&f->quads, &f->qcap, z->nq, sizeof *f->quads) ||
        !grow((void **)&f->lines, &f->lcap, z->nl, sizeof *f->lines))
        return pl__world_error(w, PL_ERR_NOMEM, "restore: out of memory");
    COPY(f->quads, z->quads, z->nq);
    f->nq = z->nq;
    COPY(f->lines, z->lines, z->nl);
    f->nl = z->nl;
    f->par = z->par; /* remeshing sets the initial heads from the elevation */
    if (valid) {
        if (!keep_mesh) f->mesh_dirty = 1;
        else if (!keep_bcs && !z->bc_dirty) f->bc_dirty = 1;
        if (f->mesh_dirty || f->bc_dirty) {
            pl_status st = pl__fluid_ensure_built(w);
            if (st != PL_OK) return st;
        }
        if (f->mesh.nn != z->nn || f->mesh.ne != z->ne || f->sys.nnz != z->nnz)
            return pl__world_error(w, PL_ERR_STATE, "restore: the fluid mesh (%d nodes, %d triangles) does not match the "
                                              "snapshot's (%d nodes, %d triangles)",
                             f->mesh.nn, f->mesh.ne, z->nn, z->ne);
        const int nn = z->nn, ne = z->ne;
        COPY(f->head, z->head, nn);
        COPY(f->head_prev, z->head_prev, nn);
        COPY(f->perm, z->perm, ne);
        COPY(f->perm_assembled, z->perm_assembled, ne);
        COPY(f->solid, z->solid, ne);
        COPY(f->voidr, z->voidr, ne);
        COPY(f->porosity, z->porosity, ne);
        COPY(f->grad, z->grad, 2 * ne);
        if (z->has_perm_user) {
            if (!f->perm_user) f->perm_user = pl_malloc(sizeof(double) * (size_t)ne);
            if (!f->perm_user) return pl__world_error(w, PL_ERR_NOMEM, "restore: out of memory");
            COPY(f->perm_user, z->perm_user, ne);
        } else {
            pl_free(f->perm_user);
            f->perm_user = NULL;
        }
        COPY(f->sys.kval, z->kval, z->nnz);
        COPY(f->sys.mval, z->mval, z->nnz);
        COPY(f->sys.mlump, z->mlump, nn);
        /* consolidation arrays exist from the first update with FLUID_CONSOLIDATION on; their
           presence alone changes the assembly (storage per element) */
        if (z->has_cons) {
            if (!f->src && pl_fl_consolidation_alloc(f) != PL_OK)
                return pl__world_error(w, PL_ERR_NOMEM, "restore: out of memory");
            COPY(f->src, z->src, nn);
            COPY(f->stor, z->stor, ne);
            COPY(f->stor_assembled, z->stor_assembled, ne);
        } else if (f->src) {
            pl_fl_consolidation_free(f);
        }
        if (!grow((void **)&f->cover, &f->cover_cap, z->ncover, sizeof *f->cover))
            return pl__world_error(w, PL_ERR_NOMEM, "restore: out of memory");
        COPY(f->cover, z->cover, z->ncover);
        f->ncover = z->ncover;
        if (z->has_cover_start) {
            if (z->cover_bodies + 1 > f->body_cap || !f->body_cover_start || !f->cover_xyr) {
                const int nc = z->cover_bodies + 1 + 64;
                int32_t *p = pl_realloc(f->body_cover_start, sizeof(int32_t) * (size_t)nc);
                if (p) f->body_cover_start = p;
                double *q = pl_realloc(f->cover_xyr, sizeof(double) * 3 * (size_t)nc);
                if (q) f->cover_xyr = q;
                if (!p || !q) return pl__world_error(w, PL_ERR_NOMEM, "restore: out of memory");
                f->body_cap = nc;
            }
            COPY(f->body_cover_start, z->body_cover_start, z->cover_bodies + 1);
            COPY(f->cover_xyr, z->cover_xyr, 3 * z->cover_bodies);
        }
        f->cover_bodies = z->cover_bodies;
    } else {
        /* the snapshot's model had no current mesh: build it at the next use, as it would */
        f->mesh_dirty = 1;
        f->cover_bodies = 0;
        f->ncover = 0;
    }
    /* consolidation reference (also set by soil_reset without the consolidation arrays) */
    if (z->ref_n > 0) {
        if (z->ref_n > f->ref_cap || !f->ref_pos || !f->ref_ang) {
            const int nc = z->ref_n + 64;
            pl_vec2 *p = pl_realloc(f->ref_pos, sizeof(pl_vec2) * (size_t)nc);
            if (p) f->ref_pos = p;
            double *a = pl_realloc(f->ref_ang, sizeof(double) * (size_t)nc);
            if (a) f->ref_ang = a;
            if (!p || !a) return pl__world_error(w, PL_ERR_NOMEM, "restore: out of memory");
            f->ref_cap = nc;
        }
        COPY(f->ref_pos, z->ref_pos, z->ref_n);
        COPY(f->ref_ang, z->ref_ang, z->ref_n);
    }
    f->ref_n = z->ref_n;
    if (z->fcache_n > 0) {
        if (!grow((void **)&f->fcache, &f->fcache_cap, z->fcache_n, 3 * sizeof *f->fcache))
            return pl__world_error(w, PL_ERR_NOMEM, "restore: out of memory");
        COPY(f->fcache, z->fcache, 3 * z->fcache_n);
    }
    f->fcache_n = z->fcache_n;
    /* flags, phase, parameters */
    if (valid) {
        f->mesh_dirty = z->mesh_dirty;
        f->bc_dirty = z->bc_dirty;
        f->built = z->built;
    }
#define PL_FL_RESTORE(field) f->field = z->field;
    PL_FL_SNAPSHOT_SCALARS(PL_FL_RESTORE)
#undef PL_FL_RESTORE
    memcpy(f->geometry_file, z->geometry_file, sizeof f->geometry_file);
    memcpy(f->pressures_file, z->pressures_file, sizeof f->pressures_file);
    f->sys.factorised = 0; /* the live factor is of another matrix: refactorize at the next solve */
    return PL_OK;
}

uint64_t pl__fluid_hash(const struct pl_fluid *f, uint64_t h) {
    if (!f) return h;
    h = pl_hash_bytes(h, &f->initialised, sizeof f->initialised);
    h = pl_hash_bytes(h, &f->refresh_pending, sizeof f->refresh_pending);
    h = pl_hash_bytes(h, &f->steps_since, sizeof f->steps_since);
    h = pl_hash_bytes(h, &f->time_since, sizeof f->time_since);
    h = pl_hash_bytes(h, &f->time, sizeof f->time);
    if (f->built && !f->mesh_dirty && f->head) {
        h = pl_hash_bytes(h, f->head, sizeof(double) * (size_t)f->mesh.nn);
        h = pl_hash_bytes(h, f->perm, sizeof(double) * (size_t)f->mesh.ne);
        h = pl_hash_bytes(h, f->solid, sizeof(double) * (size_t)f->mesh.ne);
        if (f->src) h = pl_hash_bytes(h, f->src, sizeof(double) * (size_t)f->mesh.nn);
    }
    if (f->ref_pos) h = pl_hash_bytes(h, f->ref_pos, sizeof(pl_vec2) * (size_t)f->ref_n);
    if (f->par.force_reuse && f->fcache) h = pl_hash_bytes(h, f->fcache, sizeof(double) * 3 * (size_t)f->fcache_n);
    return h;
}

/* ------------------------------------------------------------ state image (restart files) */

/* The snapshot's own scalars (sizes and flags of the arrays), besides PL_FL_SNAPSHOT_SCALARS. */
#define PL_FL_SNAPSHOT_SIZES(X)                                                                 \
    X(nq) X(nl) X(mesh_dirty) X(bc_dirty) X(built) X(nn) X(ne) X(nnz) X(ncover) X(cover_bodies) \
    X(has_cover_start) X(ref_n) X(fcache_n) X(has_perm_user) X(has_cons)

/* The snapshot's arrays and their element counts (from the scalars above: the counts the
   capture gives them in pl__fluid_snapshot). */
#define PL_FL_SNAPSHOT_ARRAYS(X)                                                                 \
    X(quads, z->nq) X(lines, z->nl) X(head, z->nn) X(head_prev, z->nn) X(perm, z->ne)             \
    X(perm_user, z->has_perm_user ? z->ne : 0) X(perm_assembled, z->ne) X(solid, z->ne)           \
    X(voidr, z->ne) X(porosity, z->ne) X(grad, 2 * (size_t)z->ne) X(kval, z->nnz) X(mval, z->nnz) \
    X(mlump, z->nn) X(src, z->has_cons ? z->nn : 0) X(stor, z->has_cons ? z->ne : 0)             \
    X(stor_assembled, z->has_cons ? z->ne : 0) X(ref_pos, z->ref_n) X(ref_ang, z->ref_n)          \
    X(cover, z->ncover) X(body_cover_start, z->has_cover_start ? (size_t)z->cover_bodies + 1 : 0) \
    X(cover_xyr, z->has_cover_start ? 3 * (size_t)z->cover_bodies : 0) X(fcache, 3 * (size_t)z->fcache_n)

/* Layout word of the Darcy section: the size of every field written (the structs among them
   are written whole: pl_fl_params, pl_fluid_stats, pl_mesh_quad, pl_fl_line, pl_fl_cover) and
   the names of the three lists, so that a build with another list or struct refuses the file. */
static uint64_t darcy_layout(void) {
    uint64_t h = PL_HASH_SEED;
    const pl_fl_snapshot *z = NULL;
#define PL_FL_LAYOUT(field)                                      \
    {                                                            \
        const uint64_t sz = sizeof z->field;                     \
        h = pl_hash_bytes(h, #field, sizeof #field);             \
        h = pl_hash_bytes(h, &sz, sizeof sz);                    \
    }
#define PL_FL_LAYOUT_ARRAY(field, count) PL_FL_LAYOUT(field[0])
    PL_FL_SNAPSHOT_SIZES(PL_FL_LAYOUT)
    PL_FL_SNAPSHOT_SCALARS(PL_FL_LAYOUT)
    PL_FL_LAYOUT(geometry_file)
    PL_FL_LAYOUT(pressures_file)
    PL_FL_SNAPSHOT_ARRAYS(PL_FL_LAYOUT_ARRAY)
#undef PL_FL_LAYOUT
#undef PL_FL_LAYOUT_ARRAY
    (void)z;
    return h;
}

/* Writes the model's state: a capture as for rewind (pl__fluid_snapshot: one classification
   of the fields, above), serialised field by field. */
pl_status pl__fluid_save(const struct pl_fluid *f, pl_image *img) {
    pl_fl_snapshot *z = pl__fluid_snapshot(f, NULL);
    if (!z) return PL_ERR_NOMEM;
    const uint64_t layout = darcy_layout();
    pl_status st = pl__image_put(img, &layout, sizeof layout);
#define PL_FL_PUT(field) \
    if (st == PL_OK) st = pl__image_put(img, &z->field, sizeof z->field);
    PL_FL_SNAPSHOT_SIZES(PL_FL_PUT)
    PL_FL_SNAPSHOT_SCALARS(PL_FL_PUT)
    PL_FL_PUT(geometry_file)
    PL_FL_PUT(pressures_file)
#undef PL_FL_PUT
#define PL_FL_PUT_ARRAY(field, count)                                                  \
    if (st == PL_OK) {                                                                 \
        const size_t n_ = (size_t)(count);                                             \
        st = n_ > 0 && !z->field ? PL_ERR_STATE                                        \
                                 : pl__image_put_array(img, z->field, sizeof *z->field, n_); \
    }
    PL_FL_SNAPSHOT_ARRAYS(PL_FL_PUT_ARRAY)
#undef PL_FL_PUT_ARRAY
    pl__fluid_snapshot_free(&z);
    return st;
}

/* Reads a section written by pl__fluid_save into a snapshot, then restores it as a rewind
   does (pl__fluid_restore: remeshes and rebuilds the system for a fresh model). */
pl_status pl__fluid_load(pl_world *w, struct pl_fluid *f, pl_image *img) {
    uint64_t layout = 0;
    if (pl__image_get(img, &layout, sizeof layout) != PL_OK)
        return pl__world_error(w, PL_ERR_IO, "load state: the darcy section is empty");
    if (layout != darcy_layout())
        return pl__world_error(w, PL_ERR_STATE,
                               "load state: the darcy model's state was written by a build with another layout "
                               "(resume it with the build that wrote it)");
    pl_fl_snapshot *z = pl_calloc(1, sizeof *z);
    if (!z) return pl__world_error(w, PL_ERR_NOMEM, "load state: out of memory");
    pl_status st = PL_OK;
#define PL_FL_GET(field) \
    if (st == PL_OK) st = pl__image_get(img, &z->field, sizeof z->field);
    PL_FL_SNAPSHOT_SIZES(PL_FL_GET)
    PL_FL_SNAPSHOT_SCALARS(PL_FL_GET)
    PL_FL_GET(geometry_file)
    PL_FL_GET(pressures_file)
#undef PL_FL_GET
    if (st != PL_OK) {
        pl_free(z);
        return pl__world_error(w, PL_ERR_IO, "load state: the darcy section ends inside its scalars");
    }
    z->geometry_file[sizeof z->geometry_file - 1] = '\0';
    z->pressures_file[sizeof z->pressures_file - 1] = '\0';
    const int lim = INT32_MAX / 4;
    if (z->nq < 0 || z->nl < 0 || z->nn < 0 || z->ne < 0 || z->nnz < 0 || z->ncover < 0 || z->cover_bodies < 0 ||
        z->ref_n < 0 || z->fcache_n < 0 || z->nq > lim || z->nl > lim || z->nn > lim || z->ne > lim || z->nnz > lim ||
        z->ncover > lim || z->cover_bodies > lim || z->ref_n > lim || z->fcache_n > lim) {
        pl_free(z);
        return pl__world_error(w, PL_ERR_IO, "load state: damaged darcy section (negative or huge sizes)");
    }
#define PL_FL_GET_ARRAY(field, count)                                                             \
    if (st == PL_OK) {                                                                            \
        const size_t n_ = (size_t)(count), e_ = sizeof *z->field;                                 \
        if (n_ > 0) {                                                                             \
            if (n_ > (SIZE_MAX - 16) / e_ || 16 + n_ * e_ > pl__image_left(img)) st = PL_ERR_IO;                               \
            else if (!(z->field = pl_malloc(n_ * e_))) st = PL_ERR_NOMEM;                            \
        }                                                                                         \
        if (st == PL_OK) st = pl__image_get_array(img, z->field, e_, n_);                         \
        if (st != PL_OK)                                                                          \
            pl__world_error(w, st, st == PL_ERR_NOMEM ? "load state: out of memory for the darcy array '%s'" \
                                                      : "load state: the darcy array '%s' does not fit (damaged)", \
                            #field);                                                              \
    }
    PL_FL_SNAPSHOT_ARRAYS(PL_FL_GET_ARRAY)
#undef PL_FL_GET_ARRAY
    if (st == PL_OK) st = pl__fluid_restore(w, f, z);
    pl__fluid_snapshot_free(&z);
    return st;
}
