/* Frictional heat, conduction and Archard wear against closed forms (seed 002 §4;
 * docs/rock.md "Heat" and "Wear").
 *  - sliding: a disc pressed by a constant load F onto a disc spinning at omega (guided, so
 *    the normal force is F at every step) slides at v = omega R; each disc receives
 *    alpha mu F v / 2 per second: the temperature rises at alpha mu F v / (2 m c), exactly;
 *  - two discs exchanging heat through a bond: the difference decays as exp(-lambda t),
 *    lambda = H (1/C_a + 1/C_b), H = k_th w / d;
 *  - a chain of bonded discs between two held temperatures reaches the linear profile, and
 *    carries the flux H dT / (N - 1) of a rod of N - 1 conductances in series;
 *  - the conduction limit dt sum H <= C: a step past it stops with a message;
 *  - Archard: the pressed disc slid a distance s = v t loses exactly k F s / H(T), with the
 *    hardness at its (held) temperature; a disc worn beyond its area is removed after the step. */
#include "harness.h"
#include "porelab/bonds.h"
#include "porelab/world.h"
#include <string.h>

#define R 1e-3
#define DT 1e-6

typedef struct slider {
    pl_world *w;
    int top, wheel, mtop;
    double F, mu, v;
} slider;

static slider make_slider(double F, double omega) {
    slider s;
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, 0};
    wd.dt = DT;
    s.w = pl_world_create(&wd);
    pl_material_def m = pl_default_material_def();
    m.name = "tool";
    m.density = 7800;
    m.kn = 1e7;
    m.friction = 0.4;
    s.mtop = pl_world_add_material(s.w, &m);
    m.name = "rock";
    m.density = 2600;
    const int mr = pl_world_add_material(s.w, &m);
    pl_body_def b = pl_default_body_def();
    b.material = mr;
    b.radius = 2 * R;
    b.motion = PL_MOTION_PRESCRIBED;
    s.wheel = pl_world_add_body(s.w, &b);
    pl_world_prescribe_velocity(s.w, s.wheel, (pl_vec2){0, 0}, omega);
    /* the top disc sits at the static overlap F / k_n: the normal force is F from step 0 */
    b.material = s.mtop;
    b.radius = R;
    b.motion = PL_MOTION_DYNAMIC;
    b.position = (pl_vec2){0, 3 * R - F / 1e7};
    b.guide = (pl_vec2){0, 1};
    s.top = pl_world_add_body(s.w, &b);
    pl_world_set_body_load(s.w, s.top, (pl_vec2){0, -F}, 0);
    s.F = F;
    s.mu = 0.4;
    s.v = omega * (2 * R - 0.5 * F / 1e7); /* the wheel's speed at the contact point, mid-overlap */
    return s;
}

static int sliding_heat(void) {
    slider s = make_slider(10, 20);
    const double alpha = 0.8, T0 = 300;
    pl_thermal_def t = pl_default_thermal_def();
    t.heat_capacity = 460;
    ENSURE(pl_world_set_thermal(s.w, s.mtop, &t) == PL_OK);
    ENSURE(pl_world_enable_heat(s.w, alpha, T0) == PL_OK);
    /* the shear spring first builds up to mu F (k_s v dt per step): measure once sliding */
    ENSURE(pl_world_step(s.w, 100) == PL_OK);
    const double h0 = pl_world_body_heat(s.w, s.top), hw0 = pl_world_body_heat(s.w, s.wheel);
    const double T0t = pl_world_body_temperature(s.w, s.top), T0w = pl_world_body_temperature(s.w, s.wheel);
    const int n = 5000;
    ENSURE(pl_world_step(s.w, n) == PL_OK);
    pl_body_info o;
    pl_world_body_info(s.w, s.top, &o);
    const double q = 0.5 * alpha * s.mu * s.F * s.v * n * DT; /* J to each disc */
    const double T = pl_world_body_temperature(s.w, s.top), Tw = pl_world_body_temperature(s.w, s.wheel);
    pl_world_body_info(s.w, s.wheel, &o);
    const double mw = o.mass;
    pl_world_body_info(s.w, s.top, &o);
    fprintf(stderr, "  sliding: heat to the disc %.10g J (alpha mu F v t / 2 = %.10g J); T = %.8g K (closed form %.8g K)\n",
            pl_world_body_heat(s.w, s.top) - h0, q, T, T0t + q / (o.mass * 460));
    ENSURE(T0t > T0);
    ENSURE_REL(pl_world_body_heat(s.w, s.top) - h0, q, 1e-9);
    ENSURE_REL(pl_world_body_heat(s.w, s.wheel) - hw0, q, 1e-9);
    /* temperatures: 5000 increments of ~1e-8 K added to 300 K round at ~3e-14 K each */
    ENSURE_REL(T - T0t, q / (o.mass * 460), 1e-5);
    ENSURE_REL(Tw - T0w, q / (mw * 800), 1e-5); /* the wheel: default heat capacity 800 J/(kg K) */
    pl_world_destroy(&s.w);
    return 0;
}

