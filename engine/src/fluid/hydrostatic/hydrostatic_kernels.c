/* Hydrostatic water kernels (hydrostatic_internal.h): submerged parts, loads, moving level. */
#include "fluid/hydrostatic/hydrostatic_internal.h"
#include "geom/clip.h"
#include "geom/polygon.h"
#include <math.h>
#include <string.h>

#define HS_PI 3.14159265358979323846

pl_hs_water pl_hs_water_make(const pl_hydrostatic_def *d, pl_vec2 gravity) {
    pl_hs_water wt;
    wt.x_min = d->x_min;
    wt.x_max = d->x_max;
    wt.bottom = d->bottom;
    wt.level = d->level;
    wt.rho = d->density;
    wt.beta = d->drag;
    wt.g = hypot(gravity.x, gravity.y);
    wt.up = wt.g > 0 ? (pl_vec2){-gravity.x / wt.g, -gravity.y / wt.g} : (pl_vec2){0, 1};
    return wt;
}

static double dotp(pl_vec2 a, pl_vec2 b) { return a.x * b.x + a.y * b.y; }

/* phi - sin(phi) cos(phi) = (x - sin x) / 2 with x = 2 phi, by its series for small x (the
   direct form loses all digits for a barely wetted disc). */
static double seg_fn(double phi) {
    const double x = 2 * phi;
    if (x < 0.1) {
        const double x2 = x * x;
        return 0.5 * x * x2 / 6 * (1 - x2 / 20 * (1 - x2 / 42 * (1 - x2 / 72)));
    }
    return 0.5 * (x - sin(x));
}

void pl_hs_disc_segment(pl_vec2 c, double r, pl_vec2 up, double s, pl_hs_part *out) {
    const double d = s + r; /* depth of the lowest point */
    if (!(d > 0) || !(r > 0)) {
        *out = (pl_hs_part){0, c, 0};
        return;
    }
    if (d >= 2 * r) {
        *out = (pl_hs_part){HS_PI * r * r, c, 0.5 * HS_PI * r * r * r * r};
        return;
    }
    /* half-angle phi of the submerged segment seen from the centre, measured from -up:
       cos phi = -s / r, sin phi = sqrt((1 - t)(1 + t)) with t = s / r and 1 + t = d / r */
    const double t = s / r, one_p = d / r, one_m = 2 - one_p;
    const double sn = sqrt(one_m * one_p), cs = -t;
    const double phi = atan2(sn, cs);
    const double r2 = r * r;
    const double A = r2 * seg_fn(phi);
    /* centroid along up: -(2/3) r^3 sin^3(phi) / A */
    const double u = -(2.0 / 3.0) * r * r2 * sn * sn * sn / A;
    /* J about the centre: sector (r^4 phi / 2) minus the triangle centre-chord
       (r^4 sin cos (2 + cos 2phi) / 6); written as r^4 [ (phi - sin cos)/2 + sin cos (1 - cos 2phi)/6 ]
       so that it keeps its digits for small phi: (1 - cos 2phi) = 2 sin^2 */
    const double J = r2 * r2 * (0.5 * seg_fn(phi) + sn * cs * (2 * sn * sn) / 6);
    out->area = A;
    out->centroid = (pl_vec2){c.x + u * up.x, c.y + u * up.y};
    out->j_c = J;
}

int pl_hs_water_polygon(const pl_hs_water *wt, double level, pl_vec2 out[8]) {
    const pl_vec2 up = wt->up;
    if (!(up.y > 1e-12) || !(wt->x_max > wt->x_min)) return 0;
    /* the tank is open upwards: cap it above the highest point of the surface in it */
    const double y0 = (level - wt->x_min * up.x) / up.y, y1 = (level - wt->x_max * up.x) / up.y;
    const double ytop = fmax(y0, y1);
    if (!(ytop > wt->bottom)) return 0;
    const double cap = ytop + 1e-3 * (ytop - wt->bottom) + 1e-9 * (fabs(ytop) + 1);
    const pl_vec2 rect[4] = {{wt->x_min, wt->bottom}, {wt->x_max, wt->bottom}, {wt->x_max, cap}, {wt->x_min, cap}};
    if (up.x == 0) { /* g along -y: the surface is y = level, the box is the water */
        out[0] = rect[0];
        out[1] = rect[1];
        out[2] = (pl_vec2){wt->x_max, level};
        out[3] = (pl_vec2){wt->x_min, level};
        return 4;
    }
    const pl_vec2 o = {level * up.x, level * up.y};
    return pl_clip_halfplane(rect, 4, o, up, out);
}

