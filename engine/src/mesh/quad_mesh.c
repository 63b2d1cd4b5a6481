/* Meshing fluid quads into linear triangles (seed 000 §3.5): each quad is divided into
 * ndivx x ndivy cells in (s, t) space, each cell into four triangles around its centre node,
 * and mapped with the bilinear shape functions (eqs. 3.6-3.7). Quads mesh together: coincident
 * nodes are merged and triangles with foreign nodes on a face are re-meshed into a fan (§3.5.2,
 * Fig. 3-4), the foreign nodes found by a range search over a uniform grid of nodes and ordered
 * by their distance along the face. */
#include "core/alloc.h"
#include "mesh/mesh.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DIV 4096

static double cross3(pl_vec2 a, pl_vec2 b, pl_vec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/* Validates a quad: counter-clockwise, convex, not degenerate. */
static pl_status check_quad(const pl_mesh_quad *q, int index, char *msg, int msglen) {
    int pos = 0, neg = 0;
    double size = 0;
    for (int i = 0; i < 4; i++) {
        pl_vec2 d = {q->c[(i + 1) % 4].x - q->c[i].x, q->c[(i + 1) % 4].y - q->c[i].y};
        size = fmax(size, hypot(d.x, d.y));
        if (!isfinite(q->c[i].x) || !isfinite(q->c[i].y)) {
            snprintf(msg, msglen, "fluid quad %d (id %d): corner %d is not finite", index, q->id, i + 1);
            return PL_ERR_ARG;
        }
    }
    for (int i = 0; i < 4; i++) {
        double cr = cross3(q->c[i], q->c[(i + 1) % 4], q->c[(i + 2) % 4]);
        if (cr > 1e-12 * size * size) pos++;
        else if (cr < -1e-12 * size * size) neg++;
    }
    if (q->ndivx < 1 || q->ndivy < 1 || q->ndivx > MAX_DIV || q->ndivy > MAX_DIV) {
        snprintf(msg, msglen, "fluid quad %d (id %d): ndivx and ndivy must be 1..%d (got %d, %d)", index,
                 q->id, MAX_DIV, q->ndivx, q->ndivy);
        return PL_ERR_ARG;
    }
    if (!(q->anisotropy > 0) || !isfinite(q->anisotropy)) {
        snprintf(msg, msglen, "fluid quad %d (id %d): anisotropy D_y/D_x must be > 0 (got %g)", index, q->id,
                 q->anisotropy);
        return PL_ERR_ARG;
    }
    if (neg == 4 || (neg > 0 && pos == 0)) {
        snprintf(msg, msglen,
                 "fluid quad %d (id %d) is clockwise: give the corners counter-clockwise, e.g. "
                 "(%g %g) (%g %g) (%g %g) (%g %g)",
                 index, q->id, q->c[0].x, q->c[0].y, q->c[3].x, q->c[3].y, q->c[2].x, q->c[2].y, q->c[1].x,
                 q->c[1].y);
        return PL_ERR_ARG;
    }
    if (pos != 4) {
        snprintf(msg, msglen,
                 "fluid quad %d (id %d) is not convex (or has collinear/repeated corners): corners "
                 "(%g %g) (%g %g) (%g %g) (%g %g)",
                 index, q->id, q->c[0].x, q->c[0].y, q->c[1].x, q->c[1].y, q->c[2].x, q->c[2].y, q->c[3].x,
                 q->c[3].y);
        return PL_ERR_ARG;
    }
    return PL_OK;
}

/* Bilinear map of eqs. 3.6-3.7. */
static pl_vec2 map_st(const pl_mesh_quad *q, double s, double t) {
    double h1 = 0.25 * (1 - s) * (1 - t), h2 = 0.25 * (1 + s) * (1 - t);
    double h3 = 0.25 * (1 + s) * (1 + t), h4 = 0.25 * (1 - s) * (1 + t);
    pl_vec2 p;
    p.x = h1 * q->c[0].x + h2 * q->c[1].x + h3 * q->c[2].x + h4 * q->c[3].x;
    p.y = h1 * q->c[0].y + h2 * q->c[1].y + h3 * q->c[2].y + h4 * q->c[3].y;
    return p;
}

/* ---- growable triangle list */
typedef struct tri_list {
    int32_t *v;
    int32_t *q;
    int n, cap;
} tri_list;

static int tri_push(tri_list *l, int a, int b, int c, int quad) {
    if (l->n == l->cap) {
        int nc = l->cap ? 2 * l->cap : 1024;
        int32_t *nv = pl_realloc(l->v, sizeof(int32_t) * 3 * (size_t)nc);
        if (!nv) return 0;
        l->v = nv;
        int32_t *nq = pl_realloc(l->q, sizeof(int32_t) * (size_t)nc);
        if (!nq) return 0;
        l->q = nq;
        l->cap = nc;
    }
    l->v[3 * l->n] = a;
    l->v[3 * l->n + 1] = b;
    l->v[3 * l->n + 2] = c;
    l->q[l->n] = quad;
    l->n++;
    return 1;
}

/* ---- node merge: sort by x, cluster within tol */
typedef struct xkey { double x; int32_t i; } xkey;
static int cmp_x(const void *a, const void *b) {
    const xkey *p = a, *q = b;
    if (p->x < q->x) return -1;
    if (p->x > q->x) return 1;
    return (p->i > q->i) - (p->i < q->i);
}

/* ---- uniform grid of points for range search */
typedef struct point_grid {
    pl_vec2 lo;
    double cell;
    int gx, gy;
    int32_t *start, *items;
} point_grid;

static int pgrid_build(point_grid *g, const pl_vec2 *xy, int n, pl_vec2 lo, pl_vec2 hi, double cell) {
    g->lo = lo;
    g->cell = cell;
    g->gx = (int)floor((hi.x - lo.x) / cell) + 1;
    g->gy = (int)floor((hi.y - lo.y) / cell) + 1;
    size_t nc = (size_t)g->gx * (size_t)g->gy;
    g->start = pl_calloc(nc + 1, sizeof(int32_t));
    g->items = pl_malloc(sizeof(int32_t) * (size_t)(n > 0 ? n : 1));
    if (!g->start || !g->items) return 0;
    for (int i = 0; i < n; i++) {
        int cx = (int)floor((xy[i].x - lo.x) / cell), cy = (int)floor((xy[i].y - lo.y) / cell);
        if (cx < 0) cx = 0;
        if (cy < 0) cy = 0;
        if (cx >= g->gx) cx = g->gx - 1;
        if (cy >= g->gy) cy = g->gy - 1;
        g->start[(size_t)cy * g->gx + cx + 1]++;
    }
    for (size_t c = 0; c < nc; c++) g->start[c + 1] += g->start[c];
    int32_t *fill = pl_malloc(sizeof(int32_t) * nc);
    if (!fill) return 0;
    memcpy(fill, g->start, sizeof(int32_t) * nc);
    for (int i = 0; i < n; i++) {
        int cx = (int)floor((xy[i].x - lo.x) / cell), cy = (int)floor((xy[i].y - lo.y) / cell);
        if (cx < 0) cx = 0;
        if (cy < 0) cy = 0;
        if (cx >= g->gx) cx = g->gx - 1;
        if (cy >= g->gy) cy = g->gy - 1;
        g->items[fill[(size_t)cy * g->gx + cx]++] = i;
    }
    pl_free(fill);
    return 1;
}

static void pgrid_free(point_grid *g) {
    pl_free(g->start);
    pl_free(g->items);
    memset(g, 0, sizeof *g);
}

typedef struct hang { double t; int32_t node; } hang;
static int cmp_hang(const void *a, const void *b) {
    double ta = ((const hang *)a)->t, tb = ((const hang *)b)->t;
    return (ta > tb) - (ta < tb);
}

/* Nodes strictly inside segment a-b (distance <= tol), sorted along a->b. */
static int find_on_segment(const point_grid *g, const pl_vec2 *xy, int ia, int ib, double tol, hang *out, int cap) {
    pl_vec2 a = xy[ia], b = xy[ib];
    double lx = fmin(a.x, b.x) - tol, hx = fmax(a.x, b.x) + tol;
    double ly = fmin(a.y, b.y) - tol, hy = fmax(a.y, b.y) + tol;
    int i0 = (int)floor((lx - g->lo.x) / g->cell), i1 = (int)floor((hx - g->lo.x) / g->cell);
    int j0 = (int)floor((ly - g->lo.y) / g->cell), j1 = (int)floor((hy - g->lo.y) / g->cell);
    if (i0 < 0) i0 = 0;
    if (j0 < 0) j0 = 0;
    if (i1 >= g->gx) i1 = g->gx - 1;
    if (j1 >= g->gy) j1 = g->gy - 1;
    double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy, len = sqrt(len2);
    int n = 0;
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            size_t c = (size_t)j * g->gx + i;
            for (int k = g->start[c]; k < g->start[c + 1]; k++) {
                int p = g->items[k];
                if (p == ia || p == ib) continue;
                double px = xy[p].x - a.x, py = xy[p].y - a.y;
                double t = (px * dx + py * dy) / len2;
                if (t * len <= tol || (1 - t) * len <= tol) continue;
                double dist = fabs(px * dy - py * dx) / len;
                if (dist > tol) continue;
                if (n < cap) out[n] = (hang){t, p};
                n++;
            }
        }
    if (n <= cap) qsort(out, (size_t)n, sizeof(hang), cmp_hang);
    return n;
}

