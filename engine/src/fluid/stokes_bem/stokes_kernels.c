/* Boundary-element kernels of the Stokes model (stokes_internal.h; derivations in
 * docs/stokes.md): quadrature rules, element integrals of the 2D Stokeslet, the corner
 * coefficient, interior velocity and pressure, and loads from tractions. The dense solve is in
 * stokes_solve.c. */
#include "fluid/stokes_bem/stokes_internal.h"
#include <math.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* LAPACK (Fortran symbols; OpenBLAS on Debian). */
extern void dstev_(const char *jobz, const int *n, double *d, double *e, double *z, const int *ldz, double *work,
                   int *info);

static void gauss_legendre(int n, double *x, double *w) {
    for (int i = 0; i < (n + 1) / 2; i++) {
        double z = cos(M_PI * (i + 0.75) / (n + 0.5)), pp = 0;
        for (int it = 0; it < 100; it++) {
            double p1 = 1, p2 = 0;
            for (int j = 1; j <= n; j++) {
                const double p3 = p2;
                p2 = p1;
                p1 = ((2.0 * j - 1) * z * p2 - (j - 1.0) * p3) / j;
            }
            pp = n * (z * p1 - p2) / (z * z - 1);
            const double z1 = z;
            z = z1 - p1 / pp;
            if (fabs(z - z1) < 1e-15) break;
        }
        x[i] = -z;
        x[n - 1 - i] = z;
        w[i] = w[n - 1 - i] = 2 / ((1 - z * z) * pp * pp);
    }
}

pl_status pl_sb_rules_init(pl_sb_rules *r) {
    static const int orders[6] = {1, 2, 4, 8, 16, 32};
    memset(r, 0, sizeof *r);
    for (int k = 0; k < 6; k++) {
        r->n[k] = orders[k];
        if (orders[k] == 1) {
            r->x[k][0] = 0;
            r->w[k][0] = 2;
        } else {
            gauss_legendre(orders[k], r->x[k], r->w[k]);
        }
    }
    /* Gauss rule for the weight ln(1/x) on [0, 1]: Chebyshev's algorithm on the moments
       m_k = ∫ x^k ln(1/x) dx = 1/(k+1)^2 (in long double: ordinary moments lose about a digit
       per point) gives the three-term recurrence; the Jacobi matrix's eigenvalues are the
       nodes, m_0 times the squared first components of its eigenvectors the weights. */
    enum { N = PL_SB_LOG_POINTS };
    long double mom[2 * N], sig_prev[2 * N], sig[2 * N], sig_new[2 * N], alpha[N], beta[N];
    for (int k = 0; k < 2 * N; k++) mom[k] = 1.0L / ((long double)(k + 1) * (long double)(k + 1));
    for (int l = 0; l < 2 * N; l++) {
        sig_prev[l] = 0;
        sig[l] = mom[l];
    }
    alpha[0] = mom[1] / mom[0];
    beta[0] = mom[0];
    for (int k = 1; k < N; k++) {
        for (int l = k; l < 2 * N - k; l++)
            sig_new[l] = sig[l + 1] - alpha[k - 1] * sig[l] - beta[k - 1] * sig_prev[l];
        alpha[k] = sig_new[k + 1] / sig_new[k] - sig[k] / sig[k - 1];
        beta[k] = sig_new[k] / sig[k - 1];
        for (int l = 0; l < 2 * N; l++) {
            sig_prev[l] = sig[l];
            sig[l] = (l >= k && l < 2 * N - k) ? sig_new[l] : 0;
        }
    }
    double d[N], e[N], z[N * N], work[2 * N];
    for (int k = 0; k < N; k++) {
        d[k] = (double)alpha[k];
        e[k] = k + 1 < N ? (double)sqrtl(beta[k + 1]) : 0;
    }
    int n = N, ldz = N, info = 0;
    dstev_("V", &n, d, e, z, &ldz, work, &info);
    if (info != 0) return PL_ERR_NUMERIC;
    for (int k = 0; k < N; k++) {
        r->lx[k] = d[k];
        r->lw[k] = (double)beta[0] * z[k * N] * z[k * N];
    }
    return PL_OK;
}

