/* Flow cases on fixed gmsh meshes shared by the Navier–Stokes tests and the benchmark
 * (tests/bench/bench_navier_stokes.c): lid-driven cavity (Ghia et al. 1982), Schäfer–Turek
 * DFG 2D-1, a polygonal cylinder between plates in Poiseuille flow (Richou et al. 2004, Tan
 * 1990), Kovasznay flow (exact). Each builds a mesh, a system, solves, and reports numbers. */
#ifndef PL_TEST_NS_CASES_H
#define PL_TEST_NS_CASES_H
#include "fluid/navier_stokes/ns_internal.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#define NS_PI 3.14159265358979323846

typedef struct ns_case_ctx {
    int kind;         /* 0 cavity, 1 channel (parabolic inflow), 2 kovasznay, 3 uniform(t) */
    double U, H, y0;  /* lid / centreline velocity, channel height, channel bottom */
    double re;        /* kovasznay Reynolds number */
    double value;     /* uniform flow value */
} ns_case_ctx;

static inline double ns_kov_lambda(double re) { return re / 2 - sqrt(re * re / 4 + 4 * NS_PI * NS_PI); }

static inline void ns_kov_exact(double re, double x, double y, double *u, double *v, double *q) {
    const double l = ns_kov_lambda(re);
    if (u) *u = 1 - exp(l * x) * cos(2 * NS_PI * y);
    if (v) *v = l / (2 * NS_PI) * exp(l * x) * sin(2 * NS_PI * y);
    if (q) *q = 0.5 * (1 - exp(2 * l * x));
}

static inline void ns_case_bc(void *ctx, int tag, double x, double y, double *u, double *v) {
    const ns_case_ctx *c = ctx;
    *u = *v = 0;
    switch (c->kind) {
    case 0:
        if (tag == NS_TAG_TOP) *u = c->U;
        break;
    case 1:
        if (tag == NS_TAG_LEFT || tag == NS_TAG_RIGHT) {
            const double s = (y - c->y0) / c->H;
            *u = 4 * c->U * s * (1 - s);
        }
        break;
    case 2:
        ns_kov_exact(c->re, x, y, u, v, NULL);
        break;
    case 3:
        *u = c->value;
        break;
    }
}

static inline double ns_cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* regular n-gon of circumradius R centred at (cx, cy), first vertex at angle a0, counter-clockwise */
static inline void ns_ngon(int n, double cx, double cy, double R, double a0, double *xy) {
    for (int i = 0; i < n; i++) {
        xy[2 * i] = cx + R * cos(a0 + 2 * NS_PI * i / n);
        xy[2 * i + 1] = cy + R * sin(a0 + 2 * NS_PI * i / n);
    }
}

/* Solves Stokes then (convect) Navier–Stokes by Newton; 0 ok. */
static inline int ns_case_solve(ns_system *s, int convect, char *msg, size_t n) {
    const int keep = s->convect;
    s->convect = 0;
    if (ns_system_solve(s, 0.0, 1e-10, 2, msg, n)) return -1;
    s->convect = keep && convect;
    if (s->convect && ns_system_solve(s, 0.0, 1e-10, 25, msg, n)) return -1;
    return 0;
}

/* ---------------------------------------------------------------------- cavity */

/* Ghia, Ghia & Shin (1982), J. Comput. Phys. 48, 387-411, Tables I and II, Re = 100:
   u on the vertical centreline x = 0.5, v on the horizontal centreline y = 0.5. */
static const double ghia_y[17] = {1.0000, 0.9766, 0.9688, 0.9609, 0.9531, 0.8516, 0.7344, 0.6172, 0.5000,
                                  0.4531, 0.2813, 0.1719, 0.1016, 0.0703, 0.0625, 0.0547, 0.0000};
static const double ghia_u[17] = {1.00000, 0.84123, 0.78871, 0.73722, 0.68717, 0.23151, 0.00332, -0.13641, -0.20581,
                                  -0.21090, -0.15662, -0.10150, -0.06434, -0.04775, -0.04192, -0.03717, 0.00000};
static const double ghia_x[17] = {1.0000, 0.9688, 0.9609, 0.9531, 0.9453, 0.9063, 0.8594, 0.8047, 0.5000,
                                  0.2344, 0.2266, 0.1563, 0.0938, 0.0781, 0.0703, 0.0625, 0.0000};
static const double ghia_v[17] = {0.00000, -0.05906, -0.07391, -0.08864, -0.10313, -0.16914, -0.22445, -0.24533,
                                  0.05454, 0.17527, 0.17507, 0.16077, 0.12317, 0.10890, 0.10091, 0.09233, 0.00000};