/* a row of n bonded discs touching along x */
static pl_world *chain(int n, double k_th, double c, int *mat) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, 0};
    wd.dt = 1e-5;
    pl_world *w = pl_world_create(&wd);
    pl_material_def m = pl_default_material_def();
    m.name = "rock";
    m.density = 2600;
    m.kn = 1e7;
    *mat = pl_world_add_material(w, &m);
    pl_bond_def L = pl_default_bond_def();
    L.kn = 1e7;
    L.rn = L.rt = 1e6;
    pl_world_set_bond_law(w, *mat, *mat, &L);
    for (int i = 0; i < n; i++) {
        pl_body_def b = pl_default_body_def();
        b.material = *mat;
        b.radius = R;
        b.position = (pl_vec2){2 * R * i, 0};
        pl_world_add_body(w, &b);
    }
    pl_world_bond_touching(w, 1e-9);
    pl_thermal_def t = pl_default_thermal_def();
    t.conductivity = k_th;
    t.heat_capacity = c;
    pl_world_set_thermal(w, *mat, &t);
    pl_world_enable_heat(w, 1, 300);
    return w;
}

static int two_disc_exchange(void) {
    int mat;
    pl_world *w = chain(2, 1.0, 1.0, &mat);
    ENSURE(pl_world_set_body_temperature(w, 0, 400, 0) == PL_OK);
    pl_body_info o;
    pl_world_body_info(w, 0, &o);
    const double C = o.mass * 1.0, H = 1.0 * 2 * R / (2 * R), lam = 2 * H / C;
    const int n = (int)(1.0 / (lam * 1e-5)); /* one decay time */
    ENSURE(pl_world_step(w, n) == PL_OK);
    const double diff = pl_world_body_temperature(w, 0) - pl_world_body_temperature(w, 1);
    const double exact = 100 * exp(-lam * n * 1e-5);
    fprintf(stderr, "  two discs: dT = %.6g K after %d steps, 100 exp(-lambda t) = %.6g K (%+.3f %%; explicit "
            "Euler, lambda dt = %.2g)\n", diff, n, exact, 100 * (diff - exact) / exact, lam * 1e-5);
    ENSURE_REL(diff, exact, 0.005);
    /* heat is conserved */
    ENSURE_NEAR(pl_world_body_temperature(w, 0) + pl_world_body_temperature(w, 1), 700, 1e-9);
    pl_world_destroy(&w);
    return 0;
}

static int chain_profile(void) {
    int mat;
    const int N = 8;
    pl_world *w = chain(N, 1.0, 1.0, &mat);
    ENSURE(pl_world_set_body_temperature(w, 0, 400, 1) == PL_OK);
    ENSURE(pl_world_set_body_temperature(w, N - 1, 300, 1) == PL_OK);
    ENSURE(pl_world_step(w, 200000) == PL_OK);
    double worst = 0;
    for (int i = 0; i < N; i++) {
        const double lin = 400 - 100.0 * i / (N - 1);
        worst = fmax(worst, fabs(pl_world_body_temperature(w, i) - lin));
    }
    const double h0 = pl_world_body_heat(w, N - 1);
    ENSURE(pl_world_step(w, 10000) == PL_OK);
    const double flux = (pl_world_body_heat(w, N - 1) - h0) / (10000 * 1e-5);
    const double H = 1.0, rod = H * 100 / (N - 1);
    fprintf(stderr, "  chain of %d: largest departure from the linear profile %.3g K; flux %.8g W (rod of %d "
            "conductances: %.8g W)\n", N, worst, flux, N - 1, rod);
    ENSURE(worst < 1e-6);
    ENSURE_REL(flux, rod, 1e-6);
    pl_world_destroy(&w);
    return 0;
}