int pl_sb_table_order(double rho) {
    /* Table 4.1: rho > 200: 1 point; (20, 200]: 2; (2, 20]: 4; (0.1, 2]: 16; <= 0.1: 32 */
    if (rho > 200) return 0;
    if (rho > 20) return 1;
    if (rho > 2) return 2;
    if (rho > 0.1) return 4;
    return 5;
}

pl_vec2 pl_sb_node_pos(pl_vec2 a, pl_vec2 b, int m) {
    const double s = m == 0 ? 0.25 : 0.75;
    return (pl_vec2){a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)};
}

pl_vec2 pl_sb_normal(pl_vec2 a, pl_vec2 b) {
    const double dx = b.x - a.x, dy = b.y - a.y, L = hypot(dx, dy);
    return (pl_vec2){dy / L, -dx / L};
}

static double seg_dist(pl_vec2 P, pl_vec2 a, pl_vec2 b) {
    const double dx = b.x - a.x, dy = b.y - a.y, L2 = dx * dx + dy * dy;
    double s = L2 > 0 ? ((P.x - a.x) * dx + (P.y - a.y) * dy) / L2 : 0;
    s = s < 0 ? 0 : (s > 1 ? 1 : s);
    return hypot(P.x - a.x - s * dx, P.y - a.y - s * dy);
}

/* Adds the integrals over η in [e0, e1] of element a-b (parent shape functions) for source P;
   halves the piece while it is within 0.3 of its length from P. (Table 4.1's 16 points at
   rho = 0.1 leave errors of about 1e-3 in the near-singular integrals, which shows between
   grains closer than a tenth of an element: a uniform pressure came out 0.1 % off; from
   rho = 0.3 on, 16 Gauss points are accurate to about 1e-8.) */
static void piece(const pl_sb_rules *r, pl_vec2 P, pl_vec2 a, pl_vec2 b, double e0, double e1, double mu,
                  double G[2][2][2], double H[2][2][2], int depth) {
    const pl_vec2 pa = {a.x + 0.5 * (1 + e0) * (b.x - a.x), a.y + 0.5 * (1 + e0) * (b.y - a.y)};
    const pl_vec2 pb = {a.x + 0.5 * (1 + e1) * (b.x - a.x), a.y + 0.5 * (1 + e1) * (b.y - a.y)};
    const double L = hypot(b.x - a.x, b.y - a.y), Lp = L * 0.5 * (e1 - e0);
    const double rho = seg_dist(P, pa, pb) / Lp;
    if (rho <= 0.3 && depth < 14) {
        const double em = 0.5 * (e0 + e1);
        piece(r, P, a, b, e0, em, mu, G, H, depth + 1);
        piece(r, P, a, b, em, e1, mu, G, H, depth + 1);
        return;
    }
    const int k = pl_sb_table_order(rho);
    const pl_vec2 n = pl_sb_normal(a, b);
    const double cu = 1 / (4 * M_PI * mu), jac = 0.5 * L * 0.5 * (e1 - e0);
    for (int q = 0; q < r->n[k]; q++) {
        const double eta = 0.5 * (e0 + e1) + 0.5 * (e1 - e0) * r->x[k][q];
        const double wq = r->w[k][q] * jac;
        const double rx = a.x + 0.5 * (1 + eta) * (b.x - a.x) - P.x;
        const double ry = a.y + 0.5 * (1 + eta) * (b.y - a.y) - P.y;
        const double r2 = rx * rx + ry * ry, rr = sqrt(r2);
        const double d[2] = {rx / rr, ry / rr};
        const double drdn = d[0] * n.x + d[1] * n.y;
        const double N[2] = {0.5 - eta, 0.5 + eta};
        const double lnr = log(1 / rr);
        for (int m = 0; m < 2; m++)
            for (int i = 0; i < 2; i++)
                for (int j = 0; j < 2; j++) {
                    G[m][i][j] += cu * ((i == j ? lnr : 0) + d[i] * d[j]) * N[m] * wq;
                    H[m][i][j] += -(1 / (M_PI * rr)) * drdn * d[i] * d[j] * N[m] * wq;
                }
    }
}

