/* Area-based contact law for polygons with polygons, discs and wall segments (seed 004 §3;
 * equations, choices and validation in docs/contact-laws-polygons.md).
 *
 *   overlap region  exact: convex clipping, disc-polygon sectors, or the polygon beyond a wall
 *   normal n        perpendicular to the chord through the two points where the outlines
 *                   cross (seed 004 Fig. 2); computed as the rotated sum of the first body's
 *                   outline pieces inside the other, which equals p2 - p1 for two crossings
 *                   and is the area gradient in general (shared edges, several crossings)
 *   elastic         F_el = Y A / l_char, Y = k_N of the pair (N/m in 2D),
 *                   l_char = 4 |l1| |l2| / (|l1| + |l2|) (seed 004 eq. 1); wall: l_char = |l1|
 *   damping         F_da = c (dA/dt) / w, w the chord length, c = 2 zeta' sqrt(m_red k_eff)
 *                   with k_eff = Y w / l_char (or c = c_N given), |F_da| <= F_el (seed 004 eq. 2),
 *                   zeta' chosen so that a flat impact with the cutoff rebounds with the e given,
 *                   plus the couple of the same distributed dashpot, -(c w^2 / 12) (w_b - w_a)
 *                   (polygon-polygon and polygon-wall only)
 *   friction        incremental tangential spring k_t = k_S k_eff / k_N with the Coulomb cap
 *                   |F_t| <= mu F_el + c (return mapping; the regularized Coulomb law of
 *                   seed 002 §2.3.3), tangential dashpot while sticking as in the disc law
 *   point of action the overlap centroid S; moments with the lever arms S - C (Fig. 2); for a
 *                   disc, S projected onto the line through the disc's centre along n
 *   energy          stored: Winkler (Y / 2 l_char) int d(x)^2 dx (polygon overlaps); dissipated:
 *                   F_da dA / w per step, dashpot and couple work with start-of-step velocities
 * Conventions as contact_disc.c: n from a to b, t = (-n.y, n.x), force on b +F, on a -F. */
#include "dem/contact_polygon.h"
#include "geom/clip.h"
#include <math.h>

static inline double cross2(pl_vec2 r, pl_vec2 f) { return r.x * f.y - r.y * f.x; }
static inline double dot2(pl_vec2 a, pl_vec2 b) { return a.x * b.x + a.y * b.y; }
/* plain min/max and length: the library fmin/fmax/hypot are calls with NaN and overflow
 * handling this hot path does not need (non-finite states are stopped by the guards) */
static inline double mn(double a, double b) { return a < b ? a : b; }
static inline double mx(double a, double b) { return a > b ? a : b; }
static inline double len2(double x, double y) { return sqrt(x * x + y * y); }

static inline void untouch(pl_pair *p) {
    p->touching = 0;
    p->fs = 0;
    p->fn = 0;
    p->ft = 0;
    p->overlap = 0;
    p->area_prev = 0;
    p->elastic = 0;
}

/* Velocity of the material point of body i at x. */
static inline pl_vec2 point_velocity(const pl_world *w, int i, pl_vec2 x) {
    const pl_vec2 r = {x.x - w->pos[i].x, x.y - w->pos[i].y};
    return (pl_vec2){w->vel[i].x - w->omega[i] * r.y, w->vel[i].y + w->omega[i] * r.x};
}

/* Geometry of one contact, body a and b as in the pair (n from a to b). */
typedef struct geo {
    double area;   /* m^2 */
    pl_vec2 s;     /* overlap centroid */
    pl_vec2 n;     /* unit normal a -> b */
    double chord;  /* contact width w, m */
    double thick;  /* extent of the overlap region along n, m */
    double d2;     /* Winkler integral of the thickness squared, m^3 (< 0: not available) */
    int wall;      /* 1 when one of the bodies is a wall segment */
} geo;

/* Extent of the overlap polygon along n. */
static double thickness(const pl_overlap *o, pl_vec2 n) {
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < o->n; k++) {
        const double s = dot2(o->v[k], n);
        lo = mn(lo, s);
        hi = mx(hi, s);
    }
    return o->n > 0 ? hi - lo : 0;
}

/* Winkler integral of d(x)^2 over the contact: with springs of stiffness Y / l_char per unit
 * length across the width, each compressed by the local thickness d(x) of the overlap, the
 * resultant is (Y / l_char) int d dx = Y A / l_char (eq. 1, at the overlap centroid) and the
 * stored energy is (Y / 2 l_char) int d^2 dx. In coordinates x along t, y along n the convex
 * overlap splits at its leftmost and rightmost corners into two x-monotone chains; d is their
 * difference, linear between consecutive break points, so each piece integrates exactly:
 * dx (dl^2 + dl dr + dr^2) / 3. */
