/* Element kernels of the solid (solid_internal.h): creation from a mesh, lumped masses, the
 * element bound of the critical step, the stress update (elastic, J2 radial return, small
 * strain or updated Lagrangian with the incremental spin) and the internal forces of linear
 * triangles (plain or with the FIC nodal pressure) and of Q1/P0 quadrilaterals (2x2 Gauss for
 * the deviatoric part, one mean-dilatation pressure per element). */
#include "solid/fic/solid_internal.h"
#include "core/alloc.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* LAPACK (linked by the engine): symmetric eigenvalues */
extern void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda, double *w,
                   double *work, const int *lwork, int *info);

static double shear_modulus(const pl_solid_def *d) { return d->young / (2 * (1 + d->poisson)); }
static double bulk_modulus(const pl_solid_def *d) { return d->young / (3 * (1 - 2 * d->poisson)); }

/* ---------------------------------------------------------------- geometry */


static const double GP = 0.57735026918962576451;
static const double QXI[4] = {-1, 1, 1, -1}, QETA[4] = {-1, -1, 1, 1};

/* Bilinear quadrilateral at Gauss point g: gradients and detJ (weight 1). */
static double quad_grad(const double *xy, const int32_t *n, int g, double b[4], double c[4]) {
    const double xi = QXI[g] * GP, eta = QETA[g] * GP;
    double dxi[4], deta[4];
    for (int a = 0; a < 4; a++) {
        dxi[a] = 0.25 * QXI[a] * (1 + QETA[a] * eta);
        deta[a] = 0.25 * QETA[a] * (1 + QXI[a] * xi);
    }
    double j11 = 0, j12 = 0, j21 = 0, j22 = 0;
    for (int a = 0; a < 4; a++) {
        const double x = xy[2 * n[a]], y = xy[2 * n[a] + 1];
        j11 += dxi[a] * x; j12 += dxi[a] * y;
        j21 += deta[a] * x; j22 += deta[a] * y;
    }
    const double det = j11 * j22 - j12 * j21;
    for (int a = 0; a < 4; a++) {
        b[a] = (j22 * dxi[a] - j12 * deta[a]) / det;
        c[a] = (-j21 * dxi[a] + j11 * deta[a]) / det;
    }
    return det;
}

/* Gradients of integration point g of element e on configuration xy; returns its weight
   (area share) and the element's nodes. */
static double ip_grad(const pl_sf *s, const double *xy, int e, int g, double *b, double *c) {
    const int32_t *n = &s->conn[(size_t)e * s->nen];
    return s->nen == 3 ? pl_sf_tri_grad(xy, n, b, c) : quad_grad(xy, n, g, b, c);
}

static double elem_area(const pl_sf *s, const double *xy, int e) {
    double b[4], c[4], a = 0;
    for (int g = 0; g < s->nip; g++) a += ip_grad(s, xy, e, g, b, c);
    return a;
}

/* ---------------------------------------------------------------- creation */

static int grow(void **p, size_t elem, size_t n) {
    void *q = pl_realloc(*p, elem * (n > 0 ? n : 1));
    if (!q) return 0;
    *p = q;
    return 1;
}

/* (Re)allocates every per-node and per-ip array for nn nodes and ne elements, keeping the
   first old_nn / old_ne entries and zeroing the rest. */
static int resize(pl_sf *s, int nn, int ne, int old_nn, int old_ne) {
    const size_t N = (size_t)nn, E = (size_t)ne, I = (size_t)ne * s->nip;
    const size_t oN = (size_t)old_nn, oI = (size_t)old_ne * s->nip;
#define NODE(ptr, k) if (!grow((void **)&s->ptr, sizeof *s->ptr * (k), N)) return 0; \
    memset(s->ptr + (k) * oN, 0, sizeof *s->ptr * (k) * (N - oN));
#define IP(ptr, k) if (!grow((void **)&s->ptr, sizeof *s->ptr * (k), I)) return 0; \
    memset(s->ptr + (k) * oI, 0, sizeof *s->ptr * (k) * (I - oI));
    NODE(X, 2) NODE(x, 2) NODE(v, 2) NODE(p, 1) NODE(pi, 2) NODE(gv, 1) NODE(f_prev, 2) NODE(fe_prev, 2)
    NODE(m, 1) NODE(mp, 1) NODE(mt, 1) NODE(f, 2) NODE(du, 2) NODE(rhs, 1) NODE(fc, 2) NODE(xm, 2)
    NODE(fix, 1) NODE(vpres, 2)
    IP(s, 4) IP(pe, 1) IP(ep, 4) IP(alpha, 1)
#undef NODE
#undef IP
    if (!grow((void **)&s->conn, sizeof *s->conn * s->nen, E)) return 0;
    if (!grow((void **)&s->tau, sizeof *s->tau, E)) return 0;
    return 1;
}

