/* Assembly of the Darcy-flow system (seed 000 §3.7-3.8): the fixed sparsity pattern of the
 * mesh, boundary lines applied to nodes, element admittance (eq. 3.11) and mass matrices
 * scattered into it, and the reduced SPD matrix of the free nodes (prescribed heads eliminated
 * symmetrically, eq. 3.16) handed to CHOLMOD, whose symbolic analysis is kept while the mesh
 * and the set of prescribed nodes do not change. */
#include "core/alloc.h"
#include "fluid/darcy/darcy_internal.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct ij { int32_t j, i; } ij; /* column, row */
static int cmp_ij(const void *a, const void *b) {
    const ij *p = a, *q = b;
    if (p->j != q->j) return (p->j > q->j) - (p->j < q->j);
    return (p->i > q->i) - (p->i < q->i);
}

void pl_fl_system_free(pl_fl_system *s) {
    pl_free(s->colp); pl_free(s->rowi); pl_free(s->kval); pl_free(s->mval); pl_free(s->mlump); pl_free(s->emap); pl_free(s->diag);
    pl_free(s->is_dir); pl_free(s->dir_head); pl_free(s->dir_line); pl_free(s->fload);
    pl_free(s->free_index); pl_free(s->free_node); pl_free(s->amap); pl_free(s->work);
    if (s->cc_started) {
        if (s->A) cholmod_free_sparse(&s->A, &s->cc);
        if (s->L) cholmod_free_factor(&s->L, &s->cc);
        if (s->rhs) cholmod_free_dense(&s->rhs, &s->cc);
        if (s->sol) cholmod_free_dense(&s->sol, &s->cc);
        if (s->wy) cholmod_free_dense(&s->wy, &s->cc);
        if (s->we) cholmod_free_dense(&s->we, &s->cc);
        cholmod_finish(&s->cc);
    }
    memset(s, 0, sizeof *s);
}

static int find_entry(const pl_fl_system *s, int col, int row) {
    int lo = s->colp[col], hi = s->colp[col + 1] - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (s->rowi[mid] == row) return mid;
        if (s->rowi[mid] < row) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}

/* Pattern of the full matrix (depends on the mesh only). */
static pl_status build_pattern(struct pl_fluid *f) {
    pl_fl_system *s = &f->sys;
    const pl_mesh *m = &f->mesh;
    size_t n9 = 9 * (size_t)m->ne;
    ij *pairs = pl_malloc(sizeof(ij) * n9);
    if (!pairs) return PL_ERR_NOMEM;
    for (int e = 0; e < m->ne; e++)
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) pairs[9 * e + 3 * a + b] = (ij){m->tri[3 * e + a], m->tri[3 * e + b]};
    qsort(pairs, n9, sizeof(ij), cmp_ij);
    size_t nu = 0;
    for (size_t k = 0; k < n9; k++)
        if (nu == 0 || pairs[k].j != pairs[nu - 1].j || pairs[k].i != pairs[nu - 1].i) pairs[nu++] = pairs[k];
    s->nnz = (int)nu;
    s->colp = pl_calloc((size_t)m->nn + 1, sizeof(int32_t));
    s->rowi = pl_malloc(sizeof(int32_t) * nu);
    s->kval = pl_calloc(nu, sizeof(double));
    s->mval = pl_calloc(nu, sizeof(double));
    s->emap = pl_malloc(sizeof(int32_t) * n9);
    s->diag = pl_malloc(sizeof(int32_t) * (size_t)m->nn);
    s->work = pl_calloc((size_t)m->nn, sizeof(double));
    s->mlump = pl_calloc((size_t)m->nn, sizeof(double));
    if (!s->colp || !s->rowi || !s->kval || !s->mval || !s->emap || !s->diag || !s->work || !s->mlump) {
        pl_free(pairs);
        return PL_ERR_NOMEM;
    }
    for (size_t k = 0; k < nu; k++) {
        s->rowi[k] = pairs[k].i;
        s->colp[pairs[k].j + 1]++;
    }
    for (int j = 0; j < m->nn; j++) s->colp[j + 1] += s->colp[j];
    pl_free(pairs);
    for (int e = 0; e < m->ne; e++)
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) s->emap[9 * e + 3 * a + b] = find_entry(s, m->tri[3 * e + b], m->tri[3 * e + a]);
    for (int j = 0; j < m->nn; j++) s->diag[j] = find_entry(s, j, j);
    return PL_OK;
}

static double seg_dist(pl_vec2 p, pl_vec2 a, pl_vec2 b, double *t) {
    double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    double u = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
    *t = u;
    if (u < 0) u = 0;
    if (u > 1) u = 1;
    return hypot(p.x - (a.x + u * dx), p.y - (a.y + u * dy));
}

