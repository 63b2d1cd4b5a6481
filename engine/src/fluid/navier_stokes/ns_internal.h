/* Private layout of the resolved Navier–Stokes model (seed 004, Mueller et al. 2020): element
 * kernels, the triangle mesh of the pore space, the global system with its sparse LU, all on
 * plain structs so that unit tests drive them without a world.
 *
 * Equations (per unit mass; q = p / rho is the kinematic pressure, as the seed normalises it):
 *
 *     du/dt + (u . grad) u - nu lap u + grad q = f,      div u = 0.
 *
 * Weak form for a velocity test function phi and a pressure test function psi:
 *
 *     R_u(phi) = ∫ nu grad u : grad phi + (u . grad u + D_t u - f) . phi - q div phi
 *     R_q(psi) = -∫ psi div u
 *
 * (the pressure term is integrated by parts, so an open boundary without a condition is the
 * "do nothing" outflow nu du/dn - q n = 0). D_t u is the variable-step BDF2 derivative
 *
 *     D_t u_n = a0 u_n - h,   a0 = (1 + 2w) / (tau (1 + w)),  w = tau / tau_{n-1},
 *     h = ((1 + w) u_{n-1} - w^2 / (1 + w) u_{n-2}) / tau
 *
 * (seed eq. 16 prints the factor tau_{n-1}/tau where 1/tau belongs; a0 is A9's coefficient).
 * The Jacobian (seed appendix A, re-derived; A4 should read dv/dx, A9 phi_i for the second
 * phi_j, A3/A6 are the integrated-by-parts -psi_j dphi_i/dx here):
 *
 *   dR_ui/du_j = ∫ nu grad phi_j . grad phi_i + (phi_j du/dx + u . grad phi_j + a0 phi_j) phi_i
 *   dR_ui/dv_j = ∫ phi_j du/dy phi_i
 *   dR_vi/du_j = ∫ phi_j dv/dx phi_i
 *   dR_vi/dv_j = ∫ nu grad phi_j . grad phi_i + (phi_j dv/dy + u . grad phi_j + a0 phi_j) phi_i
 *   dR_ui/dq_j = -∫ psi_j dphi_i/dx,  dR_vi/dq_j = -∫ psi_j dphi_i/dy
 *   dR_qi/du_j = -∫ psi_i dphi_j/dx,  dR_qi/dv_j = -∫ psi_i dphi_j/dy
 *
 * Elements (velocity nodes per triangle, all nodal: every unknown is a point value):
 *   P2B  P2 + cubic bubble (seed 004): vertices 0-2, edge midpoints 3-5 (edge k joins vertex k
 *        and k+1), centroid 6; phi_i = P2_i - P2_i(c) b, phi_6 = b = 27 l0 l1 l2.
 *   P2   Taylor–Hood P2/P1: nodes 0-5.
 *   MINI P1 + bubble / P1: vertices 0-2 and the centroid 3; phi_i = l_i - b/3, phi_3 = b.
 * The bubble unknowns are global unknowns (no static condensation): one per triangle and
 * component, numbered after the vertex and edge nodes. Quadrature: the six-point degree-4 rule
 * (Strang & Fix; the seed's Gockenbach rule). */
#ifndef PL_NS_INTERNAL_H
#define PL_NS_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

enum { NS_EL_P2B = 0, NS_EL_P2 = 1, NS_EL_MINI = 2 };
#define NS_MAXV 7                     /* velocity nodes per element */
#define NS_MAXN (2 * NS_MAXV + 3)     /* local unknowns: u, v, q */
#define NS_NQ 6                       /* quadrature points */

/* velocity nodes per element of a kind (7, 6, 4) */
int ns_elem_nodes(int kind);
const char *ns_elem_name(int kind);

/* ----------------------------------------------------------------- element kernels */

typedef struct ns_elem_in {
    int kind;                         /* NS_EL_* */
    double x[3], y[3];                /* vertices, counter-clockwise, m */
    double u[NS_MAXV], v[NS_MAXV];    /* velocity at the nodes, m/s */
    double q[3];                      /* kinematic pressure at the vertices, m^2/s^2 */
    double hu[NS_MAXV], hv[NS_MAXV];  /* BDF2 history h at the nodes (see above), m/s^2 */
    double a0;                        /* BDF2 coefficient of u_n, 1/s (0: stationary) */
    double nu;                        /* kinematic viscosity, m^2/s */
    double fx, fy;                    /* body force per unit mass, m/s^2 */
    int convect;                      /* 0: Stokes (no convective term) */
} ns_elem_in;

/* Residual res[n] and Jacobian jac[n*n] (row-major, jac[i*n + j] = dR_i / dx_j) of one
   element, n = 2 nodes + 3, local order u_0.., v_0.., q_0..q_2. jac may be NULL. */
void ns_elem_eval(const ns_elem_in *e, double *res, double *jac);

