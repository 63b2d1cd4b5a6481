/* Antialiased rasterizer for small primitives (see raster_aa.h).
 *
 * A shape is a closed outline of straight edges. Its coverage is computed exactly (the area
 * of each pixel inside the outline) by accumulating, for every edge and pixel row, the signed
 * area the edge leaves to its right into a small buffer over the shape's bounding box; a
 * running sum along each row then gives the winding-weighted coverage (0..1 for the simple
 * shapes and rings built here). The coverage is folded into the batch by a per-pixel maximum
 * and the touched rectangles are remembered; compositing visits them once. */
#include "raster_aa.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double TOLERANCE = 0.1; /* px, cairo's default flattening tolerance */

/* min, max, floor and ceil inline (the libm calls cost more than the arithmetic here) */
static inline double dmin(double a, double b) { return a < b ? a : b; }
static inline double dmax(double a, double b) { return a > b ? a : b; }
static inline int ifloor(double v) {
    int i = (int)v;
    return (double)i > v ? i - 1 : i;
}
static inline int iceil(double v) {
    int i = (int)v;
    return (double)i < v ? i + 1 : i;
}

typedef struct aa_rect {
    int x0, y0, x1, y1; /* pixels [x0, x1) x [y0, y1) */
} aa_rect;

struct pl_aa {
    int w, h;
    float *batch;            /* w * h coverage of the current batch (0 outside shapes) */
    float *acc;              /* accumulation buffer of one shape */
    size_t acc_cap;
    pl_vec2 *pts;            /* outline points of the shape being built */
    int npts, pts_cap;
    int *rlo, *rhi;          /* per row of the shape: first and past-last column touched */
    int row_cap;
    int *starts;             /* first point of each closed contour */
    int ncont, cont_cap;
    aa_rect *rects;          /* touched rectangles of the batch */
    int nrects, rect_cap;
    double cx0, cy0, cx1, cy1; /* clip */
    uint32_t *idata;         /* immediate mode: shapes composited as they come */
    int istride;             /* in pixels */
    unsigned sa, sr, sg, sb; /* colour, premultiplied 8-bit */
    int pen_n;               /* cos/sin of 2 pi i / pen_n: the pen of round caps and joins */
    double *pcos, *psin;
    int failed;
};

pl_aa *pl_aa_create(int width, int height) {
    pl_aa *aa = calloc(1, sizeof *aa);
    if (!aa) return NULL;
    aa->w = width;
    aa->h = height;
    aa->batch = calloc((size_t)width * (size_t)height, sizeof *aa->batch);
    if (!aa->batch) {
        free(aa);
        return NULL;
    }
    pl_aa_begin(aa, 0, 0, width, height);
    return aa;
}

void pl_aa_destroy(pl_aa *aa) {
    if (!aa) return;
    free(aa->batch);
    free(aa->acc);
    free(aa->pts);
    free(aa->starts);
    free(aa->rlo);
    free(aa->rhi);
    free(aa->rects);
    free(aa->pcos);
    free(aa->psin);
    free(aa);
}

void pl_aa_begin(pl_aa *aa, double x0, double y0, double x1, double y1) {
    aa->cx0 = fmax(x0, 0.0);
    aa->cy0 = fmax(y0, 0.0);
    aa->cx1 = fmin(x1, (double)aa->w);
    aa->cy1 = fmin(y1, (double)aa->h);
    aa->nrects = 0;
    aa->npts = aa->ncont = 0;
    aa->idata = NULL;
}

static void set_color(pl_aa *aa, pl_rgba color) {
    float a = color.a < 0.0f ? 0.0f : (color.a > 1.0f ? 1.0f : color.a);
    aa->sa = (unsigned)(a * 255.0f + 0.5f);
    aa->sr = (unsigned)(color.r * a * 255.0f + 0.5f);
    aa->sg = (unsigned)(color.g * a * 255.0f + 0.5f);
    aa->sb = (unsigned)(color.b * a * 255.0f + 0.5f);
}

void pl_aa_immediate(pl_aa *aa, uint8_t *data, int stride, pl_rgba color) {
    aa->idata = (uint32_t *)(void *)data;
    aa->istride = stride / 4;
    set_color(aa, color);
}

