/// Resolved Stokes flow between the grains by boundary elements (seed 003, Tan 1990, ch. 4;
/// docs/stokes.md).
///
/// The fluid fills the container (the world's wall segments, or the ones listed in
/// pl_stokes_def.container, chained into a convex polygon, counter-clockwise) minus the dynamic discs and convex polygons (clockwise). Each step that is
/// due, the model solves quasi-steady Stokes flow (mu lap u = grad p, div u = 0) with the
/// boundary integral equation (seed eqs. 4.37, 4.40 and 4.43)
///
///     c_ij u_j(P) + ∫ t*_ij(P,Q) u_j(Q) dΓ = ∫ u*_ij(P,Q) t_j(Q) dΓ,     c_ij = δ_ij / 2,
///     u*_ij = (1/4πμ) [ln(1/r) δ_ij + r,i r,j],   t*_ij = -(1/πr) (∂r/∂n) r,i r,j   (4.20-4.22)
///
/// on discontinuous linear elements (4.48; nodes at the quarter points, so every collocation
/// node lies on a straight piece and c = δ/2), Gauss order by distance (Table 4.1) and the
/// self-element split with a logarithmic Gauss rule (4.61-4.79, with the seed's spurious second
/// 1/(4πμ) removed). Boundary velocities are the rigid-body velocities u = v + ω × (x - c) of the
/// particles and walls; the tractions come out of one dense LU (LAPACK dgetrf/dgetrs). The
/// walls' block of the matrix is assembled and factorised once while the container keeps its
/// shape. Force and moment per particle are the integrals of the traction (4.106-4.107; the
/// moment with the correct sign of r × t, which 4.108 misprints); buoyancy -ρ_l A g is added
/// separately (4.39). The fluid pressure's gauge is fixed by a zero mean normal traction on the
/// container; on each particle the traction is fixed up to a uniform pressure that carries no
/// force or moment (seed §5.3.3), removed by the same condition.
///
/// Explicit coupling: the drag is computed from the velocities at the start of the step and
/// held for solve_every steps; with the particle's own resistance K (N s/m per m, from the
/// solution for a unit velocity of that particle) the scheme is stable only for
/// solve_every · dt < 2 m / K (and 2 I / K_rot for spin). The model checks this each solve and
/// stops with a message naming the particle and the safe step.
#ifndef PORELAB_STOKES_H
#define PORELAB_STOKES_H

#include "porelab/core.h"
#include "porelab/params.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pl_world pl_world;

/// The Stokes fluid. Fill with pl_default_stokes_def() and override what you need.
typedef struct pl_stokes_def {
    double viscosity;      ///< dynamic viscosity μ, Pa s; default 1e-3 (water)
    double density;        ///< fluid density ρ_l for buoyancy (4.39), kg/m^3; default 1000
    int disc_elements;     ///< boundary elements per disc; default 24
    int wall_elements;     ///< elements per container side (uniform); default 40
    double element_length; ///< if > 0: target element length on polygons and walls (each
                           ///< side gets max(wall_elements, ceil(length / element_length))),
                           ///< m; default 0
    int polygon_elements;  ///< elements per polygon (spread over its sides by length); default 24
    double gap;            ///< artificial gap (seed §3.4): each particle's outline shrunk by
                           ///< gap/2 so that touching grains leave a channel, m; default 0
    int solve_every;       ///< solve every N grain steps, the loads held in between; default 1
    int check_stability;   ///< 1: compute each particle's drag resistance K and refuse
                           ///< solve_every·dt >= 2m/K; default 1
    int field_grid;        ///< sample points along the longer side of the container for the
                           ///< drawing field (velocity, pressure); default 40
    int load_wall;         ///< body index of a wall held by a set force instead of its velocity
                           ///< (seed §5.3.2): its normal traction is prescribed, its normal
                           ///< velocity solved for; -1: none. Default -1
    double load_force;     ///< force the held wall applies on the fluid along its inward
                           ///< normal, N per m thickness (pressure = load_force / length);
                           ///< default 0
    int load_contacts;     ///< 1: the held wall gives the fluid only what its contacts do not
                           ///< carry: traction from load_force minus the grains' contact force
                           ///< on the wall in the last step (seed 003 §5.3.2, the unbalanced
                           ///< force); 0: all of load_force. Default 0
    int container_count;   ///< 0: the container is every wall segment of the world (default);
                           ///< 3..PL_STOKES_CONTAINER_MAX: only the wall bodies listed in
                           ///< container[] bound the fluid, and only the particles whose centre
                           ///< lies inside them are in it (the others get no drag and no
                           ///< buoyancy). Lets a world hold several boxes, one of them saturated
    int container[8];      ///< body indices of the container's walls (distinct), in any order
} pl_stokes_def;

