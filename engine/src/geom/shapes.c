/* Shape generators, outline validation and mass properties (porelab/shapes.h). */
#include "porelab/shapes.h"
#include "geom/clip.h"
#include "geom/polygon.h"
#include <math.h>
#include <stdarg.h>
#include <stdio.h>

#define PI 3.14159265358979323846

/* Relative tolerances shared by the generators and the check, so that every generated
 * outline passes the check: vertices closer than DUP_TOL x size are repeats, corners
 * whose turn has |sin| <= FLAT_TOL are straight. */
#define DUP_TOL 1e-9
#define FLAT_TOL 1e-9

static int fail(char *err, size_t cap, pl_status s, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
static int fail(char *err, size_t cap, pl_status s, const char *fmt, ...) {
    if (err && cap > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, cap, fmt, ap);
        va_end(ap);
    }
    return (int)s;
}

static double outline_size(const pl_vec2 *v, int n) {
    double lo_x = v[0].x, hi_x = v[0].x, lo_y = v[0].y, hi_y = v[0].y;
    for (int i = 1; i < n; i++) {
        lo_x = fmin(lo_x, v[i].x); hi_x = fmax(hi_x, v[i].x);
        lo_y = fmin(lo_y, v[i].y); hi_y = fmax(hi_y, v[i].y);
    }
    return fmax(hi_x - lo_x, hi_y - lo_y);
}

pl_status pl_polygon_check(const pl_vec2 *v, int n, char *err, size_t err_cap) {
    if (!v) return fail(err, err_cap, PL_ERR_ARG, "polygon: no vertices given");
    if (n < 3)
        return fail(err, err_cap, PL_ERR_ARG, "polygon: %d vertices given, at least 3 needed", n);
    if (n > PL_SHAPE_MAX_VERTICES)
        return fail(err, err_cap, PL_ERR_ARG,
                    "polygon: %d vertices given, at most %d allowed (use fewer sides)", n,
                    PL_SHAPE_MAX_VERTICES);
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i].x) || !isfinite(v[i].y))
            return fail(err, err_cap, PL_ERR_ARG, "polygon: vertex %d (%g, %g) is not finite",
                        i + 1, v[i].x, v[i].y);
    const double size = outline_size(v, n);
    if (!(size > 0))
        return fail(err, err_cap, PL_ERR_ARG, "polygon: all %d vertices coincide at (%g, %g)",
                    n, v[0].x, v[0].y);
    for (int i = 0; i < n; i++) {
        const pl_vec2 p = v[i], q = v[(i + 1) % n];
        if (hypot(q.x - p.x, q.y - p.y) <= DUP_TOL * size)
            return fail(err, err_cap, PL_ERR_ARG,
                        "polygon: vertices %d and %d coincide at (%g, %g); remove one", i + 1,
                        (i + 1) % n + 1, p.x, p.y);
    }
    const double area = pl_poly_signed_area(v, n);
    int left = 0, right = 0, first_right = -1, first_left = -1, flat = -1;
    double turning = 0;
    for (int i = 0; i < n; i++) {
        const pl_vec2 p = v[(i + n - 1) % n], q = v[i], r = v[(i + 1) % n];
        const pl_vec2 e1 = {q.x - p.x, q.y - p.y}, e2 = {r.x - q.x, r.y - q.y};
        const double cr = e1.x * e2.y - e1.y * e2.x, dt = e1.x * e2.x + e1.y * e2.y;
        const double s = cr / (hypot(e1.x, e1.y) * hypot(e2.x, e2.y));
        turning += atan2(cr, dt);
        if (fabs(s) <= FLAT_TOL) { if (flat < 0) flat = i; }
        else if (s > 0) { left++; if (first_left < 0) first_left = i; }
        else { right++; if (first_right < 0) first_right = i; }
    }
    if (flat >= 0)
        return fail(err, err_cap, PL_ERR_ARG,
                    "polygon: vertex %d (%g, %g) lies on the straight line through its "
                    "neighbours (a flat or folded-back corner); remove it",
                    flat + 1, v[flat].x, v[flat].y);
    if (right == n || (left == 0 && area < 0))
        return fail(err, err_cap, PL_ERR_ARG,
                    "polygon: vertices are in clockwise order; give them counter-clockwise "
                    "(reverse the list)");
    if (right > 0)
        return fail(err, err_cap, PL_ERR_ARG,
                    "polygon: not convex: the outline turns the wrong way at vertex %d (%g, %g); "
                    "only convex polygons are supported (split a concave grain into convex "
                    "parts or use its convex hull)",
                    (area > 0 ? first_right : first_left) + 1,
                    v[area > 0 ? first_right : first_left].x,
                    v[area > 0 ? first_right : first_left].y);
    if (fabs(turning - 2 * PI) > 1e-6)
        return fail(err, err_cap, PL_ERR_ARG,
                    "polygon: the outline winds %.3g times around its inside (it crosses "
                    "itself); give the corners of a convex polygon in counter-clockwise order",
                    turning / (2 * PI));
    if (!(area > 1e-12 * size * size))
        return fail(err, err_cap, PL_ERR_ARG, "polygon: area %g m^2 is degenerate", area);
    return PL_OK;
}

