/* Gouraud triangles rasterized by hand (see raster_gouraud.h). */
#include "raster_gouraud.h"

#include <math.h>

/* cairo works in 24.8 fixed point: vertices snapped to 1/256 px as cairo does */
#define SNAP(v) (floor((v) * 256.0 + 0.5) / 256.0)
/* Half the side of the pixel square tested for contact: a pixel [x, x+1) x [y, y+1) is
 * half-open (cairo paints floor() of each sample), so the square is shrunk by 1/256 at its
 * right and bottom sides, its centre moved by half of that. */
#define HALF (0.5 - 1.0 / 512.0)

static inline uint32_t pack(float r, float g, float b, float a) {
    /* premultiplied, rounded, clamped to 0..255 */
    if (a < 0.0f) a = 0.0f;
    if (a > 1.0f) a = 1.0f;
    r = r < 0.0f ? 0.0f : (r > 1.0f ? 1.0f : r);
    g = g < 0.0f ? 0.0f : (g > 1.0f ? 1.0f : g);
    b = b < 0.0f ? 0.0f : (b > 1.0f ? 1.0f : b);
    uint32_t A = (uint32_t)(a * 255.0f + 0.5f);
    uint32_t R = (uint32_t)(r * a * 255.0f + 0.5f);
    uint32_t G = (uint32_t)(g * a * 255.0f + 0.5f);
    uint32_t B = (uint32_t)(b * a * 255.0f + 0.5f);
    return A << 24 | R << 16 | G << 8 | B;
}

void pl_raster_gouraud(uint8_t *buf, int w, int h, int stride, int ox, int oy,
                       const pl_vec2 *pts, const pl_rgba *col, int n) {
    for (int t = 0; t < n; t++) {
        double x0 = SNAP(pts[3 * t].x) - ox, y0 = SNAP(pts[3 * t].y) - oy;
        double x1 = SNAP(pts[3 * t + 1].x) - ox, y1 = SNAP(pts[3 * t + 1].y) - oy;
        double x2 = SNAP(pts[3 * t + 2].x) - ox, y2 = SNAP(pts[3 * t + 2].y) - oy;
        double area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
        if (!(fabs(area) > 1e-12)) continue; /* degenerate (or NaN) */
        double xmin = fmin(x0, fmin(x1, x2)), xmax = fmax(x0, fmax(x1, x2));
        double ymin = fmin(y0, fmin(y1, y2)), ymax = fmax(y0, fmax(y1, y2));
        int ix0 = (int)floor(xmin), ix1 = (int)floor(xmax);
        int iy0 = (int)floor(ymin), iy1 = (int)floor(ymax);
        if (ix0 < 0) ix0 = 0;
        if (iy0 < 0) iy0 = 0;
        if (ix1 > w - 1) ix1 = w - 1;
        if (iy1 > h - 1) iy1 = h - 1;
        if (ix0 > ix1 || iy0 > iy1) continue;
        /* Edge functions e_k(x, y) = a_k x + b_k y + c_k, positive inside (sign fixed by
         * the orientation). A pixel is touched when every e_k, shifted by half the pixel's
         * extent along the edge normal, is >= 0 at the pixel centre (conservative coverage,
         * like cairo's mesh rasterizer, which paints every pixel a sample falls in). */
        double s = area > 0.0 ? 1.0 : -1.0;
        double inv = 1.0 / area;
        double ea[3], eb[3], ec[3], pad[3];
        const double X[3] = {x0, x1, x2}, Y[3] = {y0, y1, y2};
        for (int k = 0; k < 3; k++) { /* edge opposite vertex k: from vertex k+1 to k+2 */
            int i = (k + 1) % 3, j = (k + 2) % 3;
            ea[k] = s * (Y[i] - Y[j]);
            eb[k] = s * (X[j] - X[i]);
            ec[k] = s * (X[i] * Y[j] - X[j] * Y[i]);
            pad[k] = HALF * (fabs(ea[k]) + fabs(eb[k]));
        }
        /* barycentric weight of vertex k = s * e_k * inv (exactly 1 at vertex k) */
        const pl_rgba *c = col + 3 * t;
        float pr[3], pg[3], pb[3], pa[3];
        for (int k = 0; k < 3; k++) {
            pa[k] = c[k].a;
            pr[k] = c[k].r;
            pg[k] = c[k].g;
            pb[k] = c[k].b;
        }
        double wk = s * inv;
        for (int y = iy0; y <= iy1; y++) {
            double py = y + HALF, px0 = ix0 + HALF;
            uint32_t *row = (uint32_t *)(void *)(buf + (size_t)y * (size_t)stride);
            /* edge functions at the row's first pixel centre, then stepped along x */
            double e0 = ea[0] * px0 + eb[0] * py + ec[0];
            double e1 = ea[1] * px0 + eb[1] * py + ec[1];
            double e2 = ea[2] * px0 + eb[2] * py + ec[2];
            for (int x = ix0; x <= ix1; x++, e0 += ea[0], e1 += ea[1], e2 += ea[2]) {
                if (e0 < -pad[0] || e1 < -pad[1] || e2 < -pad[2]) continue;
                double l0 = e0 * wk, l1 = e1 * wk, l2 = e2 * wk;
                float f0, f1, f2;
                if (l0 >= 0.0 && l1 >= 0.0 && l2 >= 0.0) { /* inside: weights sum to 1 */
                    f0 = (float)l0;
                    f1 = (float)l1;
                    f2 = (float)l2;
                } else { /* edge pixel: weights clamped into the triangle */
                    l0 = l0 > 0.0 ? l0 : 0.0;
                    l1 = l1 > 0.0 ? l1 : 0.0;
                    l2 = l2 > 0.0 ? l2 : 0.0;
                    double sum = l0 + l1 + l2;
                    if (sum <= 0.0) { l0 = 1.0; sum = 1.0; }
                    f0 = (float)(l0 / sum);
                    f1 = (float)(l1 / sum);
                    f2 = (float)(l2 / sum);
                }
                row[x] = pack(f0 * pr[0] + f1 * pr[1] + f2 * pr[2], f0 * pg[0] + f1 * pg[1] + f2 * pg[2],
                              f0 * pb[0] + f1 * pb[1] + f2 * pb[2], f0 * pa[0] + f1 * pa[1] + f2 * pa[2]);
            }
        }
    }
}
