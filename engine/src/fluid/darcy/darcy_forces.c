/* Fluid forces on grains (seed 000 §3.11-3.12). The pressure p = rho_f g (h - z) is linear in
 * each element, so the outline integrals F = -∮ p n ds and M = ∮ (r - c) x dF are evaluated
 * exactly: polygon edges are split where they cross element edges (and where p changes sign),
 * then each piece is integrated in closed form (trapezoid for the force, eq. 3.34; the
 * quadratic moment integrand exactly, which is eq. 3.35 written as an integral). Discs are
 * integrated on their circle, arc by arc, in closed form. Dry region: the fluid pushes only
 * where p > 0 inside the mesh; outside the mesh p = 0 (partial submersion, §3.11.4 and
 * Fig. 3-11, including sign changes inside an element). Interphase drag of the porous skeleton
 * (DESIGN §3): each grain receives e (its solid area in the element) (-grad p_excess) per
 * element it covers, e the element's areal void ratio, so that the whole seepage force acts on
 * the skeleton.
 * Mesh edge (docs/fluid.md §6.1): the part of a grain pressed into a wall at the mesh's edge
 * that lies beyond the boundary (a contact overlap) is not dry: the porosity update folds it
 * into the boundary elements as pieces flagged outside, and the outline integral uses, beyond
 * the boundary, the linear field of the nearest boundary element the grain crosses
 * (pl_fl_edge_elements, from the mesh alone: also when no pieces are cut or they are pixel
 * counts), so that in still water the grain feels rho_f g A for its whole area A however far the
 * contact presses it in. */
#include "fluid/darcy/darcy_internal.h"
#include <math.h>
#include <stdlib.h>

#define BP_CAP 256
#define ARC_CAP 512

/* Elements whose field is extended beyond the mesh boundary for a body: those its pieces flagged
   outside were folded into when pieces were cut for it, else (no pieces: drag off, uniform
   permeability, no consolidation) pl_fl_edge_elements, found the first time a piece of its
   outline lies beyond the boundary. None for a body inside the mesh or one crossing the
   boundary as a solid; NULL: p = 0 beyond the boundary. */
typedef struct edge_ext {
    const pl_mesh *m;
    pl_vec2 c;
    double r;
    const pl_vec2 *v;
    int nv;
    int found, n;
    int32_t elem[PL_FL_EDGE_MAX];
} edge_ext;

static int ext_count(edge_ext *x) {
    if (!x) return 0;
    if (!x->found) {
        double w[PL_FL_EDGE_MAX];
        x->n = pl_fl_edge_elements(x->m, x->c, x->r, x->v, x->nv, x->elem, w, PL_FL_EDGE_MAX);
        x->found = 1;
    }
    return x->n;
}

/* Squared distance from x to triangle e's edges (x outside the mesh). */
static double tri_dist2(const pl_mesh *m, int e, pl_vec2 x) {
    const int32_t *v = &m->tri[3 * e];
    double best = INFINITY;
    for (int k = 0; k < 3; k++) {
        pl_vec2 P = m->xy[v[k]], Q = m->xy[v[(k + 1) % 3]];
        double dx = Q.x - P.x, dy = Q.y - P.y, L2 = dx * dx + dy * dy;
        double t = L2 > 0 ? ((x.x - P.x) * dx + (x.y - P.y) * dy) / L2 : 0;
        t = t < 0 ? 0 : (t > 1 ? 1 : t);
        double ex = P.x + t * dx - x.x, ey = P.y + t * dy - x.y;
        best = fmin(best, ex * ex + ey * ey);
    }
    return best;
}

/* The element of ext nearest to x: its linear field is the pressure at x beyond the boundary. */
static int nearest_ext(const pl_mesh *m, const int32_t *ext, int n, pl_vec2 x) {
    int best = ext[0];
    double d = n > 1 ? tri_dist2(m, ext[0], x) : 0;
    for (int k = 1; k < n; k++) {
        double dk = tri_dist2(m, ext[k], x);
        if (dk < d) { d = dk; best = ext[k]; }
    }
    return best;
}

