/// Resolved Navier–Stokes flow in the pore space (seed 004, Mueller, Kyotani & Matuttis 2020;
/// docs/navier-stokes.md).
///
/// The water fills the box [x_min, x_max] x [y_min, y_max] minus the grain cores: each disc or
/// polygon of the world whose centroid lies in the box is a hole of the fluid mesh, shrunk about
/// its centroid to core_fraction of its outline (seed §5: the fluid sees a smaller "core" than
/// the contact "shadow", so the pore space stays connected). The incompressible Navier–Stokes
/// equations
///
///     rho (du/dt + u . grad u) = -grad p + eta lap u + rho g,     div u = 0
///
/// are solved on a gmsh mesh of that domain (graded: h_near on the cores, growing to h_far at
/// grade_distance from them; seed §6.3, Fig. 10) with P2 + cubic bubble velocity and P1
/// pressure (seed eqs. 3-8; also Taylor–Hood P2/P1 and MINI), the six-point degree-4 rule,
/// Newton iterations with the analytic Jacobian (appendix A, corrected) and variable-step BDF2 in
/// time (eq. 16, corrected factor 1/tau). The sparse Jacobian is factorised by UMFPACK; its
/// symbolic analysis is kept while the mesh is unchanged.
///
/// Coupling (seed §5): every solve_every grain steps the model predicts each core's position at
/// the end of the fluid step (x + v tau, angle + omega tau), meshes the pore space around the
/// predicted cores (the mesh nodes follow the cores, the interior relaxed by Laplacian smoothing
/// of the displacement, while the smallest angle stays above remesh_angle; otherwise, or when
/// the set of cores changes, a full gmsh remesh; the previous solution and the BDF2 history are
/// interpolated onto the new nodes), prescribes the cores' rigid-body velocities
/// (no slip), solves, and integrates the stress over each core outline (eq. 21, with the
/// pressure rho q of the kinematic pressure q the solver uses) into the force and moment on the
/// grain, which the world applies over the following solve_every steps.
///
/// Box sides: the bottom and left are walls (the left is a parabolic inflow with
/// inflow_velocity > 0), the top is a wall moving at lid_velocity (open with open_top), the
/// right is a wall (a do-nothing outflow with open_right). Gravity acts on the water, so still
/// water carries hydrostatic pressure and buoyancy on the cores.
#ifndef PORELAB_NAVIER_STOKES_H
#define PORELAB_NAVIER_STOKES_H

#include "porelab/core.h"
#include "porelab/params.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pl_world pl_world;

/// Element choices (velocity / pressure).
typedef enum pl_ns_element {
    PL_NS_P2_BUBBLE = 0, ///< P2 + cubic bubble / P1 (seed 004, 7 velocity nodes); default
    PL_NS_P2 = 1,        ///< Taylor–Hood P2 / P1 (6 nodes)
    PL_NS_MINI = 2       ///< P1 + bubble / P1 (4 nodes)
} pl_ns_element;

/// The water and its mesh. Fill with pl_default_navier_stokes_def() and override what you need.
typedef struct pl_navier_stokes_def {
    double x_min, y_min;   ///< lower-left corner of the fluid box, m; default 0, 0
    double x_max, y_max;   ///< upper-right corner, m; default 1, 1
    double density;        ///< rho_F, kg/m^3; default 1000
    double viscosity;      ///< dynamic viscosity eta, Pa s; default 1e-3
    double core_fraction;  ///< core outline / contact outline (about the centroid); default 0.75 (seed §5)
    double h_near;         ///< mesh size on the cores, m; default 0.01
    double h_far;          ///< mesh size far from the cores (and everywhere without grains), m; default 0.05
    double grade_distance; ///< distance from the cores over which the size grows to h_far, m; default 0.1
    int element;           ///< pl_ns_element; default 0 (P2 + bubble)
    int solve_every;       ///< grain steps per fluid step (tau = solve_every dt); default 1
    double lid_velocity;   ///< tangential velocity of the top side (cavity lid), m/s; default 0
    double inflow_velocity;///< centreline velocity of a parabolic inflow on the left side, m/s; default 0 (wall)
    int open_right;        ///< 1: the right side is a do-nothing outflow; default 0 (wall)
    int open_top;          ///< 1: the top side is open (do-nothing); default 0 (wall)
    double newton_tol;     ///< Newton stops when max |correction| <= tol (1 + max |unknown|); default 1e-8
    double force_relaxation; ///< beta: the load applied is (1 - beta) previous + beta new (stabilises the
                           ///< explicit coupling against the added-mass instability); 1 = none. Default 0.5
    double remesh_angle;   ///< degrees: mesh nodes follow the cores (relaxation) while the smallest angle stays
                           ///< above this (or above 3/4 of the smallest angle of gmsh's last full mesh, when
                           ///< that is lower); below it (or for a new set of cores) gmsh remeshes. 0: remesh
                           ///< whenever a core moved. Default 20
    int disc_sides;        ///< sides of the polygon that stands for a disc's core; default 32
    int newton_max;        ///< Newton iterations per fluid step before the step is refused; default 20
    int project;           ///< 1: after the mesh changed (relocation or remesh) the interpolated solution and
                           ///< BDF2 history are projected onto the discretely divergence-free fields (one
                           ///< extra factorisation; docs/navier-stokes.md). Default 1
    int stability_every;   ///< fluid steps between checks of the explicit coupling's limit (below); 0: only
                           ///< the first fluid step; -1: never (to watch the instability). Default 50
} pl_navier_stokes_def;

