/* The global Navier–Stokes system on one mesh: unknown numbering, the Jacobian's sparsity
 * pattern (built once per mesh), assembly of residual and analytic Jacobian, Newton iterations
 * with UMFPACK (symbolic analysis once per pattern, numeric factorisation per Newton iteration),
 * BDF2 history, forces and mass-conservation diagnostics. */
#include "fluid/navier_stokes/ns_internal.h"
#include "core/alloc.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <umfpack.h>

static double cpu_now(void) { return (double)clock() / (double)CLOCKS_PER_SEC; }

/* global unknown of local unknown a of triangle t */
static int32_t glob(const ns_system *s, int t, int a) {
    const int nl = s->nloc;
    if (a < nl) return s->eldof[(size_t)t * nl + a];
    if (a < 2 * nl) return s->nvel + s->eldof[(size_t)t * nl + a - nl];
    return 2 * s->nvel + s->mesh.tri[3 * t + a - 2 * nl];
}

static int cmp_u64(const void *a, const void *b) {
    const uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static int64_t find_key(const uint64_t *k, int64_t n, uint64_t key) {
    int64_t lo = 0, hi = n;
    while (lo < hi) {
        const int64_t mid = (lo + hi) / 2;
        if (k[mid] < key) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

int ns_system_init(ns_system *s, ns_mesh *m, int kind, int ntags) {
    memset(s, 0, sizeof *s);
    s->mesh = *m;
    memset(m, 0, sizeof *m);
    const ns_mesh *M = &s->mesh;
    s->kind = kind;
    s->nloc = ns_elem_nodes(kind);
    const int has_edge = kind != NS_EL_MINI, has_bub = kind != NS_EL_P2;
    s->nvel = M->nv + (has_edge ? M->ne : 0) + (has_bub ? M->nt : 0);
    s->nunk = 2 * s->nvel + M->nv;
    s->ntags = ntags;
    s->pin = -1;
    const int nl = s->nloc, n = 2 * nl + 3;
    s->eldof = pl_malloc(sizeof(int32_t) * (size_t)M->nt * nl);
    s->vxy = pl_malloc(sizeof(double) * 2 * (size_t)s->nvel);
    s->tag_kind = pl_calloc((size_t)ntags + 1, 1);
    s->node_tag = pl_calloc((size_t)s->nvel, sizeof(int32_t));
    s->gu = pl_calloc((size_t)s->nvel, sizeof(double));
    s->gv = pl_calloc((size_t)s->nvel, sizeof(double));
    s->fixed = pl_calloc((size_t)s->nunk, 1);
    s->x = pl_calloc((size_t)s->nunk, sizeof(double));
    s->x1 = pl_calloc((size_t)s->nunk, sizeof(double));
    s->x2 = pl_calloc((size_t)s->nunk, sizeof(double));
    s->res = pl_calloc((size_t)s->nunk, sizeof(double));
    s->dx = pl_calloc((size_t)s->nunk, sizeof(double));
    s->hu = pl_calloc(2 * (size_t)s->nvel, sizeof(double));
    s->diag = pl_malloc(sizeof(int32_t) * (size_t)s->nunk);
    if (!s->eldof || !s->vxy || !s->tag_kind || !s->node_tag || !s->gu || !s->gv || !s->fixed || !s->x || !s->x1 ||
        !s->x2 || !s->res || !s->dx || !s->hu || !s->diag)
        return -1;
    for (int t = 0; t < M->nt; t++) {
        int32_t *d = s->eldof + (size_t)t * nl;
        for (int i = 0; i < 3; i++) d[i] = M->tri[3 * t + i];
        if (has_edge)
            for (int k = 0; k < 3; k++) d[3 + k] = M->nv + M->tri_edge[3 * t + k];
        if (has_bub) d[nl - 1] = M->nv + (has_edge ? M->ne : 0) + t;
    }
    ns_system_update_geometry(s); /* the velocity nodes' coordinates */
    /* pattern: every element entry except the zero pressure-pressure block, plus every diagonal */
    const int nvv = 2 * nl;
    const int64_t per = (int64_t)n * n - 9;
    const int64_t nk = (int64_t)M->nt * per + s->nunk;
    uint64_t *key = pl_malloc(sizeof(uint64_t) * (size_t)nk);
    if (!key) return -1;
    int64_t c = 0;
    for (int t = 0; t < M->nt; t++)
        for (int a = 0; a < n; a++)
            for (int b = 0; b < n; b++) {
                if (a >= nvv && b >= nvv) continue;
                key[c++] = (uint64_t)glob(s, t, b) * (uint64_t)s->nunk + (uint64_t)glob(s, t, a);
            }
    for (int i = 0; i < s->nunk; i++) key[c++] = (uint64_t)i * (uint64_t)s->nunk + (uint64_t)i;
    qsort(key, (size_t)c, sizeof *key, cmp_u64);
    int64_t u = 0;
    for (int64_t i = 0; i < c; i++)
        if (i == 0 || key[i] != key[i - 1]) key[u++] = key[i];
    s->nnz = (int)u;
    s->Ap = pl_calloc((size_t)s->nunk + 1, sizeof(int));
    s->Ai = pl_malloc(sizeof(int) * (size_t)u);
    s->Ax = pl_calloc((size_t)u, sizeof(double));
    s->emap = pl_malloc(sizeof(int32_t) * (size_t)M->nt * n * n);
    if (!s->Ap || !s->Ai || !s->Ax || !s->emap) {
        pl_free(key);
        return -1;
    }
    for (int64_t i = 0; i < u; i++) {
        const int col = (int)(key[i] / (uint64_t)s->nunk);
        s->Ai[i] = (int)(key[i] % (uint64_t)s->nunk);
        s->Ap[col + 1]++;
    }
    for (int j = 0; j < s->nunk; j++) s->Ap[j + 1] += s->Ap[j];
    for (int t = 0; t < M->nt; t++)
        for (int a = 0; a < n; a++)
            for (int b = 0; b < n; b++) {
                int32_t pos = -1;
                if (!(a >= nvv && b >= nvv))
                    pos = (int32_t)find_key(key, u, (uint64_t)glob(s, t, b) * (uint64_t)s->nunk + (uint64_t)glob(s, t, a));
                s->emap[((size_t)t * n + a) * n + b] = pos;
            }
    for (int i = 0; i < s->nunk; i++)
        s->diag[i] = (int32_t)find_key(key, u, (uint64_t)i * (uint64_t)s->nunk + (uint64_t)i);
    pl_free(key);
    s->st.nnz_matrix = (double)u;
    return 0;
}

void ns_system_update_geometry(ns_system *s) {
    const ns_mesh *M = &s->mesh;
    const int has_edge = s->kind != NS_EL_MINI, has_bub = s->kind != NS_EL_P2;
    for (int i = 0; i < M->nv; i++) {
        s->vxy[2 * i] = M->xy[2 * i];
        s->vxy[2 * i + 1] = M->xy[2 * i + 1];
    }
    if (has_edge)
        for (int e = 0; e < M->ne; e++) {
            const double *a = M->xy + 2 * M->edge[2 * e], *b = M->xy + 2 * M->edge[2 * e + 1];
            s->vxy[2 * (M->nv + e)] = 0.5 * (a[0] + b[0]);
            s->vxy[2 * (M->nv + e) + 1] = 0.5 * (a[1] + b[1]);
        }
    if (has_bub)
        for (int t = 0; t < M->nt; t++) {
            const int j = M->nv + (has_edge ? M->ne : 0) + t;
            const int32_t *v = M->tri + 3 * t;
            s->vxy[2 * j] = (M->xy[2 * v[0]] + M->xy[2 * v[1]] + M->xy[2 * v[2]]) / 3.0;
            s->vxy[2 * j + 1] = (M->xy[2 * v[0] + 1] + M->xy[2 * v[1] + 1] + M->xy[2 * v[2] + 1]) / 3.0;
        }
}

void ns_system_free(ns_system *s) {
    if (s->numeric) umfpack_di_free_numeric(&s->numeric);
    if (s->symbolic) umfpack_di_free_symbolic(&s->symbolic);
    ns_mesh_free(&s->mesh);
    pl_free(s->vxy);
    pl_free(s->eldof);
    pl_free(s->Ap);
    pl_free(s->Ai);
    pl_free(s->Ax);
    pl_free(s->emap);
    pl_free(s->diag);
    pl_free(s->tag_kind);
    pl_free(s->node_tag);
    pl_free(s->gu);
    pl_free(s->gv);
    pl_free(s->fixed);
    pl_free(s->x);
    pl_free(s->x1);
    pl_free(s->x2);
    pl_free(s->res);
    pl_free(s->dx);
    pl_free(s->hu);
    memset(s, 0, sizeof *s);
}

void ns_system_set_bc(ns_system *s, const uint8_t *tag_kind, ns_bc_fn fn, void *ctx) {
    const ns_mesh *M = &s->mesh;
    memcpy(s->tag_kind, tag_kind, (size_t)s->ntags + 1);
    memset(s->node_tag, 0, sizeof(int32_t) * (size_t)s->nvel);
    memset(s->fixed, 0, (size_t)s->nunk);
    int any_natural = 0;
    for (int e = 0; e < M->ne; e++) {
        const int tag = M->edge_tag[e];
        if (tag <= 0) continue;
        if (tag > s->ntags || tag_kind[tag] != NS_BC_VELOCITY) {
            any_natural = 1;
            continue;
        }
        int32_t nodes[3] = {M->edge[2 * e], M->edge[2 * e + 1], -1};
        if (s->kind != NS_EL_MINI) nodes[2] = M->nv + e;
        for (int k = 0; k < 3; k++) {
            const int32_t j = nodes[k];
            if (j < 0) continue;
            if (s->node_tag[j] == 0 || tag < s->node_tag[j]) s->node_tag[j] = tag;
        }
    }
    for (int j = 0; j < s->nvel; j++) {
        if (!s->node_tag[j]) continue;
        fn(ctx, s->node_tag[j], s->vxy[2 * j], s->vxy[2 * j + 1], &s->gu[j], &s->gv[j]);
        s->fixed[j] = s->fixed[s->nvel + j] = 1;
    }
    s->pin = any_natural ? -1 : 0;
    if (s->pin >= 0) s->fixed[2 * s->nvel + s->pin] = 1;
}

/* BDF2 history at the velocity nodes for a step tau, returns a0 */
static double history(ns_system *s, double tau) {
    if (tau <= 0.0) {
        memset(s->hu, 0, sizeof(double) * 2 * (size_t)s->nvel);
        return 0.0;
    }
    double c0, c1, c2;
    ns_bdf2_coeffs(tau, s->nhist >= 2 ? s->tau1 : 0.0, &c0, &c1, &c2);
    for (int j = 0; j < 2 * s->nvel; j++) s->hu[j] = -(c1 * s->x1[j] + c2 * s->x2[j]);
    return c0;
}

static void gather(const ns_system *s, int t, double a0, ns_elem_in *e) {
    const ns_mesh *M = &s->mesh;
    const int nl = s->nloc;
    e->kind = s->kind;
    e->a0 = a0;
    e->nu = s->nu;
    e->fx = s->fx;
    e->fy = s->fy;
    e->convect = s->convect;
    for (int i = 0; i < 3; i++) {
        const int32_t v = M->tri[3 * t + i];
        e->x[i] = M->xy[2 * v];
        e->y[i] = M->xy[2 * v + 1];
        e->q[i] = s->x[2 * s->nvel + v];
    }
    for (int i = 0; i < nl; i++) {
        const int32_t j = s->eldof[(size_t)t * nl + i];
        e->u[i] = s->x[j];
        e->v[i] = s->x[s->nvel + j];
        e->hu[i] = s->hu[j];
        e->hv[i] = s->hu[s->nvel + j];
    }
}

/* residual into s->res and (when with_jac) the Jacobian into Ax; bc: replace fixed rows */
static void assemble(ns_system *s, double a0, int with_jac, int bc) {
    const int nl = s->nloc, n = 2 * nl + 3;
    memset(s->res, 0, sizeof(double) * (size_t)s->nunk);
    if (with_jac) memset(s->Ax, 0, sizeof(double) * (size_t)s->nnz);
    double re[NS_MAXN], jac[NS_MAXN * NS_MAXN];
    int32_t g[NS_MAXN];
    ns_elem_in e;
    for (int t = 0; t < s->mesh.nt; t++) {
        gather(s, t, a0, &e);
        ns_elem_eval(&e, re, with_jac ? jac : NULL);
        for (int a = 0; a < n; a++) g[a] = glob(s, t, a);
        for (int a = 0; a < n; a++) {
            if (bc && s->fixed[g[a]]) continue;
            s->res[g[a]] += re[a];
            if (!with_jac) continue;
            const int32_t *em = s->emap + ((size_t)t * n + a) * n;
            for (int b = 0; b < n; b++)
                if (em[b] >= 0) s->Ax[em[b]] += jac[a * n + b];
        }
    }
    if (!bc) return;
    for (int j = 0; j < s->nvel; j++) {
        if (!s->fixed[j]) continue;
        s->res[j] = s->x[j] - s->gu[j];
        s->res[s->nvel + j] = s->x[s->nvel + j] - s->gv[j];
        if (with_jac) s->Ax[s->diag[j]] = s->Ax[s->diag[s->nvel + j]] = 1.0;
    }
    if (s->pin >= 0) {
        const int r = 2 * s->nvel + s->pin;
        s->res[r] = s->x[r];
        if (with_jac) s->Ax[s->diag[r]] = 1.0;
    }
}

void ns_system_residual_raw(ns_system *s, double tau) {
    const double a0 = history(s, tau);
    assemble(s, a0, 0, 0);
}

int ns_system_solve(ns_system *s, double tau, double tol, int max_iter, char *msg, size_t msg_size) {
    if (tau > 0.0 && s->nhist < 1) {
        snprintf(msg, msg_size, "BDF2 step without an initial state (push the history first)");
        return -1;
    }
    const double a0 = history(s, tau);
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    umfpack_di_defaults(control);
    s->st.newton_iters = 0;
    for (int it = 0; it < max_iter; it++) {
        double t0 = cpu_now();
        assemble(s, a0, 1, 1);
        s->st.t_assemble += cpu_now() - t0;
        if (!s->symbolic) {
            t0 = cpu_now();
            const int st = umfpack_di_symbolic(s->nunk, s->nunk, s->Ap, s->Ai, s->Ax, &s->symbolic, control, info);
            s->st.t_symbolic += cpu_now() - t0;
            s->st.n_symbolic++;
            if (st != UMFPACK_OK) {
                snprintf(msg, msg_size, "UMFPACK symbolic analysis failed (status %d, %d unknowns)", st, s->nunk);
                return -1;
            }
        }
        if (s->numeric) umfpack_di_free_numeric(&s->numeric);
        t0 = cpu_now();
        int st = umfpack_di_numeric(s->Ap, s->Ai, s->Ax, s->symbolic, &s->numeric, control, info);
        s->st.t_numeric += cpu_now() - t0;
        s->st.n_numeric++;
        if (st != UMFPACK_OK) {
            snprintf(msg, msg_size, "UMFPACK factorisation failed (status %d: singular Jacobian, %d unknowns)", st,
                     s->nunk);
            return -1;
        }
        s->st.nnz_lu = info[UMFPACK_LNZ] + info[UMFPACK_UNZ];
        t0 = cpu_now();
        st = umfpack_di_solve(UMFPACK_A, s->Ap, s->Ai, s->Ax, s->dx, s->res, s->numeric, control, info);
        s->st.t_solve += cpu_now() - t0;
        s->st.n_solve++;
        if (st != UMFPACK_OK) {
            snprintf(msg, msg_size, "UMFPACK solve failed (status %d)", st);
            return -1;
        }
        double dmax = 0, xmax = 0, rmax = 0;
        for (int i = 0; i < s->nunk; i++) {
            s->x[i] -= s->dx[i];
            if (fabs(s->dx[i]) > dmax) dmax = fabs(s->dx[i]);
            if (fabs(s->x[i]) > xmax) xmax = fabs(s->x[i]);
            if (fabs(s->res[i]) > rmax) rmax = fabs(s->res[i]);
        }
        s->st.newton_iters = it + 1;
        s->st.residual = rmax;
        if (!(dmax == dmax) || !(xmax < 1e300)) {
            snprintf(msg, msg_size, "Newton iteration diverged (not a number after %d iterations)", it + 1);
            return -1;
        }
        if (!s->convect || dmax <= tol * (1.0 + xmax)) return 0;
    }
    snprintf(msg, msg_size, "Newton did not converge in %d iterations (last correction %.3g of the solution)",
             max_iter, s->st.residual);
    return -1;
}

void ns_system_push_history(ns_system *s, double tau) {
    memcpy(s->x2, s->x1, sizeof(double) * (size_t)s->nunk);
    memcpy(s->x1, s->x, sizeof(double) * (size_t)s->nunk);
    s->tau1 = tau;
    s->nhist = s->nhist < 2 ? s->nhist + 1 : 2;
    if (tau <= 0.0) s->nhist = 1;
}

/* velocity gradient and pressure of triangle t at barycentric (l1, l2) */
static void point_state_vec(const ns_system *s, const double *X, int t, double l1, double l2, double *u, double *v,
                            double *q, double grad[4]) {
    const ns_mesh *M = &s->mesh;
    const int nl = s->nloc;
    double x[3], y[3], qv[3];
    for (int i = 0; i < 3; i++) {
        const int32_t k = M->tri[3 * t + i];
        x[i] = M->xy[2 * k];
        y[i] = M->xy[2 * k + 1];
        qv[i] = X[2 * s->nvel + k];
    }
    double phi[NS_MAXV], gx[NS_MAXV], gy[NS_MAXV];
    ns_elem_basis(s->kind, x, y, l1, l2, phi, gx, gy);
    double uu = 0, vv = 0, g0 = 0, g1 = 0, g2 = 0, g3 = 0;
    for (int i = 0; i < nl; i++) {
        const int32_t j = s->eldof[(size_t)t * nl + i];
        const double a = X[j], b = X[s->nvel + j];
        uu += a * phi[i];
        vv += b * phi[i];
        g0 += a * gx[i];
        g1 += a * gy[i];
        g2 += b * gx[i];
        g3 += b * gy[i];
    }
    if (u) *u = uu;
    if (v) *v = vv;
    if (q) *q = (1.0 - l1 - l2) * qv[0] + l1 * qv[1] + l2 * qv[2];
    if (grad) {
        grad[0] = g0;
        grad[1] = g1;
        grad[2] = g2;
        grad[3] = g3;
    }
}

static void point_state(const ns_system *s, int t, double l1, double l2, double *u, double *v, double *q,
                        double grad[4]) {
    point_state_vec(s, s->x, t, l1, l2, u, v, q, grad);
}

void ns_system_point(const ns_system *s, const double *X, int t, double l1, double l2, double *u, double *v,
                     double *q) {
    point_state_vec(s, X, t, l1, l2, u, v, q, NULL);
}

void ns_system_force_line(const ns_system *s, int tag, double rho, double cx, double cy, double *fx, double *fy,
                          double *moment) {
    static const double gs[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
    static const double gw[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    const ns_mesh *M = &s->mesh;
    double Fx = 0, Fy = 0, Mz = 0;
    for (int e = 0; e < M->ne; e++) {
        if (M->edge_tag[e] != tag) continue;
        const int t = M->edge_tri[2 * e];
        int k = 0;
        while (k < 3 && M->tri_edge[3 * t + k] != e) k++;
        const double *pa = M->xy + 2 * M->tri[3 * t + k], *pb = M->xy + 2 * M->tri[3 * t + (k + 1) % 3];
        const double dx = pb[0] - pa[0], dy = pb[1] - pa[1];
        const double L = sqrt(dx * dx + dy * dy);
        /* fluid on the left of a -> b: the body's outward normal points left, into the fluid */
        const double nx = -dy / L, ny = dx / L;
        for (int g = 0; g < 3; g++) {
            double l[3] = {0, 0, 0};
            l[k] = 1.0 - gs[g];
            l[(k + 1) % 3] = gs[g];
            double q, gr[4];
            point_state(s, t, l[1], l[2], NULL, NULL, &q, gr);
            const double sxx = -q + 2.0 * s->nu * gr[0], syy = -q + 2.0 * s->nu * gr[3];
            const double sxy = s->nu * (gr[1] + gr[2]);
            const double tx = rho * (sxx * nx + sxy * ny), ty = rho * (sxy * nx + syy * ny);
            const double px = pa[0] + gs[g] * dx, py = pa[1] + gs[g] * dy;
            Fx += gw[g] * L * tx;
            Fy += gw[g] * L * ty;
            Mz += gw[g] * L * ((px - cx) * ty - (py - cy) * tx);
        }
    }
    *fx = Fx;
    *fy = Fy;
    if (moment) *moment = Mz;
}

void ns_system_force_react(ns_system *s, double tau, int tag, double rho, double cx, double cy, double *fx,
                           double *fy, double *moment) {
    ns_system_residual_raw(s, tau);
    double Fx = 0, Fy = 0, Mz = 0;
    for (int j = 0; j < s->nvel; j++) {
        if (s->node_tag[j] != tag) continue;
        const double rx = -rho * s->res[j], ry = -rho * s->res[s->nvel + j];
        Fx += rx;
        Fy += ry;
        Mz += (s->vxy[2 * j] - cx) * ry - (s->vxy[2 * j + 1] - cy) * rx;
    }
    *fx = Fx;
    *fy = Fy;
    if (moment) *moment = Mz;
}

/* barycentric coordinates of (x, y) in triangle t */
static void bary(const ns_mesh *M, int t, double x, double y, double l[3]) {
    const int32_t *v = M->tri + 3 * t;
    const double x0 = M->xy[2 * v[0]], y0 = M->xy[2 * v[0] + 1];
    const double ax = M->xy[2 * v[1]] - x0, ay = M->xy[2 * v[1] + 1] - y0;
    const double bx = M->xy[2 * v[2]] - x0, by = M->xy[2 * v[2] + 1] - y0;
    const double det = ax * by - ay * bx;
    l[1] = ((x - x0) * by - (y - y0) * bx) / det;
    l[2] = (ax * (y - y0) - ay * (x - x0)) / det;
    l[0] = 1.0 - l[1] - l[2];
}

int ns_system_locate(const ns_system *s, double x, double y, int hint, double *l1, double *l2) {
    const ns_mesh *M = &s->mesh;
    const double eps = -1e-12;
    double l[3];
    if (hint < 0 || hint >= M->nt) hint = 0;
    /* walk across the edge facing the point; a hole or the boundary ends the walk */
    int t = hint;
    for (int k = 0; k < M->nt; k++) {
        bary(M, t, x, y, l);
        int worst = 0;
        for (int i = 1; i < 3; i++)
            if (l[i] < l[worst]) worst = i;
        if (l[worst] >= eps) {
            *l1 = l[1];
            *l2 = l[2];
            return t;
        }
        /* the edge opposite vertex `worst` joins vertices worst+1 and worst+2: local edge (worst+1)%3 */
        const int e = M->tri_edge[3 * t + (worst + 1) % 3];
        const int nb = M->edge_tri[2 * e] == t ? M->edge_tri[2 * e + 1] : M->edge_tri[2 * e];
        if (nb < 0) break;
        t = nb;
    }
    for (int k = 0; k < M->nt; k++) {
        bary(M, k, x, y, l);
        if (l[0] >= eps && l[1] >= eps && l[2] >= eps) {
            *l1 = l[1];
            *l2 = l[2];
            return k;
        }
    }
    return -1;
}

int ns_system_eval(const ns_system *s, double x, double y, int hint, double *u, double *v, double *q) {
    double l1, l2;
    const int t = ns_system_locate(s, x, y, hint, &l1, &l2);
    if (t >= 0) point_state(s, t, l1, l2, u, v, q, NULL);
    return t;
}

double ns_system_div_l2(const ns_system *s) {
    double sum = 0;
    for (int t = 0; t < s->mesh.nt; t++) {
        const int32_t *v = s->mesh.tri + 3 * t;
        const double *p0 = s->mesh.xy + 2 * v[0], *p1 = s->mesh.xy + 2 * v[1], *p2 = s->mesh.xy + 2 * v[2];
        const double area = 0.5 * ((p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]));
        for (int qp = 0; qp < NS_NQ; qp++) {
            double gr[4];
            point_state(s, t, ns_quad_l1[qp], ns_quad_l2[qp], NULL, NULL, NULL, gr);
            sum += area * ns_quad_w[qp] * (gr[0] + gr[3]) * (gr[0] + gr[3]);
        }
    }
    return sqrt(sum);
}

double ns_system_flux(const ns_system *s, double ax, double ay, double bx, double by, int npts) {
    const double dx = bx - ax, dy = by - ay, L = sqrt(dx * dx + dy * dy);
    const double nx = -dy / L, ny = dx / L;
    double sum = 0;
    int hint = 0;
    for (int i = 0; i < npts; i++) {
        const double f = (i + 0.5) / npts;
        double u = 0, v = 0;
        const int t = ns_system_eval(s, ax + f * dx, ay + f * dy, hint, &u, &v, NULL);
        if (t >= 0) hint = t;
        sum += u * nx + v * ny;
    }
    return sum * L / npts;
}

/* L2 projection of the velocities of X[0..nx-1] onto the discretely divergence-free fields with
   each X's own values on the Dirichlet nodes: the linear system of one backward-Euler step of
   unit length with nu = 0, no convection and no body force, whose history is X itself,
       ∫ (u - u_X) . phi - q div phi = 0,   ∫ psi div u = 0,
   one factorisation (with the system's symbolic analysis: the pattern is the step's) and one
   solve per X. The pressures of X are kept. */
int ns_system_project_many(ns_system *s, double *const *X, int nx, char *msg, size_t msg_size) {
    const double nu = s->nu, fx = s->fx, fy = s->fy;
    const int convect = s->convect;
    double *keep_x = s->x;
    const int nv2 = 2 * s->nvel, nq = s->nunk - nv2;
    double *save = pl_malloc(sizeof(double) * (size_t)(nq + nv2 + 1));
    if (!save) {
        snprintf(msg, msg_size, "out of memory");
        return -1;
    }
    double *gsave = save + nq;
    memcpy(gsave, s->gu, sizeof(double) * (size_t)s->nvel);
    memcpy(gsave + s->nvel, s->gv, sizeof(double) * (size_t)s->nvel);
    s->nu = s->fx = s->fy = 0.0;
    s->convect = 0;
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    umfpack_di_defaults(control);
    int rc = 0;
    for (int k = 0; k < nx && !rc; k++) {
        double *Y = X[k];
        memcpy(save, Y + nv2, sizeof(double) * (size_t)nq);
        for (int j = 0; j < s->nvel; j++)
            if (s->fixed[j]) {
                s->gu[j] = Y[j];
                s->gv[j] = Y[s->nvel + j];
            }
        s->x = Y;
        memcpy(s->hu, Y, sizeof(double) * (size_t)nv2);
        double t0 = cpu_now();
        assemble(s, 1.0, k == 0, 1);
        s->st.t_assemble += cpu_now() - t0;
        if (k == 0 && !s->symbolic) {
            t0 = cpu_now();
            rc = umfpack_di_symbolic(s->nunk, s->nunk, s->Ap, s->Ai, s->Ax, &s->symbolic, control, info) != UMFPACK_OK;
            s->st.t_symbolic += cpu_now() - t0;
            s->st.n_symbolic++;
        }
        if (k == 0 && !rc) {
            if (s->numeric) umfpack_di_free_numeric(&s->numeric);
            t0 = cpu_now();
            rc = umfpack_di_numeric(s->Ap, s->Ai, s->Ax, s->symbolic, &s->numeric, control, info) != UMFPACK_OK;
            s->st.t_numeric += cpu_now() - t0;
            s->st.n_numeric++;
        }
        if (!rc) {
            t0 = cpu_now();
            rc = umfpack_di_solve(UMFPACK_A, s->Ap, s->Ai, s->Ax, s->dx, s->res, s->numeric, control, info) !=
                 UMFPACK_OK;
            s->st.t_solve += cpu_now() - t0;
            s->st.n_solve++;
        }
        if (!rc)
            for (int i = 0; i < nv2; i++) Y[i] -= s->dx[i];
        memcpy(Y + nv2, save, sizeof(double) * (size_t)nq);
    }
    if (rc) snprintf(msg, msg_size, "UMFPACK failed on the divergence projection (%d unknowns)", s->nunk);
    memcpy(s->gu, gsave, sizeof(double) * (size_t)s->nvel);
    memcpy(s->gv, gsave + s->nvel, sizeof(double) * (size_t)s->nvel);
    pl_free(save);
    s->x = keep_x;
    s->nu = nu;
    s->fx = fx;
    s->fy = fy;
    s->convect = convect;
    return rc ? -1 : 0;
}

int ns_system_project(ns_system *s, double *X, char *msg, size_t msg_size) {
    return ns_system_project_many(s, &X, 1, msg, msg_size);
}

/* Largest local mass imbalance of X's velocity: max over the pressure vertices of
   |∫ psi_i div u| / ∫ psi_i (the mean divergence around vertex i, 1/s). */
double ns_system_div_weak(ns_system *s, double *X) {
    double *keep = s->x;
    s->x = X;
    memset(s->hu, 0, sizeof(double) * 2 * (size_t)s->nvel);
    assemble(s, 0.0, 0, 0);
    s->x = keep;
    const ns_mesh *M = &s->mesh;
    double *w = pl_calloc((size_t)M->nv + 1, sizeof(double));
    if (!w) return -1;
    for (int t = 0; t < M->nt; t++) {
        const int32_t *v = M->tri + 3 * t;
        const double *p0 = M->xy + 2 * v[0], *p1 = M->xy + 2 * v[1], *p2 = M->xy + 2 * v[2];
        const double a = 0.5 * ((p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]));
        for (int i = 0; i < 3; i++) w[v[i]] += a / 3.0;
    }
    double worst = 0;
    for (int i = 0; i < M->nv; i++) worst = fmax(worst, fabs(s->res[2 * s->nvel + i]) / w[i]);
    pl_free(w);
    return worst;
}