static inline unsigned mul_un8(unsigned a, unsigned b) {
    unsigned t = a * b + 128u;
    return ((t >> 8) + t) >> 8;
}

/* OVER of the colour with coverage c (0..1] onto a premultiplied ARGB32 pixel */
static inline uint32_t blend(const pl_aa *aa, uint32_t d, float c) {
    unsigned m = (unsigned)(c * 255.0f + 0.5f);
    if (m == 0) return d;
    unsigned ma = mul_un8(aa->sa, m), inv = 255u - ma;
    unsigned da = d >> 24, dr = (d >> 16) & 255u, dg = (d >> 8) & 255u, db = d & 255u;
    da = ma + mul_un8(da, inv);
    dr = mul_un8(aa->sr, m) + mul_un8(dr, inv);
    dg = mul_un8(aa->sg, m) + mul_un8(dg, inv);
    db = mul_un8(aa->sb, m) + mul_un8(db, inv);
    return (uint32_t)(da > 255u ? 255u : da) << 24 | (dr > 255u ? 255u : dr) << 16 |
           (dg > 255u ? 255u : dg) << 8 | (db > 255u ? 255u : db);
}

static int convex_outline(pl_aa *aa, const pl_vec2 *p, int n, double w, int add);

/* ------------------------------------------------------------ shape building */

/* to 1/256 px, as cairo's 24.8 fixed point (coordinates are clamped to +-2^22 px) */
static inline double snap(double v) {
    if (!(v > -4194304.0)) v = -4194304.0;
    if (v > 4194304.0) v = 4194304.0;
    return ifloor(v * 256.0 + 0.5) * (1.0 / 256.0);
}

static void contour_start(pl_aa *aa) {
    if (aa->ncont == aa->cont_cap) {
        int nc = aa->cont_cap ? 2 * aa->cont_cap : 8;
        int *s = realloc(aa->starts, (size_t)(nc + 1) * sizeof *s);
        if (!s) {
            aa->failed = 1;
            return;
        }
        aa->starts = s;
        aa->cont_cap = nc;
    }
    aa->starts[aa->ncont++] = aa->npts;
}

static void point(pl_aa *aa, double x, double y) {
    if (aa->npts == aa->pts_cap) {
        int nc = aa->pts_cap ? 2 * aa->pts_cap : 256;
        pl_vec2 *p = realloc(aa->pts, (size_t)nc * sizeof *p);
        if (!p) {
            aa->failed = 1;
            return;
        }
        aa->pts = p;
        aa->pts_cap = nc;
    }
    aa->pts[aa->npts++] = (pl_vec2){snap(x), snap(y)};
}

/* Adds the signed area of edge (x0,y0)-(x1,y1) to the accumulation rows (buffer width bw,
 * bh rows, coordinates relative to the buffer, x within [0, bw - 2]): for each pixel row the
 * edge crosses, the area between the edge and the right side of each pixel it passes, so
 * that a running sum along the row gives the exact covered area of every pixel. */