void pl_sb_elem_regular(const pl_sb_rules *r, pl_vec2 P, pl_vec2 a, pl_vec2 b, double mu, double G[2][2][2],
                        double H[2][2][2]) {
    memset(G, 0, 8 * sizeof(double));
    memset(H, 0, 8 * sizeof(double));
    piece(r, P, a, b, -1, 1, mu, G, H, 0);
}

void pl_sb_elem_self(const pl_sb_rules *r, int ms, pl_vec2 a, pl_vec2 b, double mu, double G[2][2][2],
                     double H[2][2][2]) {
    memset(G, 0, 8 * sizeof(double));
    memset(H, 0, 8 * sizeof(double)); /* ∂r/∂n = 0 on the straight element: (4.81), (4.82) vanish */
    const double L = hypot(b.x - a.x, b.y - a.y), tau[2] = {(b.x - a.x) / L, (b.y - a.y) / L};
    const double es = ms == 0 ? -0.5 : 0.5;
    const double cu = 1 / (4 * M_PI * mu);
    double lg[2] = {0, 0}, ln[2] = {0, 0}; /* ∫ ln(1/r) N_m dΓ, ∫ N_m dΓ */
    for (int side = 0; side < 2; side++) {
        /* side 0: η = η_s - (1 + η_s) ξ (4.62-4.63); side 1: η = η_s + (1 - η_s) ζ (4.71) */
        const double span = side == 0 ? 1 + es : 1 - es, sg = side == 0 ? -1 : 1;
        const double scale = 0.5 * L * span;   /* r = scale ξ, dΓ = scale dξ */
        const double lnxr = -log(scale);        /* ln(ξ / r): smooth (constant here) */
        const int k = 4;                        /* 16 points for the smooth parts (4.69) */
        for (int q = 0; q < r->n[k]; q++) {
            const double xi = 0.5 * (1 + r->x[k][q]), wq = 0.5 * r->w[k][q] * scale;
            const double eta = es + sg * span * xi;
            const double N[2] = {0.5 - eta, 0.5 + eta};
            for (int m = 0; m < 2; m++) {
                lg[m] += lnxr * N[m] * wq; /* I^3, I^5 (4.69, 4.73 without the second 1/(4πμ)) */
                ln[m] += N[m] * wq;
            }
        }
        for (int q = 0; q < PL_SB_LOG_POINTS; q++) { /* I^4, I^6 (4.70, 4.74): ln(1/ξ) weight */
            const double xi = r->lx[q], wq = r->lw[q] * scale;
            const double eta = es + sg * span * xi;
            const double N[2] = {0.5 - eta, 0.5 + eta};
            for (int m = 0; m < 2; m++) lg[m] += N[m] * wq;
        }
    }
    for (int m = 0; m < 2; m++)
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++) G[m][i][j] = cu * ((i == j ? lg[m] : 0) + tau[i] * tau[j] * ln[m]);
}

void pl_sb_elem_self_exact(int ms, pl_vec2 a, pl_vec2 b, double mu, double G[2][2][2]) {
    const double L = hypot(b.x - a.x, b.y - a.y), tau[2] = {(b.x - a.x) / L, (b.y - a.y) / L};
    const double es = ms == 0 ? -0.5 : 0.5, cu = 1 / (4 * M_PI * mu), h = 0.5 * L;
    const double s0 = -1 - es, s1 = 1 - es; /* s = η - η_s */
#define F0(s) ((s) == 0 ? 0 : (s) * log(fabs(s)) - (s))
#define F1(s) ((s) == 0 ? 0 : 0.5 * (s) * (s) * log(fabs(s)) - 0.25 * (s) * (s))
    for (int m = 0; m < 2; m++) {
        /* N_m = α + β s */
        const double al = m == 0 ? 0.5 - es : 0.5 + es, be = m == 0 ? -1 : 1;
        const double poly = al * (s1 - s0) + be * 0.5 * (s1 * s1 - s0 * s0);
        const double lg = h * (-log(h) * poly - (al * (F0(s1) - F0(s0)) + be * (F1(s1) - F1(s0))));
        const double ln = h * poly;
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++) G[m][i][j] = cu * ((i == j ? lg : 0) + tau[i] * tau[j] * ln);
    }
