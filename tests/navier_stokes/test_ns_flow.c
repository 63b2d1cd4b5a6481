/* Navier–Stokes on fixed gmsh meshes against exact solutions: meshing determinism, Poiseuille
 * flow (reproduced exactly by the quadratic elements), Kovasznay flow (exact Navier–Stokes
 * solution, Kovasznay 1948) with the convergence order of each element, mass conservation
 * (flux through cuts, discrete divergence), BDF2 in time (exact for quadratics in t with
 * variable steps). */
#include "harness.h"
#include "navier_stokes/ns_cases.h"
#include "porelab/core.h"
#include <stdlib.h>
#include <string.h>

static char msg[512];

static int test_mesh_deterministic(void) {
    double xy[2 * 6];
    ns_ngon(6, 0.5, 0.4, 0.15, 0.3, xy);
    const int32_t off[2] = {0, 6};
    ns_domain d = {0, 0, 1.2, 0.8, 0.02, 0.1, 0.02, 0.3, 1, off, xy, 0};
    ns_mesh a, b;
    ENSURE(ns_mesh_domain(&d, &a, msg, sizeof msg) == 0);
    ENSURE(ns_mesh_domain(&d, &b, msg, sizeof msg) == 0);
    const uint64_t ha = ns_mesh_hash(&a, PL_HASH_SEED), hb = ns_mesh_hash(&b, PL_HASH_SEED);
    const double amin = ns_mesh_min_angle(&a);
    int nhole = 0, nb = 0;
    for (int e = 0; e < a.ne; e++) {
        nhole += a.edge_tag[e] == NS_TAG_HOLE0;
        nb += a.edge_tri[2 * e + 1] < 0;
    }
    printf("mesh: %d vertices, %d triangles, min angle %.1f deg, %d hole edges, hash %016llx twice %016llx\n", a.nv,
           a.nt, amin, nhole, (unsigned long long)ha, (unsigned long long)hb);
    ENSURE(ha == hb);
    ENSURE(a.nv == b.nv && a.nt == b.nt);
    ENSURE(amin > 20.0);
    ENSURE(nhole >= 6 * (int)(0.15 / 0.02));
    /* Euler: V - E + F = 1 - holes for a planar triangulation with one hole */
    ENSURE(a.nv - a.ne + a.nt == 0);
    ns_mesh_free(&a);
    ns_mesh_free(&b);
    return 0;
}

/* Channel [0, 2] x [0, 0.5], parabolic inflow U_max = 1, do-nothing outflow. Exact:
   u = 4 U s (1 - s), q = 8 nu U / H^2 (L - x) (the outflow fixes q(L) = 0). */
static int poiseuille(int kind, double *eu, double *eq, double *flux_err, double *div) {
    ns_domain d = {0, 0, 2, 0.5, 0.1, 0.1, 0, 0, 0, NULL, NULL, 0};
    ns_mesh m;
    if (ns_mesh_domain(&d, &m, msg, sizeof msg)) return -1;
    ns_system s;
    if (ns_system_init(&s, &m, kind, 4)) return -1;
    s.nu = 0.05;
    s.convect = 1;
    ns_case_ctx c = {1, 1.0, 0.5, 0, 0, 0};
    const uint8_t tk[5] = {0, 1, 0, 1, 1};
    ns_system_set_bc(&s, tk, ns_case_bc, &c);
    if (ns_case_solve(&s, 1, msg, sizeof msg)) return -1;
    *eu = *eq = 0;
    for (int j = 0; j < 200; j++) {
        const double x = 0.01 + 1.98 * (j * 0.618034 - (int)(j * 0.618034)), y = 0.5 * (j + 0.5) / 200;
        double u, v, q;
        ns_system_eval(&s, x, y, 0, &u, &v, &q);
        const double sy = y / 0.5;
        const double ue = 4 * sy * (1 - sy), qe = 8 * 0.05 / 0.25 * (2 - x);
        if (fabs(u - ue) > *eu) *eu = fabs(u - ue);
        if (fabs(v) > *eu) *eu = fabs(v);
        if (fabs(q - qe) > *eq) *eq = fabs(q - qe);
    }
    /* flux: 2/3 U H = 1/3 through every vertical cut */
    *flux_err = 0;
    for (int k = 0; k < 5; k++) {
        const double x = 0.1 + 0.45 * k;
        const double f = ns_system_flux(&s, x, 0.5, x, 0.0, 400);
        if (fabs(f - 1.0 / 3.0) > *flux_err) *flux_err = fabs(f - 1.0 / 3.0);
    }
    *div = ns_system_div_l2(&s);
    ns_system_free(&s);
    return 0;
}