typedef struct edge_rec { int32_t a, b, tri, dir; } edge_rec;
static int cmp_edge(const void *x, const void *y) {
    const edge_rec *p = x, *q = y;
    if (p->a != q->a) return (p->a > q->a) - (p->a < q->a);
    if (p->b != q->b) return (p->b > q->b) - (p->b < q->b);
    return (p->tri > q->tri) - (p->tri < q->tri);
}

void pl_mesh_free(pl_mesh *m) {
    pl_free(m->xy); pl_free(m->tri); pl_free(m->tri_quad); pl_free(m->area); pl_free(m->bc);
    pl_free(m->cell_start); pl_free(m->cell_items); pl_free(m->bedge);
    pl_free(m->tri_box); pl_free(m->tri_cell0); pl_free(m->edge_ang); pl_free(m->edge_len);
    memset(m, 0, sizeof *m);
}

pl_status pl_mesh_build(pl_mesh *m, const pl_mesh_quad *quads, int nq, char *msg, int msglen) {
    pl_mesh_free(m);
    if (nq <= 0) {
        snprintf(msg, msglen, "fluid: no fluid quad defined (add one with add_fluid_quad / add_fluid_mesh_ui)");
        return PL_ERR_STATE;
    }
    size_t nn_total = 0, ne_total = 0;
    for (int q = 0; q < nq; q++) {
        pl_status st = check_quad(&quads[q], q, msg, msglen);
        if (st != PL_OK) return st;
        size_t nx = (size_t)quads[q].ndivx, ny = (size_t)quads[q].ndivy;
        nn_total += (nx + 1) * (ny + 1) + nx * ny;
        ne_total += 4 * nx * ny;
    }
    if (nn_total > 20000000u) {
        snprintf(msg, msglen, "fluid: the quads ask for %zu nodes; at most 20,000,000", nn_total);
        return PL_ERR_ARG;
    }
    pl_vec2 *xy = pl_malloc(sizeof(pl_vec2) * nn_total);
    tri_list tl = {0};
    int32_t *rep = NULL, *order = NULL, *newid = NULL;
    point_grid pg = {0};
    hang *hbuf = NULL;
    edge_rec *edges = NULL;
    pl_status status = PL_ERR_NOMEM;
    if (!xy) goto fail;
    /* 1. mesh each quad */
    int nn = 0;
    for (int q = 0; q < nq; q++) {
        const pl_mesh_quad *Q = &quads[q];
        int nx = Q->ndivx, ny = Q->ndivy, base = nn;
        for (int j = 0; j <= ny; j++)
            for (int i = 0; i <= nx; i++) xy[nn++] = map_st(Q, -1 + 2.0 * i / nx, -1 + 2.0 * j / ny);
        int cbase = nn;
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                double s = -1 + 2.0 * (i + 0.5) / nx, t = -1 + 2.0 * (j + 0.5) / ny;
                xy[nn++] = map_st(Q, s, t);
            }
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                int p1 = base + j * (nx + 1) + i, p2 = p1 + 1, p4 = p1 + (nx + 1), p3 = p4 + 1;
                int p5 = cbase + j * nx + i;
                if (!tri_push(&tl, p1, p2, p5, q) || !tri_push(&tl, p2, p3, p5, q) || !tri_push(&tl, p3, p4, p5, q) ||
                    !tri_push(&tl, p4, p1, p5, q))
                    goto fail;
            }
    }
    /* bounding box and tolerance */
    pl_vec2 lo = xy[0], hi = xy[0];
    for (int i = 1; i < nn; i++) {
        lo.x = fmin(lo.x, xy[i].x); lo.y = fmin(lo.y, xy[i].y);
        hi.x = fmax(hi.x, xy[i].x); hi.y = fmax(hi.y, xy[i].y);
    }
    double scale = hypot(hi.x - lo.x, hi.y - lo.y);
    double tol = 1e-9 * scale;
    /* 2. merge coincident nodes (sweep in x) */
    rep = pl_malloc(sizeof(int32_t) * (size_t)nn);
    order = pl_malloc(sizeof(int32_t) * (size_t)nn);
    newid = pl_malloc(sizeof(int32_t) * (size_t)nn);
    if (!rep || !order || !newid) goto fail;
    xkey *keys = pl_malloc(sizeof(xkey) * (size_t)nn);
    if (!keys) goto fail;
    for (int i = 0; i < nn; i++) { rep[i] = i; keys[i] = (xkey){xy[i].x, i}; }
    qsort(keys, (size_t)nn, sizeof(xkey), cmp_x);
    for (int i = 0; i < nn; i++) order[i] = keys[i].i;
    pl_free(keys);
    for (int a = 0; a < nn; a++) {
        int i = order[a];
        for (int b = a + 1; b < nn && xy[order[b]].x - xy[i].x <= tol; b++) {
            int j = order[b];
            if (fabs(xy[j].y - xy[i].y) <= tol) {
                int ri = rep[i], rj = rep[j];
                while (rep[ri] != ri) ri = rep[ri];
                while (rep[rj] != rj) rj = rep[rj];
                if (ri < rj) rep[rj] = ri;
                else if (rj < ri) rep[ri] = rj;
            }
        }
    }
    int nu = 0, merged = 0;
    for (int i = 0; i < nn; i++) {
        int r = i;
        while (rep[r] != r) r = rep[r];
        rep[i] = r;
        if (r == i) { newid[i] = nu; xy[nu] = xy[i]; nu++; }
        else { newid[i] = newid[r]; merged++; }
    }
    for (int k = 0; k < 3 * tl.n; k++) tl.v[k] = newid[tl.v[k]];
    nn = nu;
    /* 3. re-mesh triangles with foreign nodes on a face (§3.5.2) */
    double avg_edge = sqrt(fmax((hi.x - lo.x) * (hi.y - lo.y), scale * scale * 1e-6) / (double)(nn > 0 ? nn : 1)) * 2;
    if (!(avg_edge > 0)) avg_edge = scale;
    while (((hi.x - lo.x) / avg_edge + 1) * ((hi.y - lo.y) / avg_edge + 1) > 4.0 * nn + 16) avg_edge *= 1.5;
    if (!pgrid_build(&pg, xy, nn, lo, hi, avg_edge)) goto fail;
    int hcap = 256;
    hbuf = pl_malloc(sizeof(hang) * hcap);
    if (!hbuf) goto fail;
    int split = 0;
    for (int t = 0; t < tl.n; t++) {
        for (int e = 0; e < 3; e++) {
            int a = tl.v[3 * t + e], b = tl.v[3 * t + (e + 1) % 3], c = tl.v[3 * t + (e + 2) % 3];
            int nh = find_on_segment(&pg, xy, a, b, tol * 10, hbuf, hcap);
            if (nh > hcap) {
                hcap = nh;
                hang *nb = pl_realloc(hbuf, sizeof(hang) * hcap);
                if (!nb) goto fail;
                hbuf = nb;
                nh = find_on_segment(&pg, xy, a, b, tol * 10, hbuf, hcap);
            }
            if (nh == 0) continue;
            /* fan from the opposite vertex c: (a,p1,c), (p1,p2,c), ..., (pk,b,c) */
            int q = tl.q[t];
            int prev = a;
            int first = 1;
            for (int k = 0; k <= nh; k++) {
                int nxt = k < nh ? hbuf[k].node : b;
                if (first) {
                    tl.v[3 * t] = prev; tl.v[3 * t + 1] = nxt; tl.v[3 * t + 2] = c;
                    first = 0;
                } else if (!tri_push(&tl, prev, nxt, c, q)) goto fail;
                prev = nxt;
            }
            split++;
            e = -1; /* re-check the (now smaller) triangle t from its first edge */
        }
    }
    /* 4. finish: areas, gradient constants, checks */
    m->nn = nn;
    m->ne = tl.n;
    m->xy = pl_realloc(xy, sizeof(pl_vec2) * (size_t)(nn > 0 ? nn : 1));
    xy = NULL;
    m->tri = tl.v;
    m->tri_quad = tl.q;
    tl.v = NULL; tl.q = NULL;
    m->area = pl_malloc(sizeof(double) * (size_t)m->ne);
    m->bc = pl_malloc(sizeof(double) * 6 * (size_t)m->ne);
    if (!m->xy || !m->area || !m->bc) goto fail;
    m->scale = scale;
    m->lo = lo;
    m->hi = hi;
    m->merged_nodes = merged;
    m->split_triangles = split;
    for (int e = 0; e < m->ne; e++) {
        const int32_t *v = &m->tri[3 * e];
        pl_vec2 pi = m->xy[v[0]], pj = m->xy[v[1]], pk = m->xy[v[2]];
        double A = 0.5 * cross3(pi, pj, pk);
        if (!(A > 1e-14 * scale * scale)) {
            snprintf(msg, msglen,
                     "fluid mesh: triangle %d of quad %d (id %d) has area %g <= 0 near (%g, %g); the quads are "
                     "badly shaped or overlap",
                     e, m->tri_quad[e], quads[m->tri_quad[e]].id, A, (pi.x + pj.x + pk.x) / 3, (pi.y + pj.y + pk.y) / 3);
            status = PL_ERR_ARG;
            goto fail;
        }
        m->area[e] = A;
        double *bc = &m->bc[6 * e];
        bc[0] = pj.y - pk.y; bc[1] = pk.y - pi.y; bc[2] = pi.y - pj.y; /* eq. 3.12 */
        bc[3] = pk.x - pj.x; bc[4] = pi.x - pk.x; bc[5] = pj.x - pi.x;
    }
    /* edges: each used once (boundary) or twice (interior, opposite directions) */
    edges = pl_malloc(sizeof(edge_rec) * 3 * (size_t)m->ne);
    if (!edges) goto fail;
    for (int e = 0; e < m->ne; e++)
        for (int k = 0; k < 3; k++) {
            int a = m->tri[3 * e + k], b = m->tri[3 * e + (k + 1) % 3];
            edges[3 * e + k] = (edge_rec){a < b ? a : b, a < b ? b : a, e, a < b ? 0 : 1};
        }
    qsort(edges, 3 * (size_t)m->ne, sizeof(edge_rec), cmp_edge);
    int nb = 0;
    for (int i = 0; i < 3 * m->ne;) {
        int j = i + 1;
        while (j < 3 * m->ne && edges[j].a == edges[i].a && edges[j].b == edges[i].b) j++;
        if (j - i > 2 || (j - i == 2 && edges[i].dir == edges[i + 1].dir)) {
            pl_vec2 p = m->xy[edges[i].a];
            snprintf(msg, msglen, "fluid mesh: fluid quads overlap near (%g, %g) (an edge is shared by %d triangles)",
                     p.x, p.y, j - i);
            status = PL_ERR_ARG;
            goto fail;
        }
        if (j - i == 1) nb++;
        i = j;
    }
    m->nbe = nb;
    m->bedge = pl_malloc(sizeof(int32_t) * 2 * (size_t)(nb > 0 ? nb : 1));
    if (!m->bedge) goto fail;
    nb = 0;
    for (int i = 0; i < 3 * m->ne;) {
        int j = i + 1;
        while (j < 3 * m->ne && edges[j].a == edges[i].a && edges[j].b == edges[i].b) j++;
        if (j - i == 1) {
            m->bedge[2 * nb] = edges[i].dir ? edges[i].b : edges[i].a;
            m->bedge[2 * nb + 1] = edges[i].dir ? edges[i].a : edges[i].b;
            nb++;
        }
        i = j;
    }
    status = pl_mesh_build_grid(m);
    if (status != PL_OK) goto fail;
    /* overlapping quads: a node strictly inside a triangle it does not belong to */
    for (int i = 0; i < m->nn; i++) {
        pl_vec2 p = m->xy[i];
        int cx = (int)floor((p.x - m->lo.x) / m->cell), cy = (int)floor((p.y - m->lo.y) / m->cell);
        if (cx >= m->gx) cx = m->gx - 1;
        if (cy >= m->gy) cy = m->gy - 1;
        size_t c = (size_t)cy * m->gx + cx;
        for (int k = m->cell_start[c]; k < m->cell_start[c + 1]; k++) {
            int e = m->cell_items[k];
            const int32_t *v = &m->tri[3 * e];
            if (v[0] == i || v[1] == i || v[2] == i) continue;
            double l[3];
            pl_mesh_barycentric(m, e, p, l);
            if (l[0] > 1e-9 && l[1] > 1e-9 && l[2] > 1e-9) {
                snprintf(msg, msglen, "fluid mesh: fluid quads %d (id %d) and another overlap: node at (%g, %g) lies inside a triangle of quad %d",
                         m->tri_quad[e], quads[m->tri_quad[e]].id, p.x, p.y, m->tri_quad[e]);
                status = PL_ERR_ARG;
                goto fail;
            }
        }
    }
    pl_free(rep); pl_free(order); pl_free(newid); pl_free(hbuf); pl_free(edges);
    pgrid_free(&pg);
    return PL_OK;
