/// The world: owns bodies, materials, contacts and (optionally) a pore-fluid model,
/// steps them together and answers read-only queries.
///
/// Units are SI by default; any consistent system works. Gravity points along -y unless set.
/// Bodies are referred to by their index (0..pl_world_body_count-1); bodies are never
/// removed, so an index stays valid for the life of the world.
#ifndef PORELAB_WORLD_H
#define PORELAB_WORLD_H

#include "porelab/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pl_world pl_world;

/* ------------------------------------------------------------------ world */

/// World parameters. Fill with pl_default_world_def() and override what you need.
/// Task hook for the contact loop: a parallel-for that runs task(ctx, begin, end) over
/// sub-ranges covering [0, n) exactly once, possibly on several threads at once, and returns
/// when all have run. The state is bit-identical with or without it and for any split.
typedef void (*pl_task_fn)(void *ctx, int begin, int end);
typedef void (*pl_parallel_for_fn)(void *user, int n, pl_task_fn task, void *ctx);

typedef struct pl_world_def {
    pl_vec2 gravity;       ///< m/s^2; default (0, -9.81). Flag GRAVITY_X / GRAVITY_Y.
    double dt;             ///< time step in s; 0 = automatic (dt_safety x critical step). Default 0.
    double dt_safety;      ///< fraction of the critical step used when dt = 0; default 0.1 (Cundall).
    double max_dt;         ///< cap on the time step, s (flag MAX_DT_CR); 0 = no cap. Default 0.
    double global_c;       ///< translational global damping C, N s/m (seed 003 eq. 2.21); default 0.
    double global_c_rot;   ///< rotational global damping C*, N m s (seed 003 eq. 2.22); default 0.
    double rayleigh_alpha; ///< mass-proportional damping alpha, 1/s (seed 000 eq. 2.5, flag RAYLEIGH_FACTOR); default 0.
    double local_damping;  ///< non-viscous damping ratio, 0..1, force-proportional (seed 002 eqs. 24-29); default 0.
    double skin;           ///< neighbour-list skin, m; 0 = automatic (0.2 x smallest dynamic radius). Default 0.
    double max_overlap_ratio; ///< guard: overlap / smaller body radius that stops the run; default 0.5.
    double energy_surge_ratio; ///< guard: kinetic energy rising above this multiple of the energy budget stops the run; default 10.
    int guard_interval;    ///< steps between (cheap) stability checks; default 1.
    int track_energy;      ///< 1: exact tallies of dissipated energy (default); 0: skip them for speed
                           ///< (energy() then reports damped and friction as 0 and no balance).
    pl_parallel_for_fn parallel_for; ///< task hook for the contact loop; NULL (default): serial
    void *parallel_user;   ///< passed to parallel_for; the world does not own it
} pl_world_def;

pl_world_def pl_default_world_def(void);
/// Sets (or with fn = NULL clears) the task hook of an existing world (pl_world_def.parallel_for);
/// kept across restores of snapshots and state images.
void pl_world_set_parallel_for(pl_world *w, pl_parallel_for_fn fn, void *user);

/// Creates a world. Returns NULL only when out of memory.
pl_world *pl_world_create(const pl_world_def *def);
/// Destroys the world and nulls the pointer.
void pl_world_destroy(pl_world **world);

/// Message describing the last error (what, where, when, what to change). Never NULL.
/// Messages about the state of a run (guards) number bodies from 1, as scenes do; argument
/// errors of C calls name the 0-based index the caller passed.
const char *pl_world_last_error(const pl_world *w);

/* -------------------------------------------------------------- materials */