static int test_poiseuille(void) {
    for (int kind = 0; kind < 3; kind++) {
        double eu, eq, ef, dv;
        ENSURE(poiseuille(kind, &eu, &eq, &ef, &dv) == 0);
        printf("Poiseuille %-13s max |u - u_exact| %.2e, max |q - q_exact| %.2e m^2/s^2, flux error %.2e, "
               "||div u|| %.2e\n",
               ns_elem_name(kind), eu, eq, ef, dv);
        /* midpoint sampling of a parabola over 400 intervals: 1/(12*400^2) relative */
        if (kind != NS_EL_MINI) {
            ENSURE(eu < 1e-10);
            ENSURE(eq < 1e-9);
            ENSURE(dv < 1e-10);
            ENSURE(ef < 1e-5);
        } else {
            /* P1 + bubble with five elements across: first-order velocity, not exact */
            ENSURE(eu < 0.06);
            ENSURE(ef < 0.02);
        }
    }
    return 0;
}

/* Kovasznay flow at Re = 40 on [-0.5, 1] x [-0.5, 1.5], exact velocity on the boundary;
   L2 velocity error on two meshes: order 3 for the quadratic elements, 2 for MINI. */
static double kovasznay_err(int kind, double h) {
    ns_domain d = {-0.5, -0.5, 1.0, 1.5, h, h, 0, 0, 0, NULL, NULL, 0};
    ns_mesh m;
    if (ns_mesh_domain(&d, &m, msg, sizeof msg)) return -1;
    ns_system s;
    if (ns_system_init(&s, &m, kind, 4)) return -1;
    s.nu = 1.0 / 40;
    s.convect = 1;
    ns_case_ctx c = {2, 0, 0, 0, 40, 0};
    const uint8_t tk[5] = {0, 1, 1, 1, 1};
    ns_system_set_bc(&s, tk, ns_case_bc, &c);
    if (ns_case_solve(&s, 1, msg, sizeof msg)) return -1;
    double e2 = 0;
    for (int t = 0; t < s.mesh.nt; t++) {
        const int32_t *v = s.mesh.tri + 3 * t;
        double x[3], y[3];
        for (int i = 0; i < 3; i++) {
            x[i] = s.mesh.xy[2 * v[i]];
            y[i] = s.mesh.xy[2 * v[i] + 1];
        }
        const double A = 0.5 * ((x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]));
        for (int q = 0; q < NS_NQ; q++) {
            const double l1 = ns_quad_l1[q], l2 = ns_quad_l2[q];
            const double px = x[0] * (1 - l1 - l2) + x[1] * l1 + x[2] * l2;
            const double py = y[0] * (1 - l1 - l2) + y[1] * l1 + y[2] * l2;
            double uh, vh, ue, ve;
            ns_system_eval(&s, px, py, t, &uh, &vh, NULL);
            ns_kov_exact(40, px, py, &ue, &ve, NULL);
            e2 += A * ns_quad_w[q] * ((uh - ue) * (uh - ue) + (vh - ve) * (vh - ve));
        }
    }
    ns_system_free(&s);
    return sqrt(e2);
}

static int test_kovasznay_order(void) {
    for (int kind = 0; kind < 3; kind++) {
        const double e1 = kovasznay_err(kind, 0.2), e2 = kovasznay_err(kind, 0.1);
        ENSURE(e1 > 0 && e2 > 0);
        const double order = log(e1 / e2) / log(2.0);
        printf("Kovasznay Re=40 %-13s L2 error h=0.2: %.3e, h=0.1: %.3e, order %.2f\n", ns_elem_name(kind), e1, e2,
               order);
        pl_validation("fluid.ns_kovasznay", "Navier-Stokes: Kovasznay flow Re=40, L2 velocity error order",
                      "exact (Kovasznay 1948): order 3 (P2, P2+bubble), 2 (MINI)", ">= 2.7 / >= 1.8",
                      "%s: %.2f (error %.2e at h=0.1)", ns_elem_name(kind), order, e2);
        ENSURE(order >= (kind == NS_EL_MINI ? 1.8 : 2.7));
        ENSURE(e2 < (kind == NS_EL_MINI ? 0.06 : 2e-3));
    }
    return 0;
}

