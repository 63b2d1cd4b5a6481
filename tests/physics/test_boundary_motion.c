/* Boundary motions: shaking table (sinusoid), servo wall (seed 003 eqs. 5.11-5.12), hinged
 * simple-shear walls (seed 003 §5.4-5.6), and allocation-free stepping once settled. */
#include "common.h"
#include "harness.h"
#include <malloc.h>

static int sinusoid_follows_law(void) {
    pl_world_def d = pl_default_world_def();
    d.dt = 1e-4;
    pl_world *w = pl_world_create(&d);
    const int m = add_material(w, "m", 2500, 1e6, -1, 0.5, 0, -1);
    const int table = add_wall(w, m, -1, 0, 1, 0);
    const int disc = add_disc(w, m, 0, 0.0099, 0.01);
    ENSURE(pl_world_set_sinusoid(w, table, (pl_vec2){0.002, 0.001}, 5, 0.1, 0.5) == PL_OK);
    double worst = 0; /* for the validation row */
    for (int k = 1; k <= 6; k++) {
        if (pl_world_step(w, 1000) != PL_OK) {
            fprintf(stderr, "  %s\n", pl_world_last_error(w));
            return 1;
        }
        const double t = pl_world_time(w);
        const double ph = t < 0.1 ? 0 : sin(2 * M_PI * 5 * (fmin(t, 0.5) - 0.1));
        const pl_body_info b = body(w, table);
        ENSURE_NEAR(b.position.x, 0.002 * ph, 1e-12);
        worst = fmax(worst, fmax(fabs(b.position.x - 0.002 * ph), fabs(b.position.y - 0.001 * ph)));
        ENSURE_NEAR(b.position.y, 0.001 * ph, 1e-12);
    }
    /* the table did work on the disc riding on it */
    const pl_energy e = pl_world_energy(w);
    fprintf(stderr, "  table work on the disc %.4g J, balance %.3g J, disc at y = %.5f\n", e.external, e.balance,
            body(w, disc).position.y);
    pl_validation("grains.shaking_table", "shaking table", "x₀ + A sin(2πf(t−t₀))", "1e-12 m",
                  "largest deviation %.1e m at 6 checks", worst);
    ENSURE(fabs(e.external) > 0);
    ENSURE(fabs(e.balance) < 0.05 * (e.damped + e.friction + fabs(e.external)) + 1e-9);
    pl_world_destroy(&w);
    return 0;
}

/* A ramped shaking (pl_world_set_sinusoid_ramp): the position follows e(t) A sin(2 pi f tau) with
   the raised-cosine envelope e over the first and last `ramp` seconds, and the table starts and
   stops without a jump of velocity (the first and last steps move it by O(dt^3), not A w dt). */
static int sinusoid_ramp(void) {
    pl_world_def d = pl_default_world_def();
    d.dt = 1e-4;
    d.gravity = (pl_vec2){0, 0};
    pl_world *w = pl_world_create(&d);
    const int m = add_material(w, "m", 2500, 1e6, -1, 0.5, 0, -1);
    const int table = add_wall(w, m, -1, 0, 1, 0);
    ENSURE(pl_world_set_sinusoid(w, table, (pl_vec2){0.002, 0}, 5, 0.1, 0.9) == PL_OK);
    ENSURE(pl_world_set_sinusoid_ramp(w, table, 0.5) != PL_OK); /* more than half of 0.8 s */
    ENSURE(pl_world_set_sinusoid_ramp(w, table, 0.2) == PL_OK);
    double first = -1, last = 0, x_prev = 0;
    for (int k = 1; k <= 10000; k++) {
        ENSURE(pl_world_step(w, 1) == PL_OK);
        const double t = pl_world_time(w), x = body(w, table).position.x;
        const double tc = fmin(fmax(t, 0.1), 0.9), tau = tc - 0.1, left = 0.9 - tc;
        const double e = tau < 0.2 ? 0.5 * (1 - cos(M_PI * tau / 0.2)) : (left < 0.2 ? 0.5 * (1 - cos(M_PI * left / 0.2)) : 1);
        ENSURE_NEAR(x, 0.002 * e * sin(2 * M_PI * 5 * tau), 1e-12);
        if (t > 0.1 && first < 0) first = fabs(x - x_prev);
        if (t <= 0.9 + 1e-9) last = fabs(x - x_prev);
        x_prev = x;
    }
    const double full = 0.002 * 2 * M_PI * 5 * 1e-4; /* a step's move at full speed */
    fprintf(stderr, "  first step after the start moves %.2e m, last before the stop %.2e m (full speed %.2e m)\n",
            first, last, full);
    ENSURE(first < 1e-3 * full);
    ENSURE(last < 1e-3 * full);
    pl_world_destroy(&w);
    return 0;
}

