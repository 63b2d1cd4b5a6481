/* Finite-element solid kernels on plain structs (no world): linear triangles (plain displacement
 * or FIC stabilised pressure) and Q1/P0 quadrilaterals, plane strain, lumped mass, central
 * differences, small strain or updated Lagrangian, J2 plasticity with linear hardening, and the
 * contact of discs with the boundary edges. The model class (solid_model.c) owns one pl_sf and
 * feeds it the grain view; the tests drive a pl_sf directly. docs/solids.md gives the equations.
 *
 * State (hashed, saved): x, v, p, pi, gv, stress s and pressure pe of each integration point,
 * plastic strain, f_prev, energy tallies, time, step. Input: X, conn, material, boundary
 * conditions. Derived (rebuilt): masses, tau, element critical steps, the pressure factor. */
#ifndef PL_SOLID_INTERNAL_H
#define PL_SOLID_INTERNAL_H

#include "porelab/solid.h"
#include "porelab/bonds.h"
#include <stddef.h>
#include <stdint.h>

typedef struct pl_sf_mesh {
    int nn, ne, nen;   /* nodes, elements, nodes per element (3 triangles, 4 quadrilaterals) */
    double *xy;        /* 2 nn */
    int32_t *conn;     /* nen ne, counter-clockwise */
} pl_sf_mesh;

/* A prescribed-velocity (or fixed) node set: nodes[], prescribed components (bit 1 x, bit 2 y). */
typedef struct pl_sf_set {
    int n;
    int32_t *nodes;
    int mask;
    double vx, vy;       /* m/s (0 for a fixed set) */
    double reaction[2];  /* N/m: force the set exerts on the solid's support, last step */
} pl_sf_set;

/* Traction on a boundary edge (a, b in CCW order of the solid: the outside is on the right). */
typedef struct pl_sf_traction {
    int32_t a, b;
    double tx, ty;       /* Pa, fixed direction */
    double pn;           /* Pa, normal pressure pushing into the solid (follows the edge) */
} pl_sf_traction;

/* Energy ledger (J per m thickness). */
typedef struct pl_sf_energy {
    double kinetic;      /* at the last integer step (mean of the half-step velocities) */
    double internal;     /* work of the internal forces (stored elastic + plastic dissipation) */
    double external;     /* work of tractions, gravity, contact and the prescribed sets */
    double damping;      /* dissipated by the mass-proportional damping */
    double plastic;      /* plastic dissipation (part of internal) */
    double contact;      /* work of the grain contacts on the solid (part of external) */
} pl_sf_energy;

typedef struct pl_sf {
    pl_solid_def def;
    int nn, ne, nen, nip; /* integration points per element: 1 (triangle) or 4 (quadrilateral) */
    /* input */
    double *X;           /* 2 nn reference positions */
    int32_t *conn;
    uint8_t *fix;        /* per node: bits of prescribed components */
    double *vpres;       /* 2 nn prescribed velocity */
    pl_sf_set *sets;
    int nsets;
    pl_sf_traction *trac;
    int ntrac;
    int32_t *bedge;      /* 2 per boundary edge (CCW: outside on the right of a->b) */
    int nbedge;
    pl_vec2 gravity;
    /* state */
    double *x, *v;       /* 2 nn current positions, half-step velocities */
    double *p, *pi;      /* nn nodal pressure (FIC), 2 nn projected gradient */
    double *gv;          /* nn FIC: accumulated int N_a d(eps_v) over the steps (G^T u) */
    double *s;           /* 4 per ip: deviatoric stress xx, yy, zz, xy (Pa) */
    double *pe;          /* per ip: element pressure (plain, Q1/P0), Pa */
    double *ep;          /* 4 per ip: plastic strain xx, yy, zz, xy (tensor) */
    double *alpha;       /* per ip: equivalent plastic strain */
    double *f_prev;      /* 2 nn internal force at the last step (energy trapezoid) */
    double *fe_prev;     /* 2 nn external force at the last step */
    pl_sf_energy e;
    double time;
    int64_t step;
    /* derived */
    double *m;           /* nn lumped mass, kg/m */
    double *mp;          /* nn pressure mass int N dA */
    double *mt;          /* nn projection mass int tau N dA (lumped) */
    double *tau;         /* per element: alpha h^2 / (2 G) */
    double dt_crit;      /* smallest element bound 2 / omega_max, s */
    int dt_elem;         /* element giving it */
    double fic_rho;      /* explicit FIC: spectral radius estimate of the pressure iteration */
    void *chol;          /* semi-implicit FIC: the factor of M_p/K + L (solid_pressure.c) */
    /* scratch */
    double *f;           /* 2 nn force */
    double *du;          /* 2 nn displacement increment of the step */
    double *rhs;         /* nn */
    double *fc;          /* 2 nn contact force on the solid this step */
    double *xm;          /* 2 nn mid-step configuration (updated Lagrangian) */
    /* frictional heat and Archard wear of the element side (NULL while off; state when on) */
    double *heat;        /* nn heat received by each boundary node, J/m */
    double *wear;        /* nn worn area at each boundary node, m^2/m */
    double heat_fraction;/* share of the friction work turned into heat (half to each side) */
    double t0;           /* initial temperature, K */
    pl_thermal_def thermal; /* c, Archard k, H(T) of the solid's material */
    char err[320];
} pl_sf;

