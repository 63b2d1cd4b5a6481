/* Porosity and permeability of each element from the grains covering it (seed 000 §3.6).
 * Solid area per element: exact (triangle clipped by convex polygons, circle-triangle
 * intersection for discs; default) or the thesis's pixellation (pixel centres tested against
 * the element and the grains, union of grains, resolution settable). The void ratio
 * e = (A - A_s) / A_s (eq. 3.9) is clamped to 0.01..99 and mapped to a conductivity by
 * Kozeny-Carman e^3 / (1 + e) (eq. 3.8) between FLUID_PERM_LOW and FLUID_PERM_HIGH. */
#include "core/alloc.h"
#include "fluid/darcy/darcy_internal.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double cross(pl_vec2 a, pl_vec2 b) { return a.x * b.y - a.y * b.x; }

/* Signed area of disc(0, r) intersected with triangle (0, a, b). The chord a-b meets the
   circle at parameters t1 <= t2; clamping them to [0, 1] covers every case (ends inside,
   outside or exactly on the circle) with one formula: sector + triangle + sector. */
static double sector(pl_vec2 u, pl_vec2 v, double r2) {
    return 0.5 * r2 * atan2(cross(u, v), u.x * v.x + u.y * v.y);
}

static double tri_circle_signed(pl_vec2 a, pl_vec2 b, double r) {
    const double r2 = r * r;
    pl_vec2 d = {b.x - a.x, b.y - a.y};
    double A = d.x * d.x + d.y * d.y;
    if (A <= 0) return 0;
    double B = a.x * d.x + a.y * d.y, C = a.x * a.x + a.y * a.y - r2;
    double disc = B * B - A * C;
    if (disc <= 0) return sector(a, b, r2); /* the line misses the disc */
    double sq = sqrt(disc);
    double t1 = (-B - sq) / A, t2 = (-B + sq) / A;
    if (t1 < 0) t1 = 0;
    if (t2 > 1) t2 = 1;
    if (t1 >= t2) return sector(a, b, r2); /* the chord lies outside the disc */
    pl_vec2 p1 = {a.x + t1 * d.x, a.y + t1 * d.y}, p2 = {a.x + t2 * d.x, a.y + t2 * d.y};
    if (t1 == 0) p1 = a;
    if (t2 == 1) p2 = b;
    return sector(a, p1, r2) + 0.5 * cross(p1, p2) + sector(p2, b, r2);
}

double pl_fl_tri_disc_area(const pl_vec2 t[3], pl_vec2 c, double r) {
    double s = 0;
    for (int k = 0; k < 3; k++) {
        pl_vec2 a = {t[k].x - c.x, t[k].y - c.y}, b = {t[(k + 1) % 3].x - c.x, t[(k + 1) % 3].y - c.y};
        s += tri_circle_signed(a, b, r);
    }
    return fabs(s);
}

#define CLIP_MAX (2 * PL_MAX_POLY_VERTICES_FL + 8)
#define PL_MAX_POLY_VERTICES_FL 64

/* Area of a convex polygon (counter-clockwise) clipped by a triangle (Sutherland-Hodgman). */
double pl_fl_tri_poly_area(const pl_vec2 t[3], const pl_vec2 *v, int n) {
    pl_vec2 buf[2][CLIP_MAX];
    int cnt = n < CLIP_MAX - 4 ? n : CLIP_MAX - 4;
    memcpy(buf[0], v, sizeof(pl_vec2) * (size_t)cnt);
    int cur = 0;
    for (int k = 0; k < 3 && cnt > 0; k++) {
        pl_vec2 a = t[k], b = t[(k + 1) % 3];
        pl_vec2 ab = {b.x - a.x, b.y - a.y};
        const pl_vec2 *in = buf[cur];
        pl_vec2 *out = buf[1 - cur];
        int m = 0;
        for (int i = 0; i < cnt; i++) {
            pl_vec2 p = in[i], q = in[(i + 1) % cnt];
            double sp = cross(ab, (pl_vec2){p.x - a.x, p.y - a.y});
            double sq = cross(ab, (pl_vec2){q.x - a.x, q.y - a.y});
            if (sp >= 0) out[m++] = p;
            if ((sp >= 0) != (sq >= 0)) {
                double u = sp / (sp - sq);
                out[m++] = (pl_vec2){p.x + u * (q.x - p.x), p.y + u * (q.y - p.y)};
            }
            if (m >= CLIP_MAX - 1) break;
        }
        cnt = m;
        cur = 1 - cur;
    }
    double a2 = 0;
    for (int i = 0; i < cnt; i++) a2 += cross(buf[cur][i], buf[cur][(i + 1) % cnt]);
    return a2 > 0 ? 0.5 * a2 : 0;
}

