/* Overlap kernels (see clip.h). All kernels work in coordinates relative to the first
 * vertex of the first outline, so bodies far from the origin keep their precision. */
#include "geom/clip.h"
#include "porelab/world.h"
#include <math.h>
#include <string.h>

#define PI_CLIP 3.14159265358979323846

_Static_assert(PL_CLIP_MAX_IN >= PL_MAX_POLY_VERTICES, "clip buffers smaller than a polygon body");

static inline pl_vec2 v_sub(pl_vec2 a, pl_vec2 b) { return (pl_vec2){a.x - b.x, a.y - b.y}; }
static inline pl_vec2 v_add(pl_vec2 a, pl_vec2 b) { return (pl_vec2){a.x + b.x, a.y + b.y}; }
static inline double v_dot(pl_vec2 a, pl_vec2 b) { return a.x * b.x + a.y * b.y; }
static inline double v_cross(pl_vec2 a, pl_vec2 b) { return a.x * b.y - a.y * b.x; }
static inline pl_vec2 v_lerp(pl_vec2 a, pl_vec2 b, double t) {
    return (pl_vec2){a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

double pl_clip_area_centroid(const pl_vec2 *v, int n, pl_vec2 *centroid) {
    if (n < 3) {
        if (centroid) *centroid = n > 0 ? v[0] : (pl_vec2){0, 0};
        return 0;
    }
    const pl_vec2 o = v[0];
    double a = 0, cx = 0, cy = 0;
    for (int i = 1; i + 1 < n; i++) {
        const pl_vec2 p = v_sub(v[i], o), q = v_sub(v[i + 1], o);
        const double cr = v_cross(p, q);
        a += cr;
        cx += (p.x + q.x) * cr;
        cy += (p.y + q.y) * cr;
    }
    if (centroid) *centroid = a != 0 ? (pl_vec2){o.x + cx / (3 * a), o.y + cy / (3 * a)} : o;
    return 0.5 * a;
}

/* One Sutherland-Hodgman pass with edge labels: lab[k] labels the edge v[k] -> v[k+1].
 * Keeps {x : (x - o) . nrm <= 0}; edges created along the clip line get line_label. */
static int clip_pass(const pl_vec2 *v, const int *lab, int n, pl_vec2 o, pl_vec2 nrm,
                     int line_label, pl_vec2 *ov, int *olab) {
    int m = 0;
    double dc = v_dot(v_sub(v[0], o), nrm);
    for (int k = 0; k < n; k++) {
        const int k1 = k + 1 < n ? k + 1 : 0;
        const double dn = v_dot(v_sub(v[k1], o), nrm);
        if (dc <= 0) {
            ov[m] = v[k];
            olab[m++] = lab[k];
            if (dn > 0) { /* leaving: the edge continues along the clip line */
                ov[m] = v_lerp(v[k], v[k1], dc / (dc - dn));
                olab[m++] = line_label;
            }
        } else if (dn < 0) { /* entering: the edge from the entry point is part of edge k */
            ov[m] = v_lerp(v[k], v[k1], dc / (dc - dn));
            olab[m++] = lab[k];
        }
        dc = dn;
    }
    return m;
}

/* Removes repeated vertices (closer than tol) from a labelled cyclic list; a merged vertex
 * keeps the label of the last edge leaving it (the zero-length edges vanish). */
static int dedupe(pl_vec2 *v, int *lab, int n, double tol) {
    if (n == 0) return 0;
    const double t2 = tol * tol;
    int m = 1;
    for (int k = 1; k < n; k++) {
        const pl_vec2 d = v_sub(v[k], v[m - 1]);
        if (v_dot(d, d) <= t2) {
            lab[m - 1] = lab[k];
        } else {
            v[m] = v[k];
            lab[m++] = lab[k];
        }
    }
    while (m > 1) {
        const pl_vec2 d = v_sub(v[m - 1], v[0]);
        if (v_dot(d, d) > t2) break;
        /* the last vertex coincides with the first: drop it; its edge was zero length */
        m--;
    }
    return m;
}

static double extent(const pl_vec2 *p, int n, pl_vec2 o) {
    double e = 0;
    for (int i = 0; i < n; i++) {
        const pl_vec2 d = v_sub(p[i], o);
        e = fmax(e, fmax(fabs(d.x), fabs(d.y)));
    }
    return e;
}

/* Records the crossing points (vertices where the label owner changes) and picks the pair
 * farthest apart. owner(l) = l >= 0. */
static void find_crossings(const pl_vec2 *v, const int *lab, int n, pl_vec2 o, pl_overlap *out) {
    out->cross_n = 0;
    for (int k = 0; k < n; k++) {
        const int in = lab[k > 0 ? k - 1 : n - 1], ou = lab[k];
        if ((in >= 0) != (ou >= 0)) {
            if (out->cross_n < PL_CLIP_MAX_CROSS) out->cross[out->cross_n] = v_add(v[k], o);
            out->cross_n++;
        }
    }
    out->p1 = out->p2 = out->centroid;
    out->chord = 0;
    const int nc = out->cross_n < PL_CLIP_MAX_CROSS ? out->cross_n : PL_CLIP_MAX_CROSS;
    double best = -1;
    for (int i = 0; i < nc; i++)
        for (int j = i + 1; j < nc; j++) {
            const pl_vec2 d = v_sub(out->cross[j], out->cross[i]);
            const double l2 = v_dot(d, d);
            if (l2 > best) { best = l2; out->p1 = out->cross[i]; out->p2 = out->cross[j]; }
        }
    if (best > 0) out->chord = sqrt(best);
}

static void clear(pl_overlap *out) {
    out->area = 0;
    out->centroid = (pl_vec2){0, 0};
    out->cross_n = 0;
    out->p1 = out->p2 = (pl_vec2){0, 0};
    out->chord = 0;
    out->chord_vec = (pl_vec2){0, 0};
    out->n = 0;
}

double pl_clip_convex(const pl_vec2 *p, int np, const pl_vec2 *q, int nq, pl_overlap *out) {
    clear(out);
    if (np < 3 || nq < 3 || np > PL_CLIP_MAX_IN || nq > PL_CLIP_MAX_IN) return 0;
    const pl_vec2 o = p[0];
    pl_vec2 bufa[PL_CLIP_MAX_OUT], bufb[PL_CLIP_MAX_OUT], ql[PL_CLIP_MAX_IN];
    int laba[PL_CLIP_MAX_OUT], labb[PL_CLIP_MAX_OUT];
    for (int i = 0; i < np; i++) { bufa[i] = v_sub(p[i], o); laba[i] = i; }
    for (int j = 0; j < nq; j++) ql[j] = v_sub(q[j], o);
    pl_vec2 *cur = bufa, *nxt = bufb;
    int *lc = laba, *ln = labb;
    int n = np;
    for (int j = 0; j < nq && n > 0; j++) {
        const pl_vec2 a = ql[j], b = ql[j + 1 < nq ? j + 1 : 0];
        const pl_vec2 nrm = {b.y - a.y, a.x - b.x}; /* outward normal of a CCW edge */
        n = clip_pass(cur, lc, n, a, nrm, -1 - j, nxt, ln);
        pl_vec2 *t = cur; cur = nxt; nxt = t;
        int *tl = lc; lc = ln; ln = tl;
    }
    /* round-off of the clipped points scales with their distance from o */
    double scale = 0;
    for (int k = 0; k < n; k++) {
        const double ax = fabs(cur[k].x), ay = fabs(cur[k].y);
        scale = ax > scale ? ax : scale;
        scale = ay > scale ? ay : scale;
    }
    n = dedupe(cur, lc, n, 1e-13 * scale);
    if (n < 3) return 0;
    pl_vec2 c;
    const double area = pl_clip_area_centroid(cur, n, &c);
    if (!(area > 0)) return 0;
    out->area = area;
    out->centroid = v_add(c, o);
    out->n = n;
    pl_vec2 sum = {0, 0};
    for (int k = 0; k < n; k++) {
        out->v[k] = v_add(cur[k], o);
        if (lc[k] >= 0) sum = v_add(sum, v_sub(cur[k + 1 < n ? k + 1 : 0], cur[k]));
    }
    out->chord_vec = sum;
    find_crossings(cur, lc, n, o, out);
    return area;
}

/* Signed sector of radius r between directions u and v (relative to the centre): area and
 * first moment about the centre. */
static void sector(pl_vec2 u, pl_vec2 v, double r, double *area, pl_vec2 *mom) {
    const double ang = atan2(v_cross(u, v), v_dot(u, v));
    const double lu = sqrt(v_dot(u, u)), lv = sqrt(v_dot(v, v));
    if (lu == 0 || lv == 0) return;
    const pl_vec2 uh = {u.x / lu, u.y / lu}, vh = {v.x / lv, v.y / lv};
    *area += 0.5 * r * r * ang;
    const double k = r * r * r / 3.0;
    mom->x += k * (vh.y - uh.y);
    mom->y += k * (uh.x - vh.x);
}

static void triangle(pl_vec2 u, pl_vec2 v, double *area, pl_vec2 *mom) {
    const double a = 0.5 * v_cross(u, v);
    *area += a;
    mom->x += a * (u.x + v.x) / 3.0;
    mom->y += a * (u.y + v.y) / 3.0;
}

/* Consecutive sectors of the outline (its parts outside the circle) merged into one: seen from
 * a centre strictly outside the convex polygon, any two directions to points of its outline are
 * less than pi apart, so the sum of the chain's signed angles is the single atan2 between its
 * first and last directions, and the first moments telescope (sector() adds r^3/3 times the
 * difference of the unit directions). A slab or block touched by a grain then costs one atan2
 * instead of one per edge. */
typedef struct sector_chain {
    int open;
    pl_vec2 u0, u1; /* first and last direction of the chain */
} sector_chain;

static void chain_add(sector_chain *ch, pl_vec2 u, pl_vec2 v) {
    if (!ch->open) { ch->u0 = u; ch->open = 1; }
    ch->u1 = v;
}

double pl_clip_disc(pl_vec2 c, double r, const pl_vec2 *p, int np, pl_overlap *out) {
    clear(out);
    if (np < 3 || !(r > 0)) return 0;
    double area = 0;
    pl_vec2 mom = {0, 0}, sum = {0, 0};
    const double r2 = r * r;
    int nc = 0, inside_pieces = 0, centre_inside = 1;
    pl_vec2 cross[PL_CLIP_MAX_CROSS];
    for (int i = 0; i < np && centre_inside; i++) {
        const pl_vec2 a = v_sub(p[i], c), d = v_sub(p[i + 1 < np ? i + 1 : 0], p[i]);
        if (v_cross(d, (pl_vec2){-a.x, -a.y}) < 0) centre_inside = 0;
    }
    /* centre strictly outside: sectors merged into chains (the first chain, which may continue
       the last one around the outline's start, is held back to be joined with it) */
    const int merge = !centre_inside;
    sector_chain ch = {0}, head = {0};
    int have_head = 0;
    for (int i = 0; i < np; i++) {
        const pl_vec2 a = v_sub(p[i], c), b = v_sub(p[i + 1 < np ? i + 1 : 0], c);
        const pl_vec2 d = v_sub(b, a);
        const double qa = v_dot(d, d);
        if (qa == 0) continue;
        const double qb = v_dot(a, d), qc = v_dot(a, a) - r2;
        const double disc = qb * qb - qa * qc; /* quarter discriminant */
        double t1 = 1, t2 = 0;                 /* inside part [t1, t2] of the edge */
        if (disc > 0) {
            const double s = sqrt(disc);
            /* numerically stable roots of qa t^2 + 2 qb t + qc = 0 */
            const double qq = qb >= 0 ? -(qb + s) : -(qb - s);
            double r1 = qq / qa, rr2 = qq != 0 ? qc / qq : r1;
            if (r1 > rr2) { const double t = r1; r1 = rr2; rr2 = t; }
            t1 = fmax(r1, 0.0);
            t2 = fmin(rr2, 1.0);
            if (r1 >= 0 && r1 < 1) { if (nc < PL_CLIP_MAX_CROSS) cross[nc] = v_lerp(a, b, r1); nc++; }
            if (rr2 >= 0 && rr2 < 1) { if (nc < PL_CLIP_MAX_CROSS) cross[nc] = v_lerp(a, b, rr2); nc++; }
        }
        if (t1 < t2) {
            const pl_vec2 e1 = v_lerp(a, b, t1), e2 = v_lerp(a, b, t2);
            if (!merge) {
                if (t1 > 0) sector(a, e1, r, &area, &mom);
            } else {
                if (t1 > 0) chain_add(&ch, a, e1);
                if (ch.open) { /* the chain ends where the edge enters the circle */
                    if (!have_head && inside_pieces == 0) { head = ch; have_head = 1; }
                    else sector(ch.u0, ch.u1, r, &area, &mom);
                    ch.open = 0;
                }
            }
            triangle(e1, e2, &area, &mom);
            sum = v_add(sum, v_sub(e2, e1));
            inside_pieces++;
            if (t2 < 1) {
                if (merge) chain_add(&ch, e2, b);
                else sector(e2, b, r, &area, &mom);
            }
        } else if (merge) {
            chain_add(&ch, a, b);
        } else {
            sector(a, b, r, &area, &mom);
        }
    }
    if (merge && inside_pieces > 0) {
        if (ch.open && have_head) sector(ch.u0, head.u1, r, &area, &mom); /* around the start */
        else {
            if (ch.open) sector(ch.u0, ch.u1, r, &area, &mom);
            if (have_head) sector(head.u0, head.u1, r, &area, &mom);
        }
    }
    if (inside_pieces == 0) {
        /* no edge runs inside the circle: the sectors sum to the whole disc when the centre
         * is inside the polygon and to zero (up to round-off) otherwise; decide exactly */
        if (!centre_inside) return 0;
        area = PI_CLIP * r2;
        mom = (pl_vec2){0, 0};
    }
    if (!(area > 0)) return 0;
    out->area = area;
    out->centroid = (pl_vec2){c.x + mom.x / area, c.y + mom.y / area};
    out->chord_vec = sum;
    out->cross_n = nc;
    const int m = nc < PL_CLIP_MAX_CROSS ? nc : PL_CLIP_MAX_CROSS;
    for (int k = 0; k < m; k++) out->cross[k] = v_add(cross[k], c);
    double best = -1;
    out->p1 = out->p2 = out->centroid;
    for (int i = 0; i < m; i++)
        for (int j = i + 1; j < m; j++) {
            const pl_vec2 d = v_sub(out->cross[j], out->cross[i]);
            if (v_dot(d, d) > best) { best = v_dot(d, d); out->p1 = out->cross[i]; out->p2 = out->cross[j]; }
        }
    if (best > 0) out->chord = sqrt(best);
    return area;
}

int pl_clip_halfplane(const pl_vec2 *p, int np, pl_vec2 o, pl_vec2 nrm, pl_vec2 *out) {
    int lab[PL_CLIP_MAX_OUT], olab[PL_CLIP_MAX_OUT];
    if (np > PL_CLIP_MAX_OUT - 1) return 0;
    for (int i = 0; i < np; i++) lab[i] = i;
    return clip_pass(p, lab, np, o, nrm, -1, out, olab);
}

double pl_clip_segment(const pl_vec2 *p, int np, pl_vec2 a, pl_vec2 b, pl_vec2 side,
                       pl_overlap *out, pl_vec2 *wall_normal) {
    clear(out);
    const pl_vec2 ab = v_sub(b, a);
    const double len = sqrt(v_dot(ab, ab));
    if (np < 3 || np > PL_CLIP_MAX_IN || !(len > 0)) return 0;
    const pl_vec2 u = {ab.x / len, ab.y / len};
    pl_vec2 nw = {-u.y, u.x};
    if (v_dot(v_sub(side, a), nw) < 0) nw = (pl_vec2){-nw.x, -nw.y};
    if (wall_normal) *wall_normal = nw;
    const pl_vec2 o = p[0];
    pl_vec2 bufa[PL_CLIP_MAX_OUT], bufb[PL_CLIP_MAX_OUT];
    int laba[PL_CLIP_MAX_OUT], labb[PL_CLIP_MAX_OUT];
    for (int i = 0; i < np; i++) { bufa[i] = v_sub(p[i], o); laba[i] = i; }
    const pl_vec2 al = v_sub(a, o), bl = v_sub(b, o);
    /* behind the wall line (label -1: the wall), then between the end perpendiculars
     * (labels -2, -3: not part of any outline, they only bound the wall's extent) */
    int n = clip_pass(bufa, laba, np, al, nw, -1, bufb, labb);
    n = clip_pass(bufb, labb, n, al, (pl_vec2){-u.x, -u.y}, -2, bufa, laba);
    n = clip_pass(bufa, laba, n, bl, u, -3, bufb, labb);
    const double scale = extent(p, np, o);
    n = dedupe(bufb, labb, n, 1e-13 * scale);
    if (n < 3) return 0;
    pl_vec2 cen;
    const double area = pl_clip_area_centroid(bufb, n, &cen);
    if (!(area > 0)) return 0;
    out->area = area;
    out->centroid = v_add(cen, o);
    out->n = n;
    /* The chord is the overlap's edge on the wall line; its ends are where the polygon's
     * outline crosses the wall (or the wall's end points when the polygon overhangs them). */
    pl_vec2 sum = {0, 0};
    out->cross_n = 0;
    for (int k = 0; k < n; k++) {
        out->v[k] = v_add(bufb[k], o);
        if (labb[k] == -1) {
            const pl_vec2 e0 = bufb[k], e1 = bufb[k + 1 < n ? k + 1 : 0];
            sum = v_add(sum, v_sub(e1, e0));
            if (out->cross_n + 2 <= PL_CLIP_MAX_CROSS) {
                out->cross[out->cross_n++] = v_add(e0, o);
                out->cross[out->cross_n++] = v_add(e1, o);
            }
        }
    }
    /* The chord vector runs along the polygon's part of the overlap outline, i.e. opposite
     * to the wall edge of the (counter-clockwise) overlap polygon. */
    out->chord_vec = (pl_vec2){-sum.x, -sum.y};
    if (out->cross_n >= 2) {
        out->p1 = out->cross[0];
        out->p2 = out->cross[1];
        out->chord = sqrt(v_dot(sum, sum));
    }
    return area;
}