static double winkler_d2(const pl_overlap *o, pl_vec2 n) {
    const int m = o->n;
    if (m < 3 || m > PL_CLIP_MAX_OUT) return 0;
    const pl_vec2 t = {-n.y, n.x}, o0 = o->v[0];
    double x[PL_CLIP_MAX_OUT], y[PL_CLIP_MAX_OUT];
    int kmin = 0, kmax = 0;
    for (int k = 0; k < m; k++) {
        const pl_vec2 d = {o->v[k].x - o0.x, o->v[k].y - o0.y};
        x[k] = dot2(d, t);
        y[k] = dot2(d, n);
        if (x[k] < x[kmin]) kmin = k;
        if (x[k] > x[kmax]) kmax = k;
    }
    /* chain A walks forward from kmin to kmax, chain B backward */
    int ia = kmin, ib = kmin;
    int na = ia + 1 < m ? ia + 1 : 0, nb = ib > 0 ? ib - 1 : m - 1;
    double X = x[kmin], sum = 0;
    for (int guard = 0; guard < 2 * m && X < x[kmax]; guard++) {
        while (x[na] <= X && ia != kmax) { ia = na; na = ia + 1 < m ? ia + 1 : 0; }
        while (x[nb] <= X && ib != kmax) { ib = nb; nb = ib > 0 ? ib - 1 : m - 1; }
        if (ia == kmax || ib == kmax) break;
        const double X1 = mn(x[na], x[nb]);
        const double sa = (y[na] - y[ia]) / (x[na] - x[ia]), sb = (y[nb] - y[ib]) / (x[nb] - x[ib]);
        const double dl = fabs(y[ia] + sa * (X - x[ia]) - (y[ib] + sb * (X - x[ib])));
        const double dr = fabs(y[ia] + sa * (X1 - x[ia]) - (y[ib] + sb * (X1 - x[ib])));
        sum += (X1 - X) * (dl * dl + dl * dr + dr * dr) / 3;
        X = X1;
    }
    return sum;
}

/* Extent along n of disc (c, r) intersected with polygon q: attained at polygon corners
 * inside the disc, at the crossing points, or at the circle's extreme points c -+ r n when
 * they lie inside the polygon. */
static double disc_thickness(const pl_overlap *o, pl_vec2 c, double r, const pl_vec2 *q, int nq,
                             pl_vec2 n) {
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < nq; k++) {
        const double dx = q[k].x - c.x, dy = q[k].y - c.y;
        if (dx * dx + dy * dy <= r * r) {
            lo = mn(lo, dot2(q[k], n));
            hi = mx(hi, dot2(q[k], n));
        }
    }
    const int m = o->cross_n < PL_CLIP_MAX_CROSS ? o->cross_n : PL_CLIP_MAX_CROSS;
    for (int k = 0; k < m; k++) {
        lo = mn(lo, dot2(o->cross[k], n));
        hi = mx(hi, dot2(o->cross[k], n));
    }
    for (int sgn = -1; sgn <= 1; sgn += 2) {
        const pl_vec2 e = {c.x + sgn * r * n.x, c.y + sgn * r * n.y};
        int inside = 1;
        for (int k = 0; k < nq && inside; k++) {
            const pl_vec2 a = q[k], b = q[k + 1 < nq ? k + 1 : 0];
            if ((b.x - a.x) * (e.y - a.y) - (b.y - a.y) * (e.x - a.x) < 0) inside = 0;
        }
        if (inside) {
            lo = mn(lo, dot2(e, n));
            hi = mx(hi, dot2(e, n));
        }
    }
    return hi > lo ? hi - lo : 0;
}

/* Fills g from the overlap (first outline = body `first`); returns 0 when not touching. */
static int finish_geometry(const pl_world *w, const pl_overlap *o, int first, int a, int b,
                           geo *g) {
    g->area = o->area;
    g->s = o->centroid;
    const double cl = len2(o->chord_vec.x, o->chord_vec.y);
    const double scale = w->radius[a] + w->radius[b];
    if (cl > 1e-12 * scale) {
        g->n = (pl_vec2){o->chord_vec.y / cl, -o->chord_vec.x / cl};
        if (first != a) g->n = (pl_vec2){-g->n.x, -g->n.y};
        g->chord = cl;
    } else {
        /* one outline inside the other, or a symmetric crossing with no preferred
         * direction: push along the line of the centroids */
        const pl_vec2 d = {w->pos[b].x - w->pos[a].x, w->pos[b].y - w->pos[a].y};
        const double l = len2(d.x, d.y);
        g->n = l > 0 ? (pl_vec2){d.x / l, d.y / l} : (pl_vec2){0, 1};
        g->chord = sqrt(o->area);
    }
    return 1;
}

