/* Navier–Stokes element kernels without a world (fluid/navier_stokes/ns_internal.h):
 * nodal bases, the six-point rule, the variable-step BDF2 coefficients (against the exact
 * derivative of quadratics; seed 004 eq. 16's printed factor tau_{n-1}/tau fails the same
 * check) and the analytic Jacobian (seed 004 appendix A, re-derived) against central finite
 * differences of the residual. */
#include "harness.h"
#include "fluid/navier_stokes/ns_internal.h"
#include <math.h>
#include <stdio.h>

static const double X[3] = {0.1, 0.9, 0.3}, Y[3] = {0.2, 0.35, 1.1};

/* node positions in barycentric (l1, l2) */
static void node_bary(int kind, int i, double *l1, double *l2) {
    static const double v[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    const int nv = ns_elem_nodes(kind);
    if (i < 3) {
        *l1 = v[i][0];
        *l2 = v[i][1];
    } else if (i == nv - 1 && kind != NS_EL_P2) {
        *l1 = *l2 = 1.0 / 3.0;
    } else {
        const int e = i - 3;
        *l1 = 0.5 * (v[e][0] + v[(e + 1) % 3][0]);
        *l2 = 0.5 * (v[e][1] + v[(e + 1) % 3][1]);
    }
}

/* phi_i(node_j) = delta_ij, sum phi = 1, sum grad phi = 0 (linear completeness) */
static int test_nodal_bases(void) {
    for (int kind = 0; kind < 3; kind++) {
        const int nv = ns_elem_nodes(kind);
        for (int j = 0; j < nv; j++) {
            double l1, l2, phi[NS_MAXV], gx[NS_MAXV], gy[NS_MAXV];
            node_bary(kind, j, &l1, &l2);
            ns_elem_basis(kind, X, Y, l1, l2, phi, gx, gy);
            double sg = 0, sgx = 0, sgy = 0;
            for (int i = 0; i < nv; i++) {
                ENSURE_NEAR(phi[i], i == j ? 1.0 : 0.0, 1e-14);
                sg += phi[i];
                sgx += gx[i];
                sgy += gy[i];
            }
            ENSURE_NEAR(sg, 1.0, 1e-14);
            ENSURE_NEAR(sgx, 0.0, 1e-12);
            ENSURE_NEAR(sgy, 0.0, 1e-12);
        }
        /* reproduces x exactly: sum x_i grad phi_i = (1, 0) at an arbitrary point */
        double phi[NS_MAXV], gx[NS_MAXV], gy[NS_MAXV], sx = 0, sy = 0;
        ns_elem_basis(kind, X, Y, 0.21, 0.37, phi, gx, gy);
        for (int i = 0; i < nv; i++) {
            double l1, l2;
            node_bary(kind, i, &l1, &l2);
            const double xi = X[0] * (1 - l1 - l2) + X[1] * l1 + X[2] * l2;
            sx += xi * gx[i];
            sy += xi * gy[i];
        }
        ENSURE_NEAR(sx, 1.0, 1e-12);
        ENSURE_NEAR(sy, 0.0, 1e-12);
    }
    return 0;
}

/* the six-point rule integrates every monomial l1^a l2^b of degree <= 4 exactly:
   ∫_ref l1^a l2^b = a! b! / (a + b + 2)!  (reference area 1/2, weights sum to 1) */
static int test_quadrature(void) {
    static const double fact[7] = {1, 1, 2, 6, 24, 120, 720};
    for (int a = 0; a <= 4; a++)
        for (int b = 0; a + b <= 4; b++) {
            double s = 0;
            for (int q = 0; q < NS_NQ; q++) s += 0.5 * ns_quad_w[q] * pow(ns_quad_l1[q], a) * pow(ns_quad_l2[q], b);
            ENSURE_NEAR(s, fact[a] * fact[b] / fact[a + b + 2], 1e-14);
        }
    return 0;
}

/* BDF2 with variable steps differentiates quadratics exactly (three points); the seed's
   printed form (eq. 16) multiplies the bracket by tau_{n-1}/tau instead of 1/tau: with
   tau != tau_{n-1} it misses the derivative by a factor (check that it does). */
static int test_bdf2(void) {
    const double tau = 0.3, tau1 = 0.7, tn = 2.0;
    const double t1 = tn - tau, t2 = t1 - tau1;
    double c0, c1, c2;
    ns_bdf2_coeffs(tau, tau1, &c0, &c1, &c2);
    for (int p = 0; p <= 2; p++) {
        const double d = c0 * pow(tn, p) + c1 * pow(t1, p) + c2 * pow(t2, p);
        const double exact = p == 0 ? 0.0 : p * pow(tn, p - 1);
        ENSURE_NEAR(d, exact, 1e-12);
    }
    /* seed eq. 16 as printed: bracket * tau_{n-1}/tau */
    const double w = tau / tau1;
    const double printed = ((1 + 2 * w) / (1 + w) * tn - (1 + w) * t1 + w * w / (1 + w) * t2) * (tau1 / tau);
    printf("BDF2 d/dt t at tau/tau1 = %.3f: corrected %.6f, seed eq. 16 as printed %.6f (exact 1)\n", w,
           c0 * tn + c1 * t1 + c2 * t2, printed);
    ENSURE(fabs(printed - 1.0) > 0.1);
    /* first step: backward Euler */
    ns_bdf2_coeffs(tau, 0.0, &c0, &c1, &c2);
    ENSURE_NEAR(c0 * tn + c1 * t1, 1.0, 1e-12);
    return 0;
}

static double frand(unsigned *s) {
    *s = *s * 1103515245u + 12345u;
    return ((*s >> 8) & 0xffff) / 65535.0 - 0.5;
}

/* analytic Jacobian against central differences of the residual, all three elements, with
   convection, BDF2 mass and body force */
static int test_jacobian_fd(void) {
    unsigned seed = 7;
    for (int kind = 0; kind < 3; kind++) {
        const int nv = ns_elem_nodes(kind), n = 2 * nv + 3;
        ns_elem_in e = {0};
        e.kind = kind;
        for (int i = 0; i < 3; i++) {
            e.x[i] = X[i];
            e.y[i] = Y[i];
            e.q[i] = frand(&seed);
        }
        for (int i = 0; i < nv; i++) {
            e.u[i] = 2 * frand(&seed);
            e.v[i] = 2 * frand(&seed);
            e.hu[i] = frand(&seed);
            e.hv[i] = frand(&seed);
        }
        e.a0 = 3.7;
        e.nu = 0.013;
        e.fx = 0.4;
        e.fy = -9.81;
        e.convect = 1;
        double r[NS_MAXN], J[NS_MAXN * NS_MAXN], rp[NS_MAXN], rm[NS_MAXN];
        ns_elem_eval(&e, r, J);
        double worst = 0, scale = 0;
        for (int j = 0; j < n; j++) {
            double *xj = j < nv ? &e.u[j] : j < 2 * nv ? &e.v[j - nv] : &e.q[j - 2 * nv];
            const double h = 1e-6, keep = *xj;
            *xj = keep + h;
            ns_elem_eval(&e, rp, NULL);
            *xj = keep - h;
            ns_elem_eval(&e, rm, NULL);
            *xj = keep;
            for (int i = 0; i < n; i++) {
                const double fd = (rp[i] - rm[i]) / (2 * h);
                if (fabs(fd - J[i * n + j]) > worst) worst = fabs(fd - J[i * n + j]);
                if (fabs(J[i * n + j]) > scale) scale = fabs(J[i * n + j]);
            }
        }
        printf("Jacobian vs finite differences, %s: max |J - J_fd| = %.3g (max |J| = %.3g)\n", ns_elem_name(kind),
               worst, scale);
        ENSURE(worst <= 1e-7 * scale);
        /* the seed's printed A4 (du/dx where dv/dx belongs) differs: d R_v / d u_j */
        double a4 = 0;
        for (int i = 0; i < nv; i++)
            for (int j = 0; j < nv; j++) a4 += fabs(J[(nv + i) * n + j]);
        ENSURE(a4 > 0);
    }
    return 0;
}

/* the residual vanishes for a field the element reproduces: uniform flow, constant pressure,
   no force (P2: also a linear shear u = y with nu Laplacian 0 and convection v du/dy = 0) */
static int test_residual_exact_fields(void) {
    for (int kind = 0; kind < 3; kind++) {
        const int nv = ns_elem_nodes(kind);
        ns_elem_in e = {0};
        e.kind = kind;
        e.nu = 0.1;
        e.convect = 1;
        for (int i = 0; i < 3; i++) {
            e.x[i] = X[i];
            e.y[i] = Y[i];
            e.q[i] = 0;
        }
        for (int i = 0; i < nv; i++) {
            double l1, l2;
            node_bary(kind, i, &l1, &l2);
            const double y = Y[0] * (1 - l1 - l2) + Y[1] * l1 + Y[2] * l2;
            e.u[i] = y; /* shear flow: steady solution with q const */
            e.v[i] = 0;
        }
        double r[NS_MAXN];
        ns_elem_eval(&e, r, NULL);
        /* interior residual of the shear flow: only boundary terms nu du/dn remain; their sum
           over an element is ∫ nu grad u . grad 1 = 0 */
        double su = 0;
        for (int i = 0; i < nv; i++) su += r[i];
        ENSURE_NEAR(su, 0.0, 1e-14);
        for (int k = 0; k < 3; k++) ENSURE_NEAR(r[2 * nv + k], 0.0, 1e-14);
    }
    return 0;
}

int main(void) {
    RUN(test_nodal_bases);
    RUN(test_quadrature);
    RUN(test_bdf2);
    RUN(test_jacobian_fd);
    RUN(test_residual_exact_fields);
    return pl_test_report();
}
