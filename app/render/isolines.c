/* Marching triangles with deterministic chaining of segments into polylines.
 *
 * Each triangle crossed by a level contributes one segment between two crossing points.
 * A crossing point is identified by a key: the mesh edge (i < j) it lies on, or the node
 * itself when it lies exactly on a node. Segments sharing a key are neighbours; walking
 * neighbours gives polylines (open ones first, starting at free ends, then closed loops),
 * all in triangle order, so the output does not depend on memory addresses. */
#include "isolines.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void pl_isolines_init(pl_isolines *iso) { memset(iso, 0, sizeof *iso); }

void pl_isolines_free(pl_isolines *iso) {
    free(iso->points);
    free(iso->starts);
    free(iso->levels);
    free(iso->closed);
    pl_isolines_init(iso);
}

typedef struct seg {
    uint64_t key[2];
    pl_vec2 p[2];
} seg;

typedef struct end_ref {
    uint64_t key;
    int seg, end;
} end_ref;

static int cmp_end(const void *a, const void *b) {
    const end_ref *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    if (x->seg != y->seg) return x->seg < y->seg ? -1 : 1;
    return x->end - y->end;
}

/* Crossing on edge (i, j) for a level with exactly one of the two nodes "above". */
static void crossing(const pl_vec2 *nodes, const double *v, int i, int j, double level,
                     uint64_t *key, pl_vec2 *p) {
    if (i > j) { int t = i; i = j; j = t; }
    double vi = v[i], vj = v[j];
    double t = (level - vi) / (vj - vi);
    if (t <= 0.0) { /* exactly on node i */
        *key = ((uint64_t)1 << 63) | (uint64_t)(uint32_t)i;
        *p = nodes[i];
        return;
    }
    if (t >= 1.0) {
        *key = ((uint64_t)1 << 63) | (uint64_t)(uint32_t)j;
        *p = nodes[j];
        return;
    }
    *key = ((uint64_t)(uint32_t)i << 32) | (uint64_t)(uint32_t)j;
    p->x = nodes[i].x + t * (nodes[j].x - nodes[i].x);
    p->y = nodes[i].y + t * (nodes[j].y - nodes[i].y);
}

static int reserve_points(pl_isolines *iso, int need) {
    if (need <= iso->point_cap) return 0;
    int nc = iso->point_cap ? iso->point_cap * 2 : 1024;
    while (nc < need) nc *= 2;
    pl_vec2 *p = realloc(iso->points, (size_t)nc * sizeof *p);
    if (!p) return -1;
    iso->points = p;
    iso->point_cap = nc;
    return 0;
}

static int add_line(pl_isolines *iso, double level) {
    if (iso->line_count + 2 > iso->line_cap) {
        int nc = iso->line_cap ? iso->line_cap * 2 : 64;
        int *s = realloc(iso->starts, (size_t)(nc + 1) * sizeof *s);
        if (!s) return -1;
        iso->starts = s;
        double *l = realloc(iso->levels, (size_t)nc * sizeof *l);
        if (!l) return -1;
        iso->levels = l;
        unsigned char *c = realloc(iso->closed, (size_t)nc);
        if (!c) return -1;
        iso->closed = c;
        iso->line_cap = nc;
    }
    if (iso->line_count == 0) iso->starts[0] = iso->point_count;
    iso->levels[iso->line_count] = level;
    iso->closed[iso->line_count] = 0;
    iso->line_count++;
    iso->starts[iso->line_count] = iso->point_count;
    return 0;
}

static int push_point(pl_isolines *iso, pl_vec2 p) {
    if (reserve_points(iso, iso->point_count + 1)) return -1;
    iso->points[iso->point_count++] = p;
    iso->starts[iso->line_count] = iso->point_count;
    return 0;
}

/* Index of the end sharing e's key with a different end (or -1). ends sorted by key. */
static int partner(const end_ref *ends, const int *pos, int nends, int s, int e) {
    int k = pos[2 * s + e];
    /* entries with equal keys are adjacent; pair them 0-1, 2-3, ... within the group */
    int g = k;
    while (g > 0 && ends[g - 1].key == ends[k].key) g--;
    int off = k - g;
    int other = (off % 2 == 0) ? k + 1 : k - 1;
    if (other < 0 || other >= nends || ends[other].key != ends[k].key) return -1;
    return other;
}