/* Basis at barycentric (l1, l2) (l0 = 1 - l1 - l2): phi[nodes] and, when the vertices are
   given, the gradients gx, gy (may be NULL). */
void ns_elem_basis(int kind, const double x[3], const double y[3], double l1, double l2, double *phi,
                   double *gx, double *gy);

/* Variable-step BDF2 coefficients for u' at t_n: u'_n ≈ c0 u_n + c1 u_{n-1} + c2 u_{n-2}, with
   tau = t_n - t_{n-1}, tau1 = t_{n-1} - t_{n-2}. tau1 <= 0: backward Euler (c2 = 0). */
void ns_bdf2_coeffs(double tau, double tau1, double *c0, double *c1, double *c2);

/* The six-point rule on the reference triangle: barycentric (l1, l2) and weights summing to 1. */
extern const double ns_quad_l1[NS_NQ], ns_quad_l2[NS_NQ], ns_quad_w[NS_NQ];

/* ----------------------------------------------------------------------- mesh */

typedef struct ns_mesh {
    int nv;                 /* vertices */
    double *xy;             /* 2 nv */
    int nt;                 /* triangles */
    int32_t *tri;           /* 3 nt, counter-clockwise */
    int ne;                 /* edges */
    int32_t *edge;          /* 2 ne vertex pairs */
    int32_t *tri_edge;      /* 3 nt: edge k of triangle t joins local vertices k and k+1 */
    int32_t *edge_tri;      /* 2 ne adjacent triangles (second -1 on the boundary) */
    int32_t *edge_tag;      /* ne: 0 interior, else the boundary tag (> 0) */
} ns_mesh;

void ns_mesh_free(ns_mesh *m);
/* Orients every triangle counter-clockwise and builds the edges (edge sorted by vertex pair,
   tri_edge, edge_tri; edge_tag zeroed). 0 ok, -1 out of memory. */
int ns_mesh_build_edges(ns_mesh *m);
/* Minimum interior angle of all triangles, degrees. */
double ns_mesh_min_angle(const ns_mesh *m);
/* Digest of the mesh (vertices, triangles, tags) for determinism checks. */
uint64_t ns_mesh_hash(const ns_mesh *m, uint64_t h);

/* ---------------------------------------------------------------- gmsh meshing */

/* A domain: the rectangle [x0,x1] x [y0,y1] with tags 1 (bottom), 2 (right), 3 (top), 4 (left),
   minus nholes polygons (counter-clockwise vertices, hole k tagged 5 + k). Mesh size h_near on
   the holes' outlines, growing linearly to h_far between distance d_min and d_max from them
   (gmsh Distance + Threshold fields); without holes, h_far everywhere. */
typedef struct ns_domain {
    double x0, y0, x1, y1;
    double h_near, h_far, d_min, d_max;
    int nholes;
    const int32_t *hole_offset;   /* nholes + 1 offsets into hole_xy (vertex index) */
    const double *hole_xy;        /* 2 * total vertices */
    int refine_corners;           /* box corners that also get h_near around them: bit 0
                                     bottom-left, 1 bottom-right, 2 top-right, 3 top-left */
} ns_domain;

#define NS_TAG_BOTTOM 1
#define NS_TAG_RIGHT 2
#define NS_TAG_TOP 3
#define NS_TAG_LEFT 4
#define NS_TAG_HOLE0 5

/* 1 when this build meshes (gmsh's C API, Debian libgmsh-dev). */
int ns_have_gmsh(void);
/* Meshes the domain with gmsh (Frontal-Delaunay, one thread, terminal silenced; gmsh is
   initialised and finalised inside the call unless it was initialised already). Returns 0, or -1
   with msg filled (no gmsh, gmsh error, empty mesh). */
int ns_mesh_domain(const ns_domain *d, ns_mesh *out, char *msg, size_t msg_size);

/* ------------------------------------------------------------------- system */

enum { NS_BC_NATURAL = 0, NS_BC_VELOCITY = 1 };

/* Velocity of a Dirichlet boundary at (x, y) on the boundary with the given tag. */
typedef void (*ns_bc_fn)(void *ctx, int tag, double x, double y, double *u, double *v);

typedef struct ns_stats {
    int newton_iters;
    double residual;        /* last Newton residual (max norm) */
    double t_assemble, t_symbolic, t_numeric, t_solve; /* s, accumulated */
    long n_symbolic, n_numeric, n_solve;
    double nnz_matrix, nnz_lu; /* entries of the matrix and of L + U (last factorisation) */
} ns_stats;