/// Material parameters. Stiffnesses are per unit thickness (2D, N/m); density in kg/m^2 per
/// unit thickness... i.e. mass = density x area x 1 m.
typedef struct pl_material_def {
    const char *name;      ///< unique name (copied); required
    double density;        ///< kg/m^3 (mass = density x area x 1 m); > 0
    double kn;             ///< normal contact stiffness, N/m; 0 = from young (seed 003 eq. 2.36)
    double ks;             ///< shear contact stiffness, N/m; < 0 = 2/3 of kn (seed 003 §2.2.4.7). Default -1.
    double young;          ///< Young's modulus, Pa; used when kn = 0: kn = E l / (2R) (seed 003 eq. 2.36)
    double young_overlap;  ///< overlap fraction of the radius assumed in eq. 2.36; default 0.02
    double friction;       ///< Coulomb coefficient mu = tan(phi); >= 0. Default 0.5.
    double cohesion;       ///< cohesion c in eq. 2.17, N; default 0.
    double cn;             ///< normal contact dashpot, N s/m; used when restitution < 0. Default 0.
    double cs;             ///< shear contact dashpot, N s/m; < 0 = cn x ks / kn (seed 003). Default -1.
    double restitution;    ///< coefficient of restitution 0 < e <= 1; overrides cn when >= 0. Default -1 (off).
    double rolling;        ///< rolling resistance mu_r (discs with discs and walls): the contact resists the
                           ///< relative rotation with an elastic-plastic moment, spring k_S R^2, limit
                           ///< mu_r R F_n (R = r_a r_b / (r_a + r_b), or the disc's radius on a wall;
                           ///< Iwashita & Oda 1998). A disc rests on a slope while tan(slope) <= mu_r.
                           ///< Default 0 (free rolling).
} pl_material_def;

pl_material_def pl_default_material_def(void);

/// Adds a material and returns its index (>= 0), or a negative pl_status.
int pl_world_add_material(pl_world *w, const pl_material_def *def);
/// Finds a material by name; returns its index or -1.
int pl_world_find_material(const pl_world *w, const char *name);
int pl_world_material_count(const pl_world *w);
/// Copy of the material definition (name pointer owned by the world).
pl_material_def pl_world_material(const pl_world *w, int material);

/// Overrides the pair parameters for two materials (the MIMES k_normal(i,j) tables).
/// Any field < 0 keeps the combined default. Combined defaults: kn, ks by series springs
/// (2 k1 k2 / (k1 + k2), equal to k for equal materials), friction and cohesion the smaller.
typedef struct pl_pair_def {
    double kn, ks, friction, cohesion, cn, cs, restitution, rolling;
} pl_pair_def;
pl_pair_def pl_default_pair_def(void); ///< all fields -1 (keep defaults)
/// Replaces the whole override of the pair: fields < 0 in def go back to the combined default
/// (to change one field and keep the others, read the override with pl_world_pair_override,
/// change it and set it back; the Lua world:pair merges this way).
pl_status pl_world_set_pair(pl_world *w, int material_a, int material_b, const pl_pair_def *def);
/// The override stored for the pair (fields -1 where none was given).
pl_status pl_world_pair_override(pl_world *w, int material_a, int material_b, pl_pair_def *out);
/// The parameters contacts of the pair use, after the combination rules and the override:
/// kn, ks, friction, cohesion, rolling, the dashpots cn, cs (used when restitution < 0) and
/// restitution (-1 when the pair uses dashpots).
pl_status pl_world_pair_params(pl_world *w, int material_a, int material_b, pl_pair_def *out);

/* ----------------------------------------------------------------- bodies */

typedef enum pl_shape_type {
    PL_SHAPE_DISC = 0,
    PL_SHAPE_POLYGON = 1, ///< convex polygon (rectangles, n-gons, tessellated superquadrics)
    PL_SHAPE_SEGMENT = 2  ///< wall: a line segment, always kinematic (fixed or prescribed)
} pl_shape_type;

typedef enum pl_motion_type {
    PL_MOTION_DYNAMIC = 0,   ///< moves under forces
    PL_MOTION_FIXED = 1,     ///< never moves
    PL_MOTION_PRESCRIBED = 2 ///< follows a prescribed velocity or motion law (MIMES set_velocity)
} pl_motion_type;

