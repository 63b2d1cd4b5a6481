/* Elastic solid kernels without a world (engine/src/solid/fic/solid_internal.h) against closed
 * forms. Each test prints its numbers (VALIDATION lines, copied into docs/solids.md).
 *
 * - wave: a free bar (plane strain) struck at one end by a smooth velocity pulse carries it at
 *   the plane-strain bar speed c = sqrt(E' / rho), E' = E / (1 - nu^2) (Graff, Wave Motion in
 *   Elastic Solids, §2.1 and §8.2 long-wave limit); kinetic + elastic energy after the pulse
 *   stays at the work put in (central differences: O(dt^2)), tolerance 0.5 %;
 * - cantilever: tip deflection under an end load P converges to Timoshenko's beam value
 *   delta = P L^3 / (3 E' I) + P L / (kappa G A), kappa = 5/6 (Timoshenko & Gere, Mechanics of
 *   Materials, §9.10), finest mesh within 2 %, observed order printed;
 * - Lamé: thick cylinder under internal pressure (plane strain; Timoshenko & Goodier, Theory of
 *   Elasticity, §28): u_r(r) = (1 + nu) p a^2 / (E (b^2 - a^2)) ((1 - 2 nu) r + b^2 / r) and the
 *   mean stress 2 (1 + nu) p a^2 / (3 (b^2 - a^2)), uniform; FIC within 2 % at nu = 0.3 and
 *   0.4999, plain triangles lock at 0.4999 (u_r below 60 % of the exact value);
 * - explicit FIC refused at nu = 0.4999 with a message naming the semi-implicit variant. */
#include "harness.h"
#include "solid_test_util.h"
#include "core/alloc.h"
#include <stdlib.h>
#include <string.h>

static int wave_case(int form) {
    pl_solid_def d = sf_steel(form);
    const double L = 100, H = 1;
    pl_sf *s = sf_rect(&d, 0, 0, L, H, 400, 4);
    ENSURE(s);
    const int set = pl_sf_add_set(s, -1e-9, -1, 1e-9, H + 1, 1, 0, 0);
    ENSURE(set >= 0);
    const double Ep = d.young / (1 - d.poisson * d.poisson), c0 = sqrt(Ep / d.density);
    const double T = 2e-3, v0 = 0.1, dt = 0.5 * s->dt_crit;
    const int n1 = sf_nearest(s, 30, 0.5), n2 = sf_nearest(s, 70, 0.5);
    const double x1 = s->X[2 * n1], x2 = s->X[2 * n2];
    double m1 = 0, t1 = 0, m2 = 0, t2 = 0, e_after = NAN, dev = 0;
    const double t_end = (x2 + 1.2 * c0 * T) / c0;
    while (s->time < t_end) {
        const double t = s->time + dt / 2; /* the half-step velocity */
        const double vp = t < T ? v0 * pow(sin(M_PI * t / T), 2) : 0;
        for (int k = 0; k < s->sets[set].n; k++) s->vpres[2 * s->sets[set].nodes[k]] = vp;
        const double U = pl_sf_elastic_energy(s);
        ENSURE(pl_sf_step(s, dt, NULL) == PL_OK);
        const double E = s->e.kinetic + U; /* both at the step's start time */
        if (s->time - dt > T + 2 * dt) {
            if (isnan(e_after)) e_after = E;
            dev = fmax(dev, fabs(E - e_after) / e_after);
        }
        m1 += s->v[2 * n1], t1 += t * s->v[2 * n1];
        m2 += s->v[2 * n2], t2 += t * s->v[2 * n2];
    }
    const double c = (x2 - x1) / (t2 / m2 - t1 / m1);
    const double win = s->e.external;
    fprintf(stderr, "wave (%s): c = %.2f m/s, closed form %.2f (E' = E/(1-nu^2)); energy drift %.2e; work in %.4g J/m, "
                    "stored %.4g J/m\n",
            form == PL_SOLID_PLAIN ? "plain" : "FIC", c, c0, dev, win, e_after);
    pl_validation("solids.wave", "bar struck at one end: wave speed; energy after the pulse",
                  "c = sqrt(E/((1-nu^2) rho)) (plane strain)", "1 %; 0.5 %", "%s: c = %.1f m/s vs %.1f (%.2f %%), drift %.2g %%",
                  form == PL_SOLID_PLAIN ? "plain" : "FIC", c, c0, 100 * (c - c0) / c0, 100 * dev);
    ENSURE_REL(c, c0, 0.01);
    ENSURE(dev < 0.005);
    ENSURE_REL(e_after, win, 0.01);
    pl_sf_destroy(s);
    return 0;
}

static int test_wave_plain(void) { return wave_case(PL_SOLID_PLAIN); }
static int test_wave_fic(void) { return wave_case(PL_SOLID_FIC_SEMI_IMPLICIT); }

