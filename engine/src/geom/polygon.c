#include "geom/polygon.h"
#include <math.h>

double pl_poly_signed_area(const pl_vec2 *v, int n) {
    double a = 0;
    for (int i = 0; i < n; i++) {
        const pl_vec2 p = v[i], q = v[(i + 1) % n];
        a += p.x * q.y - q.x * p.y;
    }
    return 0.5 * a;
}

pl_vec2 pl_poly_centroid(const pl_vec2 *v, int n) {
    /* Shift to the first vertex to limit round-off for polygons far from the origin. */
    const pl_vec2 o = v[0];
    double a = 0, cx = 0, cy = 0;
    for (int i = 0; i < n; i++) {
        const double px = v[i].x - o.x, py = v[i].y - o.y;
        const double qx = v[(i + 1) % n].x - o.x, qy = v[(i + 1) % n].y - o.y;
        const double cr = px * qy - qx * py;
        a += cr;
        cx += (px + qx) * cr;
        cy += (py + qy) * cr;
    }
    if (a == 0) return o;
    return (pl_vec2){o.x + cx / (3 * a), o.y + cy / (3 * a)};
}

double pl_poly_polar_moment(const pl_vec2 *v, int n) {
    const pl_vec2 c = pl_poly_centroid(v, n);
    double j = 0;
    for (int i = 0; i < n; i++) {
        const double px = v[i].x - c.x, py = v[i].y - c.y;
        const double qx = v[(i + 1) % n].x - c.x, qy = v[(i + 1) % n].y - c.y;
        const double cr = px * qy - qx * py;
        j += cr * (px * px + px * qx + qx * qx + py * py + py * qy + qy * qy);
    }
    return fabs(j) / 12.0;
}

int pl_poly_is_convex_ccw(const pl_vec2 *v, int n) {
    if (n < 3) return 0;
    for (int i = 0; i < n; i++) {
        const pl_vec2 p = v[i], q = v[(i + 1) % n], r = v[(i + 2) % n];
        const double cr = (q.x - p.x) * (r.y - q.y) - (q.y - p.y) * (r.x - q.x);
        if (!(cr > 0)) return 0;
    }
    return pl_poly_signed_area(v, n) > 0;
}
