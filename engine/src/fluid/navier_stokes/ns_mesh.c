/* The triangle mesh of the pore space: edges, boundary tags, quality and digest. */
#include "fluid/navier_stokes/ns_internal.h"
#include "core/alloc.h"
#include "porelab/core.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void ns_mesh_free(ns_mesh *m) {
    pl_free(m->xy);
    pl_free(m->tri);
    pl_free(m->edge);
    pl_free(m->tri_edge);
    pl_free(m->edge_tri);
    pl_free(m->edge_tag);
    memset(m, 0, sizeof *m);
}

typedef struct half_edge {
    int32_t a, b; /* a < b */
    int32_t t, k;
} half_edge;

static int cmp_half(const void *pa, const void *pb) {
    const half_edge *x = pa, *y = pb;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    if (x->b != y->b) return x->b < y->b ? -1 : 1;
    if (x->t != y->t) return x->t < y->t ? -1 : 1;
    return 0;
}

int ns_mesh_build_edges(ns_mesh *m) {
    for (int t = 0; t < m->nt; t++) {
        int32_t *v = m->tri + 3 * t;
        const double *p0 = m->xy + 2 * v[0], *p1 = m->xy + 2 * v[1], *p2 = m->xy + 2 * v[2];
        const double det = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]);
        if (det < 0) {
            const int32_t s = v[1];
            v[1] = v[2];
            v[2] = s;
        }
    }
    half_edge *h = pl_malloc(sizeof *h * (size_t)(3 * m->nt));
    if (!h) return -1;
    for (int t = 0; t < m->nt; t++)
        for (int k = 0; k < 3; k++) {
            const int32_t a = m->tri[3 * t + k], b = m->tri[3 * t + (k + 1) % 3];
            h[3 * t + k] = (half_edge){a < b ? a : b, a < b ? b : a, t, k};
        }
    qsort(h, (size_t)(3 * m->nt), sizeof *h, cmp_half);
    int ne = 0;
    for (int i = 0; i < 3 * m->nt; i++)
        if (i == 0 || h[i].a != h[i - 1].a || h[i].b != h[i - 1].b) ne++;
    pl_free(m->edge);
    pl_free(m->tri_edge);
    pl_free(m->edge_tri);
    pl_free(m->edge_tag);
    m->edge = pl_malloc(sizeof(int32_t) * (size_t)(2 * ne));
    m->edge_tri = pl_malloc(sizeof(int32_t) * (size_t)(2 * ne));
    m->edge_tag = pl_calloc((size_t)ne, sizeof(int32_t));
    m->tri_edge = pl_malloc(sizeof(int32_t) * (size_t)(3 * m->nt));
    if (!m->edge || !m->edge_tri || !m->edge_tag || !m->tri_edge) {
        pl_free(h);
        return -1;
    }
    int e = -1;
    for (int i = 0; i < 3 * m->nt; i++) {
        if (i == 0 || h[i].a != h[i - 1].a || h[i].b != h[i - 1].b) {
            e++;
            m->edge[2 * e] = h[i].a;
            m->edge[2 * e + 1] = h[i].b;
            m->edge_tri[2 * e] = h[i].t;
            m->edge_tri[2 * e + 1] = -1;
        } else {
            m->edge_tri[2 * e + 1] = h[i].t;
        }
        m->tri_edge[3 * h[i].t + h[i].k] = e;
    }
    m->ne = ne;
    pl_free(h);
    return 0;
}

double ns_mesh_min_angle(const ns_mesh *m) {
    double amin = 180.0;
    for (int t = 0; t < m->nt; t++) {
        for (int k = 0; k < 3; k++) {
            const double *p = m->xy + 2 * m->tri[3 * t + k];
            const double *a = m->xy + 2 * m->tri[3 * t + (k + 1) % 3];
            const double *b = m->xy + 2 * m->tri[3 * t + (k + 2) % 3];
            const double ax = a[0] - p[0], ay = a[1] - p[1], bx = b[0] - p[0], by = b[1] - p[1];
            const double ang = atan2(fabs(ax * by - ay * bx), ax * bx + ay * by) * 180.0 / 3.14159265358979323846;
            if (ang < amin) amin = ang;
        }
    }
    return amin;
}

uint64_t ns_mesh_hash(const ns_mesh *m, uint64_t h) {
    h = pl_hash_bytes(h, &m->nv, sizeof m->nv);
    h = pl_hash_bytes(h, &m->nt, sizeof m->nt);
    h = pl_hash_bytes(h, m->xy, sizeof(double) * (size_t)(2 * m->nv));
    h = pl_hash_bytes(h, m->tri, sizeof(int32_t) * (size_t)(3 * m->nt));
    if (m->edge_tag) h = pl_hash_bytes(h, m->edge_tag, sizeof(int32_t) * (size_t)m->ne);
    return h;
}
