/* The FIC stabilised pressure of the linear triangles (seed 002 §5, eqs. 83, 90-92, 99-100, 104;
 * the discrete matrices reconstructed in docs/solids.md from Oñate, Rojek, Taylor & Zienkiewicz
 * 2004). With nodal pressure p, projected gradient pi and tau_e = alpha h_e^2 / (2 G):
 *
 *   (M_p / K) p^{n+1} + L p^{n+1} + Q pi^{n+1} = g^{n+1},  g^{n+1} = g^n + G^T du  (eq. 83/99)
 *   pi^{n+1} = -M_tau^-1 Q^T p^{n+1}                                 (projection, eq. 100)
 *
 * g (s->gv, state) accumulates the volumetric strain integral int N_a d(eps_v): the pressure
 * equation is the static FIC equation of the seed's refs. [4, 30] in total form, evaluated once
 * per step. (A literal incremental reading, (M_p/K) dp + L p^{n+1} + Q pi^n = G^T du with the
 * total p in the stabilising terms, adds L p + Q pi once per step: the static limit then depends
 * on the number of steps taken, and Cook's membrane came out 10 % too soft.)
 *
 * M_p = int N_a (lumped), L_ab = int tau grad N_a . grad N_b, Q_a(pi) = int tau grad N_a . pi,
 * (G^T du)_a = int N_a d(eps_v), M_tau = int tau N_a (lumped). Semi-implicit (the three-step
 * form, eqs. 102-103: pi eliminated): S p^{n+1} = g^{n+1} with S = M_p/K + L - Q M_tau^-1 Q^T,
 * symmetric positive definite, factorised once by CHOLMOD (analysis reused; in the updated
 * Lagrangian form refactorised each step on the current configuration). The pressure force
 * G p is then G S^-1 G^T u, symmetric and bounded by the plain element's volumetric stiffness
 * (S >= M_p/K), so the element bound of the critical step stays valid. (With pi lagged one step,
 * the four-step form of eqs. 99-100, the coupled iteration grew slowly at nu = 0.4999.)
 * Explicit (eq. 104):
 * p^{n+1} = K M_p^-1 (g^{n+1} - L p^n - Q pi^n), stable while the spectral radius of
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
    int32_t *n2e_start, *n2e; /* elements around each node (CSR) */
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
    pl_free(f->n2e_start);
    pl_free(f->n2e);
    pl_free(f);
    s->chol = NULL;
}

/* Elements around each node (for the projection term Q M_tau^-1 Q^T). */
static pl_status node_elements(pl_sf *s, fic_chol *f) {
    f->n2e_start = pl_calloc((size_t)s->nn + 1, sizeof *f->n2e_start);
    f->n2e = pl_malloc(sizeof *f->n2e * 3 * (size_t)(s->ne > 0 ? s->ne : 1));
    if (!f->n2e_start || !f->n2e) return PL_ERR_NOMEM;
    for (int e = 0; e < s->ne; e++)
        for (int a = 0; a < 3; a++) f->n2e_start[s->conn[3 * e + a] + 1]++;
    for (int i = 0; i < s->nn; i++) f->n2e_start[i + 1] += f->n2e_start[i];
    int32_t *fill = pl_malloc(sizeof *fill * (size_t)(s->nn > 0 ? s->nn : 1));
    if (!fill) return PL_ERR_NOMEM;
    memcpy(fill, f->n2e_start, sizeof *fill * (size_t)s->nn);
    for (int e = 0; e < s->ne; e++)
        for (int a = 0; a < 3; a++) f->n2e[fill[s->conn[3 * e + a]]++] = e;
    pl_free(fill);
    return PL_OK;
}

/* S = M_p/K + L - Q M_tau^-1 Q^T on the configuration xy (upper triangle), its numeric
   factorisation (the symbolic analysis of the first call reused: the pattern is the mesh's). */