static int servo_holds_force(void) {
    pl_world_def d = pl_default_world_def();
    d.gravity = (pl_vec2){0, 0};
    d.global_c = 5;
    pl_world *w = pl_world_create(&d);
    const int m = add_material(w, "m", 2500, 1e6, -1, 0.3, 0, -1);
    add_wall(w, m, 0, 0, 0.1, 0);
    add_wall(w, m, 0, 0, 0, 0.2);
    add_wall(w, m, 0.1, 0, 0.1, 0.2);
    for (int j = 0; j < 5; j++)
        for (int i = 0; i < 5; i++) add_disc(w, m, 0.01 + 0.02 * i, 0.01 + 0.021 * j, 0.0099);
    const int piston = add_wall(w, m, 0, 0.12, 0.1, 0.12);
    const double target = 200; /* N per metre of depth */
    ENSURE(pl_world_set_servo(w, piston, (pl_vec2){0, -1}, target, 0.5, 0.2) == PL_OK);
    ENSURE(pl_world_step(w, (int)(1.0 / pl_world_dt(w))) == PL_OK);
    double fmax = 0, fmin = 1e300;
    for (int k = 0; k < 200; k++) {
        ENSURE(pl_world_step(w, 10) == PL_OK);
        const double f = body(w, piston).force.y; /* grains push the piston up */
        fmax = fmax < f ? f : fmax;
        fmin = fmin > f ? f : fmin;
    }
    fprintf(stderr, "  servo: piston force %.2f .. %.2f N (target %.0f)\n", fmin, fmax, target);
    pl_validation("grains.servo", "servo wall (Tan 1990 eqs. 5.11–5.12)", "holds target force", "1 %",
                  "%.2f–%.2f N for %.0f N", fmin, fmax, target);
    ENSURE_NEAR(fmin, target, 0.01 * target);
    ENSURE_NEAR(fmax, target, 0.01 * target);
    pl_world_destroy(&w);
    return 0;
}

static int hinged_walls_follow_top(void) {
    pl_world_def d = pl_default_world_def();
    d.gravity = (pl_vec2){0, 0};
    d.dt = 1e-4;
    pl_world *w = pl_world_create(&d);
    const int m = add_material(w, "m", 2500, 1e6, -1, 0.3, 0, -1);
    const double H = 0.1;
    const int left = add_wall(w, m, 0, 0, 0, 1.5 * H);
    const int right = add_wall(w, m, 0.2, 0, 0.2, 1.5 * H);
    const int top = add_wall(w, m, -0.1, H, 0.3, H);
    add_disc(w, m, 0.1, 0.05, 0.01);
    ENSURE(pl_world_prescribe_velocity(w, top, (pl_vec2){0.01, 0}, 0) == PL_OK);
    ENSURE(pl_world_set_hinge(w, left, (pl_vec2){0, 0}, top, H) == PL_OK);
    ENSURE(pl_world_set_hinge(w, right, (pl_vec2){0.2, 0}, top, H) == PL_OK);
    ENSURE(pl_world_step(w, 30000) == PL_OK); /* 3 s: top moved 0.03 m, shear strain 0.3 */
    const double dx = body(w, top).position.x - 0.1;
    ENSURE_NEAR(dx, 0.03, 1e-9);
    pl_vec2 v[2];
    pl_world_body_vertices(w, left, v, 2);
    /* the left wall stays a line through its pivot with slope dx / H, and keeps its length */
    ENSURE_NEAR(v[0].x, 0, 1e-9);
    ENSURE_NEAR(v[0].y, 0, 1e-9);
    ENSURE_NEAR((v[1].x - v[0].x) / (v[1].y - v[0].y), dx / H, 1e-9);
    ENSURE_NEAR(hypot(v[1].x - v[0].x, v[1].y - v[0].y), 1.5 * H, 1e-9);
    pl_world_body_vertices(w, right, v, 2);
    ENSURE_NEAR(v[0].x, 0.2, 1e-9);
    ENSURE_NEAR((v[1].x - v[0].x) / (v[1].y - v[0].y), dx / H, 1e-9);
    fprintf(stderr, "  hinge: top displaced %.4f m, side walls at %.4f rad\n", dx, atan(dx / H));
    pl_validation("grains.hinge", "hinged simple-shear walls", "line through pivot at atan(dx/H), constant length",
                  "1e-9", "walls at %.4f rad after dx = %.4f m, within 1e-9", atan(dx / H), dx);
    pl_world_destroy(&w);
    return 0;
}

