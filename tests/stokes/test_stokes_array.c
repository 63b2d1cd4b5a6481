/* Stokes flow through a square array of fixed discs (boundary elements, no world): the drag
 * per disc against Drummond & Tahir's square-array result, the permeability that follows, and
 * its ratio to the Kozeny–Carman law (the rung below: the Darcy model's permeability).
 *
 * Set-up: one row of NCOL discs (radius a, spacing l, solid fraction c = π a^2 / l^2) in a
 * channel of height l whose walls are the row's mirror planes (slip: u_y = 0, t_x = 0), so the
 * row is one period of the infinite array in y; uniform inflow and outflow U (the superficial
 * velocity) two spacings before and after the row. The middle disc's drag F is the array's:
 *   Drummond & Tahir (1984), square array, flow along a row:
 *   F/(μU) = 4π / (-ln(c)/2 - 0.738 + c - 0.887 c^2 + 2.038 c^3), a dilute expansion whose
 *   truncation error grows as c^4; checked within 2 % at c = 0.05, 0.1, 0.2;
 *   permeability k = μ U l^2 / F (force balance of one cell: Δp l = F);
 *   Kozeny–Carman for fibres (Kozeny constant 5, specific surface 4/d): k_KC = ε^3 d^2 /
 *   (80 (1 - ε)^2), d = 2a, ε = 1 - c; the ratio k / k_KC is printed (not a law to check
 *   against: KC is an empirical fit for random packings);
 *   the Darcy model's form k = C1 e^3/(1+e) (seed 000 eq. 3.8, e = ε/(1-ε)): the C1 that would
 *   reproduce this array is printed as C1 = k_h (1 + e) / e^3 with k_h = k ρ g / μ for water. */
#include "harness.h"
#include "stokes_cases.h"
#include <stdio.h>

static pl_sb_rules R;

static double array_drag(double c, int ncol, int ndisc, double *k_perm) {
    const double a = 1, l = a * sqrt(M_PI / c), mu = 1, U = 1;
    const double L = (ncol + 4) * l;
    pl_sb_bnd b;
    memset(&b, 0, sizeof b);
    const int nx = (int)(ncol + 4) * 12, ny = 12;
    pl_sb_bnd_curve(&b, (pl_vec2){0, 0}, 0);
    pl_sb_bnd_line(&b, (pl_vec2){0, 0}, (pl_vec2){L, 0}, nx);
    pl_sb_bnd_line(&b, (pl_vec2){L, 0}, (pl_vec2){L, l}, ny);
    pl_sb_bnd_line(&b, (pl_vec2){L, l}, (pl_vec2){0, l}, nx);
    pl_sb_bnd_line(&b, (pl_vec2){0, l}, (pl_vec2){0, 0}, ny);
    b.nfixed = 1;
    for (int e = 0; e < b.ne; e++) {
        const int horizontal = fabs(b.a[e].y - b.b[e].y) < 1e-12;
        for (int m = 0; m < 2; m++) {
            double *u = b.u + 4 * e + 2 * m, *t = b.t + 4 * e + 2 * m;
            uint8_t *k = b.kind + 4 * e + 2 * m;
            if (horizontal) { /* mirror plane: no normal flow, no shear */
                k[0] = PL_SB_TRAC;
                t[0] = 0;
                k[1] = PL_SB_VEL;
                u[1] = 0;
            } else {
                u[0] = U;
                u[1] = 0;
            }
        }
    }
    for (int i = 0; i < ncol; i++) pl_sb_bnd_disc(&b, (pl_vec2){(2.5 + i) * l, 0.5 * l}, a, ndisc, 1, 0);
    pl_sb_solver s;
    memset(&s, 0, sizeof s);
    double F = NAN;
    if (pl_sb_solve(&s, &b, &R, mu, NULL) == PL_OK) {
        const int c0 = 1 + ncol / 2;
        pl_vec2 f;
        double M;
        pl_sb_curve_load(&b, b.t, b.curve_start[c0], b.curve_start[c0 + 1], b.centre[c0], &f, &M);
        F = f.x / (mu * U);
        *k_perm = mu * U * l * l / f.x;
    }
    pl_sb_solver_free(&s);
    pl_sb_bnd_free(&b);
    return F;
}

static int square_array(void) {
    const double cs[3] = {0.05, 0.1, 0.2};
    for (int i = 0; i < 3; i++) {
        const double c = cs[i], a = 1;
        double k = 0;
        const double F = array_drag(c, 7, 48, &k);
        const double dt = 4 * M_PI / (-0.5 * log(c) - 0.738 + c - 0.887 * c * c + 2.038 * c * c * c);
        const double eps = 1 - c, d = 2 * a, e = eps / (1 - eps);
        const double kkc = eps * eps * eps * d * d / (80 * (1 - eps) * (1 - eps));
        /* C1 for water (ρ g / μ = 1000 x 9.81 / 1e-3) and a = 1 mm grains: k scales with a^2 */
        const double k_si = k * 1e-6, c1 = k_si * 1000 * 9.81 / 1e-3 * (1 + e) / (e * e * e);
        printf("square array c = %.2f: F/(mu U) = %.3f, Drummond & Tahir %.3f (%+.2f %%); k/a^2 = %.4f, "
               "Kozeny-Carman k/a^2 = %.4f, ratio %.2f; Darcy FLUID_KC_C1 for a = 1 mm in water: %.3g m/s\n",
               c, F, dt, 100 * (F / dt - 1), k / (a * a), kkc / (a * a), k / kkc, c1);
        printf("VALIDATION|fluid.stokes_array_c%02d|drag in a square array of discs, c = %.2f|Drummond & Tahir 1984: "
               "%.3f|2 %%|%.3f (%+.2f %%); k/k_KC = %.2f\n",
               (int)lround(100 * c), c, dt, F, 100 * (F / dt - 1), k / kkc);
        ENSURE_REL(F, dt, 0.02);
    }
    return 0;
}

int main(void) {
    if (pl_sb_rules_init(&R) != PL_OK) return 1;
    RUN(square_array);
    return pl_test_report();
}