static int mesh_fits(const pl_solid_def *d, const pl_sf_mesh *m, char *msg, size_t len) {
    const int want = d->formulation == PL_SOLID_Q1P0 ? 4 : 3;
    if (m->nen != want) {
        snprintf(msg, len, "solid: the %s formulation needs %s, the mesh has %d-node elements",
                 want == 4 ? "Q1/P0" : "triangle", want == 4 ? "quadrilaterals" : "triangles", m->nen);
        return 0;
    }
    if (m->nn <= 0 || m->ne <= 0) {
        snprintf(msg, len, "solid: the mesh is empty (%d nodes, %d elements)", m->nn, m->ne);
        return 0;
    }
    for (int e = 0; e < m->ne; e++) {
        for (int a = 0; a < m->nen; a++)
            if (m->conn[e * m->nen + a] < 0 || m->conn[e * m->nen + a] >= m->nn) {
                snprintf(msg, len, "solid: element %d refers to node %d (the mesh has %d nodes)", e + 1,
                         m->conn[e * m->nen + a] + 1, m->nn);
                return 0;
            }
    }
    return 1;
}

pl_sf *pl_sf_create(const pl_solid_def *d, const pl_sf_mesh *mesh, char *msg, size_t len) {
    if (!mesh_fits(d, mesh, msg, len)) return NULL;
    pl_sf *s = pl_calloc(1, sizeof *s);
    if (!s) return NULL;
    s->def = *d;
    s->nen = mesh->nen;
    s->nip = s->nen == 3 ? 1 : 4;
    if (pl_sf_append(s, mesh) != PL_OK) {
        snprintf(msg, len, "%s", s->err);
        pl_sf_destroy(s);
        return NULL;
    }
    return s;
}

pl_status pl_sf_append(pl_sf *s, const pl_sf_mesh *mesh) {
    if (!mesh_fits(&s->def, mesh, s->err, sizeof s->err)) return PL_ERR_ARG;
    const int nn0 = s->nn, ne0 = s->ne;
    if (!resize(s, nn0 + mesh->nn, ne0 + mesh->ne, nn0, ne0)) {
        snprintf(s->err, sizeof s->err, "solid: out of memory for %d nodes", nn0 + mesh->nn);
        return PL_ERR_NOMEM;
    }
    for (int i = 0; i < mesh->nn; i++) {
        s->X[2 * (nn0 + i)] = s->x[2 * (nn0 + i)] = mesh->xy[2 * i];
        s->X[2 * (nn0 + i) + 1] = s->x[2 * (nn0 + i) + 1] = mesh->xy[2 * i + 1];
    }
    for (int e = 0; e < mesh->ne; e++) {
        int32_t *c = &s->conn[(size_t)(ne0 + e) * s->nen];
        for (int a = 0; a < s->nen; a++) c[a] = nn0 + mesh->conn[e * s->nen + a];
        /* counter-clockwise */
        const double a2 = s->nen == 3 ? 2 * elem_area(s, s->X, ne0 + e) : 0;
        if (s->nen == 3 && a2 < 0) {
            const int32_t t = c[1];
            c[1] = c[2];
            c[2] = t;
        }
    }
    s->nn = nn0 + mesh->nn;
    s->ne = ne0 + mesh->ne;
    return pl_sf_prepare(s);
}