/* u = (t^2, 0) everywhere with f = (2t, 0): BDF2 reproduces it exactly with variable steps
   (history given exactly). */
static int test_bdf2_time(void) {
    ns_domain d = {0, 0, 1, 1, 0.34, 0.34, 0, 0, 0, NULL, NULL, 0};
    ns_mesh m;
    ENSURE(ns_mesh_domain(&d, &m, msg, sizeof msg) == 0);
    ns_system s;
    ENSURE(ns_system_init(&s, &m, NS_EL_P2B, 4) == 0);
    s.nu = 0.1;
    s.convect = 1;
    ns_case_ctx c = {3, 0, 0, 0, 0, 0};
    const uint8_t tk[5] = {0, 1, 1, 1, 1};
    double t = 0.5, tau_prev = 0.2;
    /* exact history at t - tau_prev - 0.3 and t - tau_prev ... set x2, x1 */
    const double t2 = t - 0.3, t1 = t;
    for (int j = 0; j < s.nvel; j++) {
        s.x2[j] = t2 * t2;
        s.x1[j] = t1 * t1;
        s.x[j] = t1 * t1;
    }
    s.tau1 = 0.3;
    s.nhist = 2;
    double worst = 0;
    const double steps[4] = {0.1, 0.25, 0.05, 0.4};
    for (int k = 0; k < 4; k++) {
        const double tau = steps[k];
        t += tau;
        c.value = t * t;
        ns_system_set_bc(&s, tk, ns_case_bc, &c);
        s.fx = 2 * t;
        ENSURE(ns_system_solve(&s, tau, 1e-12, 10, msg, sizeof msg) == 0);
        for (int j = 0; j < s.nvel; j++)
            if (fabs(s.x[j] - t * t) > worst) worst = fabs(s.x[j] - t * t);
        ns_system_push_history(&s, tau);
    }
    (void)tau_prev;
    printf("BDF2, u = t^2 with steps 0.1, 0.25, 0.05, 0.4: max error %.2e\n", worst);
    ENSURE(worst < 1e-11);
    ns_system_free(&s);
    return 0;
}

/* Interpolation onto a new mesh and the divergence projection (ns_system_project): the steady
   DFG-like flow past a 24-gon in a channel (Re = 20, parabolic in- and outflow, Q = 2/3 U H) is
   solved on one mesh, interpolated pointwise onto a second mesh of the same domain (finer near
   the hole) and projected. Point interpolation leaves a local mass imbalance (mean divergence
   around the pressure vertices) and flux errors through the cuts; the projection removes the
   first to round-off (the discrete continuity equations hold again) and must not worsen the
   second. Flux reference: Q = 2/3 x 0.3 m/s x 0.41 m = 0.082 m^2/s through every cut. */
