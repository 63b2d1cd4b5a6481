/* Element kernels of the resolved Navier–Stokes model: bases (P2 + bubble, P2, MINI), the
 * six-point quadrature, the element residual and its analytic Jacobian (ns_internal.h gives the
 * equations and the corrections to seed 004's appendix A). */
#include "fluid/navier_stokes/ns_internal.h"
#include <string.h>

/* Strang & Fix / Dunavant six-point rule, degree 4 (seed 004 §4.2, Gockenbach). */
#define QA 0.445948490915965
#define QB 0.091576213509771
#define QWA 0.223381589678011
#define QWB 0.109951743655322
const double ns_quad_l1[NS_NQ] = {QA, 1.0 - 2.0 * QA, QA, QB, 1.0 - 2.0 * QB, QB};
const double ns_quad_l2[NS_NQ] = {QA, QA, 1.0 - 2.0 * QA, QB, QB, 1.0 - 2.0 * QB};
const double ns_quad_w[NS_NQ] = {QWA, QWA, QWA, QWB, QWB, QWB};

int ns_elem_nodes(int kind) { return kind == NS_EL_P2B ? 7 : kind == NS_EL_P2 ? 6 : 4; }

const char *ns_elem_name(int kind) { return kind == NS_EL_P2B ? "P2+bubble/P1" : kind == NS_EL_P2 ? "P2/P1" : "MINI"; }

/* Basis values and derivatives with respect to the barycentric coordinates (l0, l2, l2 treated
   as independent: grad phi = sum_k dphi/dl_k grad l_k). */
static void basis_bary(int kind, const double l[3], double *phi, double dl[][3]) {
    const double b = 27.0 * l[0] * l[1] * l[2];
    const double db[3] = {27.0 * l[1] * l[2], 27.0 * l[0] * l[2], 27.0 * l[0] * l[1]};
    if (kind == NS_EL_MINI) {
        for (int i = 0; i < 3; i++) {
            phi[i] = l[i] - b / 3.0;
            for (int k = 0; k < 3; k++) dl[i][k] = (k == i ? 1.0 : 0.0) - db[k] / 3.0;
        }
        phi[3] = b;
        for (int k = 0; k < 3; k++) dl[3][k] = db[k];
        return;
    }
    for (int i = 0; i < 3; i++) {
        phi[i] = l[i] * (2.0 * l[i] - 1.0);
        for (int k = 0; k < 3; k++) dl[i][k] = k == i ? 4.0 * l[i] - 1.0 : 0.0;
    }
    for (int e = 0; e < 3; e++) {
        const int a = e, c = (e + 1) % 3;
        phi[3 + e] = 4.0 * l[a] * l[c];
        for (int k = 0; k < 3; k++) dl[3 + e][k] = k == a ? 4.0 * l[c] : k == c ? 4.0 * l[a] : 0.0;
    }
    if (kind == NS_EL_P2B) {
        /* nodal enrichment: the P2 functions vanish at the centroid, phi_6 = b there */
        static const double at_c[6] = {-1.0 / 9.0, -1.0 / 9.0, -1.0 / 9.0, 4.0 / 9.0, 4.0 / 9.0, 4.0 / 9.0};
        for (int i = 0; i < 6; i++) {
            phi[i] -= at_c[i] * b;
            for (int k = 0; k < 3; k++) dl[i][k] -= at_c[i] * db[k];
        }
        phi[6] = b;
        for (int k = 0; k < 3; k++) dl[6][k] = db[k];
    }
}

/* gradients of the barycentric coordinates and twice the signed area */
static double bary_grad(const double x[3], const double y[3], double gl[3][2]) {
    const double det = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    for (int k = 0; k < 3; k++) {
        const int a = (k + 1) % 3, c = (k + 2) % 3;
        gl[k][0] = (y[a] - y[c]) / det;
        gl[k][1] = (x[c] - x[a]) / det;
    }
    return det;
}

void ns_elem_basis(int kind, const double x[3], const double y[3], double l1, double l2, double *phi, double *gx,
                   double *gy) {
    const double l[3] = {1.0 - l1 - l2, l1, l2};
    double dl[NS_MAXV][3];
    basis_bary(kind, l, phi, dl);
    if (!gx || !gy) return;
    double gl[3][2];
    bary_grad(x, y, gl);
    const int nv = ns_elem_nodes(kind);
    for (int i = 0; i < nv; i++) {
        gx[i] = dl[i][0] * gl[0][0] + dl[i][1] * gl[1][0] + dl[i][2] * gl[2][0];
        gy[i] = dl[i][0] * gl[0][1] + dl[i][1] * gl[1][1] + dl[i][2] * gl[2][1];
    }
}