pl_status pl_polygon_mass_properties(const pl_vec2 *v, int n, double density,
                                     pl_mass_props *out, char *err, size_t err_cap) {
    const pl_status s = pl_polygon_check(v, n, err, err_cap);
    if (s != PL_OK) return s;
    if (!(density > 0) || !isfinite(density))
        return fail(err, err_cap, PL_ERR_ARG, "density %g kg/m^3 must be > 0", density);
    out->area = pl_poly_signed_area(v, n);
    out->centroid = pl_poly_centroid(v, n);
    out->polar_moment = pl_poly_polar_moment(v, n);
    out->mass = density * out->area;
    out->inertia = density * out->polar_moment;
    double r = 0;
    for (int i = 0; i < n; i++)
        r = fmax(r, hypot(v[i].x - out->centroid.x, v[i].y - out->centroid.y));
    out->bounding_radius = r;
    return PL_OK;
}

/* Rotates local points by angle and moves them to center. */
static void place(pl_vec2 *v, int n, pl_vec2 center, double angle) {
    const double c = cos(angle), s = sin(angle);
    for (int i = 0; i < n; i++) {
        const double x = v[i].x, y = v[i].y;
        v[i] = (pl_vec2){center.x + c * x - s * y, center.y + s * x + c * y};
    }
}

/* Drops repeated and straight corners (to the check's tolerances) until none is left. */
static int clean_outline(pl_vec2 *v, int n) {
    const double size = outline_size(v, n);
    int changed = 1;
    while (changed && n > 3) {
        changed = 0;
        for (int i = 0; i < n && n > 3; i++) {
            const pl_vec2 p = v[(i + n - 1) % n], q = v[i], r = v[(i + 1) % n];
            const pl_vec2 e1 = {q.x - p.x, q.y - p.y}, e2 = {r.x - q.x, r.y - q.y};
            const double l1 = hypot(e1.x, e1.y), l2 = hypot(e2.x, e2.y);
            const int dup = l1 <= DUP_TOL * size;
            const int flat = !dup && l2 > DUP_TOL * size &&
                             fabs(e1.x * e2.y - e1.y * e2.x) <= FLAT_TOL * l1 * l2;
            if (dup || flat) {
                for (int k = i; k + 1 < n; k++) v[k] = v[k + 1];
                n--;
                changed = 1;
            }
        }
    }
    return n;
}

static int check_cap(int need, int cap, char *err, size_t err_cap, const char *what) {
    if (cap < need)
        return fail(err, err_cap, PL_ERR_ARG, "%s: output holds %d vertices, %d needed", what,
                    cap, need);
    return PL_OK;
}