void pl_sf_destroy(pl_sf *s) {
    if (!s) return;
    pl_sf_fic_free(s);
    pl_free(s->X); pl_free(s->x); pl_free(s->v); pl_free(s->p); pl_free(s->pi); pl_free(s->gv); pl_free(s->f_prev);
    pl_free(s->fe_prev); pl_free(s->m); pl_free(s->mp); pl_free(s->mt); pl_free(s->f); pl_free(s->du);
    pl_free(s->rhs); pl_free(s->fc); pl_free(s->xm); pl_free(s->fix); pl_free(s->vpres); pl_free(s->s); pl_free(s->pe);
    pl_free(s->ep); pl_free(s->alpha); pl_free(s->conn); pl_free(s->tau); pl_free(s->bedge);
    pl_free(s->heat); pl_free(s->wear);
    for (int k = 0; k < s->nsets; k++) pl_free(s->sets[k].nodes);
    pl_free(s->sets);
    pl_free(s->trac);
    pl_free(s);
}

/* ---------------------------------------------------------------- critical step */

double pl_sf_element_dt(const pl_sf *s, int e, const double *xy) {
    const double G = shear_modulus(&s->def), lam = s->def.young * s->def.poisson /
                                                   ((1 + s->def.poisson) * (1 - 2 * s->def.poisson));
    const int nd = 2 * s->nen;
    double K[64] = {0}, b[4], c[4], area = 0;
    for (int g = 0; g < s->nip; g++) {
        const double w = ip_grad(s, xy, e, g, b, c);
        area += w;
        /* K += w B^T D B, plane strain D with lambda + 2G on the diagonal */
        for (int a = 0; a < s->nen; a++)
            for (int q = 0; q < s->nen; q++) {
                K[(2 * a) * nd + 2 * q] += w * ((lam + 2 * G) * b[a] * b[q] + G * c[a] * c[q]);
                K[(2 * a) * nd + 2 * q + 1] += w * (lam * b[a] * c[q] + G * c[a] * b[q]);
                K[(2 * a + 1) * nd + 2 * q] += w * (lam * c[a] * b[q] + G * b[a] * c[q]);
                K[(2 * a + 1) * nd + 2 * q + 1] += w * ((lam + 2 * G) * c[a] * c[q] + G * b[a] * b[q]);
            }
    }
    if (!(area > 0)) return 0;
    double ev[8], work[64];
    int info = 0, lwork = 64;
    dsyev_("N", "U", &nd, K, &nd, ev, work, &lwork, &info);
    const double mnode = s->def.density * area / s->nen;
    const double w2 = ev[nd - 1] / mnode;
    return info == 0 && w2 > 0 ? 2 / sqrt(w2) : 0;
}

/* ---------------------------------------------------------------- prepare */

static int cmp_edge(const void *pa, const void *pb) {
    const int64_t *a = pa, *b = pb;
    return (a[0] > b[0]) - (a[0] < b[0]);
}

/* Boundary edges: element edges met once, kept in the element's CCW direction. */
static pl_status boundary_edges(pl_sf *s) {
    const size_t ne = (size_t)s->ne * s->nen;
    int64_t *key = pl_malloc(sizeof *key * 2 * (ne > 0 ? ne : 1));
    if (!key) return PL_ERR_NOMEM;
    for (int e = 0; e < s->ne; e++)
        for (int a = 0; a < s->nen; a++) {
            const int32_t i = s->conn[e * s->nen + a], j = s->conn[e * s->nen + (a + 1) % s->nen];
            const int64_t lo = i < j ? i : j, hi = i < j ? j : i;
            const size_t k = (size_t)e * s->nen + a;
            key[2 * k] = lo * (int64_t)s->nn + hi;
            key[2 * k + 1] = (int64_t)i * s->nn + j;
        }
    qsort(key, ne, 2 * sizeof *key, cmp_edge);
    pl_free(s->bedge);
    s->bedge = pl_malloc(sizeof *s->bedge * 2 * (ne > 0 ? ne : 1));
    if (!s->bedge) {
        pl_free(key);
        return PL_ERR_NOMEM;
    }
    s->nbedge = 0;
    for (size_t k = 0; k < ne;) {
        size_t l = k + 1;
        while (l < ne && key[2 * l] == key[2 * k]) l++;
        if (l - k == 1) {
            s->bedge[2 * s->nbedge] = (int32_t)(key[2 * k + 1] / s->nn);
            s->bedge[2 * s->nbedge + 1] = (int32_t)(key[2 * k + 1] % s->nn);
            s->nbedge++;
        }
        k = l;
    }
    pl_free(key);
    return PL_OK;
}

