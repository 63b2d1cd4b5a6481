/* Kernels of the boundary-element Stokes model (porelab/stokes.h, seed 003 ch. 4) on plain
 * structs, so that the unit tests drive them without a world: quadrature rules, the element
 * integrals of the Stokeslet (regular, nearly singular and on the source's own element), the
 * corner coefficient, the dense block solve with a reusable factor of the container's block,
 * loads from tractions and the interior velocity and pressure. stokes_model.c wraps them as the
 * model class; docs/stokes.md derives every formula. */
#ifndef PL_STOKES_INTERNAL_H
#define PL_STOKES_INTERNAL_H

#include "porelab/core.h"
#include <stddef.h>
#include <stdint.h>

/* Gauss-Legendre rules of Table 4.1 (1, 2, 4, 16, 32 points; 8 for the interior field) and a
   Gauss rule for ∫_0^1 ln(1/x) f(x) dx (nodes of the polynomials orthogonal with that weight,
   from the exact moments 1/(k+1)^2 by Chebyshev's algorithm and LAPACK dstev). */
#define PL_SB_LOG_POINTS 8
typedef struct pl_sb_rules {
    double x[6][32], w[6][32]; /* orders 1, 2, 4, 8, 16, 32 on [-1, 1] */
    int n[6];
    double lx[PL_SB_LOG_POINTS], lw[PL_SB_LOG_POINTS];
} pl_sb_rules;
/* PL_ERR_NUMERIC if LAPACK's eigen-solver fails. */
pl_status pl_sb_rules_init(pl_sb_rules *r);
/* Index into x/w of the Table 4.1 order for rho = r_min / L. */
int pl_sb_table_order(double rho);

/* Discontinuous linear element a -> b (4.48): nodes at η = -1/2 and +1/2 (the quarter points),
   N_0 = 1/2 - η, N_1 = 1/2 + η. The fluid lies on the left of a -> b; the outward normal of the
   fluid is n = (dy, -dx)/L. */
pl_vec2 pl_sb_node_pos(pl_vec2 a, pl_vec2 b, int m);
pl_vec2 pl_sb_normal(pl_vec2 a, pl_vec2 b);

/* ∫ u*_ij N_m dΓ (G[m][i][j]) and ∫ t*_ij N_m dΓ (H[m][i][j]) over element a-b for a source
   point P off the element: Gauss order from Table 4.1, and pieces halved until each has
   r_min / L > 0.1 (nearly singular sources: close grains, adjacent elements). */
void pl_sb_elem_regular(const pl_sb_rules *r, pl_vec2 P, pl_vec2 a, pl_vec2 b, double mu, double G[2][2][2],
                        double H[2][2][2]);
/* The same for P = node ms of the element itself (4.61-4.82): split at η_s, ln(1/r) =
   ln(ξ/r) + ln(1/ξ), the first by Gauss, the second by the logarithmic rule. H = 0 exactly
   (∂r/∂n = 0 on a straight element). */
void pl_sb_elem_self(const pl_sb_rules *r, int ms, pl_vec2 a, pl_vec2 b, double mu, double G[2][2][2],
                     double H[2][2][2]);
/* Closed form of the self-element G (tests). */
void pl_sb_elem_self_exact(int ms, pl_vec2 a, pl_vec2 b, double mu, double G[2][2][2]);

/* Corner coefficient (4.38): the fluid occupies the wedge from direction th1 to th2
   counter-clockwise (th2 - th1 = the interior angle θ in (0, 2π)); c = δ/2 for θ = π.
   (The seed's printed form has th1 and th2 interchanged in the trigonometric terms.) Not
   needed by the solve: discontinuous elements put no collocation node on a corner. */
void pl_sb_corner_c(double th1, double th2, double c[2][2]);

/* Boundary of the fluid: elements grouped in closed curves (curve 0 .. nfixed-1: the
   container's, whose block is cached; then the particles). Per node component: the kind
   (PL_SB_VEL: velocity given, traction solved; PL_SB_TRAC: traction given, velocity solved) and
   both values (given and solved). */
