/* J2 plasticity with linear hardening and the updated Lagrangian form, without a world.
 * - simple shear of a square (every node driven by v = (gamma_dot y, 0), homogeneous strain):
 *   elastic up to tau_y = sigma_y / sqrt(3), then tau = tau_y + G H' / (G + H') (gamma - tau_y/G)
 *   with H' = H / 3, and sqrt(3) tau = sigma_y + H eps_p (von Mises with linear isotropic
 *   hardening under proportional loading, where radial return is exact: Simo & Hughes,
 *   Computational Inelasticity, §3.3), tolerance 1e-6 relative;
 * - a rigid rotation by 60 degrees (every node driven by v = omega k x (x - c)): the updated
 *   Lagrangian stress stays below 1e-6 of E (objective), the small-strain form does not
 *   (its spurious strain 1 - cos 60 = 0.5 gives stresses of order E). */
#include "harness.h"
#include "solid_test_util.h"
#include <string.h>

static int test_simple_shear(void) {
    pl_solid_def d = pl_default_solid_def();
    d.young = 1;
    d.poisson = 0.3;
    d.density = 1;
    d.formulation = PL_SOLID_PLAIN;
    d.yield_stress = 1e-3;
    d.hardening = 0.1;
    pl_sf *s = sf_rect(&d, 0, 0, 1, 1, 4, 4);
    ENSURE(s);
    ENSURE(pl_sf_add_set(s, -1, -1, 2, 2, 3, 0, 0) >= 0);
    for (int i = 0; i < s->nn; i++) s->vpres[2 * i] = s->v[2 * i] = 1e-3 * s->X[2 * i + 1]; /* gamma_dot = 1e-3 */
    const double G = d.young / (2 * (1 + d.poisson)), Hp = d.hardening / 3, ty = d.yield_stress / sqrt(3);
    double worst = 0, worst_a = 0;
    const double dt = 0.5 * s->dt_crit;
    for (int k = 0; k < 4000; k++) {
        ENSURE(pl_sf_step(s, dt, NULL) == PL_OK);
        const double gam = 1e-3 * s->time;
        const double tref = gam < ty / G ? G * gam : ty + G * Hp / (G + Hp) * (gam - ty / G);
        for (int e = 0; e < s->ne; e++) {
            const double tau = s->s[4 * e + 3];
            worst = fmax(worst, fabs(tau - tref) / tref);
            if (gam > 2 * ty / G) {
                const double aref = (sqrt(3) * tref - d.yield_stress) / d.hardening;
                worst_a = fmax(worst_a, fabs(s->alpha[e] - aref) / aref);
            }
        }
    }
    const double gam = 1e-3 * s->time;
    fprintf(stderr, "simple shear to gamma = %.4g (%.1f x yield): worst relative error of tau %.2e, of eps_p %.2e\n",
            gam, gam * G / ty, worst, worst_a);
    pl_validation("solids.j2_shear", "simple shear, J2 with linear hardening: tau(gamma), eps_p",
                  "tau_y + G H'/(G+H') (gamma - gamma_y), H' = H/3", "1e-6", "worst %.1e (tau), %.1e (eps_p) to %.1f x yield",
                  worst, worst_a, gam * G / ty);
    ENSURE(worst < 1e-6 && worst_a < 1e-6);
    ENSURE(gam * G / ty > 2);
    pl_sf_destroy(s);
    return 0;
}

static double rotate_block(int large) {
    pl_solid_def d = pl_default_solid_def();
    d.young = 1;
    d.poisson = 0.3;
    d.density = 1;
    d.formulation = PL_SOLID_PLAIN;
    d.large_strain = large;
    pl_sf *s = sf_rect(&d, -0.5, -0.5, 0.5, 0.5, 4, 4);
    if (!s) return NAN;
    pl_sf_add_set(s, -1, -1, 1, 1, 3, 0, 0);
    const double om = 1, dt = 0.2 * s->dt_crit, T = M_PI / 3;
    while (s->time < T) {
        for (int i = 0; i < s->nn; i++) {
            /* exact rotation increment over the step, as a velocity */
            const double x = s->x[2 * i], y = s->x[2 * i + 1], c = cos(om * dt), sn = sin(om * dt);
            s->vpres[2 * i] = (c * x - sn * y - x) / dt;
            s->vpres[2 * i + 1] = (sn * x + c * y - y) / dt;
        }
        if (pl_sf_step(s, dt, NULL) != PL_OK) return NAN;
    }
    double smax = 0;
    for (int e = 0; e < s->ne; e++) {
        const double *st = &s->s[4 * e];
        smax = fmax(smax, fabs(st[0] + s->pe[e]) + fabs(st[1] + s->pe[e]) + fabs(st[3]));
    }
    pl_sf_destroy(s);
    return smax;
}

static int test_rigid_rotation(void) {
    const double ul = rotate_block(1), ss = rotate_block(0);
    fprintf(stderr, "rigid rotation 60 deg: largest stress updated Lagrangian %.3g E, small strain %.3g E\n", ul, ss);
    pl_validation("solids.rotation", "rigid rotation by 60 degrees: spurious stress", "0 (objective update)",
                  "1e-6 E", "updated Lagrangian %.2g E (small strain %.2g E)", ul, ss);
    ENSURE(ul < 1e-6);
    ENSURE(ss > 0.1);
    return 0;
}

int main(void) {
    RUN(test_simple_shear);
    RUN(test_rigid_rotation);
    return pl_test_report();
}