static int cmp_d(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Parameters s (0..1 along a->b) where the segment enters/leaves triangle e (Cyrus-Beck). */
static int clip_segment(const pl_mesh *m, int e, pl_vec2 a, pl_vec2 d, double *s0, double *s1) {
    const int32_t *v = &m->tri[3 * e];
    double lo = 0, hi = 1;
    for (int k = 0; k < 3; k++) {
        pl_vec2 p = m->xy[v[k]], q = m->xy[v[(k + 1) % 3]];
        /* inside: cross(q - p, x - p) >= 0 for a counter-clockwise triangle */
        double ex = q.x - p.x, ey = q.y - p.y;
        double num = ex * (a.y - p.y) - ey * (a.x - p.x); /* value at s = 0 */
        double den = ex * d.y - ey * d.x;                 /* rate in s */
        if (den == 0) {
            if (num < 0) return 0;
            continue;
        }
        double s = -num / den;
        if (den > 0) { if (s > lo) lo = s; }
        else { if (s < hi) hi = s; }
        if (lo > hi) return 0;
    }
    *s0 = lo;
    *s1 = hi;
    return 1;
}

/* Pressure at a point using element e's linear field (extrapolates slightly outside e). */
static double p_in(const struct pl_fluid *f, int e, pl_vec2 p) {
    double l[3];
    pl_mesh_barycentric(&f->mesh, e, p, l);
    const int32_t *v = &f->mesh.tri[3 * e];
    double h = l[0] * f->head[v[0]] + l[1] * f->head[v[1]] + l[2] * f->head[v[2]];
    return f->par.density * f->par.g * (h - pl_fl_z(f, p));
}

/* Exact force and moment of a linear pressure p0..p1 on a->b between u0 and u1 (fractions). */
static void piece(pl_vec2 a, pl_vec2 d, pl_vec2 c, double u0, double u1, double p0, double p1, pl_vec2 *F, double *M) {
    /* force direction per unit of u for a counter-clockwise outline: (-d.y, d.x) * p */
    double du = u1 - u0;
    double ip = du * 0.5 * (p0 + p1);
    F->x += -d.y * ip;
    F->y += d.x * ip;
    pl_vec2 r0 = {a.x + u0 * d.x - c.x, a.y + u0 * d.y - c.y}, r1 = {a.x + u1 * d.x - c.x, a.y + u1 * d.y - c.y};
    /* arm (r - c) x e with e = (-d.y, d.x): linear in u */
    double g0 = r0.x * d.x + r0.y * d.y, g1 = r1.x * d.x + r1.y * d.y;
    *M += du * (2 * g0 * p0 + g0 * p1 + g1 * p0 + 2 * g1 * p1) / 6.0;
}

static void edge_force(const struct pl_fluid *f, pl_vec2 a, pl_vec2 b, pl_vec2 c, double u0, double u1, pl_vec2 *F,
                       double *M, int depth, edge_ext *ext) {
    const pl_mesh *m = &f->mesh;
    pl_vec2 d = {b.x - a.x, b.y - a.y};
    pl_vec2 pa = {a.x + u0 * d.x, a.y + u0 * d.y}, pb = {a.x + u1 * d.x, a.y + u1 * d.y};
    pl_vec2 lo = {fmin(pa.x, pb.x), fmin(pa.y, pb.y)}, hi = {fmax(pa.x, pb.x), fmax(pa.y, pb.y)};
    int i0 = 0, j0 = 0, i1 = -1, j1 = -1;
    /* a piece wholly beyond the grid: nothing to cut it at (with an extension it is still wet) */
    if (!pl_mesh_grid_range(m, lo, hi, &i0, &j0, &i1, &j1)) {
        if (!ext_count(ext)) return;
        i0 = j0 = 0;
        i1 = j1 = -1;
    }
    double bp[BP_CAP];
    int nb = 0, overflow = 0;
    bp[nb++] = u0;
    bp[nb++] = u1;
    for (int j = j0; j <= j1 && !overflow; j++)
        for (int i = i0; i <= i1 && !overflow; i++) {
            size_t cell = (size_t)j * m->gx + i;
            for (int k = m->cell_start[cell]; k < m->cell_start[cell + 1]; k++) {
                double s0, s1;
                if (!clip_segment(m, m->cell_items[k], a, d, &s0, &s1)) continue;
                if (s1 < u0 || s0 > u1) continue;
                if (nb + 2 > BP_CAP) { overflow = 1; break; }
                if (s0 > u0 && s0 < u1) bp[nb++] = s0;
                if (s1 > u0 && s1 < u1) bp[nb++] = s1;
            }
        }
    if (overflow && depth < 40) {
        double um = 0.5 * (u0 + u1);
        edge_force(f, a, b, c, u0, um, F, M, depth + 1, ext);
        edge_force(f, a, b, c, um, u1, F, M, depth + 1, ext);
        return;
    }
    qsort(bp, (size_t)nb, sizeof(double), cmp_d);
    double len = hypot(d.x, d.y);
    double tiny = 1e-13 * (len > 0 ? 1 : 0);
    for (int k = 0; k + 1 < nb; k++) {
        double s0 = bp[k], s1 = bp[k + 1];
        if (s1 - s0 <= tiny) continue;
        double sm = 0.5 * (s0 + s1);
        pl_vec2 xm = {a.x + sm * d.x, a.y + sm * d.y};
        int e = pl_mesh_locate(m, xm);
        if (e < 0) {
            const int next = ext_count(ext);
            if (!next) continue;                    /* outside the fluid: p = 0 */
            e = nearest_ext(m, ext->elem, next, xm); /* pressed into a wall at the edge: field extended */
        }
        double p0 = p_in(f, e, (pl_vec2){a.x + s0 * d.x, a.y + s0 * d.y});
        double p1 = p_in(f, e, (pl_vec2){a.x + s1 * d.x, a.y + s1 * d.y});
        if (p0 <= 0 && p1 <= 0) continue; /* dry */
        if (p0 < 0 || p1 < 0) {           /* wetted part only (Fig. 3-11) */
            double sz = s0 + (s1 - s0) * p0 / (p0 - p1);
            if (p0 < 0) piece(a, d, c, sz, s1, 0, p1, F, M);
            else piece(a, d, c, s0, sz, p0, 0, F, M);
        } else {
            piece(a, d, c, s0, s1, p0, p1, F, M);
        }
    }
}

static void polygon_force_ext(const struct pl_fluid *f, const pl_vec2 *v, int n, pl_vec2 c, edge_ext *ext,
                              pl_vec2 *force, double *moment) {
    pl_vec2 F = {0, 0};
    double M = 0;
    for (int k = 0; k < n; k++) edge_force(f, v[k], v[(k + 1) % n], c, 0, 1, &F, &M, 0, ext);
    force->x += F.x;
    force->y += F.y;
    *moment += M;
}

void pl_fl_polygon_force(const struct pl_fluid *f, const pl_vec2 *v, int n, pl_vec2 c, pl_vec2 *force,
                         double *moment) {
    polygon_force_ext(f, v, n, c, NULL, force, moment);
}

/* Pressure on the circle in element e: p(theta) = al + be cos(theta) + ga sin(theta). */
static void circle_coeffs(const struct pl_fluid *f, int e, pl_vec2 c, double r, double *al, double *be, double *ga) {
    const double rg = f->par.density * f->par.g;
    *al = p_in(f, e, c);
    /* grad p = rho g (grad h - up), grad h the element's, kept since the last solve
       (pl_fl_update_gradients: the same expression, so the same bits) */
    const double gx = f->grad[2 * e], gy = f->grad[2 * e + 1];
    int grav = !(f->par.gravity.x == 0 && f->par.gravity.y == 0);
    *be = r * rg * (gx - (grav ? f->par.up.x : 0));
    *ga = r * rg * (gy - (grav ? f->par.up.y : 0));
}

/* Closed-form force of p = al + be cos + ga sin on the arc a0..a1 of a circle of radius r,
   positive part only (the arc is cut where p changes sign). Below the free surface p > 0 on the
   whole circle (al > R = |(be, ga)|, the usual case): then no cut and no dry test is needed,
   which the squared comparison (with a margin, so that the exact test would agree) decides
   without a square root. sin 2b is taken as 2 sin b cos b from the values already at hand. */
static void arc_force(double r, double al, double be, double ga, double a0, double a1, double *Fx, double *Fy) {
    double cut[4] = {a0, a1, a1, a1};
    int nc = 2;
    const double R2 = be * be + ga * ga;
    const int all_wet = al > 0 && al * al > R2 * (1 + 1e-9);
    if (!all_wet) {
        double R = hypot(be, ga);
        if (R > 0 && fabs(al) < R) {
            double phi = atan2(ga, be), w = acos(-al / R);
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                double z = phi + sgn * w; /* bring into (a0, a1) if it falls there */
                z -= 2 * PL_FL_PI * floor((z - a0) / (2 * PL_FL_PI));
                if (z > a0 && z < a1) cut[nc++] = z;
            }
            if (nc == 4 && cut[2] > cut[3]) { double t = cut[2]; cut[2] = cut[3]; cut[3] = t; }
            if (nc >= 3) { double t = cut[1]; for (int k = 1; k < nc - 1; k++) cut[k] = cut[k + 1]; cut[nc - 1] = t; }
        }
    }
    for (int k = 0; k + 1 < nc; k++) {
        double b0 = cut[k], b1 = cut[k + 1];
        if (b1 <= b0) continue;
        if (!all_wet) {
            double bm = 0.5 * (b0 + b1);
            if (al + be * cos(bm) + ga * sin(bm) <= 0) continue; /* dry arc */
        }
        double s0 = sin(b0), s1 = sin(b1), c0 = cos(b0), c1 = cos(b1);
        double d2 = s1 * c1 - s0 * c0; /* (sin 2b1 - sin 2b0) / 2 */
        double Icc = 0.5 * (b1 - b0) + 0.5 * d2;
        double Iss = 0.5 * (b1 - b0) - 0.5 * d2;
        double Isc = 0.5 * (s1 * s1 - s0 * s0);
        *Fx -= r * (al * (s1 - s0) + be * Icc + ga * Isc);
        *Fy -= r * (al * (c0 - c1) + be * Isc + ga * Iss);
    }
}