static int extract_level(const pl_vec2 *nodes, const int *tris, int tri_count, const double *v,
                         double level, pl_isolines *iso) {
    int nseg = 0, cap = 0;
    seg *segs = NULL;
    for (int t = 0; t < tri_count; t++) {
        const int *n = tris + 3 * t;
        int above[3];
        for (int k = 0; k < 3; k++) above[k] = v[n[k]] >= level;
        int na = above[0] + above[1] + above[2];
        if (na == 0 || na == 3) continue;
        /* the lone node (above or below) is the one whose two edges are crossed */
        int lone = 0;
        for (int k = 0; k < 3; k++)
            if ((na == 1 && above[k]) || (na == 2 && !above[k])) lone = k;
        int a = n[lone], b = n[(lone + 1) % 3], c = n[(lone + 2) % 3];
        seg s;
        crossing(nodes, v, a, b, level, &s.key[0], &s.p[0]);
        crossing(nodes, v, a, c, level, &s.key[1], &s.p[1]);
        if (s.key[0] == s.key[1]) continue; /* degenerate: touches the level at one node */
        if (nseg == cap) {
            cap = cap ? 2 * cap : 256;
            seg *ns = realloc(segs, (size_t)cap * sizeof *ns);
            if (!ns) { free(segs); return -1; }
            segs = ns;
        }
        segs[nseg++] = s;
    }
    if (nseg == 0) { free(segs); return 0; }
    int nends = 2 * nseg;
    end_ref *ends = malloc((size_t)nends * sizeof *ends);
    int *pos = malloc((size_t)nends * sizeof *pos);
    unsigned char *used = calloc((size_t)nseg, 1);
    if (!ends || !pos || !used) { free(segs); free(ends); free(pos); free(used); return -1; }
    for (int s = 0; s < nseg; s++)
        for (int e = 0; e < 2; e++) {
            ends[2 * s + e].key = segs[s].key[e];
            ends[2 * s + e].seg = s;
            ends[2 * s + e].end = e;
        }
    qsort(ends, (size_t)nends, sizeof *ends, cmp_end);
    for (int k = 0; k < nends; k++) pos[2 * ends[k].seg + ends[k].end] = k;

    int rc = 0;
    /* pass 0: open lines from free ends; pass 1: closed loops */
    for (int pass = 0; pass < 2 && rc == 0; pass++) {
        for (int s0 = 0; s0 < nseg && rc == 0; s0++) {
            if (used[s0]) continue;
            int start_end = -1;
            if (pass == 0) {
                if (partner(ends, pos, nends, s0, 0) < 0) start_end = 0;
                else if (partner(ends, pos, nends, s0, 1) < 0) start_end = 1;
                else continue;
            } else {
                start_end = 0;
            }
            if (add_line(iso, level)) { rc = -1; break; }
            int s = s0, e = start_end;
            if (push_point(iso, segs[s].p[e])) { rc = -1; break; }
            for (;;) {
                used[s] = 1;
                int out = 1 - e;
                if (push_point(iso, segs[s].p[out])) { rc = -1; break; }
                int k = partner(ends, pos, nends, s, out);
                if (k < 0) break;
                int ns = ends[k].seg;
                if (used[ns]) {
                    if (ns == s0 && pass == 1) {
                        iso->closed[iso->line_count - 1] = 1;
                        iso->point_count--; /* the closing point repeats the first */
                        iso->starts[iso->line_count] = iso->point_count;
                    }
                    break;
                }
                s = ns;
                e = ends[k].end;
            }
        }
    }
    free(segs);
    free(ends);
    free(pos);
    free(used);
    return rc;
}

int pl_isolines_extract(const pl_vec2 *nodes, int node_count, const int *tris, int tri_count,
                        const double *values, const double *levels, int level_count,
                        pl_isolines *iso) {
    for (int t = 0; t < 3 * tri_count; t++)
        if (tris[t] < 0 || tris[t] >= node_count) return -1;
    for (int l = 0; l < level_count; l++)
        if (isfinite(levels[l]) &&
            extract_level(nodes, tris, tri_count, values, levels[l], iso))
            return -1;
    return 0;
}

double pl_nice_number(double x, int round) {
    if (!(x > 0.0) || !isfinite(x)) return 1.0;
    double e = floor(log10(x));
    double p = pow(10.0, e);
    double f = x / p, nf;
    if (round) nf = f < 1.5 ? 1.0 : (f < 3.0 ? 2.0 : (f < 7.0 ? 5.0 : 10.0));
    else nf = f <= 1.0 ? 1.0 : (f <= 2.0 ? 2.0 : (f <= 5.0 ? 5.0 : 10.0));
    return nf * p;
}

int pl_nice_levels(double vmin, double vmax, int count, double *out, int cap, double *step) {
    if (step) *step = 0.0;
    if (!(vmax > vmin) || count < 1 || !isfinite(vmin) || !isfinite(vmax)) return 0;
    double range = vmax - vmin;
    double raw = range / (count + 1);
    double e = floor(log10(raw)), p = pow(10.0, e), f = raw / p;
    /* candidate mantissas 1, 2, 2.5, 5, 10: the closest to the raw step */
    static const double m[] = {1.0, 2.0, 2.5, 5.0, 10.0};
    double best = m[0];
    for (int i = 1; i < 5; i++)
        if (fabs(log(m[i] / f)) < fabs(log(best / f))) best = m[i];
    double d = best * p;
    if (step) *step = d;
    double first = ceil(vmin / d) * d;
    int n = 0;
    for (int i = 0; n < cap && i < 10000; i++) {
        double lv = first + i * d;
        if (fabs(lv) < 1e-9 * d) lv = 0.0; /* avoid -0 and 1e-17 */
        if (lv >= vmax - 1e-9 * d) break;
        if (lv <= vmin + 1e-9 * d) continue;
        out[n++] = lv;
    }
    return n;
}