/* Computes the overlap geometry of pair p; returns 0 when the bodies do not overlap. */
static int contact_geometry(const pl_world *w, const pl_pair *p, geo *g) {
    const int a = p->a, b = p->b;
    const int sa = w->shape[a], sb = w->shape[b];
    const pl_vec2 ca = w->pos[a], cb = w->pos[b];
    pl_overlap o;
    g->wall = 0;
    if (sa == PL_SHAPE_POLYGON && sb == PL_SHAPE_POLYGON) {
        const double dx = cb.x - ca.x, dy = cb.y - ca.y, rs = w->radius[a] + w->radius[b];
        if (dx * dx + dy * dy >= rs * rs) return 0;
        const pl_vec2 *va = &w->verts_world[w->vert_offset[a]];
        const pl_vec2 *vb = &w->verts_world[w->vert_offset[b]];
        /* cheap separating-axis test along the line of the centroids before clipping: most
         * neighbour pairs that do not touch are separated along it */
        double amax = -INFINITY, bmin = INFINITY;
        for (int k = 0; k < w->vert_count[a]; k++) amax = mx(amax, (va[k].x - ca.x) * dx + (va[k].y - ca.y) * dy);
        for (int k = 0; k < w->vert_count[b]; k++) bmin = mn(bmin, (vb[k].x - ca.x) * dx + (vb[k].y - ca.y) * dy);
        if (amax <= bmin) return 0;
        if (!(pl_clip_convex(va, w->vert_count[a], vb, w->vert_count[b], &o) > 0)) return 0;
        finish_geometry(w, &o, a, a, b, g);
        g->thick = thickness(&o, g->n);
        g->d2 = winkler_d2(&o, g->n);
        return 1;
    }
    if (sa == PL_SHAPE_SEGMENT || sb == PL_SHAPE_SEGMENT) {
        const int s = sa == PL_SHAPE_SEGMENT ? a : b, q = s == a ? b : a;
        if (w->shape[q] != PL_SHAPE_POLYGON) return 0;
        const pl_vec2 *vs = &w->verts_world[w->vert_offset[s]];
        const pl_vec2 *vq = &w->verts_world[w->vert_offset[q]];
        pl_vec2 nw;
        if (!(pl_clip_segment(vq, w->vert_count[q], vs[0], vs[1], w->pos[q], &o, &nw) > 0))
            return 0;
        g->wall = 1;
        g->area = o.area;
        g->s = o.centroid;
        /* the wall normal points to the polygon; n runs from a to b */
        g->n = q == a ? (pl_vec2){-nw.x, -nw.y} : nw;
        g->chord = o.chord > 0 ? o.chord : sqrt(o.area);
        g->thick = thickness(&o, g->n);
        g->d2 = winkler_d2(&o, g->n);
        return 1;
    }
    /* polygon and disc */
    const int d = sa == PL_SHAPE_DISC ? a : b, q = d == a ? b : a;
    const double dx = w->pos[d].x - w->pos[q].x, dy = w->pos[d].y - w->pos[q].y;
    const double rs = w->radius[d] + w->radius[q];
    if (dx * dx + dy * dy >= rs * rs) return 0;
    const pl_vec2 *vq = &w->verts_world[w->vert_offset[q]];
    if (!(pl_clip_disc(w->pos[d], w->radius[d], vq, w->vert_count[q], &o) > 0)) return 0;
    finish_geometry(w, &o, q, a, b, g);
    g->thick = disc_thickness(&o, w->pos[d], w->radius[d], vq, w->vert_count[q], g->n);
    g->d2 = -1;
    /* Pressure on a circle is radial, so the resultant on the disc passes through its centre:
     * the force acts on the line through the centre along n (the chord's perpendicular
     * bisector), at the projection of the overlap centroid onto it. Applied at the centroid
     * itself, a frictionless contact with a corner off the centre line would exert a constant
     * moment on the disc and spin it up without bound. */
    const pl_vec2 c = w->pos[d], r = {g->s.x - c.x, g->s.y - c.y};
    const double along = dot2(r, g->n);
    g->s = (pl_vec2){c.x + along * g->n.x, c.y + along * g->n.y};
    return 1;
}