/* Arcs of the circle inside triangle e: the intersection of the three half-planes, each an
   arc interval of the angle; returns the number of arcs (at most 3) written to arcs. The
   signed distances of the centre to the three edges are taken first, so that a circle wholly
   outside one edge costs no trigonometry; edge angles and lengths are the mesh's (built once). */
static int circle_in_triangle(const pl_mesh *m, int e, pl_vec2 c, double r, double arcs[][2]) {
    const int32_t *v = &m->tri[3 * e];
    const double *L3 = &m->edge_len[3 * e];
    double sk[3];
    for (int k = 0; k < 3; k++) {
        pl_vec2 P = m->xy[v[k]], Q = m->xy[v[(k + 1) % 3]];
        double ex = Q.x - P.x, ey = Q.y - P.y;
        double d0 = ex * (c.y - P.y) - ey * (c.x - P.x); /* cross(e, c - P) */
        sk[k] = -d0 / (r * L3[k]);
        if (sk[k] >= 1) return 0; /* none of the circle is on the inner side of this edge */
    }
    /* current set as intervals in [0, 2 pi) */
    double cur[6][2];
    int n = 1;
    cur[0][0] = 0;
    cur[0][1] = 2 * PL_FL_PI;
    for (int k = 0; k < 3 && n > 0; k++) {
        double s = sk[k];
        if (s <= -1) continue;          /* the whole circle is inside this half-plane */
        double al = m->edge_ang[3 * e + k], as = asin(s);
        double lo = al + as, hi = al + PL_FL_PI - as; /* sin(theta - al) >= s */
        lo -= 2 * PL_FL_PI * floor(lo / (2 * PL_FL_PI));
        hi = lo + (PL_FL_PI - 2 * as);
        double half[2][2];
        int nh = 0;
        if (hi <= 2 * PL_FL_PI) { half[0][0] = lo; half[0][1] = hi; nh = 1; }
        else { half[0][0] = lo; half[0][1] = 2 * PL_FL_PI; half[1][0] = 0; half[1][1] = hi - 2 * PL_FL_PI; nh = 2; }
        double next[6][2];
        int nn = 0;
        for (int a = 0; a < n; a++)
            for (int b = 0; b < nh; b++) {
                double x0 = fmax(cur[a][0], half[b][0]), x1 = fmin(cur[a][1], half[b][1]);
                if (x1 > x0 && nn < 6) { next[nn][0] = x0; next[nn][1] = x1; nn++; }
            }
        n = nn;
        for (int a = 0; a < n; a++) { cur[a][0] = next[a][0]; cur[a][1] = next[a][1]; }
    }
    for (int a = 0; a < n; a++) { arcs[a][0] = cur[a][0]; arcs[a][1] = cur[a][1]; }
    return n;
}