/// Stability of the explicit coupling (docs/navier-stokes.md, "Coupling"). The load a grain feels
/// over a fluid step is the relaxed fluid force of the step before, computed around the grain's
/// predicted motion. For one grain of mass m whose fluid force responds to its velocity as
/// dF = -D dv (D per unit length, from the added mass of the fluid it accelerates and from the
/// drag; the model measures D from its own factorised Jacobian: one extra solve per grain and
/// direction), the load and velocity obey a two-step recurrence that is stable when
///
///     beta (1 + D tau / m) < 2      (and likewise with the moment response and the inertia),
///
/// beta = force_relaxation, tau the fluid step. At the first fluid step and every
/// stability_every fluid steps the model checks every dynamic grain and refuses the step past
/// the limit with a message naming the grain, D tau / m, the limit and a safe force_relaxation.
#define PL_NAVIER_STOKES_PARAM_COUNT 23
extern const pl_param pl_navier_stokes_params[PL_NAVIER_STOKES_PARAM_COUNT];
extern const int pl_navier_stokes_param_count;

/// Defaults of the table (above).
pl_navier_stokes_def pl_default_navier_stokes_def(void);

/// Attaches resolved Navier–Stokes water. Checks every field against the table and refuses a
/// box without area, h_near > h_far, a second attach, and a build without gmsh (the message
/// names the Debian package libgmsh-dev). The mesh is built on the first step or prepare.
pl_status pl_world_attach_navier_stokes(pl_world *w, const pl_navier_stokes_def *def);
/// 1 when the world has Navier–Stokes water.
int pl_world_has_navier_stokes(const pl_world *w);

/// Field quantities for pl_world_field_sample beyond porelab/fluid.h's PL_FLUID_PRESSURE (Pa).
enum {
    PL_NS_FIELD_SPEED = 16,      ///< |u|, m/s
    PL_NS_FIELD_VELOCITY_X = 17, ///< u_x, m/s
    PL_NS_FIELD_VELOCITY_Y = 18  ///< u_y, m/s
};

/// Velocity (m/s) and pressure (Pa) at a point of the last solution; returns 1 inside the fluid
/// mesh, 0 outside (then all 0).
int pl_world_navier_stokes_at(const pl_world *w, pl_vec2 p, pl_vec2 *velocity, double *pressure);
/// Fluid force (N per m thickness) and moment about the predicted centroid (N m) on one body,
/// as last computed (eq. 21); zero for a body that is not a core.
pl_status pl_world_navier_stokes_body_force(const pl_world *w, int body, pl_vec2 *force, double *moment);

/// Counters and CPU times (s, accumulated since attach).
typedef struct pl_ns_stats {
    long fluid_steps;      ///< fluid steps solved
    long remeshes;         ///< full gmsh meshes built (the first included)
    long relocations;      ///< fluid steps whose mesh followed the cores by node relocation
    long newton_iters;     ///< Newton iterations in total
    long symbolic, numeric;///< UMFPACK symbolic analyses and numeric factorisations
    int vertices, triangles, unknowns; ///< the current mesh and system
    double min_angle;      ///< smallest angle of the current mesh, degrees
    double nnz_matrix, nnz_lu; ///< entries of the Jacobian and of L + U (last factorisation)
    double t_mesh, t_relocate, t_interp, t_assembly, t_factor, t_solve, t_forces;
    double t_stability;    ///< the coupling-limit checks (their extra solves)
    double t_project;      ///< the divergence projections after a mesh change (not in t_assembly, t_factor)
    double coupling_ratio; ///< largest beta (1 + D tau / m) of the last check (stable below 2)
    int coupling_body;     ///< the grain it belongs to (-1: none checked)
    double coupling_translation, coupling_rotation; ///< largest D tau / m and D tau / I of the last check
} pl_ns_stats;
pl_status pl_world_navier_stokes_stats(const pl_world *w, pl_ns_stats *out);

#ifdef __cplusplus
}
#endif
#endif
