/* Angle of repose: polygons against discs (seed 004 §2.1 and Fig. 1: "round particles ...
 * cannot form heaps without unphysical twists", polygons "form stable heaps"; issue 3: "a heap
 * of polygons reaches a clearly larger angle of repose than a heap of discs with the same
 * friction (report both angles)").
 *
 * 150 grains are poured on a floor (three every 0.06 s, released 2.5 cm above the heap's top
 * near x = 0), once as
 * random convex polygons inscribed in ellipses (5-9 corners, half axes 5-7.5 mm, aspect
 * 0.6-1, seed 004 §2.1) and once as discs of the same areas; same density, stiffness,
 * restitution and friction mu = 0.5 (grain-grain and grain-floor). After the grains come to
 * rest the surface profile (highest outline point per 6 mm bin) is fitted by a straight line
 * on each flank between 20 % and 80 % of the heap height; the angle is the mean of the two,
 * averaged over two pours (seeds). Pass: polygon angle > disc angle + 8 degrees, and the
 * polygon angle lies in the range
 * reported for 2D polygon heaps with mu ~ 0.5 (roughly 20-35 degrees; e.g. Matuttis & Chen,
 * Understanding the Discrete Element Method, 2014, ch. 7). */
#include "harness.h"
#include "polygon_common.h"
#include <stdlib.h>

#define NB 150
#define BIN 0.006

typedef struct heap_result {
    double angle_left, angle_right, angle, height, ke, time;
    int on_floor_region;
} heap_result;

static double fit_slope(const double *x, const double *y, int n) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int i = 0; i < n; i++) { sx += x[i]; sy += y[i]; sxx += x[i] * x[i]; sxy += x[i] * y[i]; }
    const double den = n * sxx - sx * sx;
    return den != 0 ? (n * sxy - sx * sy) / den : 0;
}

/* Surface profile and flank fits. */
static void measure(pl_world *w, int first, heap_result *r) {
    enum { NBIN = 2 * 67 };
    const double x0 = -0.4;
    double h[NBIN * 3];
    const int nbin = (int)(0.8 / BIN);
    for (int k = 0; k < nbin; k++) h[k] = 0;
    for (int i = first; i < pl_world_body_count(w); i++) {
        const pl_body_info b = poly_body(w, i);
        pl_vec2 v[64];
        int n = pl_world_body_vertices(w, i, v, 64);
        if (b.shape == PL_SHAPE_DISC) {
            n = 32;
            for (int k = 0; k < n; k++)
                v[k] = (pl_vec2){b.position.x + b.radius * cos(2 * PI * k / n),
                                 b.position.y + b.radius * sin(2 * PI * k / n)};
        }
        for (int k = 0; k < n; k++) {
            const int bi = (int)floor((v[k].x - x0) / BIN);
            if (bi >= 0 && bi < nbin && v[k].y > h[bi]) h[bi] = v[k].y;
        }
    }
    int peak = 0;
    for (int k = 1; k < nbin; k++)
        if (h[k] > h[peak]) peak = k;
    const double H = h[peak];
    r->height = H;
    double xs[NBIN * 3], ys[NBIN * 3];
    int n = 0;
    for (int k = peak; k >= 0; k--) { /* left flank: walk down from the peak */
        if (h[k] < 0.2 * H) break;
        if (h[k] <= 0.8 * H) { xs[n] = x0 + (k + 0.5) * BIN; ys[n] = h[k]; n++; }
    }
    r->angle_left = n >= 2 ? atan(fabs(fit_slope(xs, ys, n))) * 180 / PI : 0;
    n = 0;
    for (int k = peak; k < nbin; k++) {
        if (h[k] < 0.2 * H) break;
        if (h[k] <= 0.8 * H) { xs[n] = x0 + (k + 0.5) * BIN; ys[n] = h[k]; n++; }
    }
    r->angle_right = n >= 2 ? atan(fabs(fit_slope(xs, ys, n))) * 180 / PI : 0;
    r->angle = 0.5 * (r->angle_left + r->angle_right);
}