static pl_status factorize(pl_sf *s, fic_chol *f, const double *xy) {
    const double K = bulk(&s->def);
    size_t cap = (size_t)s->ne * 6;
    for (int k = 0; k < s->nn; k++) {
        const size_t m = 2 * (size_t)(f->n2e_start[k + 1] - f->n2e_start[k]) + 1;
        cap += m * (m + 1) / 2;
    }
    cholmod_triplet *T = cholmod_allocate_triplet((size_t)s->nn, (size_t)s->nn, cap, 1, CHOLMOD_REAL, &f->cc);
    if (!T) return PL_ERR_NOMEM;
    int *Ti = T->i, *Tj = T->j;
    double *Tx = T->x;
    size_t nz = 0;
#define PUT(r, c, v) do { const int r_ = (r), c_ = (c); Ti[nz] = r_ < c_ ? r_ : c_; Tj[nz] = r_ < c_ ? c_ : r_; \
        Tx[nz++] = (v); } while (0)
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[3 * (size_t)e];
        double b[3], c[3];
        const double A = pl_sf_tri_grad(xy, n, b, c);
        for (int a = 0; a < 3; a++)
            for (int q = a; q < 3; q++)
                PUT(n[a], n[q], s->tau[e] * A * (b[a] * b[q] + c[a] * c[q]) + (a == q ? A / (3 * K) : 0));
    }
    /* - sum_k Q_ak . Q_bk / m_tau,k with Q_ak = sum_{e around k} tau_e A_e / 3 grad N_a */
    enum { MAXN = 64 };
    int32_t nb[MAXN];
    double qx[MAXN], qy[MAXN];
    for (int k = 0; k < s->nn; k++) {
        int m = 0;
        for (int32_t q = f->n2e_start[k]; q < f->n2e_start[k + 1]; q++) {
            const int e = f->n2e[q];
            const int32_t *n = &s->conn[3 * (size_t)e];
            double b[3], c[3];
            const double A = pl_sf_tri_grad(xy, n, b, c);
            for (int a = 0; a < 3; a++) {
                int j = 0;
                while (j < m && nb[j] != n[a]) j++;
                if (j == m) {
                    if (m == MAXN) {
                        cholmod_free_triplet(&T, &f->cc);
                        snprintf(s->err, sizeof s->err, "solid: node %d has more than %d neighbours", k + 1, MAXN);
                        return PL_ERR_ARG;
                    }
                    nb[m] = n[a], qx[m] = qy[m] = 0, m++;
                }
                qx[j] += s->tau[e] * A / 3 * b[a];
                qy[j] += s->tau[e] * A / 3 * c[a];
            }
        }
        for (int i = 0; i < m; i++)
            for (int j = i; j < m; j++) PUT(nb[i], nb[j], -(qx[i] * qx[j] + qy[i] * qy[j]) / s->mt[k]);
    }
#undef PUT
    T->nnz = nz;
    if (f->A) cholmod_free_sparse(&f->A, &f->cc);
    f->A = cholmod_triplet_to_sparse(T, nz, &f->cc);
    cholmod_free_triplet(&T, &f->cc);
    if (!f->A) return PL_ERR_NOMEM;
    if (!f->L) {
        f->L = cholmod_analyze(f->A, &f->cc);
        if (!f->L || f->cc.status < CHOLMOD_OK) return PL_ERR_NUMERIC;
    }
    if (!cholmod_factorize(f->A, f->L, &f->cc) || f->cc.status == CHOLMOD_NOT_POSDEF) {
        snprintf(s->err, sizeof s->err,
                 "solid: the FIC pressure matrix M_p/K + L - Q M_tau^-1 Q^T is not positive definite (CHOLMOD "
                 "status %d); an element has collapsed",
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
    f->b = cholmod_zeros((size_t)s->nn, 1, CHOLMOD_REAL, &f->cc);
    pl_status st = f->b ? node_elements(s, f) : PL_ERR_NOMEM;
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
    /* gv += G^T du; r = gv (semi-implicit, pi implicit) or gv - L p^n - Q pi^n (explicit) */
    const int semi = s->def.formulation == PL_SOLID_FIC_SEMI_IMPLICIT;
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[3 * (size_t)e];
        double b[3], c[3];
        const double Ad = pl_sf_tri_grad(xd, n, b, c);
        double ev = 0;
        for (int a = 0; a < 3; a++) ev += b[a] * du[2 * n[a]] + c[a] * du[2 * n[a] + 1];
        for (int a = 0; a < 3; a++) s->gv[n[a]] += Ad / 3 * ev;
    }
    memcpy(r, s->gv, sizeof *r * (size_t)s->nn);
    for (int e = 0; e < s->ne && !semi; e++) {
        const int32_t *n = &s->conn[3 * (size_t)e];
        double b[3], c[3];
        const double A = pl_sf_tri_grad(xy, n, b, c);
        const double gx = (s->pi[2 * n[0]] + s->pi[2 * n[1]] + s->pi[2 * n[2]]) / 3 +
                          b[0] * s->p[n[0]] + b[1] * s->p[n[1]] + b[2] * s->p[n[2]];
        const double gy = (s->pi[2 * n[0] + 1] + s->pi[2 * n[1] + 1] + s->pi[2 * n[2] + 1]) / 3 +
                          c[0] * s->p[n[0]] + c[1] * s->p[n[1]] + c[2] * s->p[n[2]];
        for (int a = 0; a < 3; a++) r[n[a]] -= s->tau[e] * A * (b[a] * gx + c[a] * gy);
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
        memcpy(f->b->x, r, sizeof *r * (size_t)s->nn);
        if (!cholmod_solve2(CHOLMOD_A, f->L, f->b, NULL, &f->x, NULL, &f->wy, &f->we, &f->cc)) {
            snprintf(s->err, sizeof s->err, "solid: the FIC pressure solve failed (CHOLMOD status %d)", f->cc.status);
            return PL_ERR_NUMERIC;
        }
        memcpy(s->p, f->x->x, sizeof *s->p * (size_t)s->nn);
    } else {
        for (int i = 0; i < s->nn; i++) s->p[i] = K * r[i] / s->mp[i];
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