static void acc_edge(float *acc, int bw, int bh, int *lo, int *hi, double x0, double y0, double x1,
                     double y1) {
    if (y0 == y1) return;
    double dir = 1.0;
    if (y0 > y1) {
        double t = x0; x0 = x1; x1 = t;
        t = y0; y0 = y1; y1 = t;
        dir = -1.0;
    }
    double dxdy = (x1 - x0) / (y1 - y0);
    int r0 = ifloor(y0), r1 = iceil(y1);
    if (r0 < 0) r0 = 0;
    if (r1 > bh) r1 = bh;
    for (int r = r0; r < r1; r++) {
        double ya = dmax(y0, (double)r), yb = dmin(y1, (double)(r + 1));
        double dy = yb - ya;
        if (!(dy > 0.0)) continue;
        double xa = x0 + (ya - y0) * dxdy, xb = x0 + (yb - y0) * dxdy;
        double d = dy * dir;
        double xl = xa < xb ? xa : xb, xr = xa < xb ? xb : xa;
        float *row = acc + (size_t)r * (size_t)bw;
        int il = ifloor(xl), ir = iceil(xr);
        if (il < lo[r]) lo[r] = il;
        if (ir + 1 > hi[r]) hi[r] = ir + 1; /* deposits reach column ir (or il + 1) */
        if (ir <= il + 1) { /* the edge stays within pixel column il */
            double xm = 0.5 * (xa + xb) - il;
            row[il] += (float)(d * (1.0 - xm));
            row[il + 1] += (float)(d * xm);
        } else { /* across columns il .. ir-1: trapezoid areas */
            double s = 1.0 / (xr - xl);
            double f0 = xl - il;
            double a0 = 0.5 * s * (1.0 - f0) * (1.0 - f0);
            double f1 = xr - (ir - 1);
            double am = 0.5 * s * f1 * f1;
            row[il] += (float)(d * a0);
            if (ir == il + 2) {
                row[il + 1] += (float)(d * (1.0 - a0 - am));
            } else {
                double a1 = s * (1.5 - f0);
                row[il + 1] += (float)(d * (a1 - a0));
                for (int i = il + 2; i < ir - 1; i++) row[i] += (float)(d * s);
                double a2 = a1 + (ir - il - 3) * s;
                row[ir - 1] += (float)(d * (1.0 - a2 - am));
            }
            row[ir] += (float)(d * am);
        }
    }
}

/* Rasterizes the contours built so far as one shape into the batch and clears them. */
static void shape_end(pl_aa *aa) {
    int np = aa->npts, nc = aa->ncont;
    aa->npts = aa->ncont = 0;
    if (aa->failed || np < 3 || nc < 1) return;
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (int i = 0; i < np; i++) {
        pl_vec2 q = aa->pts[i];
        x0 = dmin(x0, q.x);
        x1 = dmax(x1, q.x);
        y0 = dmin(y0, q.y);
        y1 = dmax(y1, q.y);
    }
    if (!(isfinite(x0) && isfinite(x1) && isfinite(y0) && isfinite(y1))) return;
    /* the rectangle of pixels to rasterize: the shape's box within the clip */
    int px0 = ifloor(dmax(x0, aa->cx0)), px1 = iceil(dmin(x1, aa->cx1));
    int py0 = ifloor(dmax(y0, aa->cy0)), py1 = iceil(dmin(y1, aa->cy1));
    if (px1 <= px0 || py1 <= py0) return;
    int bw = px1 - px0 + 2, bh = py1 - py0;
    size_t need = (size_t)bw * (size_t)bh;
    if (need > aa->acc_cap) {
        float *a = realloc(aa->acc, need * sizeof *a);
        if (!a) {
            aa->failed = 1;
            return;
        }
        aa->acc = a;
        aa->acc_cap = need;
    }
    if (bh > aa->row_cap) {
        int *lo = realloc(aa->rlo, (size_t)bh * sizeof *lo);
        if (lo) aa->rlo = lo;
        int *hi = realloc(aa->rhi, (size_t)bh * sizeof *hi);
        if (hi) aa->rhi = hi;
        if (!lo || !hi) {
            aa->failed = 1;
            return;
        }
        aa->row_cap = bh;
    }
    memset(aa->acc, 0, need * sizeof *aa->acc);
    for (int r = 0; r < bh; r++) {
        aa->rlo[r] = bw;
        aa->rhi[r] = 0;
    }
    /* x clamped into the buffer: outside parts move onto its left or right border, which
     * keeps every pixel's coverage inside (the running sum starts at the left border) */
    double xmax = px1 - px0;
    aa->starts[nc] = np;
    for (int c = 0; c < nc; c++) {
        int a = aa->starts[c], b = aa->starts[c + 1];
        for (int i = a; i < b; i++) {
            pl_vec2 p = aa->pts[i], q = aa->pts[i + 1 < b ? i + 1 : a];
            double ax = dmin(dmax(p.x - px0, 0.0), xmax), bx = dmin(dmax(q.x - px0, 0.0), xmax);
            acc_edge(aa->acc, bw, bh, aa->rlo, aa->rhi, ax, p.y - py0, bx, q.y - py0);
        }
    }
    /* clip coverage at fractional clip borders */
    for (int r = 0; r < bh; r++) {
        int y = py0 + r;
        double fy = dmin(y + 1.0, aa->cy1) - dmax((double)y, aa->cy0);
        const float *row = aa->acc + (size_t)r * (size_t)bw;
        float *out = aa->batch + (size_t)y * (size_t)aa->w;
        uint32_t *px = aa->idata ? aa->idata + (size_t)y * (size_t)aa->istride : NULL;
        float run = 0.0f;
        /* before the first deposit of the row the sum is 0; after the last it is the
         * row's total winding, 0 for closed outlines */
        int i_end = aa->rhi[r] < px1 - px0 ? aa->rhi[r] : px1 - px0;
        for (int i = aa->rlo[r]; i < i_end; i++) {
            run += row[i];
            float cov = fabsf(run);
            if (cov <= 0.0f) continue;
            if (cov > 1.0f) cov = 1.0f;
            int x = px0 + i;
            if (fy < 1.0 || x < aa->cx0 || x + 1 > aa->cx1) {
                double fx = dmin(x + 1.0, aa->cx1) - dmax((double)x, aa->cx0);
                cov *= (float)(dmax(0.0, fx) * dmax(0.0, fy));
            }
            if (px) px[x] = blend(aa, px[x], cov);
            else if (cov > out[x]) out[x] = cov;
        }
    }
    if (aa->idata) return;
    if (aa->nrects == aa->rect_cap) {
        int ncap = aa->rect_cap ? 2 * aa->rect_cap : 64;
        aa_rect *r = realloc(aa->rects, (size_t)ncap * sizeof *r);
        if (!r) {
            aa->failed = 1;
            return;
        }
        aa->rects = r;
        aa->rect_cap = ncap;
    }
    aa->rects[aa->nrects++] = (aa_rect){px0, py0, px1, py1};
}