double pl_fl_porosity_3d(double n2d) {
    /* DESIGN §3: maps hexagonal discs (n2 = 0.0931) to FCC spheres (n3 = 0.2595) */
    double s = 1 - n2d;
    if (s < 0) s = 0;
    return 1 - 2.0 / sqrt(PL_FL_PI * sqrt(3.0)) * s * sqrt(s);
}

static double kc(double e) { return e * e * e / (1 + e); }

double pl_fl_kc_map(const pl_fl_params *p, double e) {
    if (p->kc_mode == 1) {
        double k = p->kc_c1 * kc(e);
        return k < p->perm_low ? p->perm_low : (k > p->perm_high ? p->perm_high : k);
    }
    double f0 = kc(0.01), f1 = kc(99.0);
    return p->perm_low + (p->perm_high - p->perm_low) * (kc(e) - f0) / (f1 - f0);
}

static int point_in_body(const pl_fl_bodies *b, int i, pl_vec2 p) {
    if (b->shape[i] == PL_SHAPE_DISC) {
        double dx = p.x - b->pos[i].x, dy = p.y - b->pos[i].y;
        return dx * dx + dy * dy <= b->radius[i] * b->radius[i];
    }
    const pl_vec2 *v = &b->verts[b->vert_offset[i]];
    int n = b->vert_count[i];
    for (int k = 0; k < n; k++) {
        pl_vec2 a = v[k], c = v[(k + 1) % n];
        if ((c.x - a.x) * (p.y - a.y) - (c.y - a.y) * (p.x - a.x) < 0) return 0;
    }
    return 1;
}

static int push_cover(struct pl_fluid *f, int body, int elem, double area, int outside) {
    if (f->ncover == f->cover_cap) {
        int nc = f->cover_cap ? 2 * f->cover_cap : 4096;
        pl_fl_cover *p = pl_realloc(f->cover, sizeof(pl_fl_cover) * (size_t)nc);
        if (!p) return 0;
        f->cover = p;
        f->cover_cap = nc;
    }
    f->cover[f->ncover++] = (pl_fl_cover){body, elem, area, outside};
    return 1;
}

/* Pixel solid areas for the candidate pairs of one element (union of grains). */
static void pixel_element(struct pl_fluid *f, const pl_fl_bodies *b, int e, int c0, int c1, int32_t *pair_of) {
    const pl_mesh *m = &f->mesh;
    const int32_t *v = &m->tri[3 * e];
    pl_vec2 t0 = m->xy[v[0]], t1 = m->xy[v[1]], t2 = m->xy[v[2]];
    double lx = fmin(t0.x, fmin(t1.x, t2.x)), hx = fmax(t0.x, fmax(t1.x, t2.x));
    double ly = fmin(t0.y, fmin(t1.y, t2.y)), hy = fmax(t0.y, fmax(t1.y, t2.y));
    double side = fmax(hx - lx, hy - ly) / f->par.pixels;
    int nx = (int)ceil((hx - lx) / side), ny = (int)ceil((hy - ly) / side);
    double pa = side * side;
    int in_tri = 0, solid = 0;
    for (int k = c0; k < c1; k++) f->cover[pair_of[k]].area = 0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            pl_vec2 p = {lx + (i + 0.5) * side, ly + (j + 0.5) * side};
            double l[3];
            pl_mesh_barycentric(m, e, p, l);
            if (l[0] < 0 || l[1] < 0 || l[2] < 0) continue;
            in_tri++;
            int hit = 0;
            for (int k = c0; k < c1; k++) {
                pl_fl_cover *cv = &f->cover[pair_of[k]];
                if (point_in_body(b, cv->body, p)) {
                    if (!hit) cv->area += pa; /* a pixel counts once, for the first grain */
                    hit = 1;
                }
            }
            solid += hit;
        }
    /* the thesis measures the element area with the same pixels (eq. 3.9); scale to the
       exact area so that the ratio solid/element is the pixel ratio */
    double scale = in_tri > 0 ? m->area[e] / (in_tri * pa) : 0;
    for (int k = c0; k < c1; k++) f->cover[pair_of[k]].area *= scale;
    f->solid[e] = solid * pa * scale;
}