#undef F0
#undef F1
}

void pl_sb_corner_c(double th1, double th2, double c[2][2]) {
    const double th = th2 - th1;
    /* c_ij = (1/π) ∫_{θ1}^{θ2} e_i e_j dθ (the fluid's part of a small circle about P, from
       t* on it). The seed's (4.38) is this with θ1 and θ2 interchanged in the trigonometric
       terms: its angles run the other way round (its Figure 4.2). */
    c[0][0] = (2 * th + (sin(2 * th2) - sin(2 * th1))) / (4 * M_PI);
    c[1][1] = (2 * th - (sin(2 * th2) - sin(2 * th1))) / (4 * M_PI);
    c[0][1] = c[1][0] = (cos(2 * th1) - cos(2 * th2)) / (4 * M_PI);
}

void pl_sb_curve_load(const pl_sb_bnd *bnd, const double *t, int e0, int e1, pl_vec2 c, pl_vec2 *F, double *M) {
    double fx = 0, fy = 0, m = 0;
    const double g = 0.5 / sqrt(3.0); /* 2-point Gauss on [0, 1]: exact for (linear x) x (linear t) */
    for (int e = e0; e < e1; e++) {
        const pl_vec2 a = bnd->a[e], b = bnd->b[e];
        const double L = hypot(b.x - a.x, b.y - a.y);
        const double *te = t + 4 * e;
        for (int q = 0; q < 2; q++) {
            const double s = q == 0 ? 0.5 - g : 0.5 + g, eta = 2 * s - 1;
            const double N0 = 0.5 - eta, N1 = 0.5 + eta;
            const double tx = N0 * te[0] + N1 * te[2], ty = N0 * te[1] + N1 * te[3];
            const double x = a.x + s * (b.x - a.x) - c.x, y = a.y + s * (b.y - a.y) - c.y;
            fx -= 0.5 * L * tx;
            fy -= 0.5 * L * ty;
            m -= 0.5 * L * (x * ty - y * tx);
        }
    }
    F->x = fx;
    F->y = fy;
    *M = m;
}

double pl_sb_curve_flux(const pl_sb_bnd *bnd, int e0, int e1) {
    double q = 0;
    for (int e = e0; e < e1; e++) {
        const pl_vec2 n = pl_sb_normal(bnd->a[e], bnd->b[e]);
        const double L = hypot(bnd->b[e].x - bnd->a[e].x, bnd->b[e].y - bnd->a[e].y);
        const double *u = bnd->u + 4 * e;
        q += 0.5 * L * ((u[0] + u[2]) * n.x + (u[1] + u[3]) * n.y);
    }
    return q;
}

/* Interior point: velocity u_i = Σ ∫ u*_ij t_j - ∫ t*_ij u_j (4.92) and pressure
   p = -∫ (r·t) / (2π r^2) dΓ + (μ/π) ∫ [u·n / r^2 - 2 (r·u)(r·n) / r^4] dΓ (r = Q - P), the
   pressures of the single and double layers (docs/stokes.md; the trace of 4.93 with the
   stress kernel 4.95 corrected). Pieces are halved near P as in piece(). */
