/* A square on an inclined floor (issue 3: "tips at theta > 45 deg when friction prevents
 * sliding; slides first when mu < tan theta"). Rigid-block statics on an incline (any
 * mechanics text, e.g. Meriam & Kraige, Engineering Mechanics: Statics, ch. 6):
 *   - it stays when mu >= tan(theta) and the weight's line of action passes inside the base,
 *     i.e. theta < 45 deg for a square;
 *   - it tips over its downhill corner when theta > 45 deg and friction holds it (mu > tan theta);
 *   - it slides without tipping when mu < tan(theta) and mu < 1 (the resultant of N and mu N
 *     then passes inside the base), with the acceleration a = g (sin theta - mu cos theta).
 * The floor is a fixed wall segment tilted by theta, the square (L = 2 cm, 1 kg per metre) is
 * placed on it at rest. Each case runs at one fixed angle. */
#include "harness.h"
#include "polygon_common.h"
#include <stdlib.h>

typedef struct run_result {
    double slide;      /* displacement of the centroid along the slope (downhill > 0), m */
    double turn;       /* rotation, rad (tipping downhill is counter-clockwise, > 0) */
    double t_tip;      /* time when the rotation passed 0.2 rad (or -1) */
    double slide_tip;  /* slide displacement at that time */
    double v_slope;    /* downhill velocity at the end, m/s */
    double v_mid, t_mid; /* downhill velocity at mid run, and its time */
    double t_end;
} run_result;

static int run_incline(double theta_deg, double mu, double kn, double t_end, run_result *r) {
    const double th = theta_deg * PI / 180, L = 0.02;
    pl_world_def d = pl_default_world_def();
    d.gravity = (pl_vec2){0, -9.81};
    pl_world *w = pl_world_create(&d);
    const int m = poly_material(w, "block", 2500, kn, mu, 0.3);
    const pl_vec2 u = {cos(th), sin(th)}, n = {-sin(th), cos(th)};
    const double len = 0.5;
    const int floor = poly_add_wall(w, m, -len * u.x, -len * u.y, len * u.x, len * u.y);
    const pl_vec2 c0 = {0.5 * L * n.x, 0.5 * L * n.y};
    const int sq = poly_add_box(w, m, c0.x, c0.y, L, L, th, PL_MOTION_DYNAMIC);
    if (floor < 0 || sq < 0) return 0;
    const double dt = pl_world_dt(w);
    if (getenv("PL_VERBOSE")) fprintf(stderr, "  dt = %.3g s\n", dt);
    const int steps = (int)ceil(t_end / dt);
    r->t_tip = -1;
    r->slide_tip = 0;
    r->v_mid = 0;
    int ok = 1;
    for (int s = 0; s < steps; s++) {
        if (!poly_run(w, 1)) { ok = 0; break; }
        const pl_body_info b = poly_body(w, sq);
        const double slide = -((b.position.x - c0.x) * u.x + (b.position.y - c0.y) * u.y);
        if (r->t_tip < 0 && b.angle > 0.2) {
            r->t_tip = pl_world_time(w);
            r->slide_tip = slide;
        }
        if (s == steps / 2) {
            r->v_mid = -(b.velocity.x * u.x + b.velocity.y * u.y);
            r->t_mid = pl_world_time(w);
        }
        r->slide = slide;
        r->turn = b.angle;
        r->v_slope = -(b.velocity.x * u.x + b.velocity.y * u.y);
    }
    r->t_end = pl_world_time(w);
    pl_world_destroy(&w);
    return ok;
}

/* Quasi-static tilting: the floor turns about the square's contact at omega_t; returns the
 * floor angles (deg) at which the square first tips (its rotation relative to the floor
 * exceeds 0.2 rad) and first slides (its material point at the contact moves along the
 * floor, relative to the floor, faster than 1e-4 m/s), or 90 when it does not happen before 60 degrees. */