int pl_shape_rectangle(pl_vec2 center, double width, double height, double angle,
                       pl_vec2 *out, int cap, char *err, size_t err_cap) {
    if (!(width > 0) || !(height > 0) || !isfinite(width) || !isfinite(height))
        return fail(err, err_cap, PL_ERR_ARG,
                    "rectangle: width %g and height %g must both be > 0", width, height);
    if (!isfinite(angle) || !isfinite(center.x) || !isfinite(center.y))
        return fail(err, err_cap, PL_ERR_ARG, "rectangle: centre and angle must be finite");
    const int s = check_cap(4, cap, err, err_cap, "rectangle");
    if (s) return s;
    const double hx = 0.5 * width, hy = 0.5 * height;
    out[0] = (pl_vec2){-hx, -hy};
    out[1] = (pl_vec2){hx, -hy};
    out[2] = (pl_vec2){hx, hy};
    out[3] = (pl_vec2){-hx, hy};
    place(out, 4, center, angle);
    return 4;
}

int pl_shape_regular_polygon(pl_vec2 center, double circumradius, int sides, double angle,
                             pl_vec2 *out, int cap, char *err, size_t err_cap) {
    if (sides < 3 || sides > PL_SHAPE_MAX_VERTICES)
        return fail(err, err_cap, PL_ERR_ARG, "regular polygon: sides = %d, valid 3..%d", sides,
                    PL_SHAPE_MAX_VERTICES);
    if (!(circumradius > 0) || !isfinite(circumradius))
        return fail(err, err_cap, PL_ERR_ARG, "regular polygon: radius %g must be > 0",
                    circumradius);
    if (!isfinite(angle) || !isfinite(center.x) || !isfinite(center.y))
        return fail(err, err_cap, PL_ERR_ARG, "regular polygon: centre and angle must be finite");
    const int s = check_cap(sides, cap, err, err_cap, "regular polygon");
    if (s) return s;
    for (int k = 0; k < sides; k++) {
        const double t = 2 * PI * k / sides;
        out[k] = (pl_vec2){circumradius * cos(t), circumradius * sin(t)};
    }
    place(out, sides, center, angle);
    return sides;
}

pl_superquad_def pl_default_superquad_def(void) {
    pl_superquad_def d;
    d.center = (pl_vec2){0, 0};
    d.a = 0.005;
    d.b = 0.005;
    d.n1 = 2;
    d.n2 = 2;
    d.sides = 16;
    d.angle = 0;
    return d;
}

/* sgn(c) |c|^e, with exact 0 and +-1 */
static double signed_pow(double c, double e) {
    if (c == 0) return 0;
    const double m = pow(fabs(c), e);
    return c < 0 ? -m : m;
}

int pl_shape_superquad(const pl_superquad_def *d, pl_vec2 *out, int cap, char *err,
                       size_t err_cap) {
    if (!d) return fail(err, err_cap, PL_ERR_ARG, "superquad: no definition given");
    if (!(d->a > 0) || !(d->b > 0) || !isfinite(d->a) || !isfinite(d->b))
        return fail(err, err_cap, PL_ERR_ARG, "superquad: half axes a = %g, b = %g must be > 0",
                    d->a, d->b);
    if (!(d->n1 >= 1) || !(d->n2 >= 1))
        return fail(err, err_cap, PL_ERR_ARG,
                    "superquad: exponents n1 = %g, n2 = %g must be >= 1 (smaller exponents give "
                    "concave, star-like outlines, which polygon bodies cannot represent)",
                    d->n1, d->n2);
    if (d->sides < 4 || d->sides > PL_SHAPE_MAX_VERTICES)
        return fail(err, err_cap, PL_ERR_ARG, "superquad: sides = %d, valid 4..%d", d->sides,
                    PL_SHAPE_MAX_VERTICES);
    if (!isfinite(d->angle) || !isfinite(d->center.x) || !isfinite(d->center.y))
        return fail(err, err_cap, PL_ERR_ARG, "superquad: centre and angle must be finite");
    const int s = check_cap(d->sides, cap, err, err_cap, "superquad");
    if (s) return s;
    const int n = d->sides;
    const double e1 = isinf(d->n1) ? 0 : 2 / d->n1, e2 = isinf(d->n2) ? 0 : 2 / d->n2;
    for (int k = 0; k < n; k++) {
        /* exact axis points for the quarter turns so symmetric shapes stay symmetric */
        double c, sn;
        if (4 * k % n == 0) {
            const int q = 4 * k / n;
            c = q == 0 ? 1 : q == 2 ? -1 : 0;
            sn = q == 1 ? 1 : q == 3 ? -1 : 0;
        } else {
            const double t = 2 * PI * k / n;
            c = cos(t);
            sn = sin(t);
        }
        out[k] = (pl_vec2){d->a * signed_pow(c, e1), d->b * signed_pow(sn, e2)};
    }
    const int m = clean_outline(out, n);
    place(out, m, d->center, d->angle);
    const pl_status st = pl_polygon_check(out, m, err, err_cap);
    return st == PL_OK ? m : (int)st;
}