/* Boundary lines -> prescribed nodes and flux loads; free numbering. */
static pl_status apply_lines(struct pl_fluid *f) {
    pl_fl_system *s = &f->sys;
    const pl_mesh *m = &f->mesh;
    int nn = m->nn;
    pl_free(s->is_dir); pl_free(s->dir_head); pl_free(s->dir_line); pl_free(s->fload); pl_free(s->free_index); pl_free(s->free_node);
    s->is_dir = pl_calloc((size_t)nn, 1);
    s->dir_head = pl_calloc((size_t)nn, sizeof(double));
    s->dir_line = pl_malloc(sizeof(int32_t) * (size_t)nn);
    s->fload = pl_calloc((size_t)nn, sizeof(double));
    s->free_index = pl_malloc(sizeof(int32_t) * (size_t)nn);
    s->free_node = pl_malloc(sizeof(int32_t) * (size_t)nn);
    if (!s->is_dir || !s->dir_head || !s->dir_line || !s->fload || !s->free_index || !s->free_node) return PL_ERR_NOMEM;
    double tol = 1e-7 * m->scale;
    for (int i = 0; i < nn; i++) s->dir_line[i] = -1;
    for (int l = 0; l < f->nl; l++) {
        const pl_fl_line *L = &f->lines[l];
        if (L->kind == PL_FL_LINE_HEAD) {
            for (int i = 0; i < nn; i++) {
                double t;
                if (seg_dist(m->xy[i], L->a, L->b, &t) <= tol) {
                    s->is_dir[i] = 1;
                    s->dir_head[i] = L->value; /* pressure head; total head added per update */
                    s->dir_line[i] = l;
                }
            }
        } else {
            for (int k = 0; k < m->nbe; k++) {
                int a = m->bedge[2 * k], b = m->bedge[2 * k + 1];
                double ta, tb;
                if (seg_dist(m->xy[a], L->a, L->b, &ta) <= tol && seg_dist(m->xy[b], L->a, L->b, &tb) <= tol) {
                    double len = hypot(m->xy[b].x - m->xy[a].x, m->xy[b].y - m->xy[a].y);
                    s->fload[a] += 0.5 * L->value * len; /* consistent load of eq. 3.14 */
                    s->fload[b] += 0.5 * L->value * len;
                }
            }
        }
    }
    s->nf = 0;
    for (int i = 0; i < nn; i++) {
        if (s->is_dir[i]) s->free_index[i] = -1;
        else { s->free_index[i] = s->nf; s->free_node[s->nf++] = i; }
    }
    return PL_OK;
}

/* Reduced matrix pattern (upper triangle of the free block) and its symbolic analysis. */
static pl_status build_reduced(struct pl_fluid *f) {
    pl_fl_system *s = &f->sys;
    const int nn = f->mesh.nn;
    if (s->A) cholmod_free_sparse(&s->A, &s->cc);
    if (s->L) cholmod_free_factor(&s->L, &s->cc);
    if (s->rhs) cholmod_free_dense(&s->rhs, &s->cc);
    if (s->sol) cholmod_free_dense(&s->sol, &s->cc);
    if (s->wy) cholmod_free_dense(&s->wy, &s->cc);
    if (s->we) cholmod_free_dense(&s->we, &s->cc);
    pl_free(s->amap);
    s->amap = pl_malloc(sizeof(int32_t) * (size_t)s->nnz);
    if (!s->amap) return PL_ERR_NOMEM;
    s->analysed = s->factorised = 0;
    if (s->nf == 0) {
        for (int p = 0; p < s->nnz; p++) s->amap[p] = -1;
        return PL_OK;
    }
    size_t anz = 0;
    for (int j = 0; j < nn; j++) {
        int fj = s->free_index[j];
        if (fj < 0) continue;
        for (int p = s->colp[j]; p < s->colp[j + 1]; p++) {
            int fi = s->free_index[s->rowi[p]];
            if (fi >= 0 && fi <= fj) anz++;
        }
    }
    s->A = cholmod_allocate_sparse((size_t)s->nf, (size_t)s->nf, anz, 1, 1, 1, CHOLMOD_REAL, &s->cc);
    if (!s->A) return PL_ERR_NOMEM;
    int *Ap = s->A->p, *Ai = s->A->i;
    double *Ax = s->A->x;
    size_t k = 0;
    for (int j = 0; j < nn; j++) {
        int fj = s->free_index[j];
        for (int p = s->colp[j]; p < s->colp[j + 1]; p++) s->amap[p] = -1;
        if (fj < 0) continue;
        Ap[fj] = (int)k;
        for (int p = s->colp[j]; p < s->colp[j + 1]; p++) {
            int fi = s->free_index[s->rowi[p]];
            if (fi >= 0 && fi <= fj) {
                Ai[k] = fi;
                Ax[k] = 0;
                s->amap[p] = (int32_t)k;
                k++;
            }
        }
    }
    Ap[s->nf] = (int)k;
    s->rhs = cholmod_zeros((size_t)s->nf, 1, CHOLMOD_REAL, &s->cc);
    if (!s->rhs) return PL_ERR_NOMEM;
    s->L = cholmod_analyze(s->A, &s->cc);
    if (!s->L || s->cc.status < CHOLMOD_OK) return PL_ERR_NUMERIC;
    s->analysed = 1;
    f->stats.analyses++;
    return PL_OK;
}