typedef struct ns_cavity_result {
    double err_u, err_v;   /* max |u - u_Ghia| over Ghia's interior points, / lid speed */
    double u_min, v_min, v_max;
    double div_l2;
    int nunk, nt;
    double t_mesh, t_total;
    ns_stats st;
} ns_cavity_result;

/* Unit cavity, lid u = 1 on top (the top corners belong to the walls), nu = 1/re; mesh size h,
   graded to h_corner at the lid's corners (where the velocity jumps). */
static inline int ns_case_cavity(int kind, double h, double h_corner, double re, ns_cavity_result *r, char *msg,
                                 size_t n) {
    memset(r, 0, sizeof *r);
    const double t0 = ns_cpu();
    ns_domain d = {0, 0, 1, 1, h_corner, h, 0, 0.5, 0, NULL, NULL, h_corner < h ? 12 : 0};
    ns_mesh m;
    if (ns_mesh_domain(&d, &m, msg, n)) return -1;
    r->t_mesh = ns_cpu() - t0;
    ns_system s;
    if (ns_system_init(&s, &m, kind, 4)) return -1;
    s.nu = 1.0 / re;
    s.convect = 1;
    ns_case_ctx c = {0, 1.0, 1, 0, 0, 0};
    const uint8_t tk[5] = {0, 1, 1, 1, 1};
    ns_system_set_bc(&s, tk, ns_case_bc, &c);
    if (ns_case_solve(&s, 1, msg, n)) {
        ns_system_free(&s);
        return -1;
    }
    int hint = 0;
    for (int i = 1; i < 16; i++) {
        double u, v;
        hint = ns_system_eval(&s, 0.5, ghia_y[i], hint, &u, NULL, NULL);
        if (fabs(u - ghia_u[i]) > r->err_u) r->err_u = fabs(u - ghia_u[i]);
        hint = ns_system_eval(&s, ghia_x[i], 0.5, hint, NULL, &v, NULL);
        if (fabs(v - ghia_v[i]) > r->err_v) r->err_v = fabs(v - ghia_v[i]);
    }
    r->u_min = r->v_min = 1e9;
    r->v_max = -1e9;
    for (int i = 1; i < 400; i++) {
        double u, v;
        hint = ns_system_eval(&s, 0.5, i / 400.0, hint, &u, NULL, NULL);
        if (u < r->u_min) r->u_min = u;
        hint = ns_system_eval(&s, i / 400.0, 0.5, hint, NULL, &v, NULL);
        if (v < r->v_min) r->v_min = v;
        if (v > r->v_max) r->v_max = v;
    }
    r->div_l2 = ns_system_div_l2(&s);
    r->nunk = s.nunk;
    r->nt = s.mesh.nt;
    r->st = s.st;
    ns_system_free(&s);
    r->t_total = ns_cpu() - t0;
    return 0;
}

/* ------------------------------------------------------------------ DFG 2D-1 */

typedef struct ns_dfg_result {
    double cd, cl, dp;          /* reaction (volume) form */
    double cd_line, cl_line;    /* stress line integral, seed eq. 21 */
    double flux_in, flux_mid, flux_out, div_l2;
    int nunk, nt;
    double t_total;
    ns_stats st;
} ns_dfg_result;

/* Schäfer & Turek (1996), benchmark 2D-1: channel 2.2 x 0.41, cylinder r = 0.05 at
   (0.2, 0.2) as an npoly-gon of the circle's area, nu = 1e-3, rho = 1, U_max = 0.3 (mean 0.2,
   Re = 20); do-nothing outflow. c_D = 2 F_x / (rho Ubar^2 D), Delta p = p(0.15,0.2) - p(0.25,0.2). */