/* Length of segment a-b inside the body (disc c, r or convex counter-clockwise polygon v, n), and
   the fraction t0..t1 of a-b where it is. */
static double chord_body(pl_vec2 a, pl_vec2 b, pl_vec2 c, double r, const pl_vec2 *v, int n) {
    pl_vec2 d = {b.x - a.x, b.y - a.y};
    double L2 = d.x * d.x + d.y * d.y, t0 = 0, t1 = 1;
    if (!(L2 > 0)) return 0;
    if (!v) {
        pl_vec2 o = {a.x - c.x, a.y - c.y};
        double B = o.x * d.x + o.y * d.y, C = o.x * o.x + o.y * o.y - r * r, disc = B * B - L2 * C;
        if (disc <= 0) return 0;
        double sq = sqrt(disc);
        t0 = fmax(0, (-B - sq) / L2);
        t1 = fmin(1, (-B + sq) / L2);
    } else {
        if (!pl_fl_clip_segment_convex(a, d, v, n, &t0, &t1)) return 0;
    }
    return t1 > t0 ? (t1 - t0) * sqrt(L2) : 0;
}

/* Edge q of element e lies on the mesh boundary: nothing of the mesh just beyond its midpoint. */
static int boundary_edge(const pl_mesh *m, int e, int q) {
    const int32_t *v = &m->tri[3 * e];
    pl_vec2 P = m->xy[v[q]], Q = m->xy[v[(q + 1) % 3]];
    /* outward normal of a counter-clockwise edge: (dy, -dx) */
    const double eps = 1e-7;
    pl_vec2 x = {0.5 * (P.x + Q.x) + eps * (Q.y - P.y), 0.5 * (P.y + Q.y) - eps * (Q.x - P.x)};
    return pl_mesh_locate(m, x) < 0;
}

/* Grains pressed into a wall at the mesh's edge (docs/fluid.md §6.1). A contact overlap is the
   soft-contact stand-in for a point contact: the grain does not really reach into the wall, the
   water surrounds it up to the contact, and it displaces its whole area. The body is such a grain
   when, on every boundary edge it crosses, its depth beyond the edge is at most PL_FL_EDGE_SLIVER
   of its thickness across the edge. Found from the mesh alone (any porosity method, with or
   without pieces cut): the boundary elements are met in the order the porosity update meets them
   (grid cells row by row, an element in the first cell of its box within the range). */