typedef struct pl_body_def {
    pl_shape_type shape;
    pl_motion_type motion;
    int material;           ///< material index; required
    pl_vec2 position;       ///< disc: centre. polygon: ignored (centroid from vertices). segment: ignored.
    double radius;          ///< disc radius, m; > 0
    const pl_vec2 *vertices;///< polygon: world vertices, counter-clockwise, convex (copied)
    int vertex_count;       ///< polygon: 3..PL_MAX_POLY_VERTICES
    pl_vec2 a, b;           ///< segment end points (world)
    double angle;           ///< initial rotation, rad (applied about the centroid)
    pl_vec2 velocity;       ///< initial velocity, m/s
    double omega;           ///< initial angular velocity, rad/s (counter-clockwise positive)
    int user_id;            ///< free id kept for the scene (MIMES ids); default -1
    int fixed_rotation;     ///< 1: a dynamic body that moves but never turns (a guided piston:
                            ///< the guide takes the moment); its angle stays as given
    pl_vec2 guide;          ///< dynamic body: moves only along this direction (normalised; a
                            ///< guided piston, which also never turns); {0, 0}: free
} pl_body_def;

#define PL_MAX_POLY_VERTICES 64

pl_body_def pl_default_body_def(void);

/// Adds a body and returns its index, or a negative pl_status (message in pl_world_last_error).
int pl_world_add_body(pl_world *w, const pl_body_def *def);
int pl_world_body_count(const pl_world *w);

/// Read-only information about one body.
typedef struct pl_body_info {
    pl_shape_type shape;
    pl_motion_type motion;
    int material;
    int user_id;
    pl_vec2 position;      ///< centroid (segment: mid point)
    double angle;
    pl_vec2 velocity;
    double omega;
    double mass;           ///< kg (infinite bodies: 0)
    double inertia;        ///< kg m^2 about the centroid
    double radius;         ///< disc radius; polygon/segment: bounding radius about the centroid
    double area;           ///< m^2 (segment 0)
    int vertex_count;      ///< polygon vertex count (segment 2, disc 0)
    pl_vec2 force;         ///< resultant force of the last step (contacts + fluid + body), N
    double torque;         ///< resultant moment of the last step, N m
} pl_body_info;

pl_status pl_world_body_info(const pl_world *w, int body, pl_body_info *out);
/// Writes the body's outline in world coordinates (polygon vertices, or the 2 segment end
/// points) into out[0..cap) and returns the vertex count (discs: 0).
int pl_world_body_vertices(const pl_world *w, int body, pl_vec2 *out, int cap);

/// Bulk copies for renderers and diagnostics; each returns the number written (<= cap).
int pl_world_copy_positions(const pl_world *w, pl_vec2 *out, int cap);
int pl_world_copy_velocities(const pl_world *w, pl_vec2 *out, int cap);

/// Setters (between steps only).
pl_status pl_world_set_body_position(pl_world *w, int body, pl_vec2 p, double angle);
pl_status pl_world_set_body_velocity(pl_world *w, int body, pl_vec2 v, double omega);
/// Makes the body kinematic with a constant prescribed velocity (MIMES set_velocity).
pl_status pl_world_prescribe_velocity(pl_world *w, int body, pl_vec2 v, double omega);
/// Changes the motion type (fix or release a body).
pl_status pl_world_set_body_motion(pl_world *w, int body, pl_motion_type motion);
/// Guided rotation: on = 1 keeps the body's angle fixed (omega 0) whatever its motion type's
/// forces; the moments on it are taken by the guide and do no work. 0 frees it again.
pl_status pl_world_set_body_fixed_rotation(pl_world *w, int body, int on);
/// Linear guide: the body moves only along dir (its velocity across it is held at zero, the
/// guide takes the force) and never turns; dir = {0, 0} removes the guide (the rotation stays
/// fixed until pl_world_set_body_fixed_rotation(w, body, 0)).
pl_status pl_world_set_body_guide(pl_world *w, int body, pl_vec2 dir);
/// Adds a constant external force (N) and moment (N m) acting every step until changed.
pl_status pl_world_set_body_load(pl_world *w, int body, pl_vec2 force, double moment);
/// Prescribed sinusoidal motion (shaking table): the body's position follows
/// x(t) = x0 + amplitude sin(2 pi frequency (t - t_start)) for t_start <= t <= t_stop and rests
/// outside; x0 is its position when called. amplitude in m, frequency in Hz (> 0).
pl_status pl_world_set_sinusoid(pl_world *w, int body, pl_vec2 amplitude, double frequency, double t_start,
                                double t_stop);