pl_status pl_sf_prepare(pl_sf *s) {
    const double G = shear_modulus(&s->def);
    memset(s->m, 0, sizeof *s->m * (size_t)s->nn);
    memset(s->mp, 0, sizeof *s->mp * (size_t)s->nn);
    memset(s->mt, 0, sizeof *s->mt * (size_t)s->nn);
    s->dt_crit = INFINITY;
    s->dt_elem = -1;
    for (int e = 0; e < s->ne; e++) {
        const double A = elem_area(s, s->X, e);
        if (!(A > 0)) {
            const int32_t *c = &s->conn[e * s->nen];
            snprintf(s->err, sizeof s->err,
                     "solid: element %d (nodes %d %d %d) has area %g m^2; the mesh must have positive "
                     "elements",
                     e + 1, c[0] + 1, c[1] + 1, c[2] + 1, A);
            return PL_ERR_ARG;
        }
        s->tau[e] = s->def.fic_alpha * 2 * A / (2 * G); /* h^2 = 2 A */
        const int32_t *c = &s->conn[e * s->nen];
        for (int a = 0; a < s->nen; a++) {
            s->m[c[a]] += s->def.density * A / s->nen;
            s->mp[c[a]] += A / s->nen;
            s->mt[c[a]] += s->tau[e] * A / s->nen;
        }
        const double dte = pl_sf_element_dt(s, e, s->X);
        if (dte < s->dt_crit) {
            s->dt_crit = dte;
            s->dt_elem = e;
        }
    }
    pl_sf_fic_free(s);
    return boundary_edges(s);
}

/* ---------------------------------------------------------------- selections */

int pl_sf_nodes_in_box(const pl_sf *s, double x0, double y0, double x1, double y1, int32_t *out, int cap) {
    int n = 0;
    for (int i = 0; i < s->nn; i++) {
        const double x = s->X[2 * i], y = s->X[2 * i + 1];
        if (x >= x0 && x <= x1 && y >= y0 && y <= y1) {
            if (out && n < cap) out[n] = i;
            n++;
        }
    }
    return n;
}

int pl_sf_add_set(pl_sf *s, double x0, double y0, double x1, double y1, int mask, double vx, double vy) {
    const int n = pl_sf_nodes_in_box(s, x0, y0, x1, y1, NULL, 0);
    pl_sf_set *ns = pl_realloc(s->sets, sizeof *ns * (size_t)(s->nsets + 1));
    if (!ns) return PL_ERR_NOMEM;
    s->sets = ns;
    pl_sf_set *st = &s->sets[s->nsets];
    memset(st, 0, sizeof *st);
    st->nodes = pl_malloc(sizeof *st->nodes * (size_t)(n > 0 ? n : 1));
    if (!st->nodes) return PL_ERR_NOMEM;
    st->n = pl_sf_nodes_in_box(s, x0, y0, x1, y1, st->nodes, n);
    st->mask = mask;
    st->vx = vx;
    st->vy = vy;
    for (int k = 0; k < st->n; k++) {
        const int i = st->nodes[k];
        s->fix[i] |= (uint8_t)mask;
        if (mask & 1) s->vpres[2 * i] = vx, s->v[2 * i] = vx;
        if (mask & 2) s->vpres[2 * i + 1] = vy, s->v[2 * i + 1] = vy;
    }
    return s->nsets++;
}

int pl_sf_add_traction(pl_sf *s, double x0, double y0, double x1, double y1, double tx, double ty, double pn) {
    int n = 0;
    for (int k = 0; k < s->nbedge; k++) {
        const int a = s->bedge[2 * k], b = s->bedge[2 * k + 1];
        int in = 1;
        for (int q = 0; q < 2; q++) {
            const int i = q ? b : a;
            const double x = s->X[2 * i], y = s->X[2 * i + 1];
            if (!(x >= x0 && x <= x1 && y >= y0 && y <= y1)) in = 0;
        }
        if (!in) continue;
        pl_sf_traction *t = pl_realloc(s->trac, sizeof *t * (size_t)(s->ntrac + 1));
        if (!t) return PL_ERR_NOMEM;
        s->trac = t;
        s->trac[s->ntrac++] = (pl_sf_traction){a, b, tx, ty, pn};
        n++;
    }
    return n;
}