int pl_fl_edge_elements(const pl_mesh *m, pl_vec2 c, double r, const pl_vec2 *pv, int pn, int32_t *elem, double *wt,
                        int cap) {
    pl_vec2 lo = {c.x - r, c.y - r}, hi = {c.x + r, c.y + r};
    if (pv) {
        lo = hi = pv[0];
        for (int k = 1; k < pn; k++) {
            lo.x = fmin(lo.x, pv[k].x); lo.y = fmin(lo.y, pv[k].y);
            hi.x = fmax(hi.x, pv[k].x); hi.y = fmax(hi.y, pv[k].y);
        }
    }
    int i0, j0, i1, j1;
    if (!pl_mesh_grid_range(m, lo, hi, &i0, &j0, &i1, &j1)) return 0;
    int n = 0;
    for (int gj = j0; gj <= j1; gj++)
        for (int gi = i0; gi <= i1; gi++) {
            size_t cell = (size_t)gj * m->gx + gi;
            for (int k = m->cell_start[cell]; k < m->cell_start[cell + 1]; k++) {
                const int e = m->cell_items[k];
                const double *tb = &m->tri_box[4 * e];
                if (tb[2] < lo.x || tb[0] > hi.x || tb[3] < lo.y || tb[1] > hi.y) continue;
                const int ti0 = m->tri_cell0[2 * e], tj0 = m->tri_cell0[2 * e + 1];
                if (gi != (ti0 > i0 ? ti0 : i0) || gj != (tj0 > j0 ? tj0 : j0)) continue;
                const int32_t *v = &m->tri[3 * e];
                double w = 0;
                for (int q = 0; q < 3; q++) {
                    pl_vec2 P = m->xy[v[q]], Q = m->xy[v[(q + 1) % 3]];
                    double ch = chord_body(P, Q, c, r, pv, pn);
                    if (!(ch > 0) || !boundary_edge(m, e, q)) continue;
                    double L = hypot(Q.x - P.x, Q.y - P.y);
                    pl_vec2 nn = {(Q.y - P.y) / L, -(Q.x - P.x) / L}; /* outward */
                    double out, th;
                    if (!pv) {
                        out = (c.x - P.x) * nn.x + (c.y - P.y) * nn.y + r;
                        th = 2 * r;
                    } else {
                        double shi = -INFINITY, slo = INFINITY;
                        for (int j = 0; j < pn; j++) {
                            double sj = (pv[j].x - P.x) * nn.x + (pv[j].y - P.y) * nn.y;
                            shi = fmax(shi, sj);
                            slo = fmin(slo, sj);
                        }
                        out = shi;
                        th = shi - slo;
                    }
                    if (out > PL_FL_EDGE_SLIVER * th) return 0; /* crosses the boundary as a solid */
                    w += ch;
                }
                if (w > 0 && n < cap) {
                    elem[n] = e;
                    wt[n] = w;
                    n++;
                }
            }
        }
    return n;
}

/* The part of body i beyond the mesh boundary when it is a grain pressed into a wall at the
   mesh's edge (pl_fl_edge_elements): its area, A_body - sum of its pieces, is added as pieces
   flagged outside to the boundary elements whose boundary edges the body crosses, shared by the
   length of the body on each edge. Forces (Gauss form and the outline integral, which extends the
   field of those elements beyond the boundary), drag, solid area and the consolidation source
   then all see the whole grain, as they would if the mesh went on past the wall. A body reaching
   deeper (piston, lid, wall slab) keeps p = 0 beyond the boundary. With pixel areas the pieces
   are the pixel counts, so the outside part is A_body less those (a pixel estimate of it).
   Returns 0 only when out of memory. */
static int fold_outside(struct pl_fluid *f, const pl_fl_bodies *b, int i, const pl_vec2 *pv, int pn) {
    const pl_mesh *m = &f->mesh;
    const int k0 = f->body_cover_start[i], k1 = f->ncover; /* body i's pieces are the last ones */
    if (k0 == k1) return 1; /* wholly outside the mesh (or no area): nothing to fold */
    const int pixel = f->par.porosity_method == 1;
    const pl_vec2 c = b->pos[i];
    const double r = b->radius[i];
    double A = 0;
    if (!pv) A = PL_FL_PI * r * r;
    else
        for (int k = 0; k < pn; k++) A += 0.5 * (pv[k].x * pv[(k + 1) % pn].y - pv[(k + 1) % pn].x * pv[k].y);
    int32_t el[PL_FL_EDGE_MAX];
    double w[PL_FL_EDGE_MAX];
    int n = 0;
    if (pixel) { /* candidates only so far: first whether it is an edge grain at all */
        n = pl_fl_edge_elements(m, c, r, pv, pn, el, w, PL_FL_EDGE_MAX);
        if (n == 0) return 1;
    }
    double ain = 0;
    for (int k = k0; k < k1; k++) {
        if (!pixel) { ain += f->cover[k].area; continue; }
        const int32_t *v = &m->tri[3 * f->cover[k].elem];
        pl_vec2 t[3] = {m->xy[v[0]], m->xy[v[1]], m->xy[v[2]]};
        ain += pv ? pl_fl_tri_poly_area(t, pv, pn) : pl_fl_tri_disc_area(t, c, r);
    }
    const double aout = A - ain;
    if (!(aout > 1e-12 * A)) return 1;
    if (!pixel) n = pl_fl_edge_elements(m, c, r, pv, pn, el, w, PL_FL_EDGE_MAX);
    double wsum = 0;
    for (int k = 0; k < n; k++) wsum += w[k];
    if (!(wsum > 0)) return 1;
    for (int k = 0; k < n; k++) {
        double a = aout * w[k] / wsum;
        if (!pixel) f->solid[el[k]] += a; /* pixel areas: added after the pixel pass */
        if (!push_cover(f, i, el[k], a, 1)) return 0;
    }
    return 1;
}

