/* The dense boundary-element system [A]Y = R (seed 4.55) and its solve by LAPACK LU, with the
 * container's block factorised once while the container keeps its geometry (stokes_internal.h).
 *
 * Unknowns: [container node components | container gauge | particle node components |
 * particle gauges]. With F the container block, the system is [F B; C D] and is solved by the
 * Schur complement S = D - C F^-1 B: F's LU is reused, only B, C, D are assembled, and S
 * (the particles' size) is factorised each solve. */
#define _POSIX_C_SOURCE 200809L
#include "core/alloc.h"
#include "core/clock.h"
#include "fluid/stokes_bem/stokes_internal.h"
#include <math.h>
#include <string.h>
#include <time.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

extern void dgetrf_(const int *m, const int *n, double *a, const int *lda, int *ipiv, int *info);
extern void dgetrs_(const char *trans, const int *n, const int *nrhs, const double *a, const int *lda,
                    const int *ipiv, double *b, const int *ldb, int *info);
extern void dgemm_(const char *ta, const char *tb, const int *m, const int *n, const int *k, const double *alpha,
                   const double *a, const int *lda, const double *b, const int *ldb, const double *beta, double *c,
                   const int *ldc);
extern void dgemv_(const char *t, const int *m, const int *n, const double *alpha, const double *a, const int *lda,
                   const double *x, const int *incx, const double *beta, double *y, const int *incy);


void pl_sb_solver_free(pl_sb_solver *s) {
    pl_free(s->F);
    pl_free(s->Kf);
    pl_free(s->fpiv);
    pl_free(s->A);
    pl_free(s->R);
    pl_free(s->X);
    pl_free(s->spiv);
    memset(s, 0, sizeof *s);
}

static int grow(void **p, size_t *cap, size_t need) {
    if (need <= *cap && *p) return 0;
    pl_free(*p);
    *p = pl_malloc(need ? need : 1);
    *cap = *p ? need : 0;
    return *p ? 0 : -1;
}

/* 1 when the uniform pressure t = n on curve c is left free by its conditions: every
   traction-given component is tangential (n's component 0 there, a slip wall), so the curve
   needs a gauge. */
static int needs_gauge(const pl_sb_bnd *b, int c) {
    for (int e = b->curve_start[c]; e < b->curve_start[c + 1]; e++) {
        const pl_vec2 n = pl_sb_normal(b->a[e], b->b[e]);
        for (int d = 0; d < 4; d++)
            if (b->kind[4 * e + d] != PL_SB_VEL && fabs(d % 2 == 0 ? n.x : n.y) > 1e-9) return 0;
    }
    return 1;
}