/* Damping ratio for the area law from the pair's restitution. With the cutoff of eq. 2
 * (|F_da| <= F_el) a linear contact rebounds faster than the free damped oscillator, so
 * zeta from e = exp(-pi zeta / sqrt(1 - zeta^2)) would miss the requested e (e = 0.3 gives
 * 0.48). The table holds zeta' e at e = 0.02, 0.04, ..., 1 such that a flat contact with the
 * cutoff, m x'' = -k x - clip(2 zeta' sqrt(m k) x', -k x, k x), rebounds with exactly e
 * (solved once by RK4 and bisection, docs/contact-laws-polygons.md); zeta' e is smooth
 * (about 0.35 for small e), so it is interpolated linearly in e. */
static const double zeta_times_e[50] = {
    0.35182, 0.34811, 0.34316, 0.33731, 0.33076, 0.32366, 0.31611, 0.30820,
    0.29998, 0.29152, 0.28287, 0.27409, 0.26520, 0.25626, 0.24731, 0.23837,
    0.22949, 0.22070, 0.21202, 0.20348, 0.19510, 0.18689, 0.17886, 0.17102,
    0.16335, 0.15586, 0.14854, 0.14138, 0.13436, 0.12747, 0.12070, 0.11402,
    0.10744, 0.10093, 0.09449, 0.08809, 0.08175, 0.07543, 0.06914, 0.06287,
    0.05661, 0.05035, 0.04410, 0.03784, 0.03157, 0.02529, 0.01900, 0.01269,
    0.00635, 0.00000,
};

static double cutoff_zeta(double zeta) {
    if (!(zeta > 0)) return 0;
    if (zeta >= 1) zeta = 0.999999;
    const double e = exp(-3.14159265358979323846 * zeta / sqrt(1 - zeta * zeta));
    if (e <= 0.02) return zeta_times_e[0] / mx(e, 1e-6);
    const double x = e / 0.02 - 1;
    int i = (int)x;
    if (i >= 49) return 0;
    const double f = x - i;
    return ((1 - f) * zeta_times_e[i] + f * zeta_times_e[i + 1]) / e;
}

/* l_char of seed 004 eq. 1; for a wall (rigid, no centre) the spring spans only the
 * polygon's arm, l_char = |l1|. Floored at 5% of the smaller body radius so that a centroid
 * driven into the overlap cannot make the force infinite (the overlap guard fires first). */
static double char_length(const pl_world *w, int a, int b, pl_vec2 s, int wall) {
    const int sa = w->shape[a];
    const double l1 = len2(s.x - w->pos[a].x, s.y - w->pos[a].y);
    const double l2 = len2(s.x - w->pos[b].x, s.y - w->pos[b].y);
    double lc, rmin;
    if (wall) {
        const int q = sa == PL_SHAPE_SEGMENT ? b : a;
        lc = q == a ? l1 : l2;
        rmin = w->radius[q];
    } else {
        lc = l1 + l2 > 0 ? 4 * l1 * l2 / (l1 + l2) : 0;
        rmin = mn(w->radius[a], w->radius[b]);
    }
    return mx(lc, 0.05 * rmin);
}