double pl_hs_tank_area(const pl_hs_water *wt, double level) {
    if (wt->up.x == 0 && wt->up.y > 0) return level > wt->bottom ? (level - wt->bottom) * (wt->x_max - wt->x_min) : 0;
    pl_vec2 p[8], c;
    const int n = pl_hs_water_polygon(wt, level, p);
    return n >= 3 ? pl_clip_area_centroid(p, n, &c) : 0;
}

/* The disc (or polygon box) lies between the side walls and above the bottom: the surface is
   the only cut. */
static int inside_tank(const pl_hs_water *wt, double xlo, double xhi, double ylo) {
    return xlo >= wt->x_min && xhi <= wt->x_max && ylo >= wt->bottom;
}

void pl_hs_disc_part(const pl_hs_water *wt, double level, pl_vec2 c, double r, pl_hs_part *out) {
    if (!(wt->up.y > 1e-12) || c.x + r <= wt->x_min || c.x - r >= wt->x_max || c.y + r <= wt->bottom) {
        *out = (pl_hs_part){0, c, 0};
        return;
    }
    const double s = level - dotp(c, wt->up);
    if (inside_tank(wt, c.x - r, c.x + r, c.y - r) || s <= -r) {
        pl_hs_disc_segment(c, r, wt->up, s, out);
        return;
    }
    /* the disc crosses a side wall or the bottom of the region: exact disc-polygon clip; its
       second moment is taken as the full disc's per unit area (r^2 / 2) about c, plus the
       offset of the part (only the rotational drag uses it) */
    pl_vec2 wp[8];
    const int nw = pl_hs_water_polygon(wt, level, wp);
    if (nw < 3) {
        *out = (pl_hs_part){0, c, 0};
        return;
    }
    pl_overlap ov;
    const double A = pl_clip_disc(c, r, wp, nw, &ov);
    if (!(A > 0)) {
        *out = (pl_hs_part){0, c, 0};
        return;
    }
    out->area = A;
    out->centroid = ov.centroid;
    out->j_c = A * 0.5 * r * r;
}

void pl_hs_polygon_part(const pl_hs_water *wt, double level, const pl_vec2 *v, int n, pl_vec2 c,
                        pl_hs_part *out) {
    *out = (pl_hs_part){0, c, 0};
    if (n < 3 || n > PL_CLIP_MAX_IN || !(wt->up.y > 1e-12)) return;
    double xlo = v[0].x, xhi = v[0].x, ylo = v[0].y, ylo_h = dotp(v[0], wt->up), hhi = ylo_h;
    for (int k = 1; k < n; k++) {
        xlo = fmin(xlo, v[k].x);
        xhi = fmax(xhi, v[k].x);
        ylo = fmin(ylo, v[k].y);
        const double h = dotp(v[k], wt->up);
        ylo_h = fmin(ylo_h, h);
        hhi = fmax(hhi, h);
    }
    if (ylo_h >= level || xhi <= wt->x_min || xlo >= wt->x_max) return;
    pl_vec2 buf[PL_CLIP_MAX_OUT];
    const pl_vec2 *part = v;
    int m = n;
    if (inside_tank(wt, xlo, xhi, ylo)) {
        if (hhi > level) {
            const pl_vec2 o = {level * wt->up.x, level * wt->up.y};
            m = pl_clip_halfplane(v, n, o, wt->up, buf);
            part = buf;
        }
    } else {
        pl_vec2 wp[8];
        const int nw = pl_hs_water_polygon(wt, level, wp);
        if (nw < 3) return;
        pl_overlap ov;
        if (!(pl_clip_convex(v, n, wp, nw, &ov) > 0) || ov.n < 3) return;
        m = ov.n;
        memcpy(buf, ov.v, (size_t)m * sizeof *buf);
        part = buf;
    }
    if (m < 3) return;
    pl_vec2 cs;
    const double A = pl_clip_area_centroid(part, m, &cs);
    if (!(A > 0)) return;
    out->area = A;
    out->centroid = cs;
    if (wt->beta > 0) {
        const double dx = cs.x - c.x, dy = cs.y - c.y;
        out->j_c = pl_poly_polar_moment(part, m) + A * (dx * dx + dy * dy);
    }
}

void pl_hs_body_part(const pl_hs_water *wt, double level, const pl_grain_view *g, int i, pl_hs_part *out) {
    const pl_vec2 c = g->pos[i];
    if (g->shape[i] == PL_SHAPE_DISC) pl_hs_disc_part(wt, level, c, g->radius[i], out);
    else if (g->shape[i] == PL_SHAPE_POLYGON)
        pl_hs_polygon_part(wt, level, g->verts + g->vert_offset[i], g->vert_count[i], c, out);
    else *out = (pl_hs_part){0, c, 0};
}

