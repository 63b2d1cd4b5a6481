/// Finite-element solids beside the grains (seed 002, Oñate & Rojek 2004, §5–6; docs/solids.md).
///
/// Plane strain, explicit dynamics with a lumped mass matrix and central differences (seed
/// eqs. 3–5 for the grains, 97–98 for the nodes), small strain or updated Lagrangian. Elements:
///   - PL_SOLID_PLAIN: linear triangles, displacement only (locks when nearly incompressible);
///   - PL_SOLID_FIC_EXPLICIT / PL_SOLID_FIC_SEMI_IMPLICIT: linear triangles with equal-order
///     linear pressure p and projected pressure gradient pi, the finite-calculus (FIC)
///     stabilised pressure equation (seed eqs. 83, 90–92)
///         int q dp/K - int q d(eps_v) + int tau grad q . (grad p + pi) = 0,
///         int tau w . (grad p + pi) = 0,          tau = alpha h^2 / (2 G),
///     in total form (the volumetric strain integral accumulated over the steps), solved each
///     step explicitly (eq. 104, needs K tau small enough: refused otherwise) or semi-implicitly
///     with pi eliminated, S = M_p/K + L - Q M_tau^-1 Q^T factorised by CHOLMOD (eqs. 102-103);
///   - PL_SOLID_Q1P0: bilinear quadrilaterals, constant pressure per element (mean dilatation),
///     the reference element of the seed's §7.4.
/// Materials: linear elastic (E, nu) and J2 plasticity with linear isotropic hardening
/// (yield_stress > 0; radial return). Contact with discs (seed §6, eqs. 105–109): penetration
/// from the disc centre to the boundary edge, normal spring-dashpot, regularised Coulomb
/// friction, reaction spread to the edge nodes with the edge's linear shape functions; convex
/// polygons by their vertices inside the solid and the solid's convex corners inside them.
/// The critical step, 2/omega_max bounded element by element, enters the world's automatic
/// step; a run whose step exceeds it is stopped with a message.
#ifndef PORELAB_SOLID_H
#define PORELAB_SOLID_H

#include "porelab/core.h"
#include "porelab/params.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pl_world pl_world;

/// Element formulations (pl_solid_def.formulation).
typedef enum pl_solid_formulation {
    PL_SOLID_PLAIN = 0,             ///< linear triangles, displacement only
    PL_SOLID_FIC_EXPLICIT = 1,      ///< triangles + FIC pressure, explicit pressure (eq. 104)
    PL_SOLID_FIC_SEMI_IMPLICIT = 2, ///< triangles + FIC pressure, implicit by CHOLMOD (eqs. 102-103)
    PL_SOLID_Q1P0 = 3               ///< bilinear quadrilaterals, constant pressure (mean dilatation)
} pl_solid_formulation;

/// The solid's material, formulation and contact. Fill with pl_default_solid_def().
typedef struct pl_solid_def {
    double young;          ///< Young's modulus E, Pa; default 2e11
    double poisson;        ///< Poisson's ratio nu, 0..0.49999; default 0.3
    double density;        ///< rho, kg/m^3; default 7800
    int formulation;       ///< pl_solid_formulation; default PL_SOLID_FIC_SEMI_IMPLICIT
    int large_strain;      ///< 1: updated Lagrangian (B on the current configuration, stress
                           ///< rotated by the incremental spin); 0: small strain. Default 0
    double yield_stress;   ///< J2 initial yield stress sigma_y, Pa; 0: elastic. Default 0
    double hardening;      ///< linear isotropic hardening modulus H (sigma_y + H eps_p), Pa; default 0
    double fic_alpha;      ///< FIC: tau = alpha h^2 / (2 G) (h: element size); default 0.1
    double damping;        ///< mass-proportional damping c (force -c m v), 1/s; default 0
    double contact_stiffness; ///< grain-edge normal spring k_n, N/m per m; default 1e8
    double contact_damping;///< grain-edge normal dashpot c_n, N s/m per m; default 0
    double friction;       ///< grain-edge Coulomb coefficient mu; default 0
    double slip_velocity;  ///< regularisation of Coulomb friction: F_t = mu F_n tanh(|v_t|/v_e), m/s; default 1e-3
} pl_solid_def;