static int run_heap(int polygons, uint64_t seed, heap_result *r) {
    pl_world_def d = pl_default_world_def();
    d.gravity = (pl_vec2){0, -9.81};
    pl_world *w = pl_world_create(&d);
    const int m = poly_material(w, "grain", 2650, 1e5, 0.5, 0.3);
    poly_add_wall(w, m, -0.4, 0, 0.4, 0);
    poly_add_wall(w, m, -0.4, 0.3, -0.4, 0);
    poly_add_wall(w, m, 0.4, 0, 0.4, 0.3);
    const int first = pl_world_body_count(w);
    pl_rng rng;
    pl_rng_seed(&rng, seed);
    const pl_random_polygon_def pd = pl_default_random_polygon_def();
    int added = 0, ok = 1;
    double dt = 0;
    for (int s = 0; s < 200 && ok; s++) { /* at most 12 s */
        if (added < NB) {
            /* pour: three grains every 0.06 s, released 2.5 cm above the heap's top (the
             * highest slow grain near x = 0), and at least 1.6 cm above the grains still
             * falling there */
            double top = 0, high = 0;
            for (int i = first; i < pl_world_body_count(w); i++) {
                const pl_body_info b = poly_body(w, i);
                const double v = hypot(b.velocity.x, b.velocity.y);
                if (fabs(b.position.x) < 0.03 && v < 0.1) top = fmax(top, b.position.y);
                if (fabs(b.position.x) < 0.03) high = fmax(high, b.position.y);
            }
            top = fmax(top, high - 0.025 + 0.016); /* clear of the last batch still falling */
            for (int j = 0; j < 3 && added < NB; j++, added++) {
                const pl_vec2 c = {-0.015 + 0.015 * j + pl_rng_range(&rng, -2e-3, 2e-3), top + 0.025};
                pl_vec2 v[64];
                const int n = pl_shape_random_polygon(&pd, &rng, c, v, 64, NULL, 0);
                if (n < 3) return 0;
                int id;
                if (polygons) {
                    id = poly_add(w, m, v, n, PL_MOTION_DYNAMIC);
                } else {
                    /* disc of the same area at the polygon's centroid */
                    pl_mass_props mp;
                    pl_polygon_mass_properties(v, n, 2650, &mp, NULL, 0);
                    id = poly_add_disc(w, m, mp.centroid.x, mp.centroid.y, sqrt(mp.area / PI));
                }
                if (id < 0) return 0;
            }
            dt = pl_world_dt(w);
        }
        if (!poly_run(w, (int)(0.06 / dt))) ok = 0;
        r->ke = pl_world_energy(w).kinetic;
        if (added >= NB && r->ke < 1e-6) break;
    }
    r->time = pl_world_time(w);
    measure(w, first, r);
    pl_world_destroy(&w);
    return ok;
}

static int polygons_heap_steeper_than_discs(void) {
    /* two pours each (seeds 2020 and 2021): one heap of 150 grains scatters by a few degrees */
    heap_result p[2], c[2];
    for (int k = 0; k < 2; k++) {
        ENSURE(run_heap(1, 2020 + k, &p[k]));
        ENSURE(run_heap(0, 2020 + k, &c[k]));
        fprintf(stderr,
                "  seed %d polygons: angle %.1f deg (left %.1f, right %.1f), height %.3f m, KE %.2g J at t = %.2f s\n"
                "  seed %d discs:    angle %.1f deg (left %.1f, right %.1f), height %.3f m, KE %.2g J at t = %.2f s\n",
                2020 + k, p[k].angle, p[k].angle_left, p[k].angle_right, p[k].height, p[k].ke, p[k].time,
                2020 + k, c[k].angle, c[k].angle_left, c[k].angle_right, c[k].height, c[k].ke, c[k].time);
    }
    const double ap = 0.5 * (p[0].angle + p[1].angle), ac = 0.5 * (c[0].angle + c[1].angle);
    fprintf(stderr, "  mean angle of repose: polygons %.1f deg, discs %.1f deg\n", ap, ac);
    pl_validation("polygon.heap", "heap of polygons vs discs, same friction (150 grains, plain floor)",
                  "polygons clearly steeper (Mueller et al. 2020 Fig. 1)", "> discs + 8°; polygons 15–40°",
                  "%.1f° vs %.1f° (mean of two pours: %.1f° and %.1f° vs %.1f° and %.1f°)", ap, ac, p[0].angle,
                  p[1].angle, c[0].angle, c[1].angle);
    ENSURE(ap > ac + 8);
    ENSURE(ap > 15 && ap < 40);
    ENSURE(p[0].height > 1.5 * c[0].height && p[1].height > 1.5 * c[1].height);
    return 0;
}

int main(void) {
    RUN(polygons_heap_steeper_than_discs);
    return pl_test_report();
}
