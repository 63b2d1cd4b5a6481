/* The §5.1 disc between walls (seed 003) with the fluid rungs below the boundary elements, set
 * up exactly as the benchmark's comparison (tests/stokes/stokes_cases.h: sc_disc_rung;
 * docs/stokes.md, Cost). CGS units: a disc r = 0.5 cm, rho_s = 2 g/cm^3 in a liquid
 * rho_l = 1 g/cm^3 filling a 5 x 40 cm box to its top, g = 980 cm/s^2, steps of 0.5 ms.
 *
 * Reference (Archimedes): neither the hydrostatic model nor the Darcy model without
 * consolidation resists a lone moving grain (a rigid grain in an incompressible, storage-free
 * Darcy fluid drives no flow), so the disc falls freely under buoyancy:
 *   v(t) = (1 - rho_l/rho_s) g t = 14.70 cm/s at t = 0.03 s,
 * and the Darcy pore pressure is the hydrostatic p = rho_l g (20 cm - y) from the first step.
 * Tolerances: the pressure to 1e-9 of rho_l g H (round-off of the static solve; measured
 * 1e-13), the velocity to 1e-6 (measured 3e-13 for both models).
 * The regression this guards: started from zero pressure (FIRST_STEP_STATIC = 0, the Darcy
 * default) the water column first drains downwards through the grain and drags it to 32 cm/s,
 * faster than free fall; the benchmark once compared against that run. The last check runs
 * that set-up and expects the velocity check above to fail on it (it prints how far off the
 * pressure is). */
#include "harness.h"
#include "stokes_cases.h"

#define G 980.0
#define RHO_L 1.0
#define RHO_S 2.0
#define TOP 20.0

/* largest |p - rho_l g (TOP - y)| / (rho_l g 2 TOP) on a column of points beside the disc and
   under it, after one step */
static double pressure_error(pl_world *w) {
    double worst = 0;
    for (int i = 0; i <= 38; i++) {
        const pl_vec2 pt = {i % 2 ? 1.7 : -1.3, -19.0 + i};
        double p, head;
        if (!pl_world_fluid_pressure_at(w, pt, &p, &head)) return INFINITY;
        worst = fmax(worst, fabs(p - RHO_L * G * (TOP - pt.y)) / (RHO_L * G * 2 * TOP));
    }
    return worst;
}

/* fall speed after 60 steps (0.03 s) */
static double fall_speed(pl_world *w, int disc) {
    if (pl_world_step(w, 59) != PL_OK) return NAN;
    pl_body_info bi;
    pl_world_body_info(w, disc, &bi);
    return -bi.velocity.y;
}

static const double V_BUOYANT = (1 - RHO_L / RHO_S) * G * 0.03;

static int hydrostatic_rung(void) {
    int d;
    pl_status st;
    pl_world *w = sc_disc_rung(SC_RUNG_HYDROSTATIC, &d, &st);
    ENSURE(st == PL_OK);
    ENSURE(pl_world_step(w, 1) == PL_OK);
    const double v = fall_speed(w, d);
    pl_world_destroy(&w);
    printf("hydrostatic: v(0.03 s) = %.6f cm/s (buoyancy alone %.6f, rel. %.1e)\n", v, V_BUOYANT, v / V_BUOYANT - 1);
    ENSURE_REL(v, V_BUOYANT, 1e-6);
    return 0;
}

/* the Darcy rung, started from its static field (as set up) or from zero pressure: the pressure
   error after the first step and the fall speed at 0.03 s */
static int darcy_run(int zero_start, double *ep, double *v) {
    int d;
    pl_status st;
    pl_world *w = sc_disc_rung(SC_RUNG_DARCY, &d, &st);
    ENSURE(st == PL_OK);
    if (zero_start) ENSURE(pl_world_set_flag(w, "FIRST_STEP_STATIC", 0) == PL_OK);
    ENSURE(pl_world_step(w, 1) == PL_OK);
    *ep = pressure_error(w);
    *v = fall_speed(w, d);
    pl_world_destroy(&w);
    return 0;
}

static int darcy_rung_starts_static(void) {
    double ep, v;
    ENSURE(darcy_run(0, &ep, &v) == 0);
    printf("darcy (static start): pore pressure after the first step within %.1e of rho_l g H of hydrostatic; "
           "v(0.03 s) = %.6f cm/s (rel. %.1e)\n", ep, v, v / V_BUOYANT - 1);
    ENSURE(ep <= 1e-9);
    ENSURE_REL(v, V_BUOYANT, 1e-6);
    return 0;
}

static int zero_start_is_caught(void) {
    double ep, v;
    ENSURE(darcy_run(1, &ep, &v) == 0);
    printf("darcy (zero start, the old set-up): pressure off by %.2e of rho_l g H; v(0.03 s) = %.4f cm/s "
           "(free fall %.2f)\n", ep, v, G * 0.03);
    ENSURE(fabs(v / V_BUOYANT - 1) > 1e-6); /* the velocity check above fails on it */
    return 0;
}

int main(void) {
    RUN(hydrostatic_rung);
    RUN(darcy_rung_starts_static);
    RUN(zero_start_is_caught);
    return pl_test_report();
}
