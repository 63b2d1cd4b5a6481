/// Pore fluid by Darcy finite elements (seed 000, Klosek 1997, chapter 3; "MIMES").
///
/// A fluid model is attached to a world by adding fluid quads (convex, counter-clockwise,
/// meshed into ndivx x ndivy cells of four triangles each, seed 000 §3.5) and boundary lines
/// (prescribed pressure head, eq. 3.16, or prescribed inflow, eq. 3.14; all other boundaries
/// are impermeable). The unknown is the total head h = p / (rho_f g) + z (z = elevation against
/// gravity), so still water gives hydrostatic pressure and zero Darcy velocity; boundary lines
/// take pressure head p / (rho_f g) as in the thesis. Conductivities ("permeabilities" D_x, D_y
/// of eq. 3.11) are in m/s. Each step the world calls the fluid module, which (every
/// FLUID_SOLVE_TIMESTEPS grain steps) updates porosity and permeability, reassembles, solves and
/// adds the fluid force and moment to every body. Flags: FLUIDS_ON, FIRST_STEP_STATIC,
/// FLUID_PERM, FLUID_PERM_LOW, FLUID_PERM_HIGH, FLUID_SOLVE_TIMESTEPS, FLUID_DENSITY, ... (see
/// docs/fluid.md for the full table with units).
#ifndef PORELAB_FLUID_H
#define PORELAB_FLUID_H

#include "porelab/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pl_world pl_world;

/// A fluid quadrilateral (MIMES add_fluid_mesh_ui).
typedef struct pl_fluid_quad_def {
    pl_vec2 corners[4];  ///< m, counter-clockwise and convex (errors otherwise)
    int ndivx;           ///< divisions along corners 0->1 (the quad's s direction); >= 1. Default 4.
    int ndivy;           ///< divisions along corners 1->2 (t direction); >= 1. Default 4.
    int id;              ///< identification number, unique among quads; default -1 (automatic: largest id + 1)
    double anisotropy;   ///< D_y / D_x of the elements of this quad (eq. 3.11); > 0. Default 1.
} pl_fluid_quad_def;

pl_fluid_quad_def pl_default_fluid_quad_def(void);

/// Adds a fluid quad (creates the fluid model on first use). Returns the quad index (>= 0) or
/// a negative pl_status; clockwise, non-convex or degenerate quads are refused with a message.
int pl_world_add_fluid_quad(pl_world *w, const pl_fluid_quad_def *def);
/// Changes the id of a fluid quad (MIMES change_fluid_id_ui).
pl_status pl_world_change_fluid_id(pl_world *w, int old_id, int new_id);
int pl_world_fluid_quad_count(const pl_world *w);

/// Prescribes the pressure head (m of fluid: p / (rho_f g)) on every mesh node lying on the
/// segment a-b (MIMES add_fluid_bc_ui, eq. 3.16). Returns the line index or a negative status.
int pl_world_add_fluid_bc(pl_world *w, pl_vec2 a, pl_vec2 b, double pressure_head);
/// Prescribes an inflow flux q (m/s, volume per unit boundary area and time, positive into the
/// domain) on the mesh boundary edges lying on the segment a-b (eq. 3.14). Returns the line
/// index or a negative status.
int pl_world_add_fluid_flux(pl_world *w, pl_vec2 a, pl_vec2 b, double inflow);
/// Removes all boundary lines (MIMES clear_fluid_bcs_ui).
pl_status pl_world_clear_fluid_bcs(pl_world *w);

/// Meshes (if needed), updates porosity and permeability from the current bodies, and solves
/// the static problem (seed 000 §3.9.1). The result stays as the initial field for stepping.
pl_status pl_world_fluid_solve_static(pl_world *w);
/// One fluid update of length dt (s) as the stepping does (porosity, assembly, transient or
/// static solve per the flags), without computing forces or moving bodies.
pl_status pl_world_fluid_advance(pl_world *w, double dt);
/// Sets the pressure head (m) of every free node to pressure_head (initial condition).
pl_status pl_world_fluid_set_pressure_head(pl_world *w, double pressure_head);

/// The pore water shares the acceleration a of a prescribed body (a shaking table carrying the
/// tanks; shake or constant velocity): Darcy's law is written in that body's frame,
/// q = -D (grad h + a/g) (the u-p approximation: the water's acceleration is the frame's), so
/// that no-flow walls get the pressure gradient -rho_f a that accelerates the water, grains
/// feel it as buoyancy and the drag follows q. body -1: none (the default, a fixed frame).
/// The mesh itself does not move.
pl_status pl_world_fluid_set_frame(pl_world *w, int body);
/// Per-element user conductivities (m/s) used when FLUID_PERM = 2 (count = triangle count).
pl_status pl_world_fluid_set_element_permeability(pl_world *w, const double *k, int count);

/* ---------------------------------------------------------------- queries */

/// Queries are read-only: they read the field as the last prepare or step left it. Call
/// pl_world_prepare (porelab/world.h) after changing quads or lines and before reading a field
/// at t = 0; before that they report an empty mesh.
///
/// Number of mesh nodes / triangles (0 without a fluid model or before it is prepared).
int pl_world_fluid_node_count(const pl_world *w);
int pl_world_fluid_triangle_count(const pl_world *w);
/// Copies node coordinates (m); returns the number written.
int pl_world_fluid_copy_nodes(const pl_world *w, pl_vec2 *out, int cap);
/// Copies triangles as 3 node indices each, counter-clockwise; cap counts triangles.
int pl_world_fluid_copy_triangles(const pl_world *w, int *out, int cap);