/* ---------------------------------------------------------------- material */

double pl_sf_j2_return(double G, double sy, double H, double *s, double *ep, double *alpha) {
    if (!(sy > 0)) return 0;
    const double ss = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * s[3] * s[3];
    const double q = sqrt(1.5 * ss);
    const double f = q - (sy + H * *alpha);
    if (f <= 0) return 0;
    const double dg = f / (3 * G + H);
    const double k = 1.5 * dg / q; /* plastic strain increment = k s_trial */
    for (int c = 0; c < 4; c++) ep[c] += k * s[c];
    const double scale = 1 - 3 * G * dg / q;
    for (int c = 0; c < 4; c++) s[c] *= scale;
    *alpha += dg;
    return (q - 3 * G * dg) * dg;
}

double pl_sf_mises(const double *s) {
    return sqrt(1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * s[3] * s[3]));
}

/* Rotates an in-plane symmetric tensor (xx, yy, ., xy) by the angle w. */
static void rotate(double *t, double w) {
    if (w == 0) return;
    const double c = cos(w), sn = sin(w);
    const double xx = t[0], yy = t[1], xy = t[3];
    t[0] = c * c * xx - 2 * c * sn * xy + sn * sn * yy;
    t[1] = sn * sn * xx + 2 * c * sn * xy + c * c * yy;
    t[3] = c * sn * (xx - yy) + (c * c - sn * sn) * xy;
}

/* ---------------------------------------------------------------- internal force */

pl_status pl_sf_internal_force(pl_sf *s, const double *du, double *f) {
    const pl_solid_def *d = &s->def;
    const double G = shear_modulus(d), K = bulk_modulus(d);
    const int fic = d->formulation == PL_SOLID_FIC_EXPLICIT || d->formulation == PL_SOLID_FIC_SEMI_IMPLICIT;
    /* strain increments on the mid-step configuration (updated Lagrangian) or the reference */
    const double *xs = s->X;
    if (d->large_strain) {
        double *xm = s->xm;
        for (int k = 0; k < 2 * s->nn; k++) xm[k] = s->x[k] - 0.5 * du[k];
        xs = s->xm;
    }
    double plastic = 0;
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[(size_t)e * s->nen];
        double ev_mean = 0, wsum = 0;
        double dev[4][4], spin[4], wgt[4];
        for (int g = 0; g < s->nip; g++) {
            double b[4], c[4];
            const double w = ip_grad(s, xs, e, g, b, c);
            double exx = 0, eyy = 0, gxy = 0, om = 0;
            for (int a = 0; a < s->nen; a++) {
                const double ux = du[2 * n[a]], uy = du[2 * n[a] + 1];
                exx += b[a] * ux;
                eyy += c[a] * uy;
                gxy += c[a] * ux + b[a] * uy;
                om += 0.5 * (b[a] * uy - c[a] * ux);
            }
            const double evol = exx + eyy;
            dev[g][0] = exx - evol / 3;
            dev[g][1] = eyy - evol / 3;
            dev[g][2] = -evol / 3;
            dev[g][3] = 0.5 * gxy;
            spin[g] = d->large_strain ? om : 0;
            wgt[g] = w;
            ev_mean += w * evol;
            wsum += w;
        }
        ev_mean /= wsum;
        for (int g = 0; g < s->nip; g++) {
            const size_t ip = (size_t)e * s->nip + g;
            double *st = &s->s[4 * ip];
            rotate(st, spin[g]);
            if (d->large_strain && d->yield_stress > 0) rotate(&s->ep[4 * ip], spin[g]);
            for (int k = 0; k < 4; k++) st[k] += 2 * G * dev[g][k];
            plastic += wgt[g] * pl_sf_j2_return(G, d->yield_stress, d->hardening, st, &s->ep[4 * ip], &s->alpha[ip]);
        }
        if (!fic) s->pe[(size_t)e * s->nip] += K * ev_mean; /* element (mean dilatation) pressure */
    }
    s->e.plastic += plastic;
    if (fic) {
        pl_status st = pl_sf_fic_pressure(s, du);
        if (st != PL_OK) return st;
    }
    /* forces on the current configuration */
    memset(f, 0, sizeof *f * 2 * (size_t)s->nn);
    const double *xc = d->large_strain ? s->x : s->X;
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[(size_t)e * s->nen];
        const double P = fic ? (s->p[n[0]] + s->p[n[1]] + s->p[n[2]]) / 3 : s->pe[(size_t)e * s->nip];
        for (int g = 0; g < s->nip; g++) {
            double b[4], c[4];
            const double w = ip_grad(s, xc, e, g, b, c);
            const double *st = &s->s[4 * ((size_t)e * s->nip + g)];
            const double sxx = st[0] + P, syy = st[1] + P, sxy = st[3];
            for (int a = 0; a < s->nen; a++) {
                f[2 * n[a]] += w * (b[a] * sxx + c[a] * sxy);
                f[2 * n[a] + 1] += w * (c[a] * syy + b[a] * sxy);
            }
        }
    }
    return PL_OK;
}