static void interior_piece(const pl_sb_rules *r, pl_vec2 P, pl_vec2 a, pl_vec2 b, const double *ue,
                           const double *te, double e0, double e1, double mu, double acc[3], int depth) {
    const pl_vec2 pa = {a.x + 0.5 * (1 + e0) * (b.x - a.x), a.y + 0.5 * (1 + e0) * (b.y - a.y)};
    const pl_vec2 pb = {a.x + 0.5 * (1 + e1) * (b.x - a.x), a.y + 0.5 * (1 + e1) * (b.y - a.y)};
    const double L = hypot(b.x - a.x, b.y - a.y), Lp = L * 0.5 * (e1 - e0);
    const double rho = seg_dist(P, pa, pb) / Lp;
    if (rho <= 0.5 && depth < 16) {
        const double em = 0.5 * (e0 + e1);
        interior_piece(r, P, a, b, ue, te, e0, em, mu, acc, depth + 1);
        interior_piece(r, P, a, b, ue, te, em, e1, mu, acc, depth + 1);
        return;
    }
    const int k = rho > 2 ? pl_sb_table_order(rho) : 3; /* 8 points at least near the boundary */
    const int kk = k < 1 ? 1 : k;
    const pl_vec2 n = pl_sb_normal(a, b);
    const double cu = 1 / (4 * M_PI * mu), jac = 0.5 * L * 0.5 * (e1 - e0);
    for (int q = 0; q < r->n[kk]; q++) {
        const double eta = 0.5 * (e0 + e1) + 0.5 * (e1 - e0) * r->x[kk][q];
        const double wq = r->w[kk][q] * jac;
        const double rx = a.x + 0.5 * (1 + eta) * (b.x - a.x) - P.x;
        const double ry = a.y + 0.5 * (1 + eta) * (b.y - a.y) - P.y;
        const double r2 = rx * rx + ry * ry, rr = sqrt(r2);
        const double d[2] = {rx / rr, ry / rr};
        const double drdn = d[0] * n.x + d[1] * n.y;
        const double N0 = 0.5 - eta, N1 = 0.5 + eta;
        const double u[2] = {N0 * ue[0] + N1 * ue[2], N0 * ue[1] + N1 * ue[3]};
        const double t[2] = {N0 * te[0] + N1 * te[2], N0 * te[1] + N1 * te[3]};
        const double lnr = log(1 / rr), dt = d[0] * t[0] + d[1] * t[1], du = d[0] * u[0] + d[1] * u[1];
        for (int i = 0; i < 2; i++)
            acc[i] += (cu * (lnr * t[i] + d[i] * dt) + (1 / (M_PI * rr)) * drdn * d[i] * du) * wq;
        const double un = u[0] * n.x + u[1] * n.y;
        acc[2] += (-dt / (2 * M_PI * rr) + (mu / M_PI) * (un - 2 * du * drdn) / r2) * wq;
    }
}

void pl_sb_interior(const pl_sb_rules *r, const pl_sb_bnd *bnd, double mu, pl_vec2 P, pl_vec2 *u, double *p) {
    double acc[3] = {0, 0, 0};
    for (int e = 0; e < bnd->ne; e++)
        interior_piece(r, P, bnd->a[e], bnd->b[e], bnd->u + 4 * e, bnd->t + 4 * e, -1, 1, mu, acc, 0);
    u->x = acc[0];
    u->y = acc[1];
    *p = acc[2];
}

/* ------------------------------------------------------------------ builders */
#include "core/alloc.h"

void pl_sb_bnd_clear(pl_sb_bnd *b) {
    b->ne = b->ncurve = b->nfixed = 0;
    if (b->curve_start) b->curve_start[0] = 0;
}

void pl_sb_bnd_free(pl_sb_bnd *b) {
    pl_free(b->a);
    pl_free(b->b);
    pl_free(b->curve_start);
    pl_free(b->centre);
    pl_free(b->resist);
    pl_free(b->kind);
    pl_free(b->u);
    pl_free(b->t);
    memset(b, 0, sizeof *b);
}