static int tilt_floor(double mu, double kn, double omega_t, double *tip_deg, double *slide_deg,
                      double *corner_slip) {
    const double L = 0.02;
    pl_world_def d = pl_default_world_def();
    d.gravity = (pl_vec2){0, -9.81};
    pl_world *w = pl_world_create(&d);
    const int m = poly_material(w, "block", 2500, kn, mu, 0.3);
    const int floor = poly_add_wall(w, m, -0.2, 0, 0.2, 0);
    const int sq = poly_add_box(w, m, 0, L / 2, L, L, 0, PL_MOTION_DYNAMIC);
    if (floor < 0 || sq < 0) return 0;
    if (!poly_run(w, (int)(0.05 / pl_world_dt(w)))) return 0; /* settle */
    if (pl_world_prescribe_velocity(w, floor, (pl_vec2){0, 0}, omega_t) != PL_OK) return 0;
    const double dt = pl_world_dt(w), t0 = pl_world_time(w);
    const double a0 = poly_body(w, sq).angle;
    *tip_deg = *slide_deg = 90;
    *corner_slip = 0;
    int ok = 1;
    for (;;) {
        if (!poly_run(w, 10)) { ok = 0; break; }
        const double th = poly_body(w, floor).angle;
        if (th > 60 * PI / 180) break;
        const pl_body_info b = poly_body(w, sq);
        const pl_vec2 u = {cos(th), sin(th)};
        /* sliding: velocity of the square's material point at the contact point (the
         * overlap centroid) relative to the floor's, along the floor */
        pl_contact_info c;
        double vrel = 0;
        if (poly_contact(w, sq, floor, &c)) {
            const pl_vec2 r = {c.point.x - b.position.x, c.point.y - b.position.y};
            const pl_vec2 vb = {b.velocity.x - b.omega * r.y, b.velocity.y + b.omega * r.x};
            const pl_vec2 vf = {-omega_t * c.point.y, omega_t * c.point.x}; /* pivot at 0 */
            vrel = (vb.x - vf.x) * u.x + (vb.y - vf.y) * u.y;
        }
        /* (skip the first degree: the block needs a moment to pick up the floor's rotation) */
        if (*slide_deg == 90 && th > PI / 180 && fabs(vrel) > 1e-4) *slide_deg = th * 180 / PI;
        if (*tip_deg == 90 && b.angle - a0 - th > 0.2) {
            *tip_deg = th * 180 / PI;
            /* how far the downhill corner moved along the floor before the square tipped */
            pl_vec2 v[4];
            pl_world_body_vertices(w, sq, v, 4);
            int low = 0; /* the corner deepest in the floor */
            for (int k = 1; k < 4; k++)
                if (-v[k].x * u.y + v[k].y * u.x < -v[low].x * u.y + v[low].y * u.x) low = k;
            *corner_slip = v[low].x * u.x + v[low].y * u.y - (-L / 2);
        }
        if (*tip_deg < 90 || *slide_deg < 90) {
            if (pl_world_time(w) - t0 > (th + 0.05) / omega_t) break;
        }
    }
    (void)dt;
    pl_world_destroy(&w);
    return ok;
}