double pl__contact_polygon(const pl_world *w, pl_pair *p, const pl_pair_params *pp, double dt, pl_contact_out *o) {
    geo g;
    o->add.flags = 0;
    if (!contact_geometry(w, p, &g)) {
        untouch(p);
        return 0;
    }
    const int a = p->a, b = p->b;
    const pl_vec2 n = g.n, t = {-n.y, n.x};
    const double Y = pp->kn;
    const double lchar = char_length(w, a, b, g.s, g.wall);
    const double width = mx(g.chord, 1e-9 * (w->radius[a] + w->radius[b]));
    const double fel = Y * g.area / lchar;           /* seed 004 eq. 1 */
    const double keff = Y * width / lchar;           /* dF_el / d(depth), depth = A / w */
    const double depth = g.area / width;

    /* relative velocity of b's material point at S with respect to a's */
    const pl_vec2 vA = point_velocity(w, a, g.s), vB = point_velocity(w, b, g.s);
    const pl_vec2 vrel = {vB.x - vA.x, vB.y - vA.y};
    const double vt = dot2(vrel, t);

    /* damping on the rate of the overlap area (seed 004 eq. 2) with the cutoff */
    const double sinv = w->inv_mass[a] + w->inv_mass[b];
    const double mred = sinv > 0 ? 1.0 / sinv : 0;
    double cn = pp->cn;
    if (pp->zeta >= 0) cn = 2 * cutoff_zeta(pp->zeta) * sqrt(mred * keff);
    const double area_prev = p->touching ? p->area_prev : 0;
    double fda = dt > 0 ? cn * (g.area - area_prev) / (dt * width) : 0;
    if (fda > fel) fda = fel;
    if (fda < -fel) fda = -fel;
    const double fn = fel + fda;
    /* The moment of the same distributed dashpot: a relative rotation w_rel presses one end
     * of the contact in and lifts the other, d'(x) = w_rel x, and integrating (c / w) d'(x) x
     * over the width gives the couple -(c w^2 / 12) w_rel. Eq. 2 alone (a resultant on dA/dt)
     * leaves rocking on a face undamped, since the area hardly changes while it rocks. Capped
     * like eq. 2 by the largest moment the elastic pressure can exert, F_el w / 2.
     * Not for a disc: its relative rotation is rolling, and the couple would act as a
     * viscous rolling resistance that the disc laws (seed 003) do not have. */
    const int disc = w->shape[a] == PL_SHAPE_DISC || w->shape[b] == PL_SHAPE_DISC;
    const double wrel = disc ? 0 : w->omega[b] - w->omega[a];
    double mda = -cn * width * width / 12 * wrel;
    if (mda > 0.5 * fel * width) mda = 0.5 * fel * width;
    if (mda < -0.5 * fel * width) mda = -0.5 * fel * width;

    /* friction: incremental tangential spring with the Coulomb cap */
    const double kt = pp->kn > 0 ? pp->ks * keff / pp->kn : pp->ks;
    const double ct = pp->kn > 0 ? cn * pp->ks / pp->kn : 0;
    double fs = (p->touching ? p->fs : 0) - kt * vt * dt;
    double fd = -ct * vt;
    const double smax = pp->friction * fel + pp->cohesion;
    if (fabs(fs) > smax) {
        const double lim = smax > 0 ? smax : 0;
        const double slip = kt > 0 ? (fabs(fs) - lim) / kt : fabs(vt) * dt;
        o->e_friction = lim * slip;
        o->add.flags |= PL_OUT_EFRIC;
        fs = fs > 0 ? lim : -lim;
        fd = 0;
    } else if (fabs(fs + fd) > smax) {
        fd = (fs + fd > 0 ? smax : -smax) - fs; /* |S + D_S| <= S_max, as for discs */
    }
    const double ft = fs + fd;

    p->fs = fs;
    p->fn = fn;
    p->ft = ft;
    p->overlap = depth;
    p->area_prev = g.area;
    p->normal = n;
    p->point = g.s;
    p->touching = 1;
    if (w->heat_on) p->pad = (uint8_t)(smax > 0 && fabs(fs) >= smax * (1 - 1e-12)); /* sliding, read by heat.c */
    /* stored energy: the Winkler foundation's (Y / 2 l_char) int d^2 dx for polygon overlaps
     * (equal to int F_el d(delta) for flat, tilted-flat and corner contacts); for a disc, whose
     * overlap is not a polygon, int F_el d(delta) for an overlap growing as A ~ delta^q with the
     * current exponent q = w h / A (h the thickness along n), i.e. F_el h / (q + 1), exact
     * for a disc on a face (q = 3/2) and a corner in a disc (q = 2) */
    double e_n;
    if (g.d2 >= 0) {
        e_n = 0.5 * Y * g.d2 / lchar;
    } else {
        const double h = g.thick > 0 ? g.thick : depth;
        e_n = fel * h * g.area / (g.area + width * h);
    }
    p->elastic = e_n + (kt > 0 ? 0.5 * fs * fs / kt : 0);
    /* dissipation = work the dashpots take out of the bodies during this step */
    o->e_damped = fda * (g.area - area_prev) / width + (-fd * vt - mda * wrel) * dt;

    const pl_vec2 F = {fn * n.x + ft * t.x, fn * n.y + ft * t.y};
    o->add.fx = F.x;
    o->add.fy = F.y;
    const pl_vec2 ra = {g.s.x - w->pos[a].x, g.s.y - w->pos[a].y};
    const pl_vec2 rb = {g.s.x - w->pos[b].x, g.s.y - w->pos[b].y};
    o->add.tqb = cross2(rb, F) + mda;
    o->add.tqa = -(cross2(ra, F) + mda);
    o->add.flags |= PL_OUT_F | PL_OUT_TQA | PL_OUT_TQB | PL_OUT_POLY;

    const double rmin = g.wall ? w->radius[w->shape[a] == PL_SHAPE_SEGMENT ? b : a]
                               : mn(w->radius[a], w->radius[b]);
    o->ratio = rmin > 0 ? depth / rmin : 0;
    return mx(keff, kt);
}

/* The damping ratio the area law uses for a pair of restitution damping ratio zeta (for the
 * time-step estimate, timestep.c). */
double pl__polygon_cutoff_zeta(double zeta) { return cutoff_zeta(zeta); }
