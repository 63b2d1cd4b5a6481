/* Seed 003 (Tan 1990) §2.2.5 validation of the Cundall-Strack disc model.
 *
 * Table 2.1: one disc (R = 1 m, rho = 2400 kg/m^3 so m = 7539.823 kg per metre, g = 10 m/s^2,
 * k_N = 1e7 N/m) settling on a plate with dt = 1e-3 s for 5000 steps (t = 5 s):
 *   case 1 no damping: the plate force oscillates between 0 and 2W (W = 75398.23 N)
 *   case 2 global C = 1e4 N s/m:     seed 72703.36 N (3.57 % off W); we compare with the
 *                                    analytic damped oscillator, which the seed's value matches
 *   case 3 contact c_N = 1e5 N s/m:  seed 75398.66 N (0.0006 %)
 *   case 4 c_N = 1e5 and C = 4.5e5:  seed 75397.49 N (0.0010 %)
 * (The extracted table shows the c_N and C columns of cases 2 and 3 swapped; the text, "case 2
 * global only, 10 times less damping than case 3", and the errors fix the assignment used here.)
 *
 * Table 2.2: five frictionless discs between a floor and two vertical walls; theoretical forces
 * from rigid-disc statics; the seed's own errors are 0.002 % to 4.21 %.
 * Table 2.3: the same with friction (phi = 15 deg, k_S = 7e6, c_S = 7e4, C* = 4.5e5): the wall
 * reactions must sum to the total weight 376991.2 N (seed: 376991.7 N) and to zero horizontally.
 * Table 2.4: impact of two discs (m = pi kg, k_N = 1e7, dt = 1e-5, disc 1 at 6 m/s) against
 * the elastic-collision velocities (2.598, 1.5) and (-2.598, 4.5) m/s within 1 %. */
#include "common.h"
#include "harness.h"

static const double W = 7539.822368615503 * 10.0; /* weight of a 1 m disc, rho 2400, g 10 */

static double plate_force(double cn, double C, int steps, double *lo, double *hi) {
    pl_world_def d = pl_default_world_def();
    d.gravity = (pl_vec2){0, -10};
    d.dt = 1e-3;
    d.global_c = C;
    pl_world *w = pl_world_create(&d);
    const int m = add_material(w, "disc", 2400, 1e7, 0, 0, cn, 0);
    const int plate = add_wall(w, m, -5, 0, 5, 0);
    add_disc(w, m, 0, 1, 1);
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int s = 0; s < steps; s++) {
        if (pl_world_step(w, 1) != PL_OK) {
            fprintf(stderr, "%s\n", pl_world_last_error(w));
            break;
        }
        const double f = -body(w, plate).force.y;
        *lo = fmin(*lo, f);
        *hi = fmax(*hi, f);
    }
    const double f = -body(w, plate).force.y;
    pl_world_destroy(&w);
    return f;
}

/* Plate force of m x'' + c x' + k x = m g with x(0) = x'(0) = 0, at time t. */
static double analytic_plate_force(double c, double t) {
    const double m = 7539.822368615503, k = 1e7, om = sqrt(k / m), z = c / (2 * sqrt(k * m));
    const double od = om * sqrt(1 - z * z);
    const double xs = m * 10 / k;
    const double x = xs * (1 - exp(-z * om * t) * (cos(od * t) + z / sqrt(1 - z * z) * sin(od * t)));
    const double v = xs * exp(-z * om * t) * (om / sqrt(1 - z * z)) * sin(od * t);
    return k * x + c * v;
}

static int table_2_1_case1_oscillates(void) {
    double lo, hi;
    plate_force(0, 0, 5000, &lo, &hi);
    fprintf(stderr, "  case 1: plate force range %.1f .. %.1f N (W = %.1f)\n", lo, hi, W);
    pl_validation("grains.plate_undamped", "disc on plate, no damping (Tan 1990 Table 2.1 case 1)",
                  "force oscillates 0 … 2W", "1 % of W", "%.1f … %.1f N (2W = %.1f)", lo, hi, 2 * W);
    ENSURE_NEAR(lo, 0, 0.01 * W);
    ENSURE_NEAR(hi, 2 * W, 0.01 * W);
    return 0;
}