pl_status pl_fl_system_build(struct pl_fluid *f) {
    pl_fl_system *s = &f->sys;
    pl_status st;
    if (!s->cc_started) {
        cholmod_start(&s->cc);
        s->cc.print = 0;
        s->cc_started = 1;
    }
    if (!s->colp) {
        st = build_pattern(f);
        if (st != PL_OK) return st;
    }
    st = apply_lines(f);
    if (st != PL_OK) return st;
    st = build_reduced(f);
    if (st != PL_OK) {
        snprintf(f->msg, sizeof f->msg, "fluid: %s while building the reduced system (%d free nodes)",
                 st == PL_ERR_NOMEM ? "out of memory" : "CHOLMOD analysis failed", s->nf);
        return st;
    }
    f->k_dirty = 1;
    return PL_OK;
}

/* Element admittance (eq. 3.11) and mass matrices into the full pattern. */
void pl_fl_assemble(struct pl_fluid *f) {
    pl_fl_system *s = &f->sys;
    const pl_mesh *m = &f->mesh;
    const int consistent = f->par.mass_consistent;
    memset(s->kval, 0, sizeof(double) * (size_t)s->nnz);
    memset(s->mval, 0, sizeof(double) * (size_t)s->nnz);
    memset(s->mlump, 0, sizeof(double) * (size_t)m->nn);
    for (int e = 0; e < m->ne; e++) {
        const double *bc = &m->bc[6 * e];
        const double A = m->area[e];
        const double dx = f->perm[e], dy = f->perm[e] * f->quads[m->tri_quad[e]].anisotropy;
        const int32_t *map = &s->emap[9 * e];
        /* per-element storage folded into the mass matrix under FLUID_CONSOLIDATION */
        const double Se = (f->par.consolidation && f->stor) ? f->stor[e] : 1.0;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                s->kval[map[3 * a + b]] += (dx * bc[a] * bc[b] + dy * bc[3 + a] * bc[3 + b]) / (4 * A);
                if (consistent) s->mval[map[3 * a + b]] += Se * A / 12.0 * (a == b ? 2.0 : 1.0);
            }
        for (int a = 0; a < 3; a++) {
            s->mlump[m->tri[3 * e + a]] += Se * A / 3.0;
            if (!consistent) s->mval[map[4 * a]] += Se * A / 3.0;
        }
        f->perm_assembled[e] = f->perm[e];
        if (f->stor_assembled) f->stor_assembled[e] = f->par.consolidation && f->stor ? f->stor[e] : -1;
    }
    f->k_dirty = 0;
    s->factorised = 0;
    f->static_valid = 0;
    f->assembled_par = f->par;
}

/* Darcy's law in a frame accelerating with a (the pore water moves with the shaking table):
   q = -D (grad h + a/g). Its divergence term, -div(D a/g), gives the load
   -int grad N_i . D a/g dA = -(D_x b_i a_x + D_y c_i a_y) / (2 g) per element (A grad N_i =
   (b_i, c_i)/2), with the conductivities of the assembled matrix (anisotropy included). Inside a
   uniform region the loads cancel; at no-flow walls they make the pressure gradient -rho_f a
   that accelerates the water, at head lines the flow that a fixed free surface lets through. */
void pl_fl_add_frame_load(const struct pl_fluid *f, double *r) {
    const pl_mesh *m = &f->mesh;
    const pl_vec2 fa = pl_fl_frame_gradient(f);
    const double ax = fa.x, ay = fa.y;
    if (ax == 0 && ay == 0) return;
    for (int e = 0; e < m->ne; e++) {
        const double *bc = &m->bc[6 * e];
        const double dx = f->perm_assembled[e], dy = dx * f->quads[m->tri_quad[e]].anisotropy;
        const int32_t *v = &m->tri[3 * e];
        for (int a = 0; a < 3; a++) r[v[a]] -= 0.5 * (dx * bc[a] * ax + dy * bc[3 + a] * ay);
    }
}