/* Creates the solid from a mesh (copied). nen must be 3 (triangle formulations) or 4 (Q1/P0).
   Returns NULL when out of memory or the mesh does not fit the formulation (err of *msg). */
pl_sf *pl_sf_create(const pl_solid_def *d, const pl_sf_mesh *mesh, char *msg, size_t len);
void pl_sf_destroy(pl_sf *s);
/* Appends the nodes and elements of mesh (a second part; same material). */
pl_status pl_sf_append(pl_sf *s, const pl_sf_mesh *mesh);
/* Masses, tau, critical step, boundary edges, pressure factor. Call after the mesh is complete
   and before stepping (pl_sf_step calls it when needed). */
pl_status pl_sf_prepare(pl_sf *s);
/* Node selection by reference position in a box; returns count, writes up to cap indices. */
int pl_sf_nodes_in_box(const pl_sf *s, double x0, double y0, double x1, double y1, int32_t *out, int cap);
/* Prescribes velocity (vx, vy) on the components in mask of the nodes in the box (a fixed set
   has v = 0). Returns the set index or a negative status. */
int pl_sf_add_set(pl_sf *s, double x0, double y0, double x1, double y1, int mask, double vx, double vy);
/* Traction on every boundary edge with both nodes in the box. Returns the edge count. */
int pl_sf_add_traction(pl_sf *s, double x0, double y0, double x1, double y1, double tx, double ty, double pn);
/* Element-by-element bound of the critical step: 2 / sqrt(max eig(M_e^-1 K_e)) (LAPACK dsyev). */
double pl_sf_element_dt(const pl_sf *s, int e, const double *xy);
/* One central-difference step of dt with the extra nodal forces fext (2 nn, may be NULL:
   contact). Errors in s->err. */
pl_status pl_sf_step(pl_sf *s, double dt, const double *fext);
/* Internal force (into f, 2 nn) and the stress update for the increment du. Updates s, pe, ep,
   alpha and (FIC) p and pi. kernels of solid_element.c / solid_pressure.c */
pl_status pl_sf_internal_force(pl_sf *s, const double *du, double *f);
/* FIC pressure update from the displacement increment: explicit (eq. 104) or semi-implicit
   (eq. 99 with the Laplacian by CHOLMOD), then the projected gradient (eq. 100). */
pl_status pl_sf_fic_pressure(pl_sf *s, const double *du);
pl_status pl_sf_fic_prepare(pl_sf *s);
void pl_sf_fic_free(pl_sf *s);
/* J2 radial return with linear isotropic hardening on the deviatoric trial stress (4 comps),
   plane strain. Updates s (in place), ep, alpha; returns the plastic dissipation density. */
double pl_sf_j2_return(double G, double sy, double H, double *s, double *ep, double *alpha);
/* Von Mises stress of an integration point (with its pressure). */
double pl_sf_mises(const double *s);
/* Elastic strain energy (J/m) from the stresses now. */
double pl_sf_elastic_energy(const pl_sf *s);
/* Kinetic energy of velocities v (J/m). */
double pl_sf_kinetic(const pl_sf *s, const double *v);
/* State hash and image helpers. */
uint64_t pl_sf_hash(const pl_sf *s, uint64_t h);
/* nodal average of an element quantity (Mises, plastic strain, pressure) for drawing */
void pl_sf_nodal_field(const pl_sf *s, int quantity, double *out, double *work /* nn */);

