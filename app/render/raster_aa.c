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
    uint8_t *batch;          /* w * h coverage of the current batch, 0..255 (0 outside shapes) */
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
    uint32_t src;            /* the same as a premultiplied ARGB32 pixel */
    int pen_n;               /* cos/sin of 2 pi i / pen_n: the pen of round caps and joins */
    double *pcos, *psin;
    int failed;
    /* sum batches: every shape's edges go into one accumulation buffer over the image
     * ((w + 2) x h, zero between batches), composited by one running sum per row */
    int sum;
    float *facc;
    int *frlo, *frhi;        /* per image row: first and past-last column deposited */
    /* segment coverage by distance, tabulated for the last width (see seg_lut) */
    double lut_hw;
    int lut_n;
    uint8_t *lut;
    uint8_t lut_ok[16];
    int incr;                /* incremental batch (see pl_aa_incremental) */
    struct {                 /* flattened unit circles, by arcs per half turn and depth */
        int segs, depth, n;
        pl_vec2 *pts;
    } circ[8];
    int ncirc;
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
    free(aa->facc);
    free(aa->lut);
    for (int i = 0; i < aa->ncirc; i++) free(aa->circ[i].pts);
    free(aa->frlo);
    free(aa->frhi);
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
    aa->sum = 0;
    aa->incr = 0;
}

int pl_aa_begin_sum(pl_aa *aa, double x0, double y0, double x1, double y1) {
    pl_aa_begin(aa, x0, y0, x1, y1);
    if (!aa->facc) {
        aa->facc = calloc((size_t)(aa->w + 2) * (size_t)aa->h, sizeof *aa->facc);
        aa->frlo = malloc((size_t)aa->h * sizeof *aa->frlo);
        aa->frhi = malloc((size_t)aa->h * sizeof *aa->frhi);
        if (!aa->facc || !aa->frlo || !aa->frhi) {
            free(aa->facc);
            free(aa->frlo);
            free(aa->frhi);
            aa->facc = NULL;
            aa->frlo = aa->frhi = NULL;
            return -1;
        }
        for (int y = 0; y < aa->h; y++) {
            aa->frlo[y] = aa->w + 2;
            aa->frhi[y] = 0;
        }
    }
    aa->sum = 1;
    return 0;
}

static void set_color(pl_aa *aa, pl_rgba color) {
    float a = color.a < 0.0f ? 0.0f : (color.a > 1.0f ? 1.0f : color.a);
    aa->sa = (unsigned)(a * 255.0f + 0.5f);
    aa->sr = (unsigned)(color.r * a * 255.0f + 0.5f);
    aa->sg = (unsigned)(color.g * a * 255.0f + 0.5f);
    aa->sb = (unsigned)(color.b * a * 255.0f + 0.5f);
    aa->src = (uint32_t)aa->sa << 24 | aa->sr << 16 | aa->sg << 8 | aa->sb;
}

void pl_aa_immediate(pl_aa *aa, uint8_t *data, int stride, pl_rgba color) {
    aa->idata = (uint32_t *)(void *)data;
    aa->istride = stride / 4;
    set_color(aa, color);
}

void pl_aa_incremental(pl_aa *aa, uint8_t *data, int stride, pl_rgba color) {
    pl_aa_immediate(aa, data, stride, color);
    aa->incr = 1;
}

/* the coverage that, composited over a pixel already composited with coverage m0 of the same
 * colour, makes it composited with m > m0: 1 - (1 - m0)(1 - x) = m */
static inline unsigned incr_cov(unsigned m0, unsigned m) {
    if (!m0) return m;
    return ((m - m0) * 255u + (255u - m0) / 2u) / (255u - m0);
}

static inline unsigned mul_un8(unsigned a, unsigned b) {
    unsigned t = a * b + 128u;
    return ((t >> 8) + t) >> 8;
}

/* OVER of the colour with coverage c (0..1] onto a premultiplied ARGB32 pixel */
static inline unsigned cov8(float c) { return (unsigned)(c * 255.0f + 0.5f); }