static int tilting_floor_tips_near_45_deg(void) {
    double tip1, slide1, tip2, slide2, tip3, slide3, c1, c2, c3;
    const double L = 0.02;
    ENSURE(tilt_floor(1.5, 1e6, 0.05, &tip1, &slide1, &c1));
    ENSURE(tilt_floor(1.5, 1e7, 0.05, &tip2, &slide2, &c2));
    ENSURE(tilt_floor(1.5, 1e8, 0.05, &tip3, &slide3, &c3));
    fprintf(stderr, "  mu 1.5: tips at %.3f / %.3f / %.3f deg for kn 1e6 / 1e7 / 1e8 (rigid: 45); "
            "the corner had moved %.2g / %.2g / %.2g m along the floor (contact-point speed 1e-4 m/s passed at %.3g / %.3g / %.3g deg, while tipping)\n",
            tip1, tip2, tip3, c1, c2, c3, slide1, slide2, slide3);
    pl_validation("polygon.tilt_tip", "square on a slowly tilting floor, μ = 1.5", "tips at 45° (rigid) before sliding",
                  "converges with k_N; > 44° at 1e8", "%.1f° / %.1f° / %.1f° at k_N = 1e6 / 1e7 / 1e8", tip1, tip2, tip3);
    /* tips first: the contact corner has not slid (< 1 % of L) when the rotation reaches 0.2 rad */
    ENSURE(fabs(c1) < 0.01 * L && fabs(c2) < 0.01 * L && fabs(c3) < 0.01 * L);
    ENSURE(tip1 < tip2 && tip2 < tip3);                      /* converges from below ... */
    ENSURE(tip3 > 44.0 && tip3 < 45.3);                      /* ... to 45 degrees */
    ENSURE(tip1 > 40.0);
    return 0;
}

static int tilting_floor_slides_at_atan_mu(void) {
    double tip, slide, corner;
    const double mu = 0.5;
    ENSURE(tilt_floor(mu, 1e6, 0.05, &tip, &slide, &corner));
    fprintf(stderr, "  mu 0.5: slides at %.3f deg (atan mu = %.3f deg), tips at %.3g deg\n", slide,
            atan(mu) * 180 / PI, tip);
    pl_validation("polygon.tilt_slide", "same, μ = 0.5", "slides at atan μ = 26.57°", "0.3°", "%.2f°", slide);
    ENSURE_NEAR(slide, atan(mu) * 180 / PI, 0.3);
    ENSURE(tip == 90 || tip > slide);
    return 0;
}

static int slides_at_50_deg(void) {
    run_result r;
    const double th = 50 * PI / 180, mu = 0.5;
    ENSURE(run_incline(50, mu, 1e6, 0.3, &r));
    const double a = 9.81 * (sin(th) - mu * cos(th));
    const double a_meas = (r.v_slope - r.v_mid) / (r.t_end - r.t_mid);
    fprintf(stderr, "  50 deg, mu 0.5: a = %.5g m/s^2 (analytic %.5g), turn %.3g rad\n", a_meas, a, r.turn);
    pl_validation("polygon.incline_slide", "sliding block on fixed slopes (50°, μ = 0.5; 25°, μ = 0.3)",
                  "a = g (sin θ − μ cos θ)", "1 %", "%.4f vs %.4f m/s²", a_meas, a);
    ENSURE_REL(a_meas, a, 0.01);
    ENSURE(fabs(r.turn) < 0.02);
    return 0;
}

static int slides_at_25_stays_at_15_deg(void) {
    run_result r;
    const double mu = 0.3, th = 25 * PI / 180;
    ENSURE(run_incline(25, mu, 1e6, 0.3, &r));
    const double a = 9.81 * (sin(th) - mu * cos(th));
    const double a_meas = (r.v_slope - r.v_mid) / (r.t_end - r.t_mid);
    fprintf(stderr, "  25 deg, mu 0.3: a = %.5g m/s^2 (analytic %.5g), turn %.3g rad\n", a_meas, a, r.turn);
    pl_validation("polygon.incline_slide", "", "", "", "%.4f vs %.4f m/s²", a_meas, a);
    ENSURE_REL(a_meas, a, 0.01);
    ENSURE(fabs(r.turn) < 0.02);
    ENSURE(run_incline(15, mu, 1e6, 0.3, &r));
    fprintf(stderr, "  15 deg, mu 0.3: slide %.3g m, turn %.3g rad\n", r.slide, r.turn);
    ENSURE(fabs(r.slide) < 1e-4 && fabs(r.v_slope) < 1e-4);
    return 0;
}

int main(void) {
    RUN(tilting_floor_tips_near_45_deg);
    RUN(tilting_floor_slides_at_atan_mu);
    RUN(slides_at_50_deg);
    RUN(slides_at_25_stays_at_15_deg);
    return pl_test_report();
}