static int settled_stepping_allocates_nothing(void) {
    pl_world_def d = pl_default_world_def();
    pl_world *w = pl_world_create(&d);
    const int m = add_material(w, "m", 2500, 1e6, -1, 0.5, 0, -1);
    add_wall(w, m, 0, 0, 0.4, 0);
    add_wall(w, m, 0, 0, 0, 0.4);
    add_wall(w, m, 0.4, 0, 0.4, 0.4);
    for (int j = 0; j < 10; j++)
        for (int i = 0; i < 19; i++) add_disc(w, m, 0.011 + 0.02 * i + 0.002 * (j % 2), 0.011 + 0.0205 * j, 0.0095 + 0.0005 * (i % 2));
    ENSURE(pl_world_step(w, 20000) == PL_OK);
    const struct mallinfo2 a = mallinfo2();
    ENSURE(pl_world_step(w, 5000) == PL_OK);
    const struct mallinfo2 b = mallinfo2();
    fprintf(stderr, "  heap in use before/after 5000 settled steps: %zu / %zu bytes\n", a.uordblks, b.uordblks);
    pl_validation("grains.no_allocation", "no allocation once settled", "heap unchanged over 5000 steps", "exact",
                  "%zu B before, %zu B after", a.uordblks, b.uordblks);
    ENSURE(a.uordblks == b.uordblks && a.hblkhd == b.hblkhd);
    pl_world_destroy(&w);
    return 0;
}

/* Guided piston (issue 13 item 11): a body on a vertical guide under gravity, a side load
 * and a moment keeps x and its angle exactly and falls as a free body along the guide:
 * v_y = -g t (rigid-body mechanics; the central difference is exact for a constant force, to
 * rounding: 1e-9 relative). A plate dropped on one disc under one end turns when free and
 * stays level when guided (the test of the oedometer piston, scenes/soil/consolidation.lua). */
static pl_world *plate_world(int guided, int *plate) {
    pl_world_def d = pl_default_world_def();
    d.gravity = (pl_vec2){0, -9.81};
    pl_world *w = pl_world_create(&d);
    const int m = add_material(w, "m", 1000, 1e5, -1, 0.3, 0, -1);
    pl_body_def b = pl_default_body_def();
    const pl_vec2 v[4] = {{-0.05, 0.10}, {0.05, 0.10}, {0.05, 0.12}, {-0.05, 0.12}};
    b.shape = PL_SHAPE_POLYGON;
    b.material = m;
    b.vertices = v;
    b.vertex_count = 4;
    if (guided) b.guide = (pl_vec2){0, 2}; /* normalised by the engine */
    *plate = pl_world_add_body(w, &b);
    const int s = add_disc(w, m, 0.04, 0.05, 0.01); /* under the right end only */
    pl_world_set_body_motion(w, s, PL_MOTION_FIXED);
    return w;
}

static int guided_body_keeps_line_and_angle(void) {
    int plate;
    pl_world *w = plate_world(1, &plate);
    ENSURE(pl_world_set_body_load(w, plate, (pl_vec2){3, 0}, 0.2) == PL_OK);
    const pl_body_info b0 = body(w, plate);
    ENSURE(pl_world_step(w, 100) == PL_OK);
    const pl_body_info b1 = body(w, plate);
    const double t = pl_world_time(w);
    fprintf(stderr, "  guided, side load and moment: x %.17g -> %.17g, angle %.3g, v_y %.12g (-g t = %.12g)\n",
            b0.position.x, b1.position.x, b1.angle, b1.velocity.y, -9.81 * t);
    ENSURE(b1.position.x == b0.position.x);
    ENSURE(b1.angle == 0 && b1.omega == 0);
    ENSURE(b1.velocity.x == 0);
    ENSURE_REL(b1.velocity.y, -9.81 * t, 1e-9);
    pl_world_destroy(&w);
    /* landing on one disc: free, the plate turns; guided, it stays level and on its line */
    double angle[2];
    for (int g = 0; g < 2; g++) {
        w = plate_world(g, &plate);
        const double x0 = body(w, plate).position.x;
        if (pl_world_step(w, (int)(0.3 / pl_world_dt(w))) != PL_OK) {
            fprintf(stderr, "  %s\n", pl_world_last_error(w));
            return 1;
        }
        const pl_body_info b = body(w, plate);
        angle[g] = b.angle;
        fprintf(stderr, "  plate on one disc, %s: angle %.4f rad, x %.6f, contacts %d\n", g ? "guided" : "free", b.angle,
                b.position.x, pl_world_contact_count(w));
        if (g) {
            ENSURE(b.position.x == x0);
            ENSURE(pl_world_contact_count(w) == 1);
        }
        pl_world_destroy(&w);
    }
    ENSURE(fabs(sin(angle[0])) > 0.05); /* the free plate turned (it slid off the disc) */
    ENSURE(angle[1] == 0);
    return 0;
}

int main(void) {
    RUN(sinusoid_follows_law);
    RUN(sinusoid_ramp);
    RUN(servo_holds_force);
    RUN(hinged_walls_follow_top);
    RUN(guided_body_keeps_line_and_angle);
    RUN(settled_stepping_allocates_nothing);
    return pl_test_report();
}