static pl_status reserve_elems(pl_sb_bnd *b, int ne) {
    if (ne <= b->ecap) return PL_OK;
    int cap = b->ecap ? b->ecap : 64;
    while (cap < ne) cap *= 2;
    pl_vec2 *pa = pl_realloc(b->a, (size_t)cap * sizeof *pa);
    if (!pa) return PL_ERR_NOMEM;
    b->a = pa;
    pl_vec2 *pb = pl_realloc(b->b, (size_t)cap * sizeof *pb);
    if (!pb) return PL_ERR_NOMEM;
    b->b = pb;
    uint8_t *k = pl_realloc(b->kind, (size_t)cap * 4);
    if (!k) return PL_ERR_NOMEM;
    b->kind = k;
    double *u = pl_realloc(b->u, (size_t)cap * 4 * sizeof *u);
    if (!u) return PL_ERR_NOMEM;
    b->u = u;
    double *t = pl_realloc(b->t, (size_t)cap * 4 * sizeof *t);
    if (!t) return PL_ERR_NOMEM;
    b->t = t;
    b->ecap = cap;
    return PL_OK;
}

pl_status pl_sb_bnd_curve(pl_sb_bnd *b, pl_vec2 centre, int resist) {
    if (b->ncurve + 2 > b->ccap) {
        const int cap = b->ccap ? 2 * b->ccap : 16;
        int32_t *cs = pl_realloc(b->curve_start, (size_t)(cap + 1) * sizeof *cs);
        if (!cs) return PL_ERR_NOMEM;
        b->curve_start = cs;
        pl_vec2 *c = pl_realloc(b->centre, (size_t)cap * sizeof *c);
        if (!c) return PL_ERR_NOMEM;
        b->centre = c;
        uint8_t *r = pl_realloc(b->resist, (size_t)cap);
        if (!r) return PL_ERR_NOMEM;
        b->resist = r;
        b->ccap = cap;
    }
    if (b->ncurve == 0) b->curve_start[0] = b->ne;
    b->centre[b->ncurve] = centre;
    b->resist[b->ncurve] = (uint8_t)(resist != 0);
    b->ncurve++;
    b->curve_start[b->ncurve] = b->ne;
    return PL_OK;
}

pl_status pl_sb_bnd_line(pl_sb_bnd *b, pl_vec2 p, pl_vec2 q, int nel) {
    if (b->ncurve == 0 || nel < 1) return PL_ERR_ARG;
    if (reserve_elems(b, b->ne + nel) != PL_OK) return PL_ERR_NOMEM;
    for (int k = 0; k < nel; k++) {
        const double s0 = (double)k / nel, s1 = (double)(k + 1) / nel;
        const int e = b->ne++;
        b->a[e] = (pl_vec2){p.x + s0 * (q.x - p.x), p.y + s0 * (q.y - p.y)};
        b->b[e] = (pl_vec2){p.x + s1 * (q.x - p.x), p.y + s1 * (q.y - p.y)};
        for (int d = 0; d < 4; d++) {
            b->kind[4 * e + d] = PL_SB_VEL;
            b->u[4 * e + d] = b->t[4 * e + d] = 0;
        }
    }
    b->curve_start[b->ncurve] = b->ne;
    return PL_OK;
}

pl_status pl_sb_bnd_disc(pl_sb_bnd *b, pl_vec2 c, double radius, int nel, int clockwise, int resist) {
    pl_status st = pl_sb_bnd_curve(b, c, resist);
    if (st != PL_OK) return st;
    const double sg = clockwise ? -1 : 1;
    for (int k = 0; k < nel && st == PL_OK; k++) {
        const double t0 = sg * 2 * M_PI * k / nel, t1 = sg * 2 * M_PI * (k + 1) / nel;
        st = pl_sb_bnd_line(b, (pl_vec2){c.x + radius * cos(t0), c.y + radius * sin(t0)},
                            (pl_vec2){c.x + radius * cos(t1), c.y + radius * sin(t1)}, 1);
    }
    return st;
}

void pl_sb_bnd_rigid(pl_sb_bnd *b, int c, pl_vec2 v, double omega) {
    const pl_vec2 o = b->centre[c];
    for (int e = b->curve_start[c]; e < b->curve_start[c + 1]; e++)
        for (int m = 0; m < 2; m++) {
            const pl_vec2 x = pl_sb_node_pos(b->a[e], b->b[e], m);
            b->u[4 * e + 2 * m] = v.x - omega * (x.y - o.y);
            b->u[4 * e + 2 * m + 1] = v.y + omega * (x.x - o.x);
        }
}