pl_status pl_sb_solve(pl_sb_solver *s, pl_sb_bnd *bnd, const pl_sb_rules *r, double mu, double *kres) {
    const double t0 = pl_clock_seconds();
    const int ne = bnd->ne, nef = bnd->curve_start[bnd->nfixed], nd = 4 * ne, ndf = 4 * nef;
    /* gauge unknowns: one per all-velocity curve */
    int lam[4096];
    int *lam_of = bnd->ncurve <= 4096 ? lam : pl_malloc((size_t)bnd->ncurve * sizeof *lam_of);
    if (!lam_of) return PL_ERR_NOMEM;
    int nlf = 0, nlp = 0;
    for (int c = 0; c < bnd->ncurve; c++) lam_of[c] = needs_gauge(bnd, c) ? (c < bnd->nfixed ? nlf++ : nlp++) : -1;
    const int nf = ndf + nlf, n = nd + nlf + nlp, np = n - nf;
    for (int c = bnd->nfixed; c < bnd->ncurve; c++)
        if (lam_of[c] >= 0) lam_of[c] += nd + nlf;
    for (int c = 0; c < bnd->nfixed; c++)
        if (lam_of[c] >= 0) lam_of[c] += ndf;
#define UNK(d) ((d) < ndf ? (d) : (d) + nlf)
    /* resistance right-hand sides: 3 per curve with resist */
    int nres = 0;
    for (int c = 0; c < bnd->ncurve; c++) nres += bnd->resist[c] && kres ? 3 : 0;
    const int nrhs = 1 + nres;
    /* the container's key: its geometry, kinds and μ */
    uint64_t key = PL_HASH_SEED;
    key = pl_hash_bytes(key, bnd->a, (size_t)nef * sizeof(pl_vec2));
    key = pl_hash_bytes(key, bnd->b, (size_t)nef * sizeof(pl_vec2));
    key = pl_hash_bytes(key, bnd->kind, (size_t)ndf);
    key = pl_hash_bytes(key, &mu, sizeof mu);
    key = pl_hash_bytes(key, &nlf, sizeof nlf);
    if (key == 0) key = 1;
    const int reuse = s->fkey == key && s->nf == nf;
    if (grow((void **)&s->A, &s->acap, (size_t)n * (size_t)n * sizeof(double)) ||
        grow((void **)&s->R, &s->rcap, (size_t)n * (size_t)nrhs * sizeof(double)) ||
        grow((void **)&s->X, &s->xcap, (size_t)nf * (size_t)(np > 0 ? np : 1) * sizeof(double)) ||
        grow((void **)&s->spiv, &s->pcap, (size_t)(n > 0 ? n : 1) * sizeof(int))) {
        if (lam_of != lam) pl_free(lam_of);
        return PL_ERR_NOMEM;
    }
    if (!reuse) {
        pl_free(s->F);
        pl_free(s->Kf);
        pl_free(s->fpiv);
        s->F = pl_malloc((size_t)nf * (size_t)nf * sizeof(double) + 1);
        s->Kf = pl_calloc((size_t)ndf * (size_t)ndf + 1, sizeof(double));
        s->fpiv = pl_malloc((size_t)nf * sizeof(int) + 1);
        s->fkey = 0;
        if (!s->F || !s->Kf || !s->fpiv) {
            if (lam_of != lam) pl_free(lam_of);
            return PL_ERR_NOMEM;
        }
    }
    double *A = s->A, *R = s->R;
    /* zero what is assembled: all of A except F's place when it is reused */
    for (int j = 0; j < n; j++) {
        if (reuse && j < nf) memset(A + (size_t)j * n + nf, 0, (size_t)np * sizeof(double));
        else memset(A + (size_t)j * n, 0, (size_t)n * sizeof(double));
    }
    memset(R, 0, (size_t)n * (size_t)nrhs * sizeof(double));
    /* resistance column of each curve */
    int rescol_buf[4096];
    int *rescol = bnd->ncurve <= 4096 ? rescol_buf : pl_malloc((size_t)bnd->ncurve * sizeof *rescol);
    int *curve_of = pl_malloc((size_t)(ne > 0 ? ne : 1) * sizeof *curve_of);
    if (!rescol || !curve_of) {
        if (lam_of != lam) pl_free(lam_of);
        if (rescol && rescol != rescol_buf) pl_free(rescol);
        pl_free(curve_of);
        return PL_ERR_NOMEM;
    }
    for (int c = 0, col = 1; c < bnd->ncurve; c++) {
        rescol[c] = bnd->resist[c] && kres ? col : -1;
        if (rescol[c] > 0) col += 3;
        for (int e = bnd->curve_start[c]; e < bnd->curve_start[c + 1]; e++) curve_of[e] = c;
    }
    /* ---- assembly: rows = the collocation nodes, columns = the elements' node components */
    for (int er = 0; er < ne; er++) {
        for (int mr = 0; mr < 2; mr++) {
            const pl_vec2 P = pl_sb_node_pos(bnd->a[er], bnd->b[er], mr);
            const int inode = 2 * er + mr;
            for (int k = 0; k < ne; k++) {
                const int ff = er < nef && k < nef;
                if (ff && reuse) continue;
                double G[2][2][2], H[2][2][2];
                if (k == er) pl_sb_elem_self(r, mr, bnd->a[k], bnd->b[k], mu, G, H);
                else pl_sb_elem_regular(r, P, bnd->a[k], bnd->b[k], mu, G, H);
                const int ck = curve_of[k], rc = rescol[ck];
                for (int m = 0; m < 2; m++) {
                    const int knode = 2 * k + m;
                    const pl_vec2 X = pl_sb_node_pos(bnd->a[k], bnd->b[k], m);
                    for (int bb = 0; bb < 2; bb++) {
                        const int d = 2 * knode + bb, col = UNK(d);
                        const int vel = bnd->kind[d] == PL_SB_VEL;
                        for (int aa = 0; aa < 2; aa++) {
                            const int row = UNK(2 * inode + aa);
                            const double h = H[m][aa][bb] + (knode == inode && aa == bb ? 0.5 : 0);
                            const double g = G[m][aa][bb];
                            const double acoef = vel ? -g : h, kcoef = vel ? h : -g;
                            A[(size_t)col * n + row] = acoef;
                            if (ff) {
                                s->Kf[(size_t)d * ndf + (2 * inode + aa)] = kcoef;
                            } else {
                                R[row] -= kcoef * (vel ? bnd->u[d] : bnd->t[d]);
                                if (rc > 0 && vel) {
                                    const pl_vec2 c = bnd->centre[ck];
                                    const double ux = bb == 0 ? 1 : 0, uy = bb == 1 ? 1 : 0;
                                    const double ur = bb == 0 ? -(X.y - c.y) : (X.x - c.x);
                                    R[(size_t)(rc + 0) * n + row] -= kcoef * ux;
                                    R[(size_t)(rc + 1) * n + row] -= kcoef * uy;
                                    R[(size_t)(rc + 2) * n + row] -= kcoef * ur;
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    /* container rows: the known values of the container times the cached coefficients */
    if (ndf > 0) {
        double *known = pl_malloc((size_t)ndf * sizeof *known);
        if (!known) {
            if (lam_of != lam) pl_free(lam_of);
            if (rescol != rescol_buf) pl_free(rescol);
            pl_free(curve_of);
            return PL_ERR_NOMEM;
        }
        for (int d = 0; d < ndf; d++) known[d] = bnd->kind[d] == PL_SB_VEL ? bnd->u[d] : bnd->t[d];
        const double m1 = -1, one = 1;
        const int inc = 1;
        dgemv_("N", &ndf, &ndf, &m1, s->Kf, &ndf, known, &inc, &one, R, &inc);
        pl_free(known);
    }
    /* gauges: λ_c's column on the curve's rows, its row Σ w t = 0 (w = n L/2 per node) */
    const double gs = 1 / (4 * M_PI * mu);
    for (int c = 0; c < bnd->ncurve; c++) {
        const int l = lam_of[c];
        if (l < 0 || (reuse && c < bnd->nfixed)) continue;
        for (int e = bnd->curve_start[c]; e < bnd->curve_start[c + 1]; e++) {
            const pl_vec2 nn = pl_sb_normal(bnd->a[e], bnd->b[e]);
            const double L = hypot(bnd->b[e].x - bnd->a[e].x, bnd->b[e].y - bnd->a[e].y);
            for (int m = 0; m < 2; m++)
                for (int bb = 0; bb < 2; bb++) {
                    const int d = 4 * e + 2 * m + bb, u = UNK(d);
                    const double w = 0.5 * L * (bb == 0 ? nn.x : nn.y);
                    A[(size_t)u * n + l] = w;
                    A[(size_t)l * n + u] = w * gs;
                }
        }
    }
    const double t1 = pl_clock_seconds();
    /* ---- factorisation: F (cached), then the Schur complement of the particles */
    int info = 0;
    pl_status st = PL_OK;
    if (!reuse && nf > 0) {
        for (int j = 0; j < nf; j++) memcpy(s->F + (size_t)j * nf, A + (size_t)j * n, (size_t)nf * sizeof(double));
        dgetrf_(&nf, &nf, s->F, &nf, s->fpiv, &info);
        if (info != 0) st = PL_ERR_NUMERIC;
        else s->fkey = key;
    }
    s->nf = nf;
    s->n = n;
    double *D = A + (size_t)nf * n + nf; /* particle block, lda n */
    if (st == PL_OK && np > 0) {
        if (nf > 0) {
            for (int j = 0; j < np; j++)
                memcpy(s->X + (size_t)j * nf, A + (size_t)(nf + j) * n, (size_t)nf * sizeof(double));
            dgetrs_("N", &nf, &np, s->F, &nf, s->fpiv, s->X, &nf, &info);
            const double m1 = -1, one = 1;
            dgemm_("N", "N", &np, &np, &nf, &m1, A + nf, &n, s->X, &nf, &one, D, &n);
        }
        dgetrf_(&np, &np, D, &n, s->spiv, &info);
        if (info != 0) st = PL_ERR_NUMERIC;
    }
    const double t2 = pl_clock_seconds();
    /* ---- solve all right-hand sides */
    if (st == PL_OK) {
        const double m1 = -1, one = 1;
        if (nf > 0) dgetrs_("N", &nf, &nrhs, s->F, &nf, s->fpiv, R, &n, &info);
        if (np > 0) {
            if (nf > 0) dgemm_("N", "N", &np, &nrhs, &nf, &m1, A + nf, &n, R, &n, &one, R + nf, &n);
            dgetrs_("N", &np, &nrhs, D, &n, s->spiv, R + nf, &n, &info);
            if (nf > 0) dgemm_("N", "N", &nf, &nrhs, &np, &m1, s->X, &nf, R + nf, &n, &one, R, &n);
        }
        for (int d = 0; d < nd; d++) {
            const double y = R[UNK(d)];
            if (!isfinite(y)) st = PL_ERR_NUMERIC;
            if (bnd->kind[d] == PL_SB_VEL) bnd->t[d] = y;
            else bnd->u[d] = y;
        }
        /* resistances: the load on curve c for its own unit motions */
        for (int c = 0; c < bnd->ncurve && kres; c++) {
            if (rescol[c] < 0) continue;
            const int e0 = bnd->curve_start[c], e1 = bnd->curve_start[c + 1];
            double *tt = pl_malloc((size_t)(4 * (e1 - e0)) * sizeof *tt + 1);
            if (!tt) {
                st = PL_ERR_NOMEM;
                break;
            }
            for (int mode = 0; mode < 3; mode++) {
                const double *y = R + (size_t)(rescol[c] + mode) * n;
                for (int d = 4 * e0; d < 4 * e1; d++) tt[d - 4 * e0] = y[UNK(d)];
                pl_vec2 F;
                double M;
                /* pl_sb_curve_load reads t + 4e: shift the base so that index 4 e0 maps to tt[0] */
                pl_sb_bnd sub = *bnd;
                sub.a = bnd->a + e0;
                sub.b = bnd->b + e0;
                pl_sb_curve_load(&sub, tt, 0, e1 - e0, bnd->centre[c], &F, &M);
                kres[9 * c + 0 + mode] = -F.x;
                kres[9 * c + 3 + mode] = -F.y;
                kres[9 * c + 6 + mode] = -M;
            }
            pl_free(tt);
        }
    }
#undef UNK
    s->reused = reuse;
    s->nrhs = nrhs;
    s->t_assemble = t1 - t0;
    s->t_factor = t2 - t1;
    s->t_solve = pl_clock_seconds() - t2;
    if (lam_of != lam) pl_free(lam_of);
    if (rescol != rescol_buf) pl_free(rescol);
    pl_free(curve_of);
    if (st != PL_OK && !reuse) s->fkey = 0;
    return st;
}