fail:
    if (status == PL_ERR_NOMEM) snprintf(msg, msglen, "fluid mesh: out of memory");
    pl_free(xy); pl_free(tl.v); pl_free(tl.q); pl_free(rep); pl_free(order); pl_free(newid); pl_free(hbuf); pl_free(edges);
    pgrid_free(&pg);
    pl_mesh_free(m);
    return status;
}

/* ---------------------------------------------------------- point location */

pl_status pl_mesh_build_grid(pl_mesh *m) {
    pl_free(m->cell_start); pl_free(m->cell_items);
    m->cell_start = NULL; m->cell_items = NULL;
    double w = m->hi.x - m->lo.x, h = m->hi.y - m->lo.y;
    double tot = 0;
    for (int e = 0; e < m->ne; e++) tot += m->area[e];
    double cell = sqrt(2.0 * tot / m->ne);
    if (!(cell > 0)) cell = m->scale;
    while ((w / cell + 1) * (h / cell + 1) > 2.0 * m->ne + 16) cell *= 1.25;
    m->cell = cell;
    m->gx = (int)floor(w / cell) + 1;
    m->gy = (int)floor(h / cell) + 1;
    size_t nc = (size_t)m->gx * m->gy;
    m->cell_start = pl_calloc(nc + 1, sizeof(int32_t));
    if (!m->cell_start) return PL_ERR_NOMEM;
    for (int pass = 0; pass < 2; pass++) {
        int32_t *fill = NULL;
        if (pass == 1) {
            for (size_t c = 0; c < nc; c++) m->cell_start[c + 1] += m->cell_start[c];
            m->cell_items = pl_malloc(sizeof(int32_t) * (size_t)(m->cell_start[nc] > 0 ? m->cell_start[nc] : 1));
            fill = pl_malloc(sizeof(int32_t) * nc);
            if (!m->cell_items || !fill) { pl_free(fill); return PL_ERR_NOMEM; }
            memcpy(fill, m->cell_start, sizeof(int32_t) * nc);
        }
        for (int e = 0; e < m->ne; e++) {
            const int32_t *v = &m->tri[3 * e];
            pl_vec2 a = m->xy[v[0]], b = m->xy[v[1]], c = m->xy[v[2]];
            pl_vec2 lo = {fmin(a.x, fmin(b.x, c.x)), fmin(a.y, fmin(b.y, c.y))};
            pl_vec2 hi = {fmax(a.x, fmax(b.x, c.x)), fmax(a.y, fmax(b.y, c.y))};
            int i0, j0, i1, j1;
            pl_mesh_grid_range(m, lo, hi, &i0, &j0, &i1, &j1);
            for (int j = j0; j <= j1; j++)
                for (int i = i0; i <= i1; i++) {
                    size_t cidx = (size_t)j * m->gx + i;
                    if (pass == 0) m->cell_start[cidx + 1]++;
                    else m->cell_items[fill[cidx]++] = e;
                }
        }
        pl_free(fill);
    }
    /* per-triangle boxes, first cells and edge angles/lengths: the same expressions the
       per-grain loops used to evaluate for every candidate triangle at every update */
    pl_free(m->tri_box); pl_free(m->tri_cell0); pl_free(m->edge_ang); pl_free(m->edge_len);
    m->tri_box = pl_malloc(sizeof(double) * 4 * (size_t)(m->ne > 0 ? m->ne : 1));
    m->tri_cell0 = pl_malloc(sizeof(int32_t) * 2 * (size_t)(m->ne > 0 ? m->ne : 1));
    m->edge_ang = pl_malloc(sizeof(double) * 3 * (size_t)(m->ne > 0 ? m->ne : 1));
    m->edge_len = pl_malloc(sizeof(double) * 3 * (size_t)(m->ne > 0 ? m->ne : 1));
    if (!m->tri_box || !m->tri_cell0 || !m->edge_ang || !m->edge_len) return PL_ERR_NOMEM;
    for (int e = 0; e < m->ne; e++) {
        const int32_t *v = &m->tri[3 * e];
        pl_vec2 a = m->xy[v[0]], b = m->xy[v[1]], c = m->xy[v[2]];
        pl_vec2 lo = {fmin(a.x, fmin(b.x, c.x)), fmin(a.y, fmin(b.y, c.y))};
        pl_vec2 hi = {fmax(a.x, fmax(b.x, c.x)), fmax(a.y, fmax(b.y, c.y))};
        m->tri_box[4 * e] = lo.x;
        m->tri_box[4 * e + 1] = lo.y;
        m->tri_box[4 * e + 2] = hi.x;
        m->tri_box[4 * e + 3] = hi.y;
        int i0, j0, i1, j1;
        pl_mesh_grid_range(m, lo, hi, &i0, &j0, &i1, &j1);
        m->tri_cell0[2 * e] = i0;
        m->tri_cell0[2 * e + 1] = j0;
        for (int k = 0; k < 3; k++) {
            pl_vec2 P = m->xy[v[k]], Q = m->xy[v[(k + 1) % 3]];
            double ex = Q.x - P.x, ey = Q.y - P.y;
            m->edge_ang[3 * e + k] = atan2(ey, ex);
            m->edge_len[3 * e + k] = sqrt(ex * ex + ey * ey);
        }
    }
    return PL_OK;
}

