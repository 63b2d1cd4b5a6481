/* The FIC stabilised pressure of the linear triangles (seed 002 §5, eqs. 83, 90-92, 99-100, 104;
 * the discrete matrices reconstructed in docs/solids.md from Oñate, Rojek, Taylor & Zienkiewicz
 * 2004). With nodal pressure p, projected gradient pi and tau_e = alpha h_e^2 / (2 G):
 *
 *   (M_p / K) (p^{n+1} - p^n) + L p^{n+1} + Q pi^n = G^T du          (pressure, eq. 83/99)
 *   pi^{n+1} = -M_tau^-1 Q^T p^{n+1}                                 (projection, eq. 100)
 *
 * M_p = int N_a (lumped), L_ab = int tau grad N_a . grad N_b, Q_a(pi) = int tau grad N_a . pi,
 * (G^T du)_a = int N_a d(eps_v), M_tau = int tau N_a (lumped). Semi-implicit: the matrix
 * M_p / K + L is factorised once by CHOLMOD (analysis reused; in the updated Lagrangian form the
 * values are refactorised each step on the current configuration). Explicit (eq. 104):
 * p^{n+1} = p^n + K M_p^-1 (G^T du - L p^n - Q pi^n), stable while the spectral radius of
 * K M_p^-1 (L - Q M_tau^-1 Q^T) stays below one (estimated at preparation, refused above). */
#include "solid/fic/solid_internal.h"
#include "core/alloc.h"
#include <cholmod.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct fic_chol {
    cholmod_common cc;
    cholmod_sparse *A;
    cholmod_factor *L;
    cholmod_dense *b, *x, *wy, *we;
    int32_t *emap;   /* 9 per element: position of (a, b) in A->x, -1 for the lower triangle */
    int factorised;
} fic_chol;

static double bulk(const pl_solid_def *d) { return d->young / (3 * (1 - 2 * d->poisson)); }


void pl_sf_fic_free(pl_sf *s) {
    fic_chol *f = s->chol;
    if (!f) return;
    if (f->A) cholmod_free_sparse(&f->A, &f->cc);
    if (f->L) cholmod_free_factor(&f->L, &f->cc);
    if (f->b) cholmod_free_dense(&f->b, &f->cc);
    if (f->x) cholmod_free_dense(&f->x, &f->cc);
    if (f->wy) cholmod_free_dense(&f->wy, &f->cc);
    if (f->we) cholmod_free_dense(&f->we, &f->cc);
    cholmod_finish(&f->cc);
    pl_free(f->emap);
    pl_free(f);
    s->chol = NULL;
}

static int cmp_i64(const void *a, const void *b) {
    const int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

/* Pattern of M_p/K + L (upper triangle, CSC) and the element map; symbolic analysis. */
static pl_status build_pattern(pl_sf *s, fic_chol *f) {
    const int nn = s->nn;
    const size_t nk = (size_t)s->ne * 6 + (size_t)nn;
    int64_t *key = pl_malloc(sizeof *key * nk);
    if (!key) return PL_ERR_NOMEM;
    size_t k = 0;
    for (int i = 0; i < nn; i++) key[k++] = (int64_t)i * nn + i;
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[3 * (size_t)e];
        for (int a = 0; a < 3; a++)
            for (int b = a + 1; b < 3; b++) {
                const int64_t lo = n[a] < n[b] ? n[a] : n[b], hi = n[a] < n[b] ? n[b] : n[a];
                key[k++] = hi * nn + lo; /* column-major: column hi, row lo */
            }
    }
    qsort(key, k, sizeof *key, cmp_i64);
    size_t u = 0;
    for (size_t q = 0; q < k; q++)
        if (u == 0 || key[q] != key[u - 1]) key[u++] = key[q];
    f->A = cholmod_allocate_sparse((size_t)nn, (size_t)nn, u, 1, 1, 1, CHOLMOD_REAL, &f->cc);
    f->emap = pl_malloc(sizeof *f->emap * 9 * (size_t)s->ne);
    if (!f->A || !f->emap) {
        pl_free(key);
        return PL_ERR_NOMEM;
    }
    int *Ap = f->A->p, *Ai = f->A->i;
    int col = 0;
    Ap[0] = 0;
    for (size_t q = 0; q < u; q++) {
        const int j = (int)(key[q] / nn), i = (int)(key[q] % nn);
        while (col < j) Ap[++col] = (int)q;
        Ai[q] = i;
    }
    while (col < nn) Ap[++col] = (int)u;
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[3 * (size_t)e];
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                const int i = n[a], j = n[b];
                int32_t pos = -1;
                if (i <= j) {
                    const int64_t kk = (int64_t)j * nn + i;
                    const int64_t *hit = bsearch(&kk, key, u, sizeof *key, cmp_i64);
                    pos = (int32_t)(hit - key);
                }
                f->emap[9 * e + 3 * a + b] = pos;
            }
    }
    pl_free(key);
    f->b = cholmod_zeros((size_t)nn, 1, CHOLMOD_REAL, &f->cc);
    if (!f->b) return PL_ERR_NOMEM;
    f->L = cholmod_analyze(f->A, &f->cc);
    if (!f->L || f->cc.status < CHOLMOD_OK) return PL_ERR_NUMERIC;
    return PL_OK;
}