/// Tapers the body's sinusoid (pl_world_set_sinusoid) in and out: the amplitude grows as
/// (1 - cos(pi tau / ramp)) / 2 over the first `ramp` seconds after t_start and shrinks the same
/// way over the last `ramp` seconds before t_stop, so that the table starts and stops without a
/// jump of velocity (a shaking table's ramp). ramp in s, 0 (none, the default) up to half of
/// t_stop - t_start.
pl_status pl_world_set_sinusoid_ramp(pl_world *w, int body, double ramp);
/// Servo-controlled body (seed 003 eqs. 5.11-5.12): moves along the unit direction it pushes in
/// with velocity v = gain (F_target - F_contact) / F_target, limited to |v| <= vmax, so that the
/// contact force it receives holds F_target (N, > 0). gain and vmax in m/s.
pl_status pl_world_set_servo(pl_world *w, int body, pl_vec2 direction, double target_force, double gain,
                             double vmax);
/// Extras of a servo body (call after pl_world_set_servo, which resets them): a drive velocity
/// (m/s) added to the servo's own motion, its component along the servo direction removed (e.g.
/// the horizontal shear of a servo-controlled top wall, seed 003 Fig. 5.19); and with_fluid = 1
/// to count the pore fluid's force on the body (pl_world_fluid_body_force) in the measured force,
/// so that the servo holds the total (contacts + water) force. Used by scenes/soil/simple_shear.lua.
pl_status pl_world_set_servo_drive(pl_world *w, int body, pl_vec2 drive, int with_fluid);
/// Hinged side wall of a simple-shear box (seed 003 §5.4-5.6): the body turns about the fixed
/// pivot so that it stays at the angle atan(dx / height) from its initial direction, where dx is
/// the horizontal displacement of the body `follow` (the top wall, moving under its own law)
/// since this call. With the top wall at a fixed height this gives constant-volume simple shear;
/// with a sinusoidal top wall, cyclic shear. height in m (> 0).
pl_status pl_world_set_hinge(pl_world *w, int body, pl_vec2 pivot, int follow, double height);
/// Sets a new density for a body (mass and inertia recomputed from its outline).
pl_status pl_world_set_body_density(pl_world *w, int body, double density);

/* --------------------------------------------------------------- contacts */

typedef struct pl_contact_info {
    int a, b;              ///< body indices (a < b)
    pl_vec2 point;         ///< contact point (polygons: overlap centroid), m
    pl_vec2 normal;        ///< unit normal from a towards b
    double fn;             ///< normal force magnitude (elastic + damping), N; >= 0 when compressive
    double ft;             ///< tangential force along the tangent t = (-n.y, n.x)... on b, N
    double overlap;        ///< overlap depth (discs) or overlap area / length (polygons), m
} pl_contact_info;

/// Number of touching contacts after the last step.
int pl_world_contact_count(const pl_world *w);
/// Copies touching contacts (deterministic order) and returns how many were written.
int pl_world_copy_contacts(const pl_world *w, pl_contact_info *out, int cap);

/* --------------------------------------------------------------- stepping */

/// Time step in use (computed on first call when automatic).
double pl_world_dt(pl_world *w);

/// Critical time step estimate and what limits it.
typedef struct pl_dt_report {
    double dt;             ///< time step that will be used, s
    double dt_critical;    ///< smallest critical step, s: 2 / omega_max over bodies and materials,
                           ///< reduced by damping (docs/stability.md, "The grain step")
    int limiting_body;     ///< body index giving dt_critical (-1 if none)
    const char *limit_kind;///< "translation", "rotation" (discs' shear spring), "polygon face", or a model's name
    int capped;            ///< 1 when MAX_DT_CR capped the step
    int fixed;             ///< 1 when the scene set dt explicitly
} pl_dt_report;
pl_dt_report pl_world_dt_report(pl_world *w);