int pl_mesh_grid_range(const pl_mesh *m, pl_vec2 lo, pl_vec2 hi, int *i0, int *j0, int *i1, int *j1) {
    double eps = 1e-9 * m->scale;
    if (hi.x < m->lo.x - eps || hi.y < m->lo.y - eps || lo.x > m->hi.x + eps || lo.y > m->hi.y + eps) {
        *i0 = *j0 = 0;
        *i1 = *j1 = -1;
        return 0;
    }
    int a = (int)floor((lo.x - eps - m->lo.x) / m->cell), b = (int)floor((hi.x + eps - m->lo.x) / m->cell);
    int c = (int)floor((lo.y - eps - m->lo.y) / m->cell), d = (int)floor((hi.y + eps - m->lo.y) / m->cell);
    *i0 = a < 0 ? 0 : a;
    *i1 = b >= m->gx ? m->gx - 1 : b;
    *j0 = c < 0 ? 0 : c;
    *j1 = d >= m->gy ? m->gy - 1 : d;
    return 1;
}

void pl_mesh_barycentric(const pl_mesh *m, int e, pl_vec2 p, double l[3]) {
    /* shape functions of eqs. 3.22-3.23: h = (a + b x + c y) / (2A), written relative to
       node k for accuracy */
    const int32_t *v = &m->tri[3 * e];
    pl_vec2 pi = m->xy[v[0]], pj = m->xy[v[1]], pk = m->xy[v[2]];
    double inv2A = 1.0 / (2 * m->area[e]);
    l[0] = ((pj.x - p.x) * (pk.y - p.y) - (pk.x - p.x) * (pj.y - p.y)) * inv2A;
    l[1] = ((pk.x - p.x) * (pi.y - p.y) - (pi.x - p.x) * (pk.y - p.y)) * inv2A;
    l[2] = 1 - l[0] - l[1];
}

int pl_mesh_locate(const pl_mesh *m, pl_vec2 p) {
    if (!m->cell_start) return -1;
    double eps = 1e-9 * m->scale;
    if (p.x < m->lo.x - eps || p.y < m->lo.y - eps || p.x > m->hi.x + eps || p.y > m->hi.y + eps) return -1;
    int cx = (int)floor((p.x - m->lo.x) / m->cell), cy = (int)floor((p.y - m->lo.y) / m->cell);
    if (cx < 0) cx = 0;
    if (cy < 0) cy = 0;
    if (cx >= m->gx) cx = m->gx - 1;
    if (cy >= m->gy) cy = m->gy - 1;
    size_t c = (size_t)cy * m->gx + cx;
    int best = -1;
    double bestmin = -1e-10;
    for (int k = m->cell_start[c]; k < m->cell_start[c + 1]; k++) {
        int e = m->cell_items[k];
        double l[3];
        pl_mesh_barycentric(m, e, p, l);
        double mn = fmin(l[0], fmin(l[1], l[2]));
        if (mn >= 0) return e;
        if (mn > bestmin) { bestmin = mn; best = e; }
    }
    return best;
}