#define PL_SOLID_PARAM_COUNT 13
/// The parameter table of pl_solid_def (Lua names as the fields; no MIMES flags).
extern const pl_param pl_solid_params[PL_SOLID_PARAM_COUNT];
pl_solid_def pl_default_solid_def(void);

/// Field quantities of the solid (pl_world_field_sample / the renderer's field layers,
/// render{ fluid_field = "mises" | "plastic_strain" | "solid_pressure" | "displacement" }),
/// averaged to the nodes. (16-18 are the Navier-Stokes fields.)
enum {
    PL_SOLID_FIELD_MISES = 32,          ///< von Mises stress, Pa
    PL_SOLID_FIELD_PLASTIC_STRAIN = 33, ///< equivalent plastic strain, 1
    PL_SOLID_FIELD_PRESSURE = 34,       ///< mean stress (tension positive), Pa
    PL_SOLID_FIELD_DISPLACEMENT = 35    ///< displacement magnitude, m
};

/// Energy ledger of the solid (J per m thickness). Balance: kinetic + internal - external +
/// damping stays at its initial value (central differences conserve it to O(dt^2)).
typedef struct pl_solid_energy {
    double kinetic, internal, external, damping, plastic, contact, elastic;
} pl_solid_energy;

/// Attaches an (empty) solid with this material and formulation; add parts with the mesh
/// functions below. One solid model per world (it may hold several parts).
pl_status pl_world_attach_solid(pl_world *w, const pl_solid_def *def);
int pl_world_has_solid(const pl_world *w);
/// Parts, meshed by gmsh (Debian libgmsh-dev; without it these refuse with PL_ERR_NOT_BUILT).
/// Structured (transfinite) meshes: nx by ny divisions; triangles are split quadrilaterals
/// (alternating diagonals), Q1/P0 keeps the quadrilaterals. Returns the part index or a status.
int pl_world_solid_rectangle(pl_world *w, double x0, double y0, double x1, double y1, int nx, int ny);
/// Four-sided part with corners c[0..3] counter-clockwise (Cook's membrane).
int pl_world_solid_quad(pl_world *w, const pl_vec2 c[4], int nx, int ny);
/// Annular sector centre (cx, cy), radii ri < ro, angles a0 < a1 (rad; a1 - a0 = 2 pi: a full
/// ring), nr radial and nt circumferential divisions.
int pl_world_solid_annulus(pl_world *w, double cx, double cy, double ri, double ro, double a0, double a1, int nr,
                           int nt);