static int cmp_arc(const void *a, const void *b) { return cmp_d(a, b); }

static void disc_force_ext(const struct pl_fluid *f, pl_vec2 c, double r, edge_ext *ext, pl_vec2 *force) {
    const pl_mesh *m = &f->mesh;
    pl_vec2 lo = {c.x - r, c.y - r}, hi = {c.x + r, c.y + r};
    int i0, j0, i1, j1;
    if (!pl_mesh_grid_range(m, lo, hi, &i0, &j0, &i1, &j1)) return;
    double Fx = 0, Fy = 0;
    /* common case: the whole circle inside the element holding its centre */
    int ec = pl_mesh_locate(m, c);
    if (ec >= 0) {
        const int32_t *v = &m->tri[3 * ec];
        int inside = 1;
        for (int k = 0; k < 3 && inside; k++) {
            pl_vec2 P = m->xy[v[k]], Q = m->xy[v[(k + 1) % 3]];
            double ex = Q.x - P.x, ey = Q.y - P.y;
            double d0 = ex * (c.y - P.y) - ey * (c.x - P.x); /* L x distance, positive inside */
            if (d0 < r * m->edge_len[3 * ec + k]) inside = 0;
        }
        if (inside) {
            double al, be, ga;
            circle_coeffs(f, ec, c, r, &al, &be, &ga);
            arc_force(r, al, be, ga, 0, 2 * PL_FL_PI, &Fx, &Fy);
            force->x += Fx;
            force->y += Fy;
            return;
        }
    }
    const int single = i0 == i1 && j0 == j1; /* no triangle can be met twice */
    double seen[ARC_CAP][2]; /* arcs inside the mesh (with an extension: the rest is beyond it) */
    int nseen = 0;
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            size_t cell = (size_t)j * m->gx + i;
            for (int k = m->cell_start[cell]; k < m->cell_start[cell + 1]; k++) {
                int e = m->cell_items[k];
                const double *tb = &m->tri_box[4 * e];
                if (tb[2] < lo.x || tb[0] > hi.x || tb[3] < lo.y || tb[1] > hi.y) continue;
                /* a triangle is listed in every cell its box overlaps: handle it only in the
                   first of those cells inside the scanned range */
                if (!single) {
                    int ti0 = m->tri_cell0[2 * e], tj0 = m->tri_cell0[2 * e + 1];
                    if (i != (ti0 > i0 ? ti0 : i0) || j != (tj0 > j0 ? tj0 : j0)) continue;
                }
                double arcs[6][2];
                int na = circle_in_triangle(m, e, c, r, arcs);
                if (na == 0) continue;
                double al, be, ga;
                circle_coeffs(f, e, c, r, &al, &be, &ga);
                for (int q = 0; q < na; q++) {
                    arc_force(r, al, be, ga, arcs[q][0], arcs[q][1], &Fx, &Fy);
                    if (ext && nseen < ARC_CAP) { seen[nseen][0] = arcs[q][0]; seen[nseen][1] = arcs[q][1]; }
                    nseen++;
                }
            }
        }
    if (ext && nseen <= ARC_CAP) {
        /* the arcs beyond the mesh boundary: gaps between the arcs inside (round-off gaps
           between neighbouring triangles, below 1e-9 rad, are left out), each integrated with the
           field of the nearest extended element */
        qsort(seen, (size_t)nseen, sizeof seen[0], cmp_arc);
        double cur = 0;
        for (int q = 0; q <= nseen; q++) {
            double g0 = cur, g1 = q < nseen ? seen[q][0] : 2 * PL_FL_PI;
            if (g1 - g0 > 1e-9) {
                const int next = ext_count(ext);
                if (!next) break; /* outside the fluid: p = 0 */
                double gm = 0.5 * (g0 + g1);
                int e = nearest_ext(m, ext->elem, next, (pl_vec2){c.x + r * cos(gm), c.y + r * sin(gm)});
                double al, be, ga;
                circle_coeffs(f, e, c, r, &al, &be, &ga);
                arc_force(r, al, be, ga, g0, g1, &Fx, &Fy);
            }
            if (q < nseen && seen[q][1] > cur) cur = seen[q][1];
        }
    }
    force->x += Fx;
    force->y += Fy;
}