void pl_hs_load(const pl_hs_water *wt, const pl_hs_part *p, pl_vec2 c, pl_vec2 v, double omega, pl_vec2 *force,
                double *moment) {
    *force = (pl_vec2){0, 0};
    *moment = 0;
    if (!(p->area > 0)) return;
    const double dx = p->centroid.x - c.x, dy = p->centroid.y - c.y;
    const double fb = wt->rho * wt->g * p->area;
    pl_vec2 F = {fb * wt->up.x, fb * wt->up.y};
    double M = dx * F.y - dy * F.x;
    if (wt->beta > 0) {
        const double bA = wt->beta * p->area;
        F.x -= bA * (v.x - omega * dy);
        F.y -= bA * (v.y + omega * dx);
        M -= bA * (dx * v.y - dy * v.x) + wt->beta * omega * p->j_c;
    }
    *force = F;
    *moment = M;
}

int pl_hs_field(const pl_hs_water *wt, double level, pl_vec2 xy[8], int32_t tri[18], double value[8], int *nt) {
    const int nn = pl_hs_water_polygon(wt, level, xy);
    *nt = nn >= 3 ? nn - 2 : 0;
    for (int k = 0; k < nn; k++) {
        const double depth = level - dotp(xy[k], wt->up);
        value[k] = depth > 0 ? wt->rho * wt->g * depth : 0;
    }
    for (int t = 0; t < *nt; t++) {
        tri[3 * t] = 0;
        tri[3 * t + 1] = t + 1;
        tri[3 * t + 2] = t + 2;
    }
    return *nt ? nn : 0;
}

double pl_hs_solid_area(const pl_hs_water *wt, double level, const pl_grain_view *g) {
    double a = 0;
    for (int i = 0; i < g->n; i++) {
        if (g->shape[i] == PL_SHAPE_SEGMENT || !(g->area[i] > 0)) continue;
        pl_hs_part p;
        pl_hs_body_part(wt, level, g, i, &p);
        a += p.area;
    }
    return a;
}

static double residual(const pl_hs_water *wt, const pl_grain_view *g, double a_water, double level, int *evals) {
    (*evals)++;
    return pl_hs_tank_area(wt, level) - pl_hs_solid_area(wt, level, g) - a_water;
}

double pl_hs_solve_level(const pl_hs_water *wt, const pl_grain_view *g, double a_water, double level0, int *evals) {
    int ev = 0;
    const double width = wt->x_max - wt->x_min;
    const double scale = fmax(width, fmax(fabs(level0 - wt->bottom), 1e-300));
    const double tol = 1e-12 * scale;
    /* the lowest level at which there is water: the surface touches the tank's lowest corner */
    const double h_low = fmin(wt->x_min * wt->up.x, wt->x_max * wt->up.x) + wt->bottom * wt->up.y;
    double a = fmax(level0, h_low), fa = residual(wt, g, a_water, a, &ev);
    if (fa == 0 || !(width > 0) || !(wt->up.y > 1e-12)) {
        if (evals) *evals = ev;
        return a;
    }
    /* bracket: dA_T/dlevel <= width / up.y, so |fa| up.y / width never overshoots from below;
       double the step until the sign changes */
    const double dir = fa < 0 ? 1 : -1;
    double step = fmax(fabs(fa) * wt->up.y / width, tol);
    double b = a, fb = fa;
    for (int k = 0; k < 200; k++) {
        b = a + dir * step;
        if (dir < 0 && b <= h_low) b = h_low;
        fb = residual(wt, g, a_water, b, &ev);
        if (fb == 0 || (fb > 0) != (fa > 0) || b == h_low) break;
        a = b;
        fa = fb;
        step *= 2;
    }
    if (fb == 0 || (fb > 0) == (fa > 0)) {
        if (evals) *evals = ev;
        return b;
    }
    /* Illinois regula falsi on [a, b] (a and b bracket the root), bisection after 60 passes */
    int side = 0;
    double c = b, fc = fb;
    for (int k = 0; k < 200 && fabs(b - a) > tol; k++) {
        c = k < 60 ? (a * fb - b * fa) / (fb - fa) : 0.5 * (a + b);
        if (!(c > fmin(a, b) && c < fmax(a, b))) c = 0.5 * (a + b);
        fc = residual(wt, g, a_water, c, &ev);
        if (fc == 0) break;
        if ((fc > 0) == (fb > 0)) {
            b = c;
            fb = fc;
            if (side == -1) fa *= 0.5;
            side = -1;
        } else {
            a = c;
            fa = fc;
            if (side == 1) fb *= 0.5;
            side = 1;
        }
        /* the residual is an area: below width x tol the level is within tol */
        if (fabs(fc) * wt->up.y < 1e-3 * tol * width) break;
    }
    if (evals) *evals = ev;
    return c;
}