enum { PL_SB_VEL = 0, PL_SB_TRAC = 1 };
typedef struct pl_sb_bnd {
    int ne, ncurve, nfixed;    /* elements, curves, fixed curves */
    pl_vec2 *a, *b;            /* ne */
    int32_t *curve_start;      /* ncurve + 1: elements of curve c are [start[c], start[c+1]) */
    pl_vec2 *centre;           /* ncurve: moment centre (body centroid) */
    uint8_t *resist;           /* ncurve: 1 = solve the unit motions (resistance) of this curve */
    uint8_t *kind;             /* 4 ne */
    double *u, *t;             /* 4 ne: velocity, traction at the nodes (given or solved) */
    int ecap, ccap;            /* capacities (pl_sb_bnd_* builders) */
} pl_sb_bnd;

/* Builders: clear, open a curve (moment centre, resistance wanted), append a straight line cut
   into nel equal elements (all node components velocity-given, values 0), close the curve.
   PL_ERR_NOMEM on allocation failure. */
void pl_sb_bnd_clear(pl_sb_bnd *b);
void pl_sb_bnd_free(pl_sb_bnd *b);
pl_status pl_sb_bnd_curve(pl_sb_bnd *b, pl_vec2 centre, int resist);
pl_status pl_sb_bnd_line(pl_sb_bnd *b, pl_vec2 p, pl_vec2 q, int nel);
/* a disc (centre, radius, nel elements) traversed clockwise (a particle) or counter-clockwise
   (a container), as its own curve */
pl_status pl_sb_bnd_disc(pl_sb_bnd *b, pl_vec2 c, double radius, int nel, int clockwise, int resist);
/* sets the velocity of every node of curve c to v + ω k × (x - centre) */
void pl_sb_bnd_rigid(pl_sb_bnd *b, int c, pl_vec2 v, double omega);

/* Dense solver with the container's block F cached (factorised) while its geometry and kinds
   do not change. All memory through pl_malloc. */
typedef struct pl_sb_solver {
    uint64_t fkey;   /* hash of the fixed geometry and kinds; 0: no cache */
    int nf, n;       /* fixed unknowns, all unknowns */
    double *F, *Kf;  /* nf x nf: LU factor of F; coefficients of the known values in F's rows */
    int *fpiv;
    size_t fcap;
    double *A;       /* n x n column-major (the particle blocks B, C, D; F's place unused) */
    double *R;       /* n x nrhs */
    double *X;       /* nf x np */
    int *spiv;
    size_t acap, rcap, xcap, pcap;
    int nrhs;
    int reused;      /* 1 when the last solve reused F */
    double t_assemble, t_factor, t_solve; /* s, last solve */
} pl_sb_solver;

void pl_sb_solver_free(pl_sb_solver *s);
/* Assembles [A]Y = R (4.55) with one gauge condition per closed curve whose conditions leave
   a uniform pressure on it free (all velocity-given, or traction given only tangentially;
   zero mean normal traction: the pressure level of the container, the
   force-free uniform pressure on a particle), solves it by LU and writes the solved values
   into bnd->t (PL_SB_VEL) or bnd->u (PL_SB_TRAC). With resist[c], also solves the unit
   motions (x, y, spin about centre[c]) of curve c with every other velocity zero and writes
   the 3x3 resistance [[Kxx Kxy Kxr][Kyx Kyy Kyr][Krx Kry Krr]] (force and moment ON the body
   for a unit velocity, negated) into kres[9 c ...] (may be NULL). PL_ERR_NUMERIC when LU
   finds the matrix singular. */
pl_status pl_sb_solve(pl_sb_solver *s, pl_sb_bnd *bnd, const pl_sb_rules *r, double mu, double *kres);

/* Force and moment (about c) of the fluid ON the body bounded by elements [e0, e1) with the
   nodal tractions t (t = σ n, n outward from the fluid, so the body feels -t):
   F = -∫ t dΓ, M = -∫ (x - c) × t dΓ (4.106-4.108 with the moment's sign corrected). */
void pl_sb_curve_load(const pl_sb_bnd *bnd, const double *t, int e0, int e1, pl_vec2 c, pl_vec2 *F, double *M);
/* Fluid flux ∮ u·n dΓ through the curve (m^2/s). */
double pl_sb_curve_flux(const pl_sb_bnd *bnd, int e0, int e1);

/* Velocity (4.92) and pressure at an interior point P from the solved boundary values. */
void pl_sb_interior(const pl_sb_rules *r, const pl_sb_bnd *bnd, double mu, pl_vec2 P, pl_vec2 *u, double *p);

#endif