void pl_aa_polygon(pl_aa *aa, const pl_vec2 *p, int n) {
    if (n < 3) return;
    contour_start(aa);
    for (int i = 0; i < n; i++) point(aa, p[i].x, p[i].y);
    shape_end(aa);
}

/* ---- circles as cairo makes them: cairo_arc splits the circle into two half turns, each
 * into Bezier arcs of at most the angle its error table allows for tolerance / r
 * (cairo-arc.c), and the fill flattens each Bezier by halving in 24.8 fixed point until its
 * control points lie within the tolerance of the chord (cairo-spline.c). Doing the same
 * gives cairo's very polygon, so discs match cairo's pixels closely. */

typedef struct fixpt {
    int32_t x, y;
} fixpt;

static inline int32_t to_fixed(double v) { return (int32_t)ifloor(v * 256.0 + 0.5); }

static double arc_max_angle(double tol) {
    static const struct { double angle, error; } table[] = {
        {M_PI / 1.0, 0.0185185185185185036127},  {M_PI / 2.0, 0.000272567143730179811158},
        {M_PI / 3.0, 2.38647043651461047433e-05}, {M_PI / 4.0, 4.2455377443222443279e-06},
        {M_PI / 5.0, 1.11281001494389081528e-06}, {M_PI / 6.0, 3.72662000942734705475e-07},
        {M_PI / 7.0, 1.47783685574284411325e-07}, {M_PI / 8.0, 6.63240432022601149057e-08},
        {M_PI / 9.0, 3.2715520137536980553e-08},  {M_PI / 10.0, 1.73863223499021216974e-08},
        {M_PI / 11.0, 9.81410988043554039085e-09}};
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
        if (table[i].error < tol) return table[i].angle;
    return M_PI / 11.0; /* radii above ~1e7 px; not reached here */
}

static double spline_error_sq(const fixpt k[4]) {
    double bdx = (k[1].x - k[0].x) / 256.0, bdy = (k[1].y - k[0].y) / 256.0;
    double cdx = (k[2].x - k[0].x) / 256.0, cdy = (k[2].y - k[0].y) / 256.0;
    if (k[0].x != k[3].x || k[0].y != k[3].y) {
        double dx = (k[3].x - k[0].x) / 256.0, dy = (k[3].y - k[0].y) / 256.0;
        double u = dx * dx + dy * dy, v = bdx * dx + bdy * dy;
        if (v > 0.0) {
            if (v >= u) { bdx -= dx; bdy -= dy; }
            else { bdx -= v / u * dx; bdy -= v / u * dy; }
        }
        v = cdx * dx + cdy * dy;
        if (v > 0.0) {
            if (v >= u) { cdx -= dx; cdy -= dy; }
            else { cdx -= v / u * dx; cdy -= v / u * dy; }
        }
    }
    double berr = bdx * bdx + bdy * bdy, cerr = cdx * cdx + cdy * cdy;
    return berr > cerr ? berr : cerr;
}