void pl_fl_disc_force(const struct pl_fluid *f, pl_vec2 c, double r, pl_vec2 *force) {
    disc_force_ext(f, c, r, NULL, force);
}

/* Pressure force on a disc from its cover pieces (Gauss): p is continuous and linear in each
   element, so -∮ p n ds = -∫ grad p dA = -Σ_e A_{disc∩e} grad p_e, where the areas are the
   exact circle-triangle pieces of the porosity update. Equal to the arc integral of
   pl_fl_disc_force (up to round-off) when the whole disc is inside the mesh and the pressure is
   positive on all of its outline (no dry part, which the arc integral cuts away); then it costs
   one gradient per piece instead of the arcs' trigonometry. Returns 0 (nothing added) when it
   does not apply: covers not computed for the disc's current position and radius (compared
   exactly with those of the last porosity update; with FLUID_POROSITY_TIMESTEPS, within a tenth
   of the radius), pixellated areas, part of the
   disc outside the mesh, or p <= 0 possible on the outline (p_e(centre) - r |grad p_e| <= 0
   in some covered element, a sufficient test). Under FLUID_CONSOLIDATION (a saturated mesh)
   negative pressures push too (except on pieces beyond the boundary). A grain pressed into a
   wall at the mesh's edge counts its part beyond the boundary among its pieces (flagged
   outside, in the boundary element: docs/fluid.md §6.1). */