/// Most walls a chosen container (pl_stokes_def.container) may list.
#define PL_STOKES_CONTAINER_MAX 8

#define PL_STOKES_PARAM_COUNT 13
/// The parameter table of pl_stokes_def (Lua names as the fields; no MIMES flags).
extern const pl_param pl_stokes_params[PL_STOKES_PARAM_COUNT];
extern const int pl_stokes_param_count;

/// Defaults of the table.
pl_stokes_def pl_default_stokes_def(void);

/// Attaches the Stokes fluid. Refused (PL_ERR_ARG / PL_ERR_STATE, message in
/// pl_world_last_error): a field out of range, a second attach.
pl_status pl_world_attach_stokes(pl_world *w, const pl_stokes_def *def);
/// 1 when the world has the Stokes fluid.
int pl_world_has_stokes(const pl_world *w);
/// The current def; PL_ERR_STATE without the model.
pl_status pl_world_stokes_def(const pl_world *w, pl_stokes_def *out);
/// Replaces the parameters between steps (same checks as attach).
pl_status pl_world_stokes_redefine(pl_world *w, const pl_stokes_def *def);
/// Solves the flow for the bodies as they are now without advancing time (the same solve a
/// step makes); the loads, resistances and the drawing field then describe this state.
pl_status pl_world_stokes_solve(pl_world *w);

/// What the last solve gave for one body.
typedef struct pl_stokes_body_result {
    pl_vec2 drag;      ///< fluid force from the tractions (without buoyancy), N/m
    double moment;     ///< fluid moment about the centroid, N m/m
    pl_vec2 buoyancy;  ///< -ρ_l A g, N/m (0 for walls)
    double k_trans;    ///< translational resistance K (largest eigenvalue of the 2x2 block), N s/m^2
    double k_rot;      ///< rotational resistance, N s
    double dt_safe;    ///< 2 min(m/K, I/K_rot): the largest stable solve_every·dt, s
} pl_stokes_body_result;

/// Result of the last solve for body i (a particle, or a wall: drag and moment only).
/// PL_ERR_STATE without a solve, PL_ERR_ARG for a body the fluid does not see.
pl_status pl_world_stokes_body(const pl_world *w, int body, pl_stokes_body_result *out);
/// Mean pressure on the wall body i from the last solve (-t·n averaged over its side), Pa;
/// NaN if the body is not a container side.
double pl_world_stokes_wall_pressure(const pl_world *w, int body);
/// Volume flux of the fluid out through the wall body i from the last solve (∫ u·n dΓ, n out of
/// the fluid), m^2/s: the solved normal velocity of a held wall (load_wall) integrated; NaN if
/// the body is not a container side.
double pl_world_stokes_wall_flux(const pl_world *w, int body);
/// Velocity (m/s) and dynamic pressure (Pa, the gauge of the solve) at an interior point from
/// the last solve (seed 4.92 and the pressure kernel of docs/stokes.md). PL_ERR_ARG outside the
/// fluid.
pl_status pl_world_stokes_point(const pl_world *w, pl_vec2 p, pl_vec2 *velocity, double *pressure);
/// Boundary nodes and unknowns of the last solve (for cost reports).
int pl_world_stokes_unknowns(const pl_world *w);

#ifdef __cplusplus
}
#endif
#endif