/// Advances n steps. Stops early and returns PL_ERR_UNSTABLE (message in last_error) when a
/// guard fires; the world then stays at the last good state for queries.
/// Builds what the queries read without advancing time: every attached model meshes, applies
/// changed boundary conditions and computes its initial field (with FIRST_STEP_STATIC, the
/// static solution the first step will use). Queries never build anything themselves; call
/// this after changing a model's input and before reading its fields (a frame at t = 0).
/// Stepping prepares by itself. Preparing does not change the results of later steps.
pl_status pl_world_prepare(pl_world *w);

/// Sets the writer that receives every file the engine makes (VTK, MIMES geometry and pressure
/// files); NULL removes it (file output is then refused with a message). The Lua binding sets
/// one that keeps files inside the output folder.
void pl_world_set_file_writer(pl_world *w, const pl_file_writer *writer);

/// Models attached to the world (world/models.c registry), in attachment order: their count,
/// short name ("darcy", "hydrostatic"), one-line description, and the CPU seconds they spent so
/// far with the number of their updates (for `porelab info`).
int pl_world_model_count(const pl_world *w);
/// A field of the attached models sampled on linear triangles for drawing, from the first
/// model that has it: quantity is a pl_fluid_node_field (porelab/fluid.h: PL_FLUID_PRESSURE,
/// ...). A P2, boundary-element or analytic field arrives as nodes, linear sub-triangles and
/// one value per node, so the renderer needs no change for a new model. Returns the node count
/// (0: none) and sets *nt; fills xy, tri (3 node indices per triangle) and value only when they
/// fit in cap_nodes / cap_tris (call with 0 caps to size the buffers). Read-only.
int pl_world_field_sample(const pl_world *w, int quantity, pl_vec2 *xy, int32_t *tri, double *value, int cap_nodes,
                          int cap_tris, int *nt);
const char *pl_world_model_name(const pl_world *w, int k);
const char *pl_world_model_label(const pl_world *w, int k);
double pl_world_model_cost(const pl_world *w, int k, long *calls);

pl_status pl_world_step(pl_world *w, int n);
double pl_world_time(const pl_world *w);
int64_t pl_world_step_count(const pl_world *w);

/* ------------------------------------------------------------ diagnostics */

typedef struct pl_energy {
    double kinetic;        ///< translational + rotational, J
    double gravitational;  ///< m g . (-y) relative to y = 0, J
    double elastic;        ///< stored in contact springs, J
    double damped;         ///< dissipated by dashpots and global damping since t = 0, J
    double friction;       ///< dissipated by Coulomb sliding since t = 0, J
    double fracture;       ///< released by bond softening, damage and breaking since t = 0, J (porelab/bonds.h)
    double external;       ///< work done on the system by prescribed bodies, loads and fluid, J
    double balance;        ///< kinetic + gravitational + elastic + damped + friction + fracture - external - initial
} pl_energy;
pl_energy pl_world_energy(const pl_world *w);

/// Total linear momentum of dynamic bodies, kg m/s.
pl_vec2 pl_world_momentum(const pl_world *w);

/// Average stress tensor of the grains whose centroids lie in the rectangle [lo, hi]:
/// sigma_ij = (1/A) sum over their contacts of f_i l_j (branch vector l from the centroid to the
/// contact point, f the contact force on the body), A the rectangle's area; compression
/// positive. out = {s_xx, s_xy, s_yx, s_yy} in Pa (N/m per unit thickness over m^2... i.e. Pa x m).
/// Returns the number of bodies counted.
int pl_world_stress_in_region(const pl_world *w, pl_vec2 lo, pl_vec2 hi, double out[4]);

/// Mean coordination number of dynamic bodies: 2 x (contacts between dynamic bodies) + contacts
/// with walls or fixed bodies, divided by the number of dynamic bodies.
double pl_world_coordination_number(const pl_world *w);

/// Writes bodies (polygons as cells with velocity, angle, material, id) and contacts (lines
/// with normal and tangential force) as VTK XML unstructured grids: PREFIX_bodies.vtu and
/// PREFIX_contacts.vtu. Returns PL_OK or PL_ERR_IO with a message.
pl_status pl_world_write_vtk(const pl_world *w, const char *prefix);