static inline fixpt half(fixpt a, fixpt b) {
    return (fixpt){a.x + ((b.x - a.x) >> 1), a.y + ((b.y - a.y) >> 1)};
}

/* Emits the start points of the flat pieces of Bezier k (its end point is the next start). */
static void flatten(pl_aa *aa, fixpt k[4], double tol_sq, int depth) {
    if (depth > 16 || spline_error_sq(k) < tol_sq) {
        point(aa, k[0].x / 256.0, k[0].y / 256.0);
        return;
    }
    fixpt ab = half(k[0], k[1]), bc = half(k[1], k[2]), cd = half(k[2], k[3]);
    fixpt abbc = half(ab, bc), bccd = half(bc, cd), mid = half(abbc, bccd);
    fixpt s1[4] = {k[0], ab, abbc, mid}, s2[4] = {mid, bccd, cd, k[3]};
    flatten(aa, s1, tol_sq, depth + 1);
    flatten(aa, s2, tol_sq, depth + 1);
}

static void circle_contour(pl_aa *aa, pl_vec2 c, double r, int reverse) {
    int start = aa->npts;
    contour_start(aa);
    double max_angle = arc_max_angle(TOLERANCE / r);
    int segs = (int)ceil(M_PI / max_angle - 1e-12); /* per half turn */
    double step = M_PI / segs, h = 4.0 / 3.0 * tan(step / 4.0);
    for (int half_turn = 0; half_turn < 2; half_turn++)
        for (int k = 0; k < segs; k++) {
            double a = half_turn * M_PI + k * step, b = a + step;
            double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b);
            fixpt kn[4] = {
                {to_fixed(c.x + r * ca), to_fixed(c.y + r * sa)},
                {to_fixed(c.x + r * ca - r * h * sa), to_fixed(c.y + r * sa + r * h * ca)},
                {to_fixed(c.x + r * cb + r * h * sb), to_fixed(c.y + r * sb - r * h * cb)},
                {to_fixed(c.x + r * cb), to_fixed(c.y + r * sb)}};
            flatten(aa, kn, TOLERANCE * TOLERANCE, 0);
        }
    if (reverse) { /* reverse the contour's points in place */
        for (int i = start, j = aa->npts - 1; i < j; i++, j--) {
            pl_vec2 t = aa->pts[i];
            aa->pts[i] = aa->pts[j];
            aa->pts[j] = t;
        }
    }
}

void pl_aa_circle(pl_aa *aa, pl_vec2 c, double r) {
    if (!(r > 0.0)) return;
    circle_contour(aa, c, r, 0);
    shape_end(aa);
}

void pl_aa_ring(pl_aa *aa, pl_vec2 c, double r0, double r1) {
    if (!(r1 > 0.0)) return;
    /* a stroked circle as cairo strokes it: its flattened polygon (radius (r0 + r1) / 2)
     * offset both ways by the half width, round joins at the corners */
    double r = 0.5 * (r0 + r1), w = r1 - r0;
    enum { MAXP = 512 };
    pl_vec2 poly[MAXP];
    int start = aa->npts, nc = aa->ncont;
    circle_contour(aa, c, r, 0);
    int n = aa->npts - start;
    if (n >= 3 && n <= MAXP && r0 > 0.0) {
        memcpy(poly, aa->pts + start, (size_t)n * sizeof *poly);
        aa->npts = start;
        aa->ncont = nc;
        if (convex_outline(aa, poly, n, w, 1) == 0) return;
    }
    aa->npts = start;
    aa->ncont = nc;
    circle_contour(aa, c, r1, 0);
    if (r0 > 0.0) circle_contour(aa, c, r0, 1);
    shape_end(aa);
}