static int table_2_1_case2_global(void) {
    double lo, hi;
    const double f = plate_force(0, 1e4, 5000, &lo, &hi);
    const double fa = analytic_plate_force(1e4, 5.0);
    fprintf(stderr, "  case 2: F(5 s) = %.2f N, analytic %.2f N, seed 72703.36 N; error vs W %.4f %% (seed 3.5742 %%)\n",
            f, fa, 100 * fabs(f - W) / W);
    pl_validation("grains.plate_global_c", "disc on plate, global C = 1e4 (case 2)",
                  "analytic damped oscillator at t = 5 s; Tan 1990: 72 703.36 N (3.574 %)",
                  "0.2 % of W vs analytic; ≤ 3.6 % vs W", "%.2f N (%.3f %%), analytic %.2f N", f,
                  100 * fabs(f - W) / W, fa);
    ENSURE_NEAR(f, fa, 0.002 * W);
    ENSURE(fabs(f - W) / W <= 0.036); /* within the seed's own error */
    return 0;
}

static int table_2_1_case3_contact(void) {
    double lo, hi;
    const double f = plate_force(1e5, 0, 5000, &lo, &hi);
    fprintf(stderr, "  case 3: F(5 s) = %.3f N, error %.5f %% (seed 0.0006 %%)\n", f, 100 * fabs(f - W) / W);
    pl_validation("grains.plate_contact_cn", "disc on plate, contact c_N = 1e5 (case 3)",
                  "W = 75 398.2 N; Tan 1990 error 0.0006 %", "0.01 %", "%.4f %%", 100 * fabs(f - W) / W);
    ENSURE_NEAR(f, W, 1e-4 * W);
    return 0;
}

static int table_2_1_case4_both(void) {
    double lo, hi;
    const double f = plate_force(1e5, 4.5e5, 5000, &lo, &hi);
    fprintf(stderr, "  case 4: F(5 s) = %.3f N, error %.5f %% (seed 0.0010 %%)\n", f, 100 * fabs(f - W) / W);
    pl_validation("grains.plate_critical", "disc on plate, c_N and C (case 4, critical)", "W; Tan 1990: 0.0010 %",
                  "0.01 %, no overshoot > 0.5 %", "%.4f %%, peak %.4f W", 100 * fabs(f - W) / W, hi / W);
    ENSURE_NEAR(f, W, 1e-4 * W);
    /* critically damped: no overshoot beyond the weight by more than 0.5 % */
    ENSURE(hi <= 1.005 * W);
    return 0;
}

/* Five discs (Fig. 2.12): floor y = 0 (wall 1), vertical walls x = 0 (wall 2) and x = 5
   (wall 3). Discs 1, 2 on the floor at x = 1, 4; disc 3 on top of both; discs 4, 5 on disc 3
   against the walls. Line-of-centres offsets (1.5, sqrt(1.75)) make cos = 0.75 as in the
   seed's theoretical forces. */
typedef struct five {
    pl_world *w;
    int wall[3], disc[5];
} five;

static five build_five(int friction) {
    five f;
    pl_world_def d = pl_default_world_def();
    d.gravity = (pl_vec2){0, -10};
    d.dt = 1e-3;
    d.global_c = 4.5e5;
    d.global_c_rot = friction ? 4.5e5 : 0;
    f.w = pl_world_create(&d);
    const int m = friction ? add_material(f.w, "disc", 2400, 1e7, 7e6, tan(15 * M_PI / 180), 1e5, 7e4)
                           : add_material(f.w, "disc", 2400, 1e7, 0, 0, 1e5, 0);
    const double h = sqrt(1.75);
    f.wall[0] = add_wall(f.w, m, -1, 0, 6, 0);
    f.wall[1] = add_wall(f.w, m, 0, 0, 0, 8);
    f.wall[2] = add_wall(f.w, m, 5, 0, 5, 8);
    f.disc[0] = add_disc(f.w, m, 1, 1, 1);
    f.disc[1] = add_disc(f.w, m, 4, 1, 1);
    f.disc[2] = add_disc(f.w, m, 2.5, 1 + h, 1);
    f.disc[3] = add_disc(f.w, m, 1, 1 + 2 * h, 1);
    f.disc[4] = add_disc(f.w, m, 4, 1 + 2 * h, 1);
    return f;
}

