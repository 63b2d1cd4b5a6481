/* The moment in the bond strength (Potyondy & Cundall 2004, eq. 9; docs/rock.md "Moment in the
 * strength"): a bond of width 2R (R = min(r_a, r_b)) per metre of thickness is a beam section
 * with A = 2R and I = (2R)^3/12; its largest tensile stress is sigma = N/A + |M| R/I. With the
 * strength sigma_c = R_n/A it breaks when N + 3|M|/R > R_n. Two discs turned in opposite
 * senses at the same rate bend the bond without slip (l_a w_a + l_b w_b = 0 for equal discs):
 * M = k_r theta exactly, N = S = 0, so the closed form is M* = R_n R / 3, reached at
 * theta* = R_n R / (3 k_r). With a steady pull N0 first the bending strength is (R_n - N0) R/3. */
#include "harness.h"
#include "porelab/bonds.h"
#include "porelab/world.h"
#include <math.h>
#include <string.h>

#define R0 1e-3
#define DT 1e-6

static pl_world *two_discs(const pl_bond_def *law, int *a, int *b) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, 0};
    wd.dt = DT;
    pl_world *w = pl_world_create(&wd);
    pl_material_def m = pl_default_material_def();
    m.name = "rock";
    m.density = 2600;
    m.kn = 1e7;
    const int mat = pl_world_add_material(w, &m);
    pl_world_set_bond_law(w, mat, mat, law);
    pl_body_def d = pl_default_body_def();
    d.material = mat;
    d.radius = R0;
    d.motion = PL_MOTION_PRESCRIBED;
    d.position = (pl_vec2){0, 0};
    *a = pl_world_add_body(w, &d);
    d.position = (pl_vec2){2 * R0, 0};
    *b = pl_world_add_body(w, &d);
    return w;
}

static pl_bond_info bond0(const pl_world *w) {
    pl_bond_info o;
    memset(&o, 0, sizeof o);
    pl_world_copy_bonds(w, 0, &o, 1);
    return o;
}

/* Bends the bond at the rate 2 om (after an optional pull to N0) and returns the moment of the
   last intact step (or -1 when it did not break within max_steps); *state gets the break kind. */
static double bend(int beam, int combined, double n0, int max_steps, int *state, double *m_step) {
    pl_bond_def L = pl_default_bond_def();
    L.kn = 1e7;
    L.kt = 4e6;
    L.kr = 2.0;  /* N m/rad */
    L.rn = 50;   /* N: M* = R_n R/3 = 0.016667 N m at theta* = 8.33 mrad */
    L.rt = 30;
    L.beam = beam;
    L.combined = combined;
    int a, b;
    pl_world *w = two_discs(&L, &a, &b);
    ENSURE(pl_world_add_bond(w, a, b) == 0);
    if (n0 > 0) { /* open the bond to N0 = k_n u0 in 100 steps, then hold */
        const double u0 = n0 / L.kn;
        pl_world_prescribe_velocity(w, b, (pl_vec2){u0 / (100 * DT), 0}, 0);
        ENSURE(pl_world_step(w, 100) == PL_OK);
    }
    const double om = 1.0; /* rad/s each: theta grows by 2 om dt = 2 urad per step */
    pl_world_prescribe_velocity(w, a, (pl_vec2){0, 0}, -om);
    pl_world_prescribe_velocity(w, b, (pl_vec2){0, 0}, om);
    *m_step = L.kr * 2 * om * DT;
    double last = 0, worst = 0;
    *state = PL_BOND_INTACT;
    for (int s = 0; s < max_steps; s++) {
        ENSURE(pl_world_step(w, 1) == PL_OK);
        const pl_bond_info o = bond0(w);
        if (o.state != PL_BOND_INTACT) {
            *state = o.state;
            break;
        }
        /* the bent bond carries M = k_r theta and neither tension change nor shear */
        worst = fmax(worst, fabs(o.m - L.kr * 2 * om * DT * (s + 1)) + fabs(o.s));
        last = o.m;
    }
    ENSURE(worst <= 1e-9);
    pl_world_destroy(&w);
    return *state == PL_BOND_INTACT ? -1 : last;
}

static int beam_bending(void) {
    const double Ms = 50 * R0 / 3; /* R_n R / 3 */
    int st;
    double dm;
    const double m1 = bend(1, 0, 0, 20000, &st, &dm);
    ENSURE(st == PL_BOND_BROKEN_TENSION);
    /* the last intact moment is within one step's increment below M*, the next above it */
    ENSURE(m1 <= Ms && m1 > Ms - dm * 1.000001);
    fprintf(stderr, "  pure bending: breaks at M = %.8g N m (closed form R_n R/3 = %.8g N m, %+.2e relative; step %.2g N m)\n",
            m1, Ms, (m1 - Ms) / Ms, dm);
    /* with a pull to N0 = R_n/2 first: (R_n - N0) R / 3 */
    const double m2 = bend(1, 0, 25, 20000, &st, &dm);
    ENSURE(st == PL_BOND_BROKEN_TENSION);
    ENSURE(m2 <= 0.5 * Ms && m2 > 0.5 * Ms - dm * 1.000001);
    fprintf(stderr, "  pull N0 = R_n/2 then bending: breaks at M = %.8g N m (closed form %.8g N m)\n", m2, 0.5 * Ms);
    /* the combined (elliptic) criterion takes the same effective tension: no shear here */
    const double m3 = bend(1, 1, 0, 20000, &st, &dm);
    ENSURE(st == PL_BOND_BROKEN_COMBINED);
    ENSURE(m3 <= Ms && m3 > Ms - dm * 1.000001);
    /* without beam the moment does not enter the strength: intact at twice M* */
    const double m4 = bend(0, 0, 0, (int)(2 * Ms / dm), &st, &dm);
    ENSURE(m4 < 0 && st == PL_BOND_INTACT);
    return 0;
}

int main(void) {
    RUN(beam_bending);
    return pl_test_report();
}