static int trig_table_pen(pl_aa *aa, int n) {
    if (aa->pen_n == n) return 0;
    double *c = realloc(aa->pcos, (size_t)n * sizeof *c);
    if (c) aa->pcos = c;
    double *s = realloc(aa->psin, (size_t)n * sizeof *s);
    if (s) aa->psin = s;
    if (!c || !s) {
        aa->pen_n = 0;
        return -1;
    }
    for (int i = 0; i < n; i++) {
        aa->pcos[i] = cos(2.0 * M_PI * i / n);
        aa->psin[i] = sin(2.0 * M_PI * i / n);
    }
    aa->pen_n = n;
    return 0;
}

/* Vertices of cairo's pen for a round cap or join of radius r (cairo-pen.c: enough vertices
 * that the polygon stays within the tolerance of the circle; an even count, at least 4). */
static int pen_vertices(double r) {
    if (TOLERANCE >= 4.0 * r) return 1;
    if (TOLERANCE >= r) return 4;
    double delta = acos(1.0 - TOLERANCE / r);
    int n = (int)ceil(2.0 * M_PI / delta);
    if (n % 2) n++;
    return n < 4 ? 4 : n;
}

/* Points of a round arc of radius hw around c from direction angle a0 turning by `sweep`
 * (radians, signed): the two ends exactly, and between them cairo's pen vertices (angles that
 * are multiples of 2 pi / pen_vertices). */
static void arc_points(pl_aa *aa, pl_vec2 c, double hw, double a0, double sweep) {
    point(aa, c.x + hw * cos(a0), c.y + hw * sin(a0));
    int np = pen_vertices(hw);
    if (np >= 4 && trig_table_pen(aa, np) == 0) {
        double step = 2.0 * M_PI / np;
        double sgn = sweep > 0.0 ? 1.0 : -1.0, total = fabs(sweep);
        double k0 = a0 / step;
        int count = (int)(total / step) + 2;
        for (int i = 1; i <= count; i++) {
            double idx = sgn > 0.0 ? floor(k0) + i : ceil(k0) - i;
            double off = (idx * step - a0) * sgn;
            if (off <= 1e-9) continue;
            if (off >= total - 1e-9) break;
            int k = (int)idx % np;
            if (k < 0) k += np;
            point(aa, c.x + hw * aa->pcos[k], c.y + hw * aa->psin[k]);
        }
    }
    point(aa, c.x + hw * cos(a0 + sweep), c.y + hw * sin(a0 + sweep));
}

void pl_aa_capsule(pl_aa *aa, pl_vec2 a, pl_vec2 b, double w) {
    double hw = 0.5 * w;
    double dx = b.x - a.x, dy = b.y - a.y, len = sqrt(dx * dx + dy * dy);
    if (!(hw > 0.0)) return;
    if (!(len > 1e-9)) {
        pl_aa_circle(aa, a, hw);
        return;
    }
    double an = atan2(dx, -dy); /* direction of the normal (-dy, dx) / len */
    contour_start(aa);
    arc_points(aa, b, hw, an, -M_PI);          /* b + n, around the far side, to b - n */
    arc_points(aa, a, hw, an + M_PI, -M_PI);   /* a - n, around, to a + n */
    shape_end(aa);
}

void pl_aa_bar(pl_aa *aa, pl_vec2 a, pl_vec2 b, double w) {
    double hw = 0.5 * w;
    double dx = b.x - a.x, dy = b.y - a.y, len = sqrt(dx * dx + dy * dy);
    if (!(hw > 0.0) || !(len > 1e-9)) return;
    double nx = -dy / len * hw, ny = dx / len * hw;
    contour_start(aa);
    point(aa, a.x + nx, a.y + ny);
    point(aa, b.x + nx, b.y + ny);
    point(aa, b.x - nx, b.y - ny);
    point(aa, a.x - nx, a.y - ny);
    shape_end(aa);
}

enum { MAX_OUTLINE = 512 };