static double mag(pl_vec2 v) { return hypot(v.x, v.y); }

/* Table 2.2 lists the seed's predicted force, the rigid-disc theory and an error column. The
   predicted forces are reproduced here to 0.01 %; the errors against theory are within the
   seed's own, except that the seed's 0.52 % for disc 3 - discs 1, 2 is inconsistent with its
   own columns: (175075.0 - 170996.9) / 170996.9 = 2.39 %, which is what we measure. */
static int table_2_2_five_discs(void) {
    five f = build_five(0);
    ENSURE(pl_world_step(f.w, 5000) == PL_OK);
    struct {
        int on, from;
        double seed, theory;
        const char *name;
    } rows[] = {
        {0, -1, 188492.5, 188495.6, "disc 1 - wall 1"}, {0, -2, 133648.0, 128247.7, "disc 1 - wall 2"},
        {1, -1, 188491.3, 188495.6, "disc 2 - wall 1"}, {1, -3, 133647.8, 128247.7, "disc 2 - wall 3"},
        {2, 0, 175075.0, 170996.9, "disc 3 - disc 1"},  {2, 1, 175079.4, 170996.9, "disc 3 - disc 2"},
        {2, 3, 115750.6, 113997.9, "disc 3 - disc 4"},  {2, 4, 115760.0, 113997.9, "disc 3 - disc 5"},
        {3, -2, 87832.7, 85498.4, "disc 4 - wall 2"},   {4, -3, 87828.2, 85498.4, "disc 5 - wall 3"},
    };
    double worst_seed = 0; /* for the validation row */
    int fail = 0;
    for (size_t k = 0; k < sizeof rows / sizeof rows[0]; k++) {
        const int on = f.disc[rows[k].on];
        const int from = rows[k].from < 0 ? f.wall[-rows[k].from - 1] : f.disc[rows[k].from];
        const double F = mag(contact_force_on(f.w, on, from));
        const double dseed = 100 * fabs(F - rows[k].seed) / rows[k].seed;
        const double err = 100 * fabs(F - rows[k].theory) / rows[k].theory;
        const double seed_err = 100 * fabs(rows[k].seed - rows[k].theory) / rows[k].theory;
        fprintf(stderr, "  %-16s %10.1f N  seed %10.1f (diff %.4f %%)  theory %10.1f  error %.3f %% (seed %.3f %%)\n",
                rows[k].name, F, rows[k].seed, dseed, rows[k].theory, err, seed_err);
        if (!(dseed <= 0.01) || !(err <= seed_err + 0.01)) fail = 1;
        worst_seed = fmax(worst_seed, dseed);
    }
    pl_validation("grains.five_discs", "five-disc stack, frictionless (Table 2.2)",
                  "Tan 1990's predicted forces, and rigid-disc theory within its own errors", "0.01 % vs Tan 1990",
                  "≤ %.4f %% vs Tan 1990 on all 10 contacts", worst_seed);
    pl_world_destroy(&f.w);
    ENSURE(!fail);
    return 0;
}