static int conduction_limit(void) {
    int mat;
    /* C = m c = 8.2e-3 J/K; two bonds of H = 1000 W/K: dt sum H = 0.02 > C */
    pl_world *w = chain(3, 1000, 1.0, &mat);
    pl_world_set_body_temperature(w, 0, 400, 0);
    const pl_status st = pl_world_step(w, 10);
    ENSURE(st == PL_ERR_UNSTABLE);
    ENSURE(strstr(pl_world_last_error(w), "heat conduction unstable") != NULL);
    ENSURE(strstr(pl_world_last_error(w), "lower the time step") != NULL);
    fprintf(stderr, "  message: %s\n", pl_world_last_error(w));
    pl_world_destroy(&w);
    return 0;
}

static int archard(void) {
    slider s = make_slider(10, 20);
    pl_thermal_def t = pl_default_thermal_def();
    t.wear = 1e-4;
    t.hardness = 2e9;
    t.softening = 1e-3; /* H(T) = H_0 (1 - beta (T - 293.15)) */
    ENSURE(pl_world_set_thermal(s.w, s.mtop, &t) == PL_OK);
    ENSURE(pl_world_enable_heat(s.w, 0, 293.15) == PL_OK);
    ENSURE(pl_world_set_body_temperature(s.w, s.top, 493.15, 1) == PL_OK); /* H = 0.8 H_0 */
    ENSURE(pl_world_enable_wear(s.w, 1) == PL_OK);
    ENSURE(pl_world_step(s.w, 100) == PL_OK); /* past the sticking build-up, as above */
    const double w0 = pl_world_body_wear(s.w, s.top);
    const int n = 5000;
    ENSURE(pl_world_step(s.w, n) == PL_OK);
    const double dist = s.v * n * DT, H = 0.8 * t.hardness;
    const double exact = t.wear * s.F * dist / H;
    fprintf(stderr, "  Archard: worn %.10g m^3/m after sliding %.6g m (k F s / H(T) = %.10g)\n",
            pl_world_body_wear(s.w, s.top) - w0, dist, exact);
    ENSURE_REL(pl_world_body_wear(s.w, s.top) - w0, exact, 1e-9);
    ENSURE(pl_world_body_wear(s.w, s.wheel) == 0); /* the rock's k is 0 */
    ENSURE(!pl_world_body_removed(s.w, s.top, NULL));
    pl_world_destroy(&s.w);
    return 0;
}

static int removal(void) {
    slider s = make_slider(10, 20);
    pl_thermal_def t = pl_default_thermal_def();
    t.wear = 1.0;
    t.hardness = 100;
    ENSURE(pl_world_set_thermal(s.w, s.mtop, &t) == PL_OK);
    ENSURE(pl_world_enable_heat(s.w, 0, 293.15) == PL_OK);
    ENSURE(pl_world_enable_wear(s.w, 1) == PL_OK);
    pl_body_info o;
    pl_world_body_info(s.w, s.top, &o);
    const double rate = t.wear * s.F * s.v * DT / t.hardness; /* m^3/m per step */
    int at = -1;
    double before = 0;
    for (int k = 1; k <= 2000 && at < 0; k++) {
        before = pl_world_body_wear(s.w, s.top);
        ENSURE(pl_world_step(s.w, 1) == PL_OK);
        if (pl_world_body_removed(s.w, s.top, NULL)) at = k;
    }
    fprintf(stderr, "  removal: worn away after %d steps (area / rate = %.4f steps once sliding)\n", at, o.area / rate);
    /* removed after the very step its wear reached its area */
    ENSURE(at > 0);
    ENSURE(before < o.area && pl_world_body_wear(s.w, s.top) >= o.area);
    ENSURE(pl_world_removed_count(s.w) == 1);
    double when = -1;
    ENSURE(pl_world_body_removed(s.w, s.top, &when) && when > 0);
    /* handles stay valid: the removed disc keeps its index, the other body answers as before */
    ENSURE(pl_world_body_count(s.w) == 2);
    ENSURE(pl_world_body_info(s.w, s.wheel, &o) == PL_OK && o.motion == PL_MOTION_PRESCRIBED);
    ENSURE(pl_world_step(s.w, 100) == PL_OK);
    ENSURE(pl_world_contact_count(s.w) == 0);
    pl_world_destroy(&s.w);
    return 0;
}

int main(void) {
    RUN(sliding_heat);
    RUN(two_disc_exchange);
    RUN(chain_profile);
    RUN(conduction_limit);
    RUN(archard);
    RUN(removal);
    return pl_test_report();
}