/* x * a / 255 rounded, on the four 8-bit channels of x at once (pixman's UN8x4_MUL_UN8: the
 * same rounding as mul_un8 per channel) */
static inline uint32_t mul4_un8(uint32_t x, unsigned a) {
    uint32_t rb = (x & 0x00FF00FFu) * a + 0x00800080u;
    rb = ((rb + ((rb >> 8) & 0x00FF00FFu)) >> 8) & 0x00FF00FFu;
    uint32_t ag = ((x >> 8) & 0x00FF00FFu) * a + 0x00800080u;
    ag = ((ag + ((ag >> 8) & 0x00FF00FFu)) >> 8) & 0x00FF00FFu;
    return rb | ag << 8;
}

/* channel-wise saturating x + y (pixman's UN8x4_ADD_UN8x4) */
static inline uint32_t add4_un8(uint32_t x, uint32_t y) {
    uint32_t rb = (x & 0x00FF00FFu) + (y & 0x00FF00FFu);
    rb = (rb | (0x10000100u - ((rb >> 8) & 0x00FF00FFu))) & 0x00FF00FFu;
    uint32_t ag = ((x >> 8) & 0x00FF00FFu) + ((y >> 8) & 0x00FF00FFu);
    ag = (ag | (0x10000100u - ((ag >> 8) & 0x00FF00FFu))) & 0x00FF00FFu;
    return rb | ag << 8;
}

/* OVER of the colour with 8-bit coverage m onto a premultiplied ARGB32 pixel */
static inline __attribute__((always_inline)) uint32_t blend8(const pl_aa *aa, uint32_t d,
                                                             unsigned m) {
    if (m == 0) return d;
    if (m == 255u && aa->sa == 255u) return aa->src; /* opaque: the colour itself */
    unsigned inv = 255u - mul_un8(aa->sa, m);
    return add4_un8(mul4_un8(aa->src, m), mul4_un8(d, inv));
}

static inline __attribute__((always_inline)) uint32_t blend(const pl_aa *aa, uint32_t d, float c) {
    return blend8(aa, d, cov8(c));
}

static int convex_outline(pl_aa *aa, const pl_vec2 *p, int n, double w, int add);

/* ------------------------------------------------------------ shape building */

/* to 1/256 px, as cairo's 24.8 fixed point (coordinates are clamped to +-2^22 px) */
static inline double snap(double v) {
    if (!(v > -4194304.0)) v = -4194304.0;
    if (v > 4194304.0) v = 4194304.0;
    return ifloor(v * 256.0 + 0.5) * (1.0 / 256.0);
}

/* Room for one more element in the growing array *arr of `used` elements (capacity *cap,
   doubling from `first`; `spare` elements are allocated beyond the capacity). 0, with
   aa->failed set, when out of memory. */
static int room(pl_aa *aa, void **arr, int *cap, int used, int first, size_t elem, int spare) {
    if (used < *cap) return 1;
    int nc = *cap ? 2 * *cap : first;
    void *p = realloc(*arr, (size_t)(nc + spare) * elem);
    if (!p) {
        aa->failed = 1;
        return 0;
    }
    *arr = p;
    *cap = nc;
    return 1;
}

static void contour_start(pl_aa *aa) {
    /* one spare slot: the contour list is closed with the end of the last contour */
    if (room(aa, (void **)&aa->starts, &aa->cont_cap, aa->ncont, 8, sizeof *aa->starts, 1))
        aa->starts[aa->ncont++] = aa->npts;
}

static void point(pl_aa *aa, double x, double y) {
    if (room(aa, (void **)&aa->pts, &aa->pts_cap, aa->npts, 256, sizeof *aa->pts, 0))
        aa->pts[aa->npts++] = (pl_vec2){snap(x), snap(y)};
}