/* Cantilever tip deflection, clamped at x = 0, shear traction P/H at x = L. */
static double cantilever(int form, int nx, int ny, double *ref) {
    pl_solid_def d = pl_default_solid_def();
    d.young = 1000;
    d.poisson = 0.3;
    d.density = 1;
    d.formulation = form;
    const double L = 10, H = 1, P = 1;
    const double Ep = d.young / (1 - d.poisson * d.poisson), I = H * H * H / 12, G = d.young / (2 * (1 + d.poisson));
    *ref = P * L * L * L / (3 * Ep * I) + P * L / (5.0 / 6.0 * G * H);
    const double w1 = 1.875 * 1.875 * sqrt(Ep * I / (d.density * H * L * L * L * L));
    d.damping = 2 * w1;
    pl_sf *s = sf_rect(&d, 0, -H / 2, L, H / 2, nx, ny);
    if (!s) return NAN;
    pl_sf_add_set(s, -1e-9, -H, 1e-9, H, 3, 0, 0);
    pl_sf_add_traction(s, L - 1e-9, -H, L + 1e-9, H, 0, -P / H, 0);
    const int tip = sf_nearest(s, L, 0);
    const double dt = 0.9 * s->dt_crit;
    if (sf_relax(s, dt, tip, 1, 1e-7, 2000, (long)(60 / w1 / dt))) return NAN;
    const double u = -(s->x[2 * tip + 1] - s->X[2 * tip + 1]);
    pl_sf_destroy(s);
    return u;
}

static int test_cantilever(void) {
    double ref = 0, u[3];
    const int nx[3] = {20, 40, 80}, ny[3] = {2, 4, 8};
    for (int k = 0; k < 3; k++) {
        u[k] = cantilever(PL_SOLID_PLAIN, nx[k], ny[k], &ref);
        fprintf(stderr, "cantilever %dx%d: tip %.5f (Timoshenko %.5f, error %.2f %%)\n", nx[k], ny[k], u[k], ref,
                100 * (u[k] - ref) / ref);
    }
    const double order = log(fabs(u[1] - u[0]) / fabs(u[2] - u[1])) / log(2.0);
    const double order_ref = log(fabs(u[1] - ref) / fabs(u[2] - ref)) / log(2.0);
    fprintf(stderr, "cantilever: observed order %.2f (successive differences), %.2f (against Timoshenko)\n", order,
            order_ref);
    /* Richardson extrapolation with the element's asymptotic order 2 */
    const double ext = u[2] + (u[2] - u[1]) / 3;
    fprintf(stderr, "cantilever: Richardson (order 2) %.5f, %.2f %% from Timoshenko\n", ext, 100 * (ext - ref) / ref);
    pl_validation("solids.cantilever", "cantilever L/H = 10 tip deflection, plain triangles, 20x2 / 40x4 / 80x8",
                  "Timoshenko beam P L^3/(3 E' I) + P L/(kappa G A)", "5 % on 80x8; extrapolated 2 %",
                  "%.4f / %.4f / %.4f vs %.4f (%.2f %% on 80x8; extrapolated %.2f %%), order %.2f", u[0], u[1],
                  u[2], ref, 100 * (u[2] - ref) / ref, 100 * (ext - ref) / ref, order);
    ENSURE(fabs(u[0] - ref) > fabs(u[1] - ref) && fabs(u[1] - ref) > fabs(u[2] - ref));
    ENSURE_REL(u[2], ref, 0.05);
    ENSURE_REL(ext, ref, 0.02);
    ENSURE(order > 1.2);
    return 0;
}

/* Lamé: quarter of a thick cylinder a = 1, b = 2, internal pressure p; returns u_r at r = a
   and the mean of the nodal (FIC) or element (plain) mean stress. */
static int lame(int form, double nu, double *ur, double *ur_ref, double *pm, double *pm_ref) {
    pl_solid_def d = pl_default_solid_def();
    d.young = 1;
    d.poisson = nu;
    d.density = 1;
    d.formulation = form;
    d.damping = 1.5;
    if (form == PL_SOLID_FIC_EXPLICIT) d.fic_alpha = 0.05; /* explicit limit: 0.0867 here */
    const double a = 1, b = 2, p = 1e-3;
    pl_sf_mesh m;
    char msg[320];
    if (pl_sf_mesh_annulus(0, 0, a, b, 0, M_PI / 2, 8, 16, PL_SF_TRI_RIGHT, &m, msg, sizeof msg) != PL_OK) {
        fprintf(stderr, "%s\n", msg);
        return 1;
    }
    pl_sf *s = pl_sf_create(&d, &m, msg, sizeof msg);
    pl_sf_mesh_free(&m);
    ENSURE(s);
    ENSURE(pl_sf_add_set(s, -1e-9, -1, 1e-9, 3, 1, 0, 0) >= 0);
    ENSURE(pl_sf_add_set(s, -1, -1e-9, 3, 1e-9, 2, 0, 0) >= 0);
    ENSURE(pl_sf_add_traction(s, -1, -1, a + 1e-9, a + 1e-9, 0, 0, p) == 16);
    const int node = sf_nearest(s, a, 0);
    if (sf_relax(s, 0.9 * s->dt_crit, node, 0, 2e-6, 2000, 2000000)) return 1;
    *ur = s->x[2 * node] - s->X[2 * node];
    *ur_ref = (1 + nu) * p * a * a / (d.young * (b * b - a * a)) * ((1 - 2 * nu) * a + b * b / a);
    *pm_ref = 2 * (1 + nu) * p * a * a / (3 * (b * b - a * a));
    double sum = 0, wsum = 0;
    double *val = pl_malloc(sizeof *val * (size_t)s->nn), *wk = pl_malloc(sizeof *wk * (size_t)s->nn);
    pl_sf_nodal_field(s, PL_SOLID_FIELD_PRESSURE, val, wk);
    for (int i = 0; i < s->nn; i++) sum += s->mp[i] * val[i], wsum += s->mp[i];
    *pm = sum / wsum;
    pl_free(val);
    pl_free(wk);
    pl_sf_destroy(s);
    return 0;
}