typedef struct ns_system {
    ns_mesh mesh;           /* owned */
    int kind, nloc, nvel, nunk;
    double *vxy;            /* 2 nvel velocity node coordinates */
    int32_t *eldof;         /* nt * nloc velocity node of each local node */
    /* Jacobian pattern, compressed columns (UMFPACK's int arrays) */
    int *Ap, *Ai;
    double *Ax;
    int nnz;
    int32_t *emap;          /* nt * n * n position of each element entry in Ax */
    int32_t *diag;          /* nunk position of the diagonal entry */
    /* boundary conditions */
    int ntags;
    uint8_t *tag_kind;      /* ntags + 1 (index = tag) */
    int32_t *node_tag;      /* nvel: Dirichlet tag of the node (0: free) */
    double *gu, *gv;        /* nvel prescribed velocity on Dirichlet nodes */
    int pin;                /* pressure vertex held at q = 0, or -1 (an open boundary exists) */
    uint8_t *fixed;         /* nunk: 1 for a Dirichlet row */
    /* physics */
    double nu, fx, fy;
    int convect;
    /* state: solution and BDF2 history (x_{n-1}, x_{n-2}, tau_{n-1}) */
    double *x, *x1, *x2;
    double tau1;            /* step that led to x1 (0: x1 is the first state) */
    int nhist;              /* history levels held: 0, 1 or 2 */
    /* scratch */
    double *res, *dx, *hu;  /* nunk, nunk, 2 nvel */
    /* UMFPACK */
    void *symbolic, *numeric;
    ns_stats st;
} ns_system;

/* Creates the system for a mesh (the system takes the mesh over; *m is zeroed). ntags: largest
   boundary tag. 0 ok, -1 out of memory. */
int ns_system_init(ns_system *s, ns_mesh *m, int kind, int ntags);
void ns_system_free(ns_system *s);
/* Recomputes the velocity node coordinates after the mesh vertices moved (same topology: the
   pattern and the UMFPACK analysis stay valid). */
void ns_system_update_geometry(ns_system *s);
/* Marks the tags with velocity conditions (tag_kind[tag] = NS_BC_*) and evaluates fn at every
   node on them. Corners: the node takes the lowest Dirichlet tag among its edges. When no tag is
   natural the pressure is pinned at vertex 0. Call again whenever the boundary velocity changes. */
void ns_system_set_bc(ns_system *s, const uint8_t *tag_kind, ns_bc_fn fn, void *ctx);
/* Newton iterations for the stationary problem (a0 = 0) or one BDF2 step of size tau (> 0) from
   the history. Converged when max |dx| <= tol * (1 + max |x|). 0 ok, -1 singular / no
   convergence (msg). */
int ns_system_solve(ns_system *s, double tau, double tol, int max_iter, char *msg, size_t msg_size);
/* Shifts the history after an accepted step of size tau: x2 = x1, x1 = x. */
void ns_system_push_history(ns_system *s, double tau);
/* Residual of the current x without boundary rows replaced (for reaction forces): res. */
void ns_system_residual_raw(ns_system *s, double tau);

/* Force (N per m thickness, already times rho) and moment about c on the boundary tag:
   line = the stress integral over the outline (seed eq. 21, 3-point Gauss per edge);
   react = the reaction (volume) form -rho sum_i R_i over the outline's nodes. */
void ns_system_force_line(const ns_system *s, int tag, double rho, double cx, double cy, double *fx, double *fy,
                          double *moment);
void ns_system_force_react(ns_system *s, double tau, int tag, double rho, double cx, double cy, double *fx,
                           double *fy, double *moment);

/* Velocity and kinematic pressure at a point (the containing triangle is found by a linear
   search from hint; returns the triangle or -1 outside). */
int ns_system_eval(const ns_system *s, double x, double y, int hint, double *u, double *v, double *q);
/* L2 norm of div u over the domain, and the flux ∫ u . n across the segment (ax,ay)-(bx,by)
   (n = left normal of b - a), sampled by npts midpoint samples. */
double ns_system_div_l2(const ns_system *s);
/* Triangle containing (x, y) (walk from hint, then a scan), barycentric l1, l2; -1 outside. */
int ns_system_locate(const ns_system *s, double x, double y, int hint, double *l1, double *l2);
/* Velocity and kinematic pressure of the unknown vector X (x, x1 or x2) in triangle t. */
void ns_system_point(const ns_system *s, const double *X, int t, double l1, double l2, double *u, double *v,
                     double *q);
double ns_system_flux(const ns_system *s, double ax, double ay, double bx, double by, int npts);
/* Projects the velocity of X (x, x1 or x2 of this system) onto the discretely divergence-free
   fields (L2 projection, one factorisation; the Dirichlet nodes keep X's values, X's pressure is
   kept): used after the solution was interpolated onto a new mesh. 0 ok, -1 (msg). */
int ns_system_project(ns_system *s, double *X, char *msg, size_t msg_size);
/* The same for several vectors with one factorisation (X[0]'s Dirichlet values are not needed by
   the matrix, so the others share it). */
int ns_system_project_many(ns_system *s, double *const *X, int nx, char *msg, size_t msg_size);
/* max_i |∫ psi_i div u| / ∫ psi_i over the pressure vertices for the velocity of X, 1/s. */
double ns_system_div_weak(ns_system *s, double *X);

#endif