pl_status pl_fl_update_porosity(struct pl_fluid *f, const pl_fl_bodies *b) {
    const pl_mesh *m = &f->mesh;
    double t0 = pl_fl_now();
    memset(f->solid, 0, sizeof(double) * (size_t)m->ne);
    f->ncover = 0;
    f->cover_bodies = 0;
    if (b->n + 1 > f->body_cap) {
        int nc = b->n + 1 + 64;
        int32_t *p = pl_realloc(f->body_cover_start, sizeof(int32_t) * (size_t)nc);
        if (!p) return PL_ERR_NOMEM;
        f->body_cover_start = p;
        double *q = pl_realloc(f->cover_xyr, sizeof(double) * 3 * (size_t)nc);
        if (!q) return PL_ERR_NOMEM;
        f->cover_xyr = q;
        f->body_cap = nc;
    }
    for (int i = 0; i < b->n; i++) {
        f->body_cover_start[i] = f->ncover;
        int sh = b->shape[i];
        if (sh != PL_SHAPE_DISC && sh != PL_SHAPE_POLYGON) continue;
        pl_vec2 c = b->pos[i];
        double r = b->radius[i];
        pl_vec2 lo = {c.x - r, c.y - r}, hi = {c.x + r, c.y + r};
        const pl_vec2 *pv = NULL;
        int pn = 0;
        if (sh == PL_SHAPE_POLYGON) {
            pv = &b->verts[b->vert_offset[i]];
            pn = b->vert_count[i];
            lo = hi = pv[0];
            for (int k = 1; k < pn; k++) {
                lo.x = fmin(lo.x, pv[k].x); lo.y = fmin(lo.y, pv[k].y);
                hi.x = fmax(hi.x, pv[k].x); hi.y = fmax(hi.y, pv[k].y);
            }
        }
        int i0, j0, i1, j1;
        if (!pl_mesh_grid_range(m, lo, hi, &i0, &j0, &i1, &j1)) continue;
        if (f->stamp_gen >= 2000000000) {
            memset(f->stamp, 0, sizeof(int32_t) * (size_t)m->ne);
            f->stamp_gen = 0;
        }
        const int32_t gen = ++f->stamp_gen;
        for (int gj = j0; gj <= j1; gj++)
            for (int gi = i0; gi <= i1; gi++) {
                size_t cell = (size_t)gj * m->gx + gi;
                for (int k = m->cell_start[cell]; k < m->cell_start[cell + 1]; k++) {
                    int e = m->cell_items[k];
                    const double *tb = &m->tri_box[4 * e];
                    if (tb[2] < lo.x || tb[0] > hi.x || tb[3] < lo.y || tb[1] > hi.y) continue;
                    /* an element spanning several cells is met once per cell: keep the first */
                    if (f->stamp[e] == gen) continue;
                    f->stamp[e] = gen;
                    const int32_t *v = &m->tri[3 * e];
                    pl_vec2 t[3] = {m->xy[v[0]], m->xy[v[1]], m->xy[v[2]]};
                    double a = 1; /* pixel method: computed per element below */
                    if (f->par.porosity_method == 0) {
                        if (sh == PL_SHAPE_DISC) {
                            /* distances of the centre to the edges decide the two cheap cases
                               (wholly outside: no piece; wholly inside: the whole disc) before the
                               closed form, which spends up to nine atan2 on a triangle */
                            int inside = 1, outside = 0;
                            for (int q = 0; q < 3; q++) {
                                pl_vec2 P = t[q], Q = t[(q + 1) % 3];
                                double dq = ((Q.x - P.x) * (c.y - P.y) - (Q.y - P.y) * (c.x - P.x)) /
                                            m->edge_len[3 * e + q];
                                if (dq <= -r) { outside = 1; break; }
                                if (dq < r) inside = 0;
                            }
                            if (outside) continue;
                            a = inside ? PL_FL_PI * r * r : pl_fl_tri_disc_area(t, c, r);
                        } else {
                            a = pl_fl_tri_poly_area(t, pv, pn);
                        }
                        if (!(a > 0)) continue;
                        f->solid[e] += a;
                    }
                    if (!push_cover(f, i, e, a, 0)) return PL_ERR_NOMEM;
                }
            }
        if (!fold_outside(f, b, i, pv, pn)) return PL_ERR_NOMEM;
    }
    f->body_cover_start[b->n] = f->ncover;
    f->cover_bodies = b->n;
    /* the state the covers belong to (the disc force reuses them while it is unchanged) */
    for (int i = 0; i < b->n; i++) {
        f->cover_xyr[3 * i] = b->pos[i].x;
        f->cover_xyr[3 * i + 1] = b->pos[i].y;
        f->cover_xyr[3 * i + 2] = b->radius[i];
    }
    if (f->par.porosity_method == 1 && f->ncover > 0) {
        /* group pairs by element (counting sort) and pixellate each element once; the
           scratch arrays are kept in the model and grow only when needed */
        if (f->pix_cap < f->ncover) {
            int32_t *p = pl_realloc(f->pix_pair, sizeof(int32_t) * (size_t)f->cover_cap);
            if (!p) return PL_ERR_NOMEM;
            f->pix_pair = p;
            f->pix_cap = f->cover_cap;
        }
        if (!f->pix_cnt) {
            f->pix_cnt = pl_malloc(sizeof(int32_t) * (size_t)(m->ne + 1));
            f->pix_fill = pl_malloc(sizeof(int32_t) * (size_t)m->ne);
            if (!f->pix_cnt || !f->pix_fill) return PL_ERR_NOMEM;
        }
        int32_t *cnt = f->pix_cnt, *fill = f->pix_fill, *pair_of = f->pix_pair;
        memset(cnt, 0, sizeof(int32_t) * (size_t)(m->ne + 1));
        /* pieces flagged outside (beyond the mesh boundary) have their area already */
        for (int k = 0; k < f->ncover; k++)
            if (!f->cover[k].outside) cnt[f->cover[k].elem + 1]++;
        for (int e = 0; e < m->ne; e++) cnt[e + 1] += cnt[e];
        memcpy(fill, cnt, sizeof(int32_t) * (size_t)m->ne);
        for (int k = 0; k < f->ncover; k++)
            if (!f->cover[k].outside) pair_of[fill[f->cover[k].elem]++] = k;
        for (int e = 0; e < m->ne; e++)
            if (cnt[e + 1] > cnt[e]) pixel_element(f, b, e, cnt[e], cnt[e + 1], pair_of);
        for (int k = 0; k < f->ncover; k++)
            if (f->cover[k].outside) f->solid[f->cover[k].elem] += f->cover[k].area;
    }
    /* void ratio (eq. 3.9) with the thesis's clamp 0.01 A <= A_s <= 0.99 A */
    for (int e = 0; e < m->ne; e++) {
        double A = m->area[e], As = f->solid[e];
        if (As < 0.01 * A) As = 0.01 * A;
        if (As > 0.99 * A) As = 0.99 * A;
        double e2 = (A - As) / As;
        f->voidr[e] = e2;
        double n = 1 - As / A;
        if (f->par.porosity_map == 1) n = pl_fl_porosity_3d(n);
        f->porosity[e] = n;
    }
    f->stats.t_porosity += pl_fl_now() - t0;
    return PL_OK;
}

void pl_fl_update_permeability(struct pl_fluid *f) {
    const pl_fl_params *p = &f->par;
    const int ne = f->mesh.ne;
    double conv = p->perm_units == 1 ? p->density * p->g / p->viscosity : 1.0;
    for (int e = 0; e < ne; e++) {
        double k;
        if (p->perm_mode == 1) {
            double n = f->porosity[e];
            double ev = n / (1 - n);
            if (ev < 0.01) ev = 0.01;
            if (ev > 99) ev = 99;
            k = pl_fl_kc_map(p, ev);
        } else if (p->perm_mode == 2 && f->perm_user) {
            k = f->perm_user[e];
        } else {
            k = p->perm_high;
        }
        k *= conv;
        f->perm[e] = k;
        if (k != f->perm_assembled[e]) f->k_dirty = 1;
    }
    if (p->mass_consistent != f->assembled_par.mass_consistent) f->k_dirty = 1;
}