static int test_lame(void) {
    const double nus[2] = {0.3, 0.4999};
    const int forms[3] = {PL_SOLID_FIC_SEMI_IMPLICIT, PL_SOLID_FIC_EXPLICIT, PL_SOLID_PLAIN};
    const char *names[3] = {"FIC semi-implicit", "FIC explicit", "plain"};
    for (int k = 0; k < 2; k++)
        for (int f = 0; f < 3; f++) {
            if (f == 1 && k == 1) continue; /* refused: test_explicit_refused */
            double ur, urr, pm, pmr;
            ENSURE(lame(forms[f], nus[k], &ur, &urr, &pm, &pmr) == 0);
            fprintf(stderr, "Lame nu = %g, %s: u_r(a) = %.6g (exact %.6g, %.2f %%), mean stress %.6g (exact %.6g, %.2f %%)\n",
                    nus[k], names[f], ur, urr, 100 * (ur - urr) / urr, pm, pmr, 100 * (pm - pmr) / pmr);
            pl_validation("solids.lame", "thick cylinder a=1, b=2, quarter, 8x16 right-diagonal triangles: u_r(a), mean stress",
                          "Lamé (plane strain)", "2 % FIC; plain at 0.4999 below 60 %",
                          "nu=%g %s: u_r %+.2f %%, p %+.2f %%", nus[k], names[f], 100 * (ur - urr) / urr,
                          100 * (pm - pmr) / pmr);
            if (f < 2) {
                ENSURE_REL(ur, urr, 0.02);
                ENSURE_REL(pm, pmr, 0.02);
            } else if (k == 1) {
                ENSURE(ur < 0.6 * urr); /* locks */
            } else {
                ENSURE_REL(ur, urr, 0.03);
            }
        }
    return 0;
}

static int test_explicit_refused(void) {
    pl_solid_def d = pl_default_solid_def();
    d.young = 1;
    d.poisson = 0.4999;
    d.density = 1;
    d.formulation = PL_SOLID_FIC_EXPLICIT;
    pl_sf *s = sf_rect(&d, 0, 0, 1, 1, 4, 4);
    ENSURE(s);
    ENSURE(pl_sf_step(s, 0.5 * s->dt_crit, NULL) == PL_ERR_UNSTABLE);
    fprintf(stderr, "explicit FIC at nu = 0.4999: %s\n", s->err);
    ENSURE(strstr(s->err, "fic_semi_implicit") != NULL);
    pl_sf_destroy(s);
    return 0;
}

static int test_step_past_critical(void) {
    pl_solid_def d = sf_steel(PL_SOLID_PLAIN);
    pl_sf *s = sf_rect(&d, 0, 0, 1, 0.2, 10, 2);
    ENSURE(s);
    ENSURE(pl_sf_step(s, 1.01 * s->dt_crit, NULL) == PL_ERR_UNSTABLE);
    fprintf(stderr, "past the critical step: %s\n", s->err);
    ENSURE(strstr(s->err, "critical step") != NULL);
    /* the element bound is a true bound: at 0.99 of it a free vibration stays bounded */
    for (int i = 0; i < s->nn; i++) s->v[2 * i + 1] = (i % 2 ? 1 : -1) * 1e-3;
    for (int k = 0; k < 20000; k++) ENSURE(pl_sf_step(s, 0.99 * s->dt_crit, NULL) == PL_OK);
    ENSURE(s->e.kinetic < 1);
    pl_sf_destroy(s);
    return 0;
}

int main(void) {
    const char *only = getenv("PL_TEST_ONLY");
    if (!only || strstr(only, "wave")) RUN(test_wave_plain);
    if (!only || strstr(only, "wave")) RUN(test_wave_fic);
    if (!only || strstr(only, "crit")) RUN(test_step_past_critical);
    if (!only || strstr(only, "crit")) RUN(test_explicit_refused);
    if (!only || strstr(only, "cant")) RUN(test_cantilever);
    if (!only || strstr(only, "lame")) RUN(test_lame);
    return pl_test_report();
}