/* ---------------------------------------------------------------- diagnostics */

double pl_sf_elastic_energy(const pl_sf *s) {
    const double G = shear_modulus(&s->def), K = bulk_modulus(&s->def);
    const int fic = s->def.formulation == PL_SOLID_FIC_EXPLICIT || s->def.formulation == PL_SOLID_FIC_SEMI_IMPLICIT;
    const double *xc = s->def.large_strain ? s->x : s->X;
    double u = 0;
    for (int e = 0; e < s->ne; e++) {
        double b[4], c[4];
        for (int g = 0; g < s->nip; g++) {
            const double w = ip_grad(s, xc, e, g, b, c);
            const double *st = &s->s[4 * ((size_t)e * s->nip + g)];
            u += w * (st[0] * st[0] + st[1] * st[1] + st[2] * st[2] + 2 * st[3] * st[3]) / (4 * G);
            if (!fic && g == 0) u += elem_area(s, xc, e) * s->pe[(size_t)e * s->nip] * s->pe[(size_t)e * s->nip] / (2 * K);
        }
    }
    if (fic)
        for (int i = 0; i < s->nn; i++) u += s->mp[i] * s->p[i] * s->p[i] / (2 * K);
    return u;
}

double pl_sf_kinetic(const pl_sf *s, const double *v) {
    double k = 0;
    for (int i = 0; i < s->nn; i++) k += 0.5 * s->m[i] * (v[2 * i] * v[2 * i] + v[2 * i + 1] * v[2 * i + 1]);
    return k;
}

void pl_sf_nodal_field(const pl_sf *s, int quantity, double *out, double *wsum) {
    const int fic = s->def.formulation == PL_SOLID_FIC_EXPLICIT || s->def.formulation == PL_SOLID_FIC_SEMI_IMPLICIT;
    if (quantity == PL_SOLID_FIELD_DISPLACEMENT) {
        for (int i = 0; i < s->nn; i++) out[i] = hypot(s->x[2 * i] - s->X[2 * i], s->x[2 * i + 1] - s->X[2 * i + 1]);
        return;
    }
    if (quantity == PL_SOLID_FIELD_PRESSURE && fic) {
        memcpy(out, s->p, sizeof *out * (size_t)s->nn);
        return;
    }
    memset(out, 0, sizeof *out * (size_t)s->nn);
    memset(wsum, 0, sizeof *wsum * (size_t)s->nn);
    for (int e = 0; e < s->ne; e++) {
        const int32_t *n = &s->conn[(size_t)e * s->nen];
        const double A = elem_area(s, s->X, e);
        double val = 0;
        const double P = fic ? (s->p[n[0]] + s->p[n[1]] + s->p[n[2]]) / 3 : s->pe[(size_t)e * s->nip];
        for (int g = 0; g < s->nip; g++) {
            const size_t ip = (size_t)e * s->nip + g;
            if (quantity == PL_SOLID_FIELD_MISES) val += pl_sf_mises(&s->s[4 * ip]) / s->nip;
            else if (quantity == PL_SOLID_FIELD_PLASTIC_STRAIN) val += s->alpha[ip] / s->nip;
            else val = P;
        }
        for (int a = 0; a < s->nen; a++) {
            out[n[a]] += A * val;
            wsum[n[a]] += A;
        }
    }
    for (int i = 0; i < s->nn; i++) out[i] = wsum[i] > 0 ? out[i] / wsum[i] : 0;
}