static int disc_force_covers(const struct pl_fluid *f, const pl_fl_bodies *b, int i, pl_vec2 *force) {
    if (f->par.porosity_method != 0 || !f->body_cover_start || !f->cover_xyr || i >= f->cover_bodies) return 0;
    const pl_vec2 c = b->pos[i];
    const double r = b->radius[i];
    if (f->cover_xyr[3 * i + 2] != r) return 0;
    const double mx = c.x - f->cover_xyr[3 * i], my = c.y - f->cover_xyr[3 * i + 1];
    /* moved since its pieces were cut: with FLUID_POROSITY_TIMESTEPS the last pieces stand (the
       consolidation source uses the same ones, so the coupling stays work-consistent) while the
       disc is within a tenth of its radius of where they were cut */
    if ((mx != 0 || my != 0) && (f->par.porosity_every <= 0 || mx * mx + my * my > 0.01 * r * r)) return 0;
    const int k0 = f->body_cover_start[i], k1 = f->body_cover_start[i + 1];
    if (k0 == k1) return 1; /* no piece: the disc lies outside the mesh, no pressure on it */
    const double rg = f->par.density * f->par.g;
    const int grav = !(f->par.gravity.x == 0 && f->par.gravity.y == 0);
    const double upx = grav ? f->par.up.x : 0, upy = grav ? f->par.up.y : 0;
    /* under FLUID_CONSOLIDATION the mesh is saturated: a negative gauge pressure is suction
       (dilating skeleton), not air above a water table, and pushes like any other pressure */
    const int saturated = f->par.consolidation;
    double asum = 0, Fx = 0, Fy = 0;
    for (int k = k0; k < k1; k++) {
        const pl_fl_cover *cv = &f->cover[k];
        const int e = cv->elem;
        double gx = rg * (f->grad[2 * e] - upx), gy = rg * (f->grad[2 * e + 1] - upy);
        /* a piece beyond the boundary: wet only where the extended field is positive (a grain
           poking through a free surface at the mesh top is dry there, saturated or not) */
        if (!saturated || cv->outside) {
            double pc = p_in(f, e, c);
            if (!(pc > 0) || pc * pc <= r * r * (gx * gx + gy * gy) * (1 + 1e-9)) return 0;
        }
        asum += cv->area;
        Fx -= cv->area * gx;
        Fy -= cv->area * gy;
    }
    const double ad = PL_FL_PI * r * r;
    /* part of the disc outside the mesh and not folded into it (a disc crossing the boundary as
       a solid): the outline integral, with p = 0 beyond the boundary. A grain pressed into a wall
       at the mesh's edge has its outside part among its pieces (flagged outside), so the sum is
       its whole area. */
    if (fabs(asum - ad) > 1e-9 * ad) return 0;
    force->x += Fx;
    force->y += Fy;
    return 1;
}