static int convex_outline(pl_aa *aa, const pl_vec2 *p, int n, double w, int add) {
    if (n < 3 || n > MAX_OUTLINE || !(w > 0.0)) return -1;
    /* orientation and convexity */
    double area = 0.0;
    for (int i = 0; i < n; i++) area += p[i].x * p[(i + 1) % n].y - p[(i + 1) % n].x * p[i].y;
    if (!(fabs(area) > 0.0)) return -1;
    double s = area > 0.0 ? 1.0 : -1.0;
    double hw = 0.5 * w;
    pl_vec2 nrm[MAX_OUTLINE];
    double off[MAX_OUTLINE];
    for (int i = 0; i < n; i++) {
        pl_vec2 a = p[i], b = p[(i + 1) % n], c = p[(i + 2) % n];
        double cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
        if (cross * s < 0.0) return -1;
        double dx = b.x - a.x, dy = b.y - a.y, len = sqrt(dx * dx + dy * dy);
        if (!(len > 1e-9)) return -1;
        /* outward normal of edge i (area > 0 in screen coordinates: clockwise on screen) */
        nrm[i] = (pl_vec2){s * dy / len, -s * dx / len};
        off[i] = nrm[i].x * a.x + nrm[i].y * a.y; /* edge line: n . x = off */
    }
    /* inner polygon: edges moved inwards by hw; it must keep all n edges (small polygons or
     * wide lines would turn it inside out: let cairo draw those) */
    pl_vec2 in[MAX_OUTLINE];
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n; /* vertex between edges i and j */
        double a1 = nrm[i].x, b1 = nrm[i].y, c1 = off[i] - hw;
        double a2 = nrm[j].x, b2 = nrm[j].y, c2 = off[j] - hw;
        double det = a1 * b2 - a2 * b1;
        if (!(fabs(det) > 1e-12)) return -1;
        in[i] = (pl_vec2){(c1 * b2 - c2 * b1) / det, (a1 * c2 - a2 * c1) / det};
    }
    for (int i = 0; i < n; i++) { /* inner edge i runs from in[i-1] to in[i] along edge i */
        pl_vec2 a = in[(i + n - 1) % n], b = in[i];
        pl_vec2 e = {p[(i + 1) % n].x - p[i].x, p[(i + 1) % n].y - p[i].y};
        if ((b.x - a.x) * e.x + (b.y - a.y) * e.y <= 0.0) return -1;
    }
    if (!add) return 0;
    /* outer contour: each edge moved out by hw, round arcs around the vertices */
    contour_start(aa);
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        pl_vec2 b = p[j];
        double ai = atan2(nrm[i].y, nrm[i].x), aj = atan2(nrm[j].y, nrm[j].x);
        double sweep = aj - ai;
        while (sweep > M_PI) sweep -= 2.0 * M_PI;
        while (sweep < -M_PI) sweep += 2.0 * M_PI;
        arc_points(aa, b, hw, ai, sweep);
    }
    /* inner contour, reversed */
    contour_start(aa);
    for (int i = n - 1; i >= 0; i--) point(aa, in[i].x, in[i].y);
    shape_end(aa);
    return 0;
}

int pl_aa_convex_outline(pl_aa *aa, const pl_vec2 *p, int n, double w) {
    return convex_outline(aa, p, n, w, 1);
}

int pl_aa_convex_outline_check(const pl_vec2 *p, int n, double w) {
    return convex_outline(NULL, p, n, w, 0);
}

/* -------------------------------------------------------------- compositing */

int pl_aa_fill(pl_aa *aa, uint8_t *data, int stride, pl_rgba color) {
    set_color(aa, color);
    for (int k = 0; k < aa->nrects; k++) {
        aa_rect r = aa->rects[k];
        for (int y = r.y0; y < r.y1; y++) {
            float *cov = aa->batch + (size_t)y * (size_t)aa->w;
            uint32_t *row = (uint32_t *)(void *)(data + (size_t)y * (size_t)stride);
            for (int x = r.x0; x < r.x1; x++) {
                float c = cov[x];
                if (c <= 0.0f) continue;
                cov[x] = 0.0f; /* composited once, even where rectangles overlap */
                row[x] = blend(aa, row[x], c);
            }
        }
    }
    int rc = aa->failed ? -1 : 0;
    aa->nrects = 0;
    aa->failed = 0;
    aa->idata = NULL;
    return rc;
}