/* Values of M_p/K + L on the configuration xy, numeric factorisation (analysis reused). */
static pl_status factorize(pl_sf *s, fic_chol *f, const double *xy) {
    const double K = bulk(&s->def);
    double *Ax = f->A->x;
    memset(Ax, 0, sizeof *Ax * ((int *)f->A->p)[s->nn]);
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[3 * (size_t)e];
        double b[3], c[3];
        const double A = pl_sf_tri_grad(xy, n, b, c);
        for (int a = 0; a < 3; a++)
            for (int q = 0; q < 3; q++) {
                const int32_t pos = f->emap[9 * e + 3 * a + q];
                if (pos < 0) continue;
                Ax[pos] += s->tau[e] * A * (b[a] * b[q] + c[a] * c[q]) + (a == q ? A / (3 * K) : 0);
            }
    }
    if (!cholmod_factorize(f->A, f->L, &f->cc) || f->cc.status == CHOLMOD_NOT_POSDEF) {
        snprintf(s->err, sizeof s->err,
                 "solid: the FIC pressure matrix M_p/K + L is not positive definite (CHOLMOD status %d); an "
                 "element has collapsed",
                 f->cc.status);
        return PL_ERR_NUMERIC;
    }
    f->factorised = 1;
    return PL_OK;
}

/* y = K M_p^-1 (L p + Q pi(p)) with pi(p) = -M_tau^-1 Q^T p: the explicit iteration's operator. */
static void explicit_operator(const pl_sf *s, const double *xy, const double *p, double *pi, double *y) {
    const double K = bulk(&s->def);
    memset(pi, 0, sizeof *pi * 2 * (size_t)s->nn);
    memset(y, 0, sizeof *y * (size_t)s->nn);
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[3 * (size_t)e];
        double b[3], c[3];
        const double A = pl_sf_tri_grad(xy, n, b, c);
        const double gx = b[0] * p[n[0]] + b[1] * p[n[1]] + b[2] * p[n[2]];
        const double gy = c[0] * p[n[0]] + c[1] * p[n[1]] + c[2] * p[n[2]];
        for (int a = 0; a < 3; a++) {
            pi[2 * n[a]] -= s->tau[e] * A / 3 * gx;
            pi[2 * n[a] + 1] -= s->tau[e] * A / 3 * gy;
        }
    }
    for (int i = 0; i < s->nn; i++) {
        pi[2 * i] /= s->mt[i];
        pi[2 * i + 1] /= s->mt[i];
    }
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[3 * (size_t)e];
        double b[3], c[3];
        const double A = pl_sf_tri_grad(xy, n, b, c);
        const double gx = b[0] * p[n[0]] + b[1] * p[n[1]] + b[2] * p[n[2]] +
                          (pi[2 * n[0]] + pi[2 * n[1]] + pi[2 * n[2]]) / 3;
        const double gy = c[0] * p[n[0]] + c[1] * p[n[1]] + c[2] * p[n[2]] +
                          (pi[2 * n[0] + 1] + pi[2 * n[1] + 1] + pi[2 * n[2] + 1]) / 3;
        for (int a = 0; a < 3; a++) y[n[a]] += s->tau[e] * A * (b[a] * gx + c[a] * gy);
    }
    for (int i = 0; i < s->nn; i++) y[i] *= K / s->mp[i];
}

pl_status pl_sf_fic_prepare(pl_sf *s) {
    if (s->def.formulation == PL_SOLID_FIC_EXPLICIT) {
        /* power iteration on the explicit operator from a deterministic start vector */
        double *p = pl_malloc(sizeof *p * (size_t)s->nn), *y = pl_malloc(sizeof *y * (size_t)s->nn);
        double *pi = pl_malloc(sizeof *pi * 2 * (size_t)s->nn);
        if (!p || !y || !pi) {
            pl_free(p); pl_free(y); pl_free(pi);
            return PL_ERR_NOMEM;
        }
        uint32_t r = 12345u;
        for (int i = 0; i < s->nn; i++) {
            r = r * 1664525u + 1013904223u;
            p[i] = (double)(r >> 8) / 16777216.0 - 0.5;
        }
        double rho = 0;
        for (int it = 0; it < 60; it++) {
            explicit_operator(s, s->X, p, pi, y);
            double ny = 0, np = 0;
            for (int i = 0; i < s->nn; i++) ny += y[i] * y[i], np += p[i] * p[i];
            rho = np > 0 ? sqrt(ny / np) : 0;
            const double sc = ny > 0 ? 1 / sqrt(ny) : 0;
            for (int i = 0; i < s->nn; i++) p[i] = y[i] * sc;
        }
        pl_free(p); pl_free(y); pl_free(pi);
        s->fic_rho = rho;
        if (!(1.05 * rho < 1)) {
            snprintf(s->err, sizeof s->err,
                     "solid: the explicit FIC pressure update is unstable for this material: spectral radius "
                     "%.3g >= 1/1.05 (K/G = %.4g, fic_alpha = %g). Use formulation = fic_semi_implicit (the "
                     "Laplacian solved by CHOLMOD) or lower fic_alpha below %.3g",
                     rho, 2 * (1 + s->def.poisson) / (3 * (1 - 2 * s->def.poisson)),
                     s->def.fic_alpha, s->def.fic_alpha * 0.9 / (1.05 * rho));
            return PL_ERR_UNSTABLE;
        }
        return PL_OK;
    }
    if (s->def.formulation != PL_SOLID_FIC_SEMI_IMPLICIT || s->chol) return PL_OK;
    fic_chol *f = pl_calloc(1, sizeof *f);
    if (!f) return PL_ERR_NOMEM;
    cholmod_start(&f->cc);
    f->cc.print = 0;
    s->chol = f;
    pl_status st = build_pattern(s, f);
    if (st == PL_OK) st = factorize(s, f, s->X);
    if (st != PL_OK) {
        if (!s->err[0]) snprintf(s->err, sizeof s->err, "solid: could not build the FIC pressure system");
        pl_sf_fic_free(s);
    }
    return st;
}