static int test_remesh_projection(void) {
    double xy[2 * 24];
    ns_ngon(24, 0.2, 0.2, 0.05, 0.0, xy);
    const int32_t off[2] = {0, 24};
    const uint8_t tk[6] = {0, 1, 1, 1, 1, 1};
    ns_case_ctx c = {1, 0.3, 0.41, 0, 0, 0};
    ns_domain da = {0, 0, 2.2, 0.41, 0.02, 0.06, 0.0, 0.3, 1, off, xy, 0};
    ns_domain db = da;
    db.h_near = 0.013;
    db.h_far = 0.05;
    ns_mesh ma, mb;
    ENSURE(ns_mesh_domain(&da, &ma, msg, sizeof msg) == 0);
    ENSURE(ns_mesh_domain(&db, &mb, msg, sizeof msg) == 0);
    ns_system a, b;
    ENSURE(ns_system_init(&a, &ma, NS_EL_P2B, 5) == 0);
    ENSURE(ns_system_init(&b, &mb, NS_EL_P2B, 5) == 0);
    a.nu = b.nu = 1e-3;
    a.convect = b.convect = 1;
    ns_system_set_bc(&a, tk, ns_case_bc, &c);
    ns_system_set_bc(&b, tk, ns_case_bc, &c);
    ENSURE(ns_case_solve(&a, 1, msg, sizeof msg) == 0);
    int hint = 0, outside = 0;
    for (int j = 0; j < b.nvel; j++) {
        double l1, l2;
        const int t = ns_system_locate(&a, b.vxy[2 * j], b.vxy[2 * j + 1], hint, &l1, &l2);
        if (t < 0) {
            outside++;
            continue;
        }
        hint = t;
        ns_system_point(&a, a.x, t, l1, l2, &b.x[j], &b.x[b.nvel + j], NULL);
    }
    const double xs[5] = {0.1, 0.5, 1.0, 1.5, 2.0}, Q = 2.0 / 3.0 * 0.3 * 0.41;
    double fa = 0, f0 = 0, f1 = 0;
    for (int k = 0; k < 5; k++) fa = fmax(fa, fabs(ns_system_flux(&a, xs[k], 0.41, xs[k], 0.0, 2000) - Q));
    for (int k = 0; k < 5; k++) f0 = fmax(f0, fabs(ns_system_flux(&b, xs[k], 0.41, xs[k], 0.0, 2000) - Q));
    const double da0 = ns_system_div_weak(&a, a.x), d0 = ns_system_div_weak(&b, b.x), l0 = ns_system_div_l2(&b);
    double *before = malloc(sizeof(double) * (size_t)b.nunk);
    ENSURE(before);
    memcpy(before, b.x, sizeof(double) * (size_t)b.nunk);
    ENSURE(ns_system_project(&b, b.x, msg, sizeof msg) == 0);
    for (int k = 0; k < 5; k++) f1 = fmax(f1, fabs(ns_system_flux(&b, xs[k], 0.41, xs[k], 0.0, 2000) - Q));
    const double d1 = ns_system_div_weak(&b, b.x), l1 = ns_system_div_l2(&b);
    double du = 0, umax = 0;
    for (int j = 0; j < 2 * b.nvel; j++) {
        du = fmax(du, fabs(b.x[j] - before[j]));
        umax = fmax(umax, fabs(before[j]));
    }
    printf("remesh %d -> %d unknowns (%d nodes outside): solved mesh: mass imbalance %.2e 1/s, flux error %.2e; "
           "interpolated: imbalance %.2e 1/s, ||div u|| %.3e, flux error %.2e m^2/s (%.3f %% of Q); projected: "
           "imbalance %.2e 1/s, ||div u|| %.3e, flux error %.2e m^2/s (%.3f %%); largest velocity change %.2e m/s "
           "(%.2f %% of max |u|)\n",
           a.nunk, b.nunk, outside, da0, fa, d0, l0, f0, 100 * f0 / Q, d1, l1, f1, 100 * f1 / Q, du, 100 * du / umax);
    pl_validation("fluid.ns_remesh_projection", "Navier-Stokes: interpolation onto a new mesh, divergence projection",
                  "discrete continuity (exact after projection)", "imbalance < 1e-9 1/s",
                  "imbalance %.1e -> %.1e 1/s, flux error %.3f %% -> %.3f %% of Q", d0, d1, 100 * f0 / Q,
                  100 * f1 / Q);
    ENSURE(outside == 0);
    ENSURE(d0 > 1e-6);            /* point interpolation is not discretely divergence-free */
    ENSURE(d1 < 1e-9);            /* the projection restores the continuity equations */
    ENSURE(f1 <= f0 * 1.05 + 1e-9);
    ENSURE(l1 <= l0);
    ENSURE(du < 0.05 * umax);     /* a small correction, not a new flow */
    free(before);
    ns_system_free(&a);
    ns_system_free(&b);
    return 0;
}

int main(void) {
    if (!ns_have_gmsh()) {
        printf("no gmsh in this build: the meshing tests are skipped\n");
        return 0;
    }
    RUN(test_mesh_deterministic);
    RUN(test_poiseuille);
    RUN(test_kovasznay_order);
    RUN(test_bdf2_time);
    RUN(test_remesh_projection);
    return pl_test_report();
}