/// 64-bit hash of the full dynamic state (positions, velocities, contact history, time; with a
/// pore fluid also its heads, conductivities, solid areas, consolidation state, reused forces
/// and update phase).
uint64_t pl_world_state_hash(const pl_world *w);

/// Axis-aligned bounds of all bodies (for cameras).
void pl_world_bounds(const pl_world *w, pl_vec2 *lo, pl_vec2 *hi);

/* -------------------------------------------------------------- snapshots */

/// A copy of the full state of a world between steps: bodies, motion laws, contacts with
/// their history, energy tallies, parameters and flags, and the pore fluid's state (fields,
/// caches that decide later results, boundary lines, the fluid update's phase; docs/fluid.md
/// §8). Restoring it and stepping gives bit-identical results to the original run (rewind in
/// the live window, restarts).
typedef struct pl_snapshot pl_snapshot;

/// Takes a snapshot; NULL when out of memory (the message says so).
pl_snapshot *pl_world_snapshot(pl_world *w);
/// Restores a snapshot into the world it was taken from (same bodies, vertices and materials;
/// a snapshot of a different world is refused with a message).
pl_status pl_world_restore(pl_world *w, const pl_snapshot *s);
/// Time of the snapshot, s, and its size in bytes.
double pl_snapshot_time(const pl_snapshot *s);
size_t pl_snapshot_bytes(const pl_snapshot *s);
void pl_snapshot_destroy(pl_snapshot **s);

/* ------------------------------------------------------------ state files */

/// The whole state of a world as bytes (a restart file): a header with a magic number, the
/// format version and a layout hash, then one checksummed section for the grains and one per
/// attached model (the layout: engine/src/world/snapshot_file.c, docs/user-guide.md "Restart
/// files"). The engine opens no file: the host writes the bytes and reads them back.
/// Loading them into a world built by the same scene and stepping on gives the bit-identical
/// state hash of the run that never stopped.
///
/// Writes the state into a new buffer (*bytes, *len; free it with pl_state_free). PL_ERR_NOMEM
/// when out of memory; PL_ERR_NOT_BUILT when an attached model cannot save its state.
pl_status pl_world_save_state(const pl_world *w, void **bytes, size_t *len);
/// Loads bytes written by pl_world_save_state into w, a world built by the same scene (same
/// bodies, outline vertices and materials, as pl_world_restore requires). A truncated or
/// damaged file gives PL_ERR_IO, a file of another format version or layout, or of another
/// world, PL_ERR_STATE, with a message; nothing of w changes then (the message says so when a
/// model fails after the checks: build the world again).
pl_status pl_world_load_state(pl_world *w, const void *bytes, size_t len);
void pl_state_free(void *bytes);

/// What the header of a state file says (checked: magic, version, header checksum, layout).
typedef struct pl_state_info {
    int version;
    double time;     ///< s
    int64_t step;
    int bodies, models;
} pl_state_info;
/// PL_OK and *out, or the status of pl_world_load_state with the message in err.
pl_status pl_state_info_of(const void *bytes, size_t len, pl_state_info *out, char *err, size_t errlen);

/* ------------------------------------------------------------------ flags */

/// Flags with the MIMES names (seed 000 Appendix B/C): TIMESTEPS, MAX_DT_CR, GRAVITY_Y, ...
/// Unknown names give PL_ERR_UNKNOWN with a message listing the valid flags; out-of-range
/// values PL_ERR_ARG naming the range; flags of features not built yet PL_ERR_NOT_BUILT.
pl_status pl_world_set_flag(pl_world *w, const char *name, double value);
pl_status pl_world_get_flag(const pl_world *w, const char *name, double *value);

typedef struct pl_flag_info {
    const char *name;
    const char *unit;
    const char *description;
    double min, max;       ///< valid range (inclusive)
    int built;             ///< 0 when the feature is recognised but not built yet
} pl_flag_info;
int pl_flag_count(void);
const pl_flag_info *pl_flag_at(int i);

#ifdef __cplusplus
}
#endif
#endif