static int table_2_3_five_discs_friction(void) {
    five f = build_five(1);
    ENSURE(pl_world_step(f.w, 5000) == PL_OK);
    pl_vec2 sum = {0, 0};
    for (int k = 0; k < 3; k++) {
        const pl_body_info b = body(f.w, f.wall[k]);
        sum.x += b.force.x;
        sum.y += b.force.y;
    }
    const double weight = 5 * W;
    fprintf(stderr, "  friction: wall reactions sum Fx = %.3f N, Fy = %.3f N (weight %.1f N; seed -0.5, 376991.7)\n",
            -sum.x, -sum.y, weight);
    /* Table 2.3 gives components in the axes of its Fig. 2.15(b); compare magnitudes (1 %) */
    struct {
        int on, from;
        double fx, fy;
        const char *name;
    } rows[] = {
        {0, -1, 167269.7, 38775.2, "disc 1 - wall 1"}, {0, -2, 28609.2, -7665.5, "disc 1 - wall 2"},
        {2, 0, 116104.0, -31109.8, "disc 3 - disc 1"}, {2, 3, 78747.3, 13561.1, "disc 3 - disc 4"},
        {3, -2, 50610.7, -13561.0, "disc 4 - wall 2"},
    };
    double worst_f = 0; /* for the validation row */
    int fail = 0;
    for (size_t k = 0; k < sizeof rows / sizeof rows[0]; k++) {
        const int on = f.disc[rows[k].on];
        const int from = rows[k].from < 0 ? f.wall[-rows[k].from - 1] : f.disc[rows[k].from];
        const double F = mag(contact_force_on(f.w, on, from)), S = hypot(rows[k].fx, rows[k].fy);
        fprintf(stderr, "  %-16s |F| %10.1f N  seed %10.1f  diff %.3f %%\n", rows[k].name, F, S, 100 * fabs(F - S) / S);
        if (!(fabs(F - S) <= 0.01 * S)) fail = 1;
        worst_f = fmax(worst_f, 100 * fabs(F - S) / S);
    }
    pl_validation("grains.five_discs_friction", "five-disc stack, friction 15° (Table 2.3)",
                  "wall reactions = total weight 376 991.1 N, ΣF_x = 0; Tan 1990's |F| per contact", "1e-3 of the weight; 1 %",
                  "ΣF_y = %.3f N, ΣF_x = %.3f N; |F| within %.2f %%", -sum.y, -sum.x, worst_f);
    ENSURE(!fail);
    ENSURE_NEAR(-sum.y, weight, 1e-3 * weight);
    ENSURE_NEAR(sum.x, 0, 1e-3 * weight);
    /* the symmetric structure gives symmetric reactions on the two side walls */
    ENSURE_NEAR(body(f.w, f.wall[1]).force.x, -body(f.w, f.wall[2]).force.x, 1e-3 * weight);
    pl_world_destroy(&f.w);
    return 0;
}

static int table_2_4_impact(void) {
    pl_world_def d = pl_default_world_def();
    d.gravity = (pl_vec2){0, 0};
    d.dt = 1e-5;
    pl_world *w = pl_world_create(&d);
    const int m = add_material(w, "disc", 1.0, 1e7, 0, 0, 0, 0); /* m = pi kg */
    const double h = sqrt(3.0);
    const int d1 = add_disc(w, m, 0, 0, 1);
    const int d2 = add_disc(w, m, -1, h + 0.264, 1); /* line of centres at 120 deg at impact */
    pl_world_set_body_velocity(w, d1, (pl_vec2){0, 6}, 0);
    ENSURE(pl_world_step(w, 100000) == PL_OK); /* t = 1 s */
    const pl_body_info b1 = body(w, d1), b2 = body(w, d2);
    fprintf(stderr, "  impact: v1 = (%.4f, %.4f) v2 = (%.4f, %.4f); theory (2.598, 1.5) (-2.598, 4.5)\n",
            b1.velocity.x, b1.velocity.y, b2.velocity.x, b2.velocity.y);
    pl_validation("grains.impact", "two-disc impact (Table 2.4)", "elastic collision (2.598, 1.5), (−2.598, 4.5) m/s",
                  "1 %", "(%.3f, %.3f), (%.3f, %.3f)", b1.velocity.x, b1.velocity.y, b2.velocity.x, b2.velocity.y);
    const double s = 3 * sqrt(3.0) / 2;
    ENSURE_REL(b1.velocity.x, s, 0.01);
    ENSURE_REL(b1.velocity.y, 1.5, 0.01);
    ENSURE_REL(b2.velocity.x, -s, 0.01);
    ENSURE_REL(b2.velocity.y, 4.5, 0.01);
    /* momentum and energy are conserved by a frictionless elastic contact */
    ENSURE_NEAR(b1.velocity.y + b2.velocity.y, 6, 1e-9);
    const double e = b1.velocity.x * b1.velocity.x + b1.velocity.y * b1.velocity.y + b2.velocity.x * b2.velocity.x +
                     b2.velocity.y * b2.velocity.y;
    ENSURE_REL(e, 36, 1e-3);
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(table_2_1_case1_oscillates);
    RUN(table_2_1_case2_global);
    RUN(table_2_1_case3_contact);
    RUN(table_2_1_case4_both);
    RUN(table_2_2_five_discs);
    RUN(table_2_3_five_discs_friction);
    RUN(table_2_4_impact);
    return pl_test_report();
}