/* Disc contact with the boundary edges (seed 002 eqs. 105-109): penetration from the centre,
   normal spring-dashpot, regularised Coulomb friction; the reaction spread to the edge's two
   nodes by the linear edge shape functions. Adds the force on the solid into fsolid (2 nn) and
   returns the force and moment on the disc. */
typedef struct pl_sf_contact_out {
    double fx, fy, m;    /* on the disc, N/m and N m/m */
    double overlap;      /* largest penetration, m */
    int touching;
    double e_dashpot, e_friction; /* dissipated this step, J/m */
    double spring;       /* energy in the contact springs now, J/m (polygons) */
    double heat_grain;   /* heat the grain's side receives this step, J/m (heat on) */
    double wear_work;    /* sum of F_n |v_t| dt of the sliding points this step, N m/m */
} pl_sf_contact_out;
void pl_sf_disc_contact(const pl_sf *s, pl_vec2 c, pl_vec2 vc, double omega, double r, double dt,
                        double *fsolid, pl_sf_contact_out *out);

/* Convex polygon grain (vertices vert, counter-clockwise, world coordinates; centroid c)
   against the boundary edges: each grain vertex inside the solid is pushed out through the
   nearest edge (penetration along its outward normal, reaction spread by the edge shape
   functions) and each convex corner node of the solid inside the grain through the grain's
   nearest edge; the same spring-dashpot and friction as the discs. */
void pl_sf_polygon_contact(const pl_sf *s, pl_vec2 c, pl_vec2 vc, double omega, const pl_vec2 *vert, int nv,
                           double dt, double *fsolid, pl_sf_contact_out *out);

/* Temperature of node i (K): t0 + heat / (m c); the solid does not conduct. */
double pl_sf_node_temperature(const pl_sf *s, int i);

/* A cohesive bond between a disc and a boundary edge (a, b): the disc's centre is tied to the
   edge's material point at shape weight t0, at the normal distance d0 and relative angle th0
   of the creation. The grains' bond law (pl_bond_law_eval) acts on the opening
   u_n = (c - q).n - d0, the slip u_t = (c - q).e and the rotation (theta - phi) - th0
   (q = (1 - t0) x_a + t0 x_b, e the edge's unit tangent at angle phi, n its outward normal). */
typedef struct pl_sf_bond {
    int32_t grain, a, b, state; /* state: pl_bond_state */
    double t0, d0, th0;
    pl_bond_history h;
    double n, s, m;             /* last tension (N/m, > 0 pulling), shear, moment */
    double un, ut, elastic;     /* last opening and slip (m), stored energy (J/m) */
    double broken_time;         /* s, -1 while intact */
} pl_sf_bond;

/* Ties a disc (centre c, angle theta, radius r) to the nearest boundary edge whose face it
   sits over within `gap` (surface to edge, m); 0 when there is none, 1 when bonded (*b filled). */
int pl_sf_bond_make(const pl_sf *s, int grain, pl_vec2 c, double theta, double r, double gap, pl_sf_bond *b);
/* Evaluates an intact bond with the law L: the force and moment on the disc into out (fx, fy,
   m), the opposite (conjugate to the edge's node motion) into fsolid. Returns the energy
   released this step (J/m); a break sets b->state. */
double pl_sf_bond_force(const pl_sf *s, const pl_bond_def *L, pl_sf_bond *b, pl_vec2 c, double theta, double r,
                        double *fsolid, pl_sf_contact_out *out);

/* Linear triangle with nodes n of the coordinates xy: area (positive counter-clockwise) and
   shape-function gradients b = dN/dx, c = dN/dy. */
static inline double pl_sf_tri_grad(const double *xy, const int32_t *n, double b[3], double c[3]) {
    const double x1 = xy[2 * n[0]], y1 = xy[2 * n[0] + 1], x2 = xy[2 * n[1]], y2 = xy[2 * n[1] + 1];
    const double x3 = xy[2 * n[2]], y3 = xy[2 * n[2] + 1];
    const double a2 = (x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1);
    b[0] = (y2 - y3) / a2; b[1] = (y3 - y1) / a2; b[2] = (y1 - y2) / a2;
    c[0] = (x3 - x2) / a2; c[1] = (x1 - x3) / a2; c[2] = (x2 - x1) / a2;
    return 0.5 * a2;
}

#endif