pl_random_polygon_def pl_default_random_polygon_def(void) {
    pl_random_polygon_def d;
    d.min_corners = 5;
    d.max_corners = 9;
    d.a_min = 0.005;
    d.a_max = 0.0075;
    d.aspect_min = 0.6;
    d.aspect_max = 1.0;
    d.jitter = 0.5;
    d.random_orientation = 1;
    return d;
}

int pl_shape_random_polygon(const pl_random_polygon_def *d, pl_rng *rng, pl_vec2 center,
                            pl_vec2 *out, int cap, char *err, size_t err_cap) {
    if (!d || !rng) return fail(err, err_cap, PL_ERR_ARG, "random polygon: no definition or rng");
    if (d->min_corners < 3 || d->max_corners > PL_SHAPE_MAX_VERTICES ||
        d->min_corners > d->max_corners)
        return fail(err, err_cap, PL_ERR_ARG,
                    "random polygon: corners %d..%d invalid; need 3 <= min <= max <= %d",
                    d->min_corners, d->max_corners, PL_SHAPE_MAX_VERTICES);
    if (!(d->a_min > 0) || !(d->a_max >= d->a_min) || !isfinite(d->a_max))
        return fail(err, err_cap, PL_ERR_ARG,
                    "random polygon: half axis range %g..%g invalid; need 0 < a_min <= a_max",
                    d->a_min, d->a_max);
    if (!(d->aspect_min > 0) || !(d->aspect_max >= d->aspect_min) || !(d->aspect_max <= 1))
        return fail(err, err_cap, PL_ERR_ARG,
                    "random polygon: aspect range %g..%g invalid; need 0 < min <= max <= 1",
                    d->aspect_min, d->aspect_max);
    if (!(d->jitter >= 0) || !(d->jitter <= 0.9))
        return fail(err, err_cap, PL_ERR_ARG, "random polygon: jitter %g, valid 0..0.9",
                    d->jitter);
    if (!isfinite(center.x) || !isfinite(center.y))
        return fail(err, err_cap, PL_ERR_ARG, "random polygon: centre must be finite");
    const int s = check_cap(d->max_corners, cap, err, err_cap, "random polygon");
    if (s) return s;
    /* fixed draw order: corners, a, aspect, phase, jitters, orientation */
    const int n = pl_rng_int(rng, d->min_corners, d->max_corners);
    const double a = pl_rng_range(rng, d->a_min, d->a_max);
    const double b = a * pl_rng_range(rng, d->aspect_min, d->aspect_max);
    const double phase = pl_rng_range(rng, 0, 2 * PI);
    for (int k = 0; k < n; k++) {
        const double t = phase + 2 * PI * (k + d->jitter * (pl_rng_uniform(rng) - 0.5)) / n;
        out[k] = (pl_vec2){a * cos(t), b * sin(t)};
    }
    const double angle = d->random_orientation ? pl_rng_range(rng, 0, 2 * PI) : 0;
    const int m = clean_outline(out, n);
    place(out, m, center, angle);
    const pl_status st = pl_polygon_check(out, m, err, err_cap);
    return st == PL_OK ? m : (int)st;
}

double pl_overlap_polygons(const pl_vec2 *p, int np, const pl_vec2 *q, int nq, pl_vec2 *centroid) {
    pl_overlap o;
    const double a = pl_clip_convex(p, np, q, nq, &o);
    if (centroid) *centroid = o.centroid;
    return a;
}

double pl_overlap_disc_polygon(pl_vec2 c, double r, const pl_vec2 *p, int np, pl_vec2 *centroid) {
    pl_overlap o;
    const double a = pl_clip_disc(c, r, p, np, &o);
    if (centroid) *centroid = o.centroid;
    return a;
}