static void push_rect(pl_aa *aa, aa_rect r) {
    if (room(aa, (void **)&aa->rects, &aa->rect_cap, aa->nrects, 64, sizeof *aa->rects, 0))
        aa->rects[aa->nrects++] = r;
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
    double ady_dx = dxdy != 0.0 ? 1.0 / fabs(dxdy) : 0.0; /* |dy/dx| */
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
        if (ir <= il + 1) { /* the edge stays within pixel column il */
            if (il + 2 > hi[r]) hi[r] = il + 2; /* deposits reach column il + 1 */
            double xm = 0.5 * (xa + xb) - il;
            row[il] += (float)(d * (1.0 - xm));
            row[il + 1] += (float)(d * xm);
        } else { /* across columns il .. ir-1: trapezoid areas */
            if (ir + 1 > hi[r]) hi[r] = ir + 1; /* deposits reach column ir */
            /* 1 / (xr - xl), with xr - xl = |dx/dy| dy */
            double s = dy >= 1.0 ? ady_dx : ady_dx / dy;
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
    if (aa->sum) { /* deposit into the image-wide buffer; composited by pl_aa_fill */
        int fbw = aa->w + 2;
        double xlo = px0, xhi = px1;
        aa->starts[nc] = np;
        for (int c = 0; c < nc; c++) {
            int a = aa->starts[c], b = aa->starts[c + 1];
            for (int i = a; i < b; i++) {
                pl_vec2 p = aa->pts[i], q = aa->pts[i + 1 < b ? i + 1 : a];
                double ax = dmin(dmax(p.x, xlo), xhi), bx = dmin(dmax(q.x, xlo), xhi);
                acc_edge(aa->facc + (size_t)py0 * (size_t)fbw, fbw, py1 - py0, aa->frlo + py0,
                         aa->frhi + py0, ax, p.y - py0, bx, q.y - py0);
            }
        }
        return;
    }
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
    /* clip coverage at fractional clip borders (pixels outside [in_x0, in_x1) are cut) */
    int in_x0 = iceil(aa->cx0), in_x1 = ifloor(aa->cx1);
    for (int r = 0; r < bh; r++) {
        int y = py0 + r;
        double fy = dmin(y + 1.0, aa->cy1) - dmax((double)y, aa->cy0);
        int row_part = fy < 1.0;
        const float *row = aa->acc + (size_t)r * (size_t)bw;
        uint8_t *out = aa->batch + (size_t)y * (size_t)aa->w;
        uint32_t *px = aa->idata ? aa->idata + (size_t)y * (size_t)aa->istride : NULL;
        float run = 0.0f;
        /* before the first deposit of the row the sum is 0; after the last it is the
         * row's total winding, 0 for closed outlines */
        int i_end = aa->rhi[r] < px1 - px0 ? aa->rhi[r] : px1 - px0;
        int i_beg = aa->rlo[r];
        if (!row_part && px0 + i_beg >= in_x0 && px0 + i_end <= in_x1) {
            /* the common case: the row inside the clip */
            if (px) {
                uint32_t *dst = px + px0;
                for (int i = i_beg; i < i_end; i++) {
                    run += row[i];
                    float cov = fabsf(run);
                    unsigned m = cov >= 1.0f ? 255u : cov8(cov);
                    if (m) dst[i] = blend8(aa, dst[i], m);
                }
            } else {
                uint8_t *dst = out + px0;
                for (int i = i_beg; i < i_end; i++) {
                    run += row[i];
                    float cov = fabsf(run);
                    unsigned m = cov >= 1.0f ? 255u : cov8(cov);
                    if (m > dst[i]) dst[i] = (uint8_t)m;
                }
            }
            continue;
        }
        for (int i = i_beg; i < i_end; i++) {
            run += row[i];
            float cov = fabsf(run);
            if (cov <= 0.0f) continue;
            if (cov > 1.0f) cov = 1.0f;
            int x = px0 + i;
            if (row_part || x < in_x0 || x >= in_x1) {
                double fx = dmin(x + 1.0, aa->cx1) - dmax((double)x, aa->cx0);
                cov *= (float)(dmax(0.0, fx) * dmax(0.0, fy));
            }
            unsigned m = cov8(cov);
            if (px) px[x] = blend8(aa, px[x], m);
            else if (m > out[x]) out[x] = (uint8_t)m;
        }
    }
    if (aa->idata) return;
    push_rect(aa, (aa_rect){px0, py0, px1, py1});
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

/* the same error as spline_error_sq, on control points in double */
static double spline_error_sq_d(const pl_vec2 k[4]) {
    fixpt f[4];
    for (int i = 0; i < 4; i++) f[i] = (fixpt){to_fixed(k[i].x), to_fixed(k[i].y)};
    return spline_error_sq(f);
}

/* The points of a circle of radius 1 flattened as cairo flattens one of radius r: segs Bezier
 * arcs per half turn, each halved depth times (a circular arc's halves are symmetric, so
 * cairo halves every piece equally often). Cached per (segs, depth); NULL when out of memory. */
static const pl_vec2 *unit_circle(pl_aa *aa, int segs, int depth, int *n) {
    for (int i = 0; i < aa->ncirc; i++)
        if (aa->circ[i].segs == segs && aa->circ[i].depth == depth) {
            *n = aa->circ[i].n;
            return aa->circ[i].pts;
        }
    int per = 1 << depth, nn = 2 * segs * per;
    pl_vec2 *pts = malloc((size_t)nn * sizeof *pts);
    if (!pts) return NULL;
    double step = M_PI / segs, h = 4.0 / 3.0 * tan(step / 4.0);
    int m = 0;
    for (int half_turn = 0; half_turn < 2; half_turn++)
        for (int k = 0; k < segs; k++) {
            double a = half_turn * M_PI + k * step, b = a + step;
            double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b);
            pl_vec2 p0 = {ca, sa}, p1 = {ca - h * sa, sa + h * ca}, p2 = {cb + h * sb, sb - h * cb},
                    p3 = {cb, sb};
            for (int j = 0; j < per; j++) {
                double t = (double)j / per, u = 1.0 - t;
                double w0 = u * u * u, w1 = 3.0 * u * u * t, w2 = 3.0 * u * t * t, w3 = t * t * t;
                pts[m++] = (pl_vec2){w0 * p0.x + w1 * p1.x + w2 * p2.x + w3 * p3.x,
                                     w0 * p0.y + w1 * p1.y + w2 * p2.y + w3 * p3.y};
            }
        }
    int slot = aa->ncirc < 8 ? aa->ncirc++ : 7;
    if (slot == 7 && aa->circ[7].pts) free(aa->circ[7].pts);
    aa->circ[slot].segs = segs;
    aa->circ[slot].depth = depth;
    aa->circ[slot].n = nn;
    aa->circ[slot].pts = pts;
    *n = nn;
    return pts;
}

static void circle_contour(pl_aa *aa, pl_vec2 c, double r, int reverse) {
    int start = aa->npts;
    contour_start(aa);
    double max_angle = arc_max_angle(TOLERANCE / r);
    int segs = (int)ceil(M_PI / max_angle - 1e-12); /* per half turn */
    double step = M_PI / segs, h = 4.0 / 3.0 * tan(step / 4.0);
    /* how often cairo halves the first arc (placed at the origin plus the centre's fraction
     * of a pixel, so that its fixed-point rounding is nearly the same) */
    double fx = c.x - floor(c.x), fy = c.y - floor(c.y), cb = cos(step), sb = sin(step);
    pl_vec2 k[4] = {{fx + r, fy}, {fx + r, fy + r * h}, {fx + r * cb + r * h * sb, fy + r * sb - r * h * cb},
                    {fx + r * cb, fy + r * sb}};
    int depth = 0;
    while (depth < 12 && spline_error_sq_d(k) >= TOLERANCE * TOLERANCE) {
        pl_vec2 ab = {0.5 * (k[0].x + k[1].x), 0.5 * (k[0].y + k[1].y)};
        pl_vec2 bc = {0.5 * (k[1].x + k[2].x), 0.5 * (k[1].y + k[2].y)};
        pl_vec2 cd = {0.5 * (k[2].x + k[3].x), 0.5 * (k[2].y + k[3].y)};
        pl_vec2 abbc = {0.5 * (ab.x + bc.x), 0.5 * (ab.y + bc.y)};
        pl_vec2 bccd = {0.5 * (bc.x + cd.x), 0.5 * (bc.y + cd.y)};
        pl_vec2 mid = {0.5 * (abbc.x + bccd.x), 0.5 * (abbc.y + bccd.y)};
        k[1] = ab;
        k[2] = abbc;
        k[3] = mid;
        depth++;
    }
    int n = 0;
    const pl_vec2 *u = unit_circle(aa, segs, depth, &n);
    if (!u) {
        aa->failed = 1;
        return;
    }
    for (int i = 0; i < n; i++) point(aa, c.x + r * u[i].x, c.y + r * u[i].y);
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

static void fill_rect(pl_aa *aa, uint8_t *data, int stride, aa_rect r) {
    for (int y = r.y0; y < r.y1; y++) {
        uint8_t *cov = aa->batch + (size_t)y * (size_t)aa->w;
        uint32_t *row = (uint32_t *)(void *)(data + (size_t)y * (size_t)stride);
        int x = r.x0;
        while (x < r.x1) {
            if (x + 8 <= r.x1) { /* skip empty runs 8 pixels at a time */
                uint64_t v;
                memcpy(&v, cov + x, 8);
                if (!v) {
                    x += 8;
                    continue;
                }
            }
            unsigned c = cov[x];
            if (c) {
                cov[x] = 0; /* composited once, even where rectangles overlap */
                row[x] = blend8(aa, row[x], c);
            }
            x++;
        }
    }
}

/* composites a sum batch: one running sum per row over the deposited columns, which are
 * cleared on the way */
static void fill_sum(pl_aa *aa, uint8_t *data, int stride) {
    int fbw = aa->w + 2;
    int in_x0 = iceil(aa->cx0), in_x1 = ifloor(aa->cx1);
    for (int y = 0; y < aa->h; y++) {
        int lo = aa->frlo[y], hi = aa->frhi[y];
        if (lo >= hi) continue;
        aa->frlo[y] = fbw;
        aa->frhi[y] = 0;
        float *acc = aa->facc + (size_t)y * (size_t)fbw;
        uint32_t *row = (uint32_t *)(void *)(data + (size_t)y * (size_t)stride);
        double fy = dmin(y + 1.0, aa->cy1) - dmax((double)y, aa->cy0);
        int end = hi < aa->w ? hi : aa->w;
        float run = 0.0f;
        for (int x = lo; x < end; x++) {
            run += acc[x];
            acc[x] = 0.0f;
            float cov = fabsf(run);
            if (cov < 0.5f / 255.0f) continue;
            if (cov > 1.0f) cov = 1.0f;
            if (fy < 1.0 || x < in_x0 || x >= in_x1) {
                double fx = dmin(x + 1.0, aa->cx1) - dmax((double)x, aa->cx0);
                cov *= (float)(dmax(0.0, fx) * dmax(0.0, fy));
            }
            row[x] = blend(aa, row[x], cov);
        }
        for (int x = end > lo ? end : lo; x < hi; x++) acc[x] = 0.0f;
    }
}

int pl_aa_fill(pl_aa *aa, uint8_t *data, int stride, pl_rgba color) {
    set_color(aa, color);
    if (aa->sum) {
        fill_sum(aa, data, stride);
        aa->sum = 0;
    }
    if (aa->incr) { /* composited already: clear the coverage */
        for (int k = 0; k < aa->nrects; k++) {
            aa_rect r = aa->rects[k];
            for (int y = r.y0; y < r.y1; y++)
                memset(aa->batch + (size_t)y * (size_t)aa->w + r.x0, 0, (size_t)(r.x1 - r.x0));
        }
        aa->nrects = 0;
    }
    /* the rectangles of many shapes overlap: when together they are larger than their
     * bounding box, the box is visited once instead */
    aa_rect box = {aa->w, aa->h, 0, 0};
    double area = 0.0;
    for (int k = 0; k < aa->nrects; k++) {
        aa_rect r = aa->rects[k];
        area += (double)(r.x1 - r.x0) * (double)(r.y1 - r.y0);
        if (r.x0 < box.x0) box.x0 = r.x0;
        if (r.y0 < box.y0) box.y0 = r.y0;
        if (r.x1 > box.x1) box.x1 = r.x1;
        if (r.y1 > box.y1) box.y1 = r.y1;
    }
    if (aa->nrects > 1 && area > (double)(box.x1 - box.x0) * (double)(box.y1 - box.y0))
        fill_rect(aa, data, stride, box);
    else
        for (int k = 0; k < aa->nrects; k++) fill_rect(aa, data, stride, aa->rects[k]);
    int rc = aa->failed ? -1 : 0;
    aa->nrects = 0;
    aa->failed = 0;
    aa->idata = NULL;
    aa->incr = 0;
    return rc;
}

/* ------------------------------------------------------------- thin segments */


/* Coverage of a pixel by a straight band, from the distribution of the pixel square projected
 * onto the band's normal: for a unit normal (nx, ny) with a = min(|nx|, |ny|), b = max, the
 * projection of a uniform point of the square is the sum of two uniform variables of widths
 * a and b, whose distribution function is quadratic, linear, quadratic. The fraction of the
 * pixel whose projection lies in [s0, s1] is exact for a straight band of any direction. */
typedef struct proj_cdf {
    float a, b, half, inv2ab, invb;
} proj_cdf;

static proj_cdf make_cdf(double nx, double ny) {
    proj_cdf p;
    double ax = fabs(nx), ay = fabs(ny);
    p.a = (float)(ax < ay ? ax : ay);
    p.b = (float)(ax < ay ? ay : ax);
    p.half = 0.5f * (p.a + p.b);
    p.inv2ab = p.a > 1e-6f ? 1.0f / (2.0f * p.a * p.b) : 0.0f;
    p.invb = 1.0f / p.b;
    return p;
}

static inline float cdf(const proj_cdf *p, float s) {
    float t = s + p->half;
    if (t <= 0.0f) return 0.0f;
    if (t >= 2.0f * p->half) return 1.0f;
    if (t < p->a) return t * t * p->inv2ab;
    if (t <= p->b) return (t - 0.5f * p->a) * p->invb;
    float u = 2.0f * p->half - t;
    return 1.0f - u * u * p->inv2ab;
}

/* The coverage of a band of half width hw at distance d from the pixel centre, 8-bit, at
 * d = i / LUT_RES, for the direction class of the band (LUT_A classes of min(|nx|, |ny|)
 * over [0, sqrt(1/2)]): filled the first time a class is used with this width. Errors:
 * rounding d to 1/128 px, at most 2/255; the direction class, at most about 2/255. */
enum { LUT_RES = 64, LUT_A = 9 };

static const uint8_t *seg_lut(pl_aa *aa, double hw, double nx, double ny, int *n) {
    if (aa->lut_hw != hw || !aa->lut) {
        int nn = (int)((hw + 0.7072) * LUT_RES) + 2;
        uint8_t *l = realloc(aa->lut, (size_t)nn * LUT_A);
        if (!l) return NULL;
        aa->lut = l;
        aa->lut_n = nn;
        aa->lut_hw = hw;
        memset(aa->lut_ok, 0, sizeof aa->lut_ok);
    }
    double am = fmin(fabs(nx), fabs(ny));
    int k = (int)(am / 0.70710678 * (LUT_A - 1) + 0.5);
    if (k > LUT_A - 1) k = LUT_A - 1;
    uint8_t *row = aa->lut + (size_t)k * (size_t)aa->lut_n;
    if (!aa->lut_ok[k]) {
        double ak = 0.70710678 * k / (LUT_A - 1);
        proj_cdf pc = make_cdf(ak, sqrt(1.0 - ak * ak));
        float fhw = (float)hw;
        for (int i = 0; i < aa->lut_n; i++) {
            float d = (float)i / LUT_RES;
            float cov = cdf(&pc, fhw - d) - cdf(&pc, -fhw - d);
            row[i] = (uint8_t)(cov <= 0.0f ? 0u : (cov >= 1.0f ? 255u : cov8(cov)));
        }
        row[aa->lut_n - 1] = 0;
        aa->lut_ok[k] = 1;
    }
    *n = aa->lut_n;
    return row;
}

/* Distance of a pixel centre from the segment a-b: q = centre - a, t and c its coordinates along
   and across the segment's direction, r = centre - b (y part), len and dx of the segment. */
static inline __attribute__((always_inline)) float seg_distance(float qx, float qy, float ry, float t, float c,
                                                                float flen, float fdx) {
    if (t <= 0.0f) return sqrtf(qx * qx + qy * qy);
    if (t >= flen) {
        const float rx = qx - fdx;
        return sqrtf(rx * rx + ry * ry);
    }
    return fabsf(c);
}

/* Coverage m (1..255) of pixel x of a row: blended into the image (px), or kept as the row's
   coverage mask (out) for a batch; incremental batches blend only what exceeds the mask. */
static inline __attribute__((always_inline)) void put_cov(const pl_aa *aa, uint32_t *px, uint8_t *out, int x,
                                                          unsigned m, int incr) {
    if (incr) {
        const unsigned m0 = out[x];
        if (m <= m0) return;
        out[x] = (uint8_t)m;
        px[x] = blend8(aa, px[x], incr_cov(m0, m));
    } else if (px) px[x] = blend8(aa, px[x], m);
    else if (m > out[x]) out[x] = (uint8_t)m;
}

void pl_aa_thin_segment(pl_aa *aa, pl_vec2 a, pl_vec2 b, double w) {
    double hw = 0.5 * w;
    if (!(hw > 0.0)) return;
    double dx = b.x - a.x, dy = b.y - a.y, len = sqrt(dx * dx + dy * dy);
    if (!(len < 1e7) || !isfinite(a.x + a.y)) return;
    double ux = 1.0, uy = 0.0;
    if (len > 1e-9) {
        ux = dx / len;
        uy = dy / len;
    } else {
        len = 0.0;
    }
    proj_cdf pc = make_cdf(uy, ux);
    double reach = hw + pc.half; /* no coverage beyond this distance from the segment */
    int px0 = ifloor(dmax(dmin(a.x, b.x) - reach, aa->cx0));
    int px1 = iceil(dmin(dmax(a.x, b.x) + reach, aa->cx1));
    int py0 = ifloor(dmax(dmin(a.y, b.y) - reach, aa->cy0));
    int py1 = iceil(dmin(dmax(a.y, b.y) + reach, aa->cy1));
    if (px1 <= px0 || py1 <= py0) return;
    double bx0 = dmin(a.x, b.x) - reach, bx1 = dmax(a.x, b.x) + reach;
    float fhw = (float)hw;
    float full = fhw - pc.half; /* closer than this: covered (never when w < a + b) */
    float fux = (float)ux, fuy = (float)uy, flen = (float)len, fdx = (float)dx;
    int cx0 = ifloor(aa->cx0), cx1 = iceil(aa->cx1);
    int incr = aa->incr && aa->idata;
    int px_any = aa->idata != NULL;
    int lut_n = 0;
    const uint8_t *lut = seg_lut(aa, hw, uy, ux, &lut_n);
    for (int y = py0; y < py1; y++) {
        double yc = y + 0.5;
        /* x range of pixel centres within reach: inside the band of half width reach
         * around the segment's line (in x: reach / |uy| either side of the line's crossing
         * with the row), within the box; a little more than needed near the ends */
        double ey = yc - a.y, fy = yc - b.y;
        double lo = bx0, hi = bx1;
        if (fabs(uy) > 1e-3) {
            double xc = a.x + ey * ux / uy, hwx = reach / fabs(uy);
            lo = dmax(lo, xc - hwx);
            hi = dmin(hi, xc + hwx);
        }
        if (!(lo <= hi)) continue;
        int xa = iceil(lo - 0.5), xb = ifloor(hi - 0.5) + 1;
        if (xa < px0) xa = px0;
        if (xb > px1) xb = px1;
        if (xa >= xb) continue;
        double fyc = dmin(y + 1.0, aa->cy1) - dmax((double)y, aa->cy0);
        uint8_t *out = aa->batch + (size_t)y * (size_t)aa->w;
        uint32_t *px = aa->idata ? aa->idata + (size_t)y * (size_t)aa->istride : NULL;
        int inside = fyc >= 1.0 && xa > cx0 && xb < cx1; /* no pixel of the row clipped */
        /* relative to a, in float; t (along) and c (across) step linearly with x */
        float qx = (float)(xa + 0.5 - a.x), qy = (float)ey, ry = (float)fy;
        float t = fux * qx + fuy * qy, c = fux * qy - fuy * qx;
        if (inside && lut) { /* the common case: tabulated coverage, no clipping */
            for (int x = xa; x < xb; x++, qx += 1.0f, t += fux, c -= fuy) {
                const float d = seg_distance(qx, qy, ry, t, c, flen, fdx);
                int li = (int)(d * LUT_RES + 0.5f);
                unsigned m = li < lut_n ? lut[li] : 0u;
                if (m) put_cov(aa, px, out, x, m, incr);
            }
            continue;
        }
        for (int x = xa; x < xb; x++, qx += 1.0f, t += fux, c -= fuy) {
            const float d = seg_distance(qx, qy, ry, t, c, flen, fdx);
            unsigned m;
            if (d <= full) m = 255u; /* the pixel lies inside the band */
            else {
                float cov = cdf(&pc, fhw - d);
                if (d < pc.half - fhw) cov -= cdf(&pc, -fhw - d);
                if (cov <= 0.0f) continue;
                if (!inside) {
                    double fx = dmin(x + 1.0, aa->cx1) - dmax((double)x, aa->cx0);
                    cov *= (float)(dmax(0.0, fx) * dmax(0.0, fyc));
                    if (cov <= 0.0f) continue;
                }
                m = cov8(cov);
                if (!m) continue;
            }
            if (m == 255u && !inside) {
                double fx = dmin(x + 1.0, aa->cx1) - dmax((double)x, aa->cx0);
                m = cov8((float)(dmax(0.0, fx) * dmax(0.0, fyc)));
                if (!m) continue;
            }
            put_cov(aa, px, out, x, m, incr);
        }
    }
    if (!px_any || incr) push_rect(aa, (aa_rect){px0, py0, px1, py1});
}


/* ------------------------------------------------------------------- arrows */

static double shoelace(const pl_vec2 *p, int n) {
    double a = 0.0;
    for (int i = 0; i < n; i++) a += p[i].x * p[(i + 1) % n].y - p[(i + 1) % n].x * p[i].y;
    return a;
}

static void contour(pl_aa *aa, const pl_vec2 *p, int n, int reverse) {
    contour_start(aa);
    for (int i = 0; i < n; i++) {
        pl_vec2 q = p[reverse ? n - 1 - i : i];
        point(aa, q.x, q.y);
    }
}

void pl_aa_arrow(pl_aa *aa, pl_vec2 a, pl_vec2 shaft_end, double w, const pl_vec2 head[3]) {
    double hw = 0.5 * w;
    double dx = shaft_end.x - a.x, dy = shaft_end.y - a.y, len = sqrt(dx * dx + dy * dy);
    double sh = 1.0; /* both contours positive: in sum batches, arrows add up */
    if (hw > 0.0 && len > 1e-9) {
        double nx = -dy / len * hw, ny = dx / len * hw;
        pl_vec2 bar[4] = {{a.x + nx, a.y + ny}, {shaft_end.x + nx, shaft_end.y + ny},
                          {shaft_end.x - nx, shaft_end.y - ny}, {a.x - nx, a.y - ny}};
        contour(aa, bar, 4, (shoelace(bar, 4) > 0.0) != (sh > 0.0));
    }
    contour(aa, head, 3, shoelace(head, 3) < 0.0);
    shape_end(aa);
}