static inline int ns_case_dfg(int kind, double h_near, double h_far, int npoly, ns_dfg_result *r, char *msg,
                              size_t n) {
    memset(r, 0, sizeof *r);
    const double t0 = ns_cpu();
    double xy[2 * 512];
    const double R = 0.05 * sqrt(2 * NS_PI / (npoly * sin(2 * NS_PI / npoly)));
    ns_ngon(npoly, 0.2, 0.2, R, 0.0, xy);
    const int32_t off[2] = {0, npoly};
    ns_domain d = {0, 0, 2.2, 0.41, h_near, h_far, 0.02, 0.25, 1, off, xy, 0};
    ns_mesh m;
    if (ns_mesh_domain(&d, &m, msg, n)) return -1;
    ns_system s;
    if (ns_system_init(&s, &m, kind, 5)) return -1;
    s.nu = 1e-3;
    s.convect = 1;
    ns_case_ctx c = {1, 0.3, 0.41, 0, 0, 0};
    const uint8_t tk[6] = {0, 1, 0, 1, 1, 1};
    ns_system_set_bc(&s, tk, ns_case_bc, &c);
    if (ns_case_solve(&s, 1, msg, n)) {
        ns_system_free(&s);
        return -1;
    }
    const double scale = 2.0 / (0.2 * 0.2 * 0.1);
    double fx, fy;
    ns_system_force_react(&s, 0.0, NS_TAG_HOLE0, 1.0, 0.2, 0.2, &fx, &fy, NULL);
    r->cd = scale * fx;
    r->cl = scale * fy;
    ns_system_force_line(&s, NS_TAG_HOLE0, 1.0, 0.2, 0.2, &fx, &fy, NULL);
    r->cd_line = scale * fx;
    r->cl_line = scale * fy;
    double qa, qb;
    /* front and back points of the cylinder: the polygon's vertices at angles pi and 0 */
    if (ns_system_eval(&s, 0.2 - R - 1e-9, 0.2, 0, NULL, NULL, &qa) < 0 ||
        ns_system_eval(&s, 0.2 + R + 1e-9, 0.2, 0, NULL, NULL, &qb) < 0) {
        snprintf(msg, n, "DFG: pressure points outside the mesh");
        ns_system_free(&s);
        return -1;
    }
    r->dp = qa - qb;
    r->flux_in = ns_system_flux(&s, 0.0, 0.41, 0.0, 0.0, 2000);
    r->flux_mid = ns_system_flux(&s, 1.0, 0.41, 1.0, 0.0, 2000);
    r->flux_out = ns_system_flux(&s, 2.2 - 1e-9, 0.41, 2.2 - 1e-9, 0.0, 2000);
    r->div_l2 = ns_system_div_l2(&s);
    r->nunk = s.nunk;
    r->nt = s.mesh.nt;
    r->st = s.st;
    ns_system_free(&s);
    r->t_total = ns_cpu() - t0;
    return 0;
}

/* ------------------------------------------- cylinder between plates (Stokes limit) */

typedef struct ns_plates_result {
    double lam_react, lam_line;   /* F / (mu U0), U0 the centreline velocity */
    double fy;
    int nunk, nt;
} ns_plates_result;

/* Fixed npoly-gon of circumradius r_poly midway between walls y = +-b, Poiseuille profile
   u = U0 (1 - y^2/b^2) prescribed at x = -L and x = +L, Stokes flow (Re -> 0). rotation: angle of
   the first vertex (pi: corner on, facing the flow; pi + pi/npoly: side on). */
static inline int ns_case_plates(int kind, int npoly, double r_poly, double rot, double b, double L, double h_near,
                                 double h_far, ns_plates_result *r, char *msg, size_t n) {
    memset(r, 0, sizeof *r);
    double xy[2 * 512];
    ns_ngon(npoly, 0.0, 0.0, r_poly, rot, xy);
    const int32_t off[2] = {0, npoly};
    ns_domain d = {-L, -b, L, b, h_near, h_far, 0.5 * r_poly, 4 * b, 1, off, xy, 0};
    ns_mesh m;
    if (ns_mesh_domain(&d, &m, msg, n)) return -1;
    ns_system s;
    if (ns_system_init(&s, &m, kind, 5)) return -1;
    s.nu = 1.0; /* mu = rho nu = 1 with rho = 1 */
    s.convect = 0;
    ns_case_ctx c = {1, 1.0, 2 * b, -b, 0, 0};
    const uint8_t tk[6] = {0, 1, 1, 1, 1, 1};
    ns_system_set_bc(&s, tk, ns_case_bc, &c);
    if (ns_case_solve(&s, 0, msg, n)) {
        ns_system_free(&s);
        return -1;
    }
    double fx, fy;
    ns_system_force_react(&s, 0.0, NS_TAG_HOLE0, 1.0, 0, 0, &fx, &fy, NULL);
    r->lam_react = fx;
    r->fy = fy;
    ns_system_force_line(&s, NS_TAG_HOLE0, 1.0, 0, 0, &fx, &fy, NULL);
    r->lam_line = fx;
    r->nunk = s.nunk;
    r->nt = s.mesh.nt;
    ns_system_free(&s);
    return 0;
}

#endif