void pl_fl_body_force(const struct pl_fluid *f, const pl_fl_bodies *b, int i, pl_vec2 *force, double *moment) {
    int sh = b->shape[i];
    /* a grain pressed into a wall at the mesh's edge, whatever the porosity method and whether
       or not pieces are cut (drag off, uniform permeability, no consolidation: the thesis's
       force mode) */
    edge_ext ext = {.m = &f->mesh, .c = b->pos[i], .r = b->radius[i]};
    if (f->body_cover_start && i < f->cover_bodies) {
        /* pieces were cut for the body: the elements its outside pieces were folded into, so that
           the force and the consolidation source use the same pieces (also while they are
           lagged, FLUID_POROSITY_TIMESTEPS: the coupling stays work-consistent) */
        ext.found = 1;
        for (int k = f->body_cover_start[i]; k < f->body_cover_start[i + 1]; k++)
            if (f->cover[k].outside && ext.n < PL_FL_EDGE_MAX) ext.elem[ext.n++] = f->cover[k].elem;
    }
    if (sh == PL_SHAPE_DISC) {
        if (!disc_force_covers(f, b, i, force)) disc_force_ext(f, b->pos[i], b->radius[i], &ext, force);
    }
    else if (sh == PL_SHAPE_POLYGON) {
        ext.v = &b->verts[b->vert_offset[i]];
        ext.nv = b->vert_count[i];
        polygon_force_ext(f, ext.v, ext.nv, b->pos[i], &ext, force, moment);
    }
    else return;
    if (f->par.drag && f->body_cover_start && i < f->cover_bodies) { /* bodies added since: none yet */
        const double rg = f->par.density * f->par.g;
        /* the drag follows the flux q = -D (grad h + a/g): in an accelerating frame the part of
           grad h that accelerates the water (-a/g) drives no flow */
        const pl_vec2 fa = pl_fl_frame_gradient(f);
        for (int k = f->body_cover_start[i]; k < f->body_cover_start[i + 1]; k++) {
            const pl_fl_cover *cv = &f->cover[k];
            double w = cv->area * f->voidr[cv->elem] * rg;
            force->x -= w * (f->grad[2 * cv->elem] + fa.x);
            force->y -= w * (f->grad[2 * cv->elem + 1] + fa.y);
        }
    }
}