pl_status pl_sf_fic_pressure(pl_sf *s, const double *du) {
    const double K = bulk(&s->def);
    const double *xy = s->def.large_strain ? s->x : s->X;
    const double *xd = s->def.large_strain ? s->xm : s->X; /* strain increment: mid-step */
    double *r = s->rhs;
    /* r = G^T du - (L p^n + Q pi^n) (explicit) or M_p p^n / K + G^T du - Q pi^n (semi-implicit) */
    memset(r, 0, sizeof *r * (size_t)s->nn);
    const int semi = s->def.formulation == PL_SOLID_FIC_SEMI_IMPLICIT;
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[3 * (size_t)e];
        double b[3], c[3];
        const double Ad = pl_sf_tri_grad(xd, n, b, c);
        double ev = 0;
        for (int a = 0; a < 3; a++) ev += b[a] * du[2 * n[a]] + c[a] * du[2 * n[a] + 1];
        const double A = pl_sf_tri_grad(xy, n, b, c);
        double gx = (s->pi[2 * n[0]] + s->pi[2 * n[1]] + s->pi[2 * n[2]]) / 3;
        double gy = (s->pi[2 * n[0] + 1] + s->pi[2 * n[1] + 1] + s->pi[2 * n[2] + 1]) / 3;
        if (!semi) {
            gx += b[0] * s->p[n[0]] + b[1] * s->p[n[1]] + b[2] * s->p[n[2]];
            gy += c[0] * s->p[n[0]] + c[1] * s->p[n[1]] + c[2] * s->p[n[2]];
        }
        for (int a = 0; a < 3; a++) r[n[a]] += Ad / 3 * ev - s->tau[e] * A * (b[a] * gx + c[a] * gy);
    }
    if (semi) {
        fic_chol *f = s->chol;
        if (!f) {
            pl_status st = pl_sf_fic_prepare(s);
            if (st != PL_OK) return st;
            f = s->chol;
        } else if (s->def.large_strain) {
            pl_status st = factorize(s, f, xy);
            if (st != PL_OK) return st;
        }
        double *b = f->b->x;
        for (int i = 0; i < s->nn; i++) b[i] = r[i] + s->mp[i] * s->p[i] / K;
        if (!cholmod_solve2(CHOLMOD_A, f->L, f->b, NULL, &f->x, NULL, &f->wy, &f->we, &f->cc)) {
            snprintf(s->err, sizeof s->err, "solid: the FIC pressure solve failed (CHOLMOD status %d)", f->cc.status);
            return PL_ERR_NUMERIC;
        }
        memcpy(s->p, f->x->x, sizeof *s->p * (size_t)s->nn);
    } else {
        for (int i = 0; i < s->nn; i++) s->p[i] += K * r[i] / s->mp[i];
    }
    /* projected gradient (eq. 100), lumped M_tau */
    memset(s->pi, 0, sizeof *s->pi * 2 * (size_t)s->nn);
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[3 * (size_t)e];
        double b[3], c[3];
        const double A = pl_sf_tri_grad(xy, n, b, c);
        const double gx = b[0] * s->p[n[0]] + b[1] * s->p[n[1]] + b[2] * s->p[n[2]];
        const double gy = c[0] * s->p[n[0]] + c[1] * s->p[n[1]] + c[2] * s->p[n[2]];
        for (int a = 0; a < 3; a++) {
            s->pi[2 * n[a]] -= s->tau[e] * A / 3 * gx;
            s->pi[2 * n[a] + 1] -= s->tau[e] * A / 3 * gy;
        }
    }
    for (int i = 0; i < s->nn; i++) {
        s->pi[2 * i] /= s->mt[i];
        s->pi[2 * i + 1] /= s->mt[i];
    }
    return PL_OK;
}