/// Unstructured triangles (gmsh Frontal-Delaunay) in a simple polygon (CCW), element size h.
int pl_world_solid_polygon(pl_world *w, const pl_vec2 *verts, int n, double h);
/// A part read from a gmsh .msh file (gmsh's C API; plane mesh, z = 0): its 3-node triangles,
/// or its 4-node quadrilaterals for Q1/P0. The file name must end in .msh; an unreadable,
/// damaged or non-plane file is refused with the file and the reason.
int pl_world_solid_mesh_file(pl_world *w, const char *path);
/// Fixes the components in mask (1 x, 2 y, 3 both) of the nodes whose reference position is in
/// the box. Returns the set index (for reactions) or a status.
int pl_world_solid_fix(pl_world *w, double x0, double y0, double x1, double y1, int mask);
/// Drives the nodes in the box at constant velocity (a rigid tool holder). Returns the set index.
int pl_world_solid_velocity(pl_world *w, double x0, double y0, double x1, double y1, int mask, double vx, double vy);
/// Sets the velocity of the free nodes in the box now (an initial velocity: a projectile).
/// Returns the number of nodes.
int pl_world_solid_initial_velocity(pl_world *w, double x0, double y0, double x1, double y1, double vx, double vy);
/// Traction (tx, ty) Pa plus normal pressure pn Pa (positive pushes into the solid) on the
/// boundary edges whose two nodes lie in the box. Returns the number of edges.
int pl_world_solid_traction(pl_world *w, double x0, double y0, double x1, double y1, double tx, double ty, double pn);
/// Force exerted on the solid by the support of set k (N/m), last step.
pl_status pl_world_solid_reaction(const pl_world *w, int set, pl_vec2 *force);
/// Displacement of the node nearest to the reference point X.
pl_status pl_world_solid_displacement(const pl_world *w, pl_vec2 X, pl_vec2 *u);
int pl_world_solid_node_count(const pl_world *w);
int pl_world_solid_element_count(const pl_world *w);
/// Critical step of the solid, s (2/omega_max over the elements), and the element giving it.
double pl_world_solid_critical_dt(const pl_world *w, int *element);
pl_status pl_world_solid_energy(const pl_world *w, pl_solid_energy *out);
/// Time spent (s, monotonic clock) in the solid since it was attached: the finite elements
/// (step, pressure, stress update) and the grain-edge contact (search and forces).
void pl_world_solid_cost(const pl_world *w, double *solid_seconds, double *contact_seconds);
/// Largest von Mises stress (Pa) and equivalent plastic strain over the integration points.
pl_status pl_world_solid_extremes(const pl_world *w, double *mises_max, double *plastic_max);
/// Total contact force of the grains on the solid (N/m), last step.
pl_vec2 pl_world_solid_contact_force(const pl_world *w);

/// Cohesion between discs and the solid (docs/solids.md): ties every disc whose centre lies
/// over a boundary edge's face and whose surface is within `gap` (m, >= 0) of it to the edge's
/// material point under it, with the grains' bond law (porelab/bonds.h: brittle, plastic or
/// damage; one law for all the solid's bonds). The bond acts in parallel with the contact; its
/// opening, slip and rotation are measured from the edge's moving material point and direction;
/// when it breaks the disc goes on as an ordinary contact. Call after every part is meshed.
/// Returns the number of bonds created or a negative status.
typedef struct pl_bond_def pl_bond_def;
typedef struct pl_bond_info pl_bond_info;
typedef struct pl_thermal_def pl_thermal_def;
int pl_world_solid_bond(pl_world *w, const pl_bond_def *law, double gap);
/// Bonds ever created; *intact (may be NULL) gets the intact ones.
int pl_world_solid_bond_count(const pl_world *w, int *intact);
/// Copies up to cap bonds: a = disc, b = the edge's first node, point = the edge's material
/// point, n/s/m the last tension (N/m, > 0 pulling), shear and moment. Returns how many.
int pl_world_solid_bonds(const pl_world *w, pl_bond_info *out, int cap);
/// Frictional heat and Archard wear on the element side (the laws of the grains' contacts,
/// docs/rock.md): each sliding grain-edge point turns `fraction` of the friction work
/// |F_t v_t| dt into heat, half to the solid (spread to the edge's nodes by the edge shape
/// functions; a node's temperature is t0 + Q/(m c), no conduction inside the solid) and half to
/// the grain (pl_world_body_contact_heat, while the world's heat is on); the solid's nodes wear
/// dV = k F_n |v_t| dt / H(T) (def: heat_capacity, wear k, hardness H_0, softening; conductivity
/// unused). Call after every part is meshed.
pl_status pl_world_solid_thermal(pl_world *w, const pl_thermal_def *def, double fraction, double t0);
/// Heat received by the solid (J/m), its worn area (m^2/m) and its hottest node (K).
pl_status pl_world_solid_thermal_totals(const pl_world *w, double *heat, double *wear, double *t_max);

#ifdef __cplusplus
}
#endif
#endif