typedef enum pl_fluid_node_field {
    PL_FLUID_HEAD = 0,           ///< total head h, m
    PL_FLUID_PRESSURE_HEAD = 1,  ///< p / (rho_f g), m
    PL_FLUID_PRESSURE = 2,       ///< p, Pa (gauge)
    PL_FLUID_EXCESS_PRESSURE = 3, ///< p - hydrostatic = rho_f g (h - h_ref), Pa; h_ref = mean prescribed head
    PL_FLUID_VELOCITY_NODE_X = 4, ///< fluid velocity x at the field's nodes (resolved models: Stokes), m/s
    PL_FLUID_VELOCITY_NODE_Y = 5, ///< fluid velocity y at the field's nodes, m/s
    PL_FLUID_ELEMENT_MESH = 64    ///< the model's own element mesh (vertices, triangles; values 0) for the
                                  ///< mesh layer, when it differs from the field's linear sub-triangles
} pl_fluid_node_field;

typedef enum pl_fluid_element_field {
    PL_FLUID_VELOCITY_X = 0,     ///< Darcy velocity (specific discharge) x, m/s (eq. 3.19)
    PL_FLUID_VELOCITY_Y = 1,     ///< m/s
    PL_FLUID_POROSITY = 2,       ///< porosity used for permeability (after the 2D->3D mapping)
    PL_FLUID_VOID_RATIO = 3,     ///< areal void ratio, clamped 0.01..99 (eq. 3.9)
    PL_FLUID_PERM_X = 4,         ///< D_x, m/s
    PL_FLUID_PERM_Y = 5,         ///< D_y, m/s
    PL_FLUID_SOLID_AREA = 6      ///< solid area of grains inside the element, m^2
} pl_fluid_element_field;

/// Copies a per-node field; returns the number written.
int pl_world_fluid_copy_node_field(const pl_world *w, pl_fluid_node_field field, double *out, int cap);
/// Copies a per-element field; returns the number written.
int pl_world_fluid_copy_element_field(const pl_world *w, pl_fluid_element_field field, double *out, int cap);
/// Pressure (Pa, gauge) and total head (m) at a point (eqs. 3.21-3.23). Returns 1 inside the
/// mesh, 0 outside (then pressure = 0 and head = NaN).
int pl_world_fluid_pressure_at(const pl_world *w, pl_vec2 p, double *pressure, double *head);
/// Net flow (m^2/s per unit thickness) entering the domain through the nodes of head line
/// `line` (negative when leaving), from the reactions K h - f of the assembled system (the
/// steady balance: in transient runs the storage term is not included).
double pl_world_fluid_line_inflow(const pl_world *w, int line);
/// Fluid force (N per m thickness) and moment about the centroid (N m) on one body for the
/// current field: pressure on its outline plus interphase drag (when on).
pl_status pl_world_fluid_body_force(const pl_world *w, int body, pl_vec2 *force, double *moment);

/// Counters and timings (s, accumulated since the model was created).
typedef struct pl_fluid_stats {
    long updates;            ///< fluid updates performed
    long factorizations;     ///< numeric factorizations
    long analyses;           ///< symbolic analyses
    long solves;             ///< triangular solves
    long skipped;            ///< updates skipped because nothing changed
    long substeps;           ///< explicit sub-steps taken in total
    int last_substeps;       ///< explicit sub-steps in the last update
    double explicit_dt_limit;///< last computed explicit stability limit, s
    double stagger_dt_limit; ///< last computed staggering limit of the undrained coupling (FLUID_CONSOLIDATION, K_f > 0): grain step x FLUID_SOLVE_TIMESTEPS must stay below it, s (0 = not computed)
    double stagger_stiffness;///< the water spring K_f / (n (1 - n)^2) behind it, N/m per m (docs/stability.md)
    double t_porosity, t_assembly, t_factor, t_solve, t_forces;
} pl_fluid_stats;
pl_status pl_world_fluid_stats(const pl_world *w, pl_fluid_stats *out);

/* ---------------------------------------------------------------- output */

/// Writes the mesh with head, pressure, excess pressure (nodes), velocity, porosity, void
/// ratio and permeability (elements) as a VTK unstructured grid (.vtu, ASCII).
pl_status pl_world_fluid_write_vtu(pl_world *w, const char *path);
/// Writes a ParaView collection (.pvd) listing files[i] at times[i].
pl_status pl_world_fluid_write_pvd(pl_world *w, const char *path, const char *const *files, const double *times, int n);
/// Thesis output files (FLUID_GEOMETRY_FILENAME / FLUID_PRESSURES_FILENAME): sets the path
/// used when FLUID_GEOMETRY_FLAG / FLUID_PRESSURES_FLAG are on. which: "geometry" or "pressures".
pl_status pl_world_fluid_set_output_file(pl_world *w, const char *which, const char *path);
/// Writes the MATLAB-readable geometry file now: one row "x y" per node, then (in
/// path + ".tri") one row "i j k" (1-based) per triangle.
pl_status pl_world_fluid_write_geometry(pl_world *w, const char *path);
/// Appends one row "t psi_1 ... psi_n" (time, then the pressure head of every node, m).
pl_status pl_world_fluid_append_pressures(pl_world *w, const char *path);

#ifdef __cplusplus
}
#endif
#endif