void ns_bdf2_coeffs(double tau, double tau1, double *c0, double *c1, double *c2) {
    if (tau1 <= 0.0) {
        *c0 = 1.0 / tau;
        *c1 = -1.0 / tau;
        *c2 = 0.0;
        return;
    }
    const double w = tau / tau1;
    /* Lagrange interpolant through (t_{n-2}, t_{n-1}, t_n) differentiated at t_n; the factor is
       1/tau (seed eq. 16 prints tau_{n-1}/tau). */
    *c0 = (1.0 + 2.0 * w) / (tau * (1.0 + w));
    *c1 = -(1.0 + w) / tau;
    *c2 = w * w / ((1.0 + w) * tau);
}

void ns_elem_eval(const ns_elem_in *e, double *res, double *jac) {
    const int nv = ns_elem_nodes(e->kind);
    const int n = 2 * nv + 3;
    const int ov = nv, oq = 2 * nv;
    double gl[3][2];
    const double area = 0.5 * bary_grad(e->x, e->y, gl);
    memset(res, 0, sizeof(double) * (size_t)n);
    if (jac) memset(jac, 0, sizeof(double) * (size_t)(n * n));
    for (int qp = 0; qp < NS_NQ; qp++) {
        const double l[3] = {1.0 - ns_quad_l1[qp] - ns_quad_l2[qp], ns_quad_l1[qp], ns_quad_l2[qp]};
        const double wq = area * ns_quad_w[qp];
        double phi[NS_MAXV], dl[NS_MAXV][3], gx[NS_MAXV], gy[NS_MAXV];
        basis_bary(e->kind, l, phi, dl);
        for (int i = 0; i < nv; i++) {
            gx[i] = dl[i][0] * gl[0][0] + dl[i][1] * gl[1][0] + dl[i][2] * gl[2][0];
            gy[i] = dl[i][0] * gl[0][1] + dl[i][1] * gl[1][1] + dl[i][2] * gl[2][1];
        }
        double u = 0, v = 0, ux = 0, uy = 0, vx = 0, vy = 0, hu = 0, hv = 0;
        for (int i = 0; i < nv; i++) {
            u += e->u[i] * phi[i];
            v += e->v[i] * phi[i];
            ux += e->u[i] * gx[i];
            uy += e->u[i] * gy[i];
            vx += e->v[i] * gx[i];
            vy += e->v[i] * gy[i];
            hu += e->hu[i] * phi[i];
            hv += e->hv[i] * phi[i];
        }
        const double q = e->q[0] * l[0] + e->q[1] * l[1] + e->q[2] * l[2];
        const double cv = e->convect ? 1.0 : 0.0;
        /* strong part multiplying phi_i */
        const double su = cv * (u * ux + v * uy) + e->a0 * u - hu - e->fx;
        const double sv = cv * (u * vx + v * vy) + e->a0 * v - hv - e->fy;
        const double div = ux + vy;
        for (int i = 0; i < nv; i++) {
            res[i] += wq * (e->nu * (ux * gx[i] + uy * gy[i]) + su * phi[i] - q * gx[i]);
            res[ov + i] += wq * (e->nu * (vx * gx[i] + vy * gy[i]) + sv * phi[i] - q * gy[i]);
        }
        for (int k = 0; k < 3; k++) res[oq + k] -= wq * l[k] * div;
        if (!jac) continue;
        for (int i = 0; i < nv; i++) {
            double *ru = jac + (size_t)i * n, *rv = jac + (size_t)(ov + i) * n;
            for (int j = 0; j < nv; j++) {
                const double visc = e->nu * (gx[j] * gx[i] + gy[j] * gy[i]);
                const double adv = cv * (u * gx[j] + v * gy[j]) + e->a0 * phi[j];
                ru[j] += wq * (visc + (adv + cv * phi[j] * ux) * phi[i]);
                ru[ov + j] += wq * cv * phi[j] * uy * phi[i];
                rv[j] += wq * cv * phi[j] * vx * phi[i];
                rv[ov + j] += wq * (visc + (adv + cv * phi[j] * vy) * phi[i]);
            }
            for (int k = 0; k < 3; k++) {
                ru[oq + k] -= wq * l[k] * gx[i];
                rv[oq + k] -= wq * l[k] * gy[i];
            }
        }
        for (int k = 0; k < 3; k++) {
            double *rq = jac + (size_t)(oq + k) * n;
            for (int j = 0; j < nv; j++) {
                rq[j] -= wq * l[k] * gx[j];
                rq[ov + j] -= wq * l[k] * gy[j];
            }
        }
    }
}
