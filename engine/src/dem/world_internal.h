/* Private layout of the world: the grain store (bodies as structure-of-arrays for the hot loops,
 * materials, neighbour pairs with their contact history, time, energy tallies) and, at its end,
 * the fields of the world layer (engine/src/world: attached models, flags). The grain engine
 * (dem/) and the world layer include this; models never do (they see world/model.h). */
#ifndef PL_WORLD_INTERNAL_H
#define PL_WORLD_INTERNAL_H

#include "porelab/world.h"
#include <stdint.h>

#define PL_ERR_LEN 2048

/* Material-pair parameters after combination rules and overrides. */
typedef struct pl_pair_params {
    double kn, ks;      /* N/m */
    double inv_ks;      /* 1/ks (0 when ks = 0), for the shear spring energy */
    double friction;    /* mu */
    double rolling;     /* rolling resistance mu_r (0: free rolling) */
    double cohesion;    /* N */
    double cn, cs;      /* N s/m, used when restitution < 0 */
    double restitution; /* < 0: use cn/cs; else damping ratio from e with the pair's mass */
    double zeta;        /* damping ratio from restitution (precomputed), or -1 */
} pl_pair_params;

typedef struct pl_material {
    pl_material_def def;
    char name[64];
} pl_material;

/* Pair kinds for the narrow phase. Body a always has the lower shape code or index. */
enum {
    PL_PAIR_DISC_DISC = 0,
    PL_PAIR_DISC_SEGMENT = 1,
    PL_PAIR_POLY_DISC = 2,    /* a polygon, b disc (or a disc, b polygon: see flags) */
    PL_PAIR_POLY_POLY = 3,
    PL_PAIR_POLY_SEGMENT = 4,
    PL_PAIR_NONE = 255        /* never interacts (e.g. two kinematic bodies) */
};

/* One neighbour pair with its persistent contact history. */
typedef struct pl_pair {
    int32_t a, b;         /* body indices, a < b */
    uint8_t kind;         /* PL_PAIR_* */
    uint8_t touching;     /* 1 when in contact after the last force evaluation */
    uint8_t swapped;      /* 1 when the shape roles are swapped relative to a/b (poly-disc) */
    uint8_t pad;
    int32_t params;       /* index into world->pair_params (material pair) */
    double cn, cs;        /* dashpots of this pair (from restitution and the pair's masses), N s/m */
    double fs;            /* shear (tangential) spring force, N (history) */
    double mr;            /* rolling spring moment on b, N m (history; discs with rolling resistance) */
    double fn;            /* normal force of the last evaluation, N (elastic + damping) */
    double ft;            /* tangential force of the last evaluation, N (on b along t) */
    double overlap;       /* overlap depth, m (polygons: area / contact length) */
    double area_prev;     /* polygons: overlap area at the previous step, m^2 (history) */
    double elastic;       /* elastic energy stored in the contact springs, J */
    pl_vec2 point;        /* contact point */
    pl_vec2 normal;       /* unit normal a -> b */
} pl_pair;

/* Boundary motion laws of prescribed bodies. */
typedef enum pl_motion_law {
    PL_LAW_CONSTANT = 0,  /* constant velocity (MIMES set_velocity) */
    PL_LAW_SINUSOID = 1,  /* x(t) = x0 + e(t) A sin(2 pi f (t - t0)) between t0 and t1, e the ramp envelope */
    PL_LAW_SERVO = 2,     /* servo wall holding a force (seed 003 eqs. 5.11-5.12) */
    PL_LAW_HINGE = 3      /* side wall of a simple-shear box turning about a pivot */
} pl_motion_law;

typedef struct pl_motion {
    int law;
    pl_vec2 velocity; double omega;      /* constant law */
    pl_vec2 amplitude; double frequency; /* sinusoid: displacement amplitude (m), Hz */
    double t_start, t_stop;
    double ramp;                         /* sinusoid: raised-cosine taper in and out, s (0: none) */
    pl_vec2 servo_dir; double servo_target; double servo_gain; double servo_vmax;
    pl_vec2 servo_drive; int servo_fluid;   /* servo extras (servo_drive.c): drive velocity, fluid force counted */
    pl_vec2 pivot, rel0; double angle0; int follow; double follow_x0, height; /* hinge */
    int fixed_rotation;                  /* any body: the angle is held (guided piston; body.c) */
    pl_vec2 guide;                       /* dynamic body: unit direction it may move along, or {0, 0} */
} pl_motion;

/* Acceleration (m/s^2) of a prescribed body's law at time t: the sinusoid's (with its ramp)
   in closed form, 0 for a constant velocity; returns 0 for laws without one (servo, hinge). */
int pl__law_acceleration(const pl_motion *m, double t, pl_vec2 *acc);

/* Per-body sums of the dashpot part (d*) and the tangential-spring part (s*) of the contact
   forces and moments of one step, for the exact energy tallies (integrate.c). */
typedef struct pl_tally {
    double dfx, dfy, dm, sfx, sfy, sm;
} pl_tally;

#include "dem/rock_internal.h" /* bonds, temperature and wear (bond.c, heat.c) */

struct pl_world {
    pl_world_def def;
    char *error;                  /* PL_ERR_LEN bytes: the last error message. A buffer of its own, so
                                     that a read-only query can report through a const world */

    /* materials */
    pl_material *materials;
    int material_count, material_cap;
    pl_pair_params *pair_params;   /* material_count^2, symmetric */
    pl_pair_def *pair_overrides;   /* material_count^2 */
    int pair_params_dirty;

    /* bodies (structure of arrays) */
    int n, cap;
    pl_vec2 *pos, *vel, *force;
    double *angle, *omega, *torque;
    double *mass, *inv_mass, *inertia, *inv_inertia;
    double *radius;               /* disc radius or bounding radius about the centroid */
    double *area;
    uint8_t *shape, *motion;
    int32_t *material, *user_id;
    pl_motion *law;               /* per body (prescribed bodies) */
    pl_vec2 *load; double *load_moment; /* constant external loads */
    int any_load;                 /* 1 once any body has a load */
    /* parts of the contact force that dissipate or store energy, for exact energy tallies:
       dashpot forces, and the tangential (Coulomb spring) forces, per body and step */
    pl_tally *tally;
    double e_shear, e_shear_prev;  /* energy in the tangential springs now / one step ago */
    double e_elastic;              /* all elastic energy in contacts at the last evaluation */
    int nonfinite_body;            /* set by the integrator: first body with a non-finite state, or -1 */
    pl_vec2 *x0;                  /* reference position for sinusoid laws */
    /* polygon and segment outlines: local vertices relative to the centroid at angle 0 */
    int32_t *vert_offset, *vert_count;
    pl_vec2 *verts_local;
    int verts_n, verts_cap;
    pl_vec2 *verts_world;         /* updated each step for polygons/segments (same indexing) */

    /* neighbour list */
    pl_pair *pairs, *pairs_scratch;
    struct pl_par *par;           /* threaded contact loop: slots and body lists (parallel.c) */
    int pair_n, pair_cap, pair_scratch_cap;
    pl_vec2 *pos_at_build;        /* positions when the list was built */
    double *angle_at_build;
    double skin;
    int need_rebuild;
    int64_t rebuilds;
    /* broadphase: bodies larger than a few typical grains (walls, blocks) are kept out of
       the grid and tested against every body */
    uint8_t *is_large;
    int32_t *large_list;
    int large_n, class_cap;
    double cell_size;
    int32_t *cand;               /* candidate partners of one body during a rebuild */
    int cand_cap;
    /* broadphase grid scratch */
    int32_t *cell_start, *cell_items, *body_cell, *cursor;
    int cell_cap, cell_items_cap, body_cell_cap, cursor_cap;
    int classify_dirty;           /* bodies added or changed motion: re-split grid/large */
    /* the grid of the last build (dem/box_query.c reads it): origin, cell, size, body count */
    double grid_lo_x, grid_lo_y, grid_h;
    int grid_nx, grid_ny, grid_n;

    /* time */
    double time;
    int64_t step;
    double dt;                    /* 0 until computed */
    pl_dt_report dt_report;

    /* energy tallies (J) */
    double e_damped, e_friction, e_external, e_initial;
    double e_ext_half;            /* the last step's load work over its second half step,
                                     F_n . v_{n+1/2} dt / 2: e_external runs half a step past the
                                     reported time t_n (dem/integrate.c, dem/diagnostics.c) */
    double e_models;              /* energy the attached models hold (world/models.c), for the surge guard */
    int energy_initialised;
    double ke_prev;

    /* guard bookkeeping from the last force evaluation */
    double worst_overlap_ratio;   /* overlap / smaller radius */
    int worst_a, worst_b;
    double e_supply0;             /* KE + elastic at the reference time (energy-surge guard) */
    double ext0;                  /* e_external at the reference time */
    double pe0;                   /* gravitational energy at t = 0 */

    /* external-force column: loads of the attached models on each body for this step, filled
       by the world before the motion laws run (world/world.c); servo walls read it */
    pl_vec2 *ext_force;
    double *ext_moment;
    uint8_t *wants_load;          /* per body: 1 when the world uses its external load */
    int ext_cap;

    /* bonds, heat and wear (dem/bond.c, dem/heat.c; porelab/bonds.h). The per-body columns
       are allocated with the others; bond-free, cold worlds never read them in the step */
    pl_bond *bonds;               /* every bond ever made, intact and broken, in creation order */
    int bond_n, bond_cap, bond_intact;
    pl_bond_law *bond_laws;       /* laws by material pair */
    int bond_law_n, bond_law_cap;
    pl_thermal *thermal;          /* per material (thermal_n <= material_count) */
    int thermal_n, thermal_cap;
    double *temperature, *heat, *wear, *removed_at; /* K, J, m^3/m, s (-1: present) */
    uint8_t *temp_hold, *removed;
    double *heat_step;            /* scratch of the heat pass: 2 per body (heat of the step, sum of H) */
    int heat_on, wear_on, wear_remove, removed_n;
    double heat_fraction, heat_t0; /* alpha; start temperature, K */
    double e_bond;                /* energy stored in intact bonds at the last evaluation, J */
    double e_fracture;            /* released by bond softening, damage and breaking, J */

    /* ---- world layer (engine/src/world only) ---- */
    /* flags (MIMES names), values indexed like the flag table (world/flags.c) */
    double *flag_values;
    /* the host's file writer: every file the engine makes goes through it (porelab/core.h) */
    pl_file_writer writer;
    /* attached models in attachment order (world/models.c) */
    struct pl_model_slot *models;
    int model_n, model_cap;
};

/* Error helper: formats into w->error and returns status. */
pl_status pl__error(const pl_world *w, pl_status s, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Pair parameters lookup. */
static inline const pl_pair_params *pl__pair_params(const pl_world *w, int ma, int mb) {
    return &w->pair_params[ma * w->material_count + mb];
}
void pl__update_pair_params(pl_world *w);

/* Body helpers */
void pl__update_world_vertices(pl_world *w, int body);
int pl__ensure_body_capacity(pl_world *w, int need);

/* Neighbour list */
pl_status pl__neighbor_update(pl_world *w);
/* Set-up check: many bodies piled on one spot (dem/crowding.c) */
pl_status pl__check_crowding(pl_world *w);
void pl__neighbor_mark_dirty(pl_world *w);

/* Forces (narrow phase). Polygon laws may raise w->worst_overlap_ratio themselves. */
void pl__compute_contact_forces(pl_world *w, double dt);
void pl__parallel_free(pl_world *w); /* parallel.c */

/* Integration */
void pl__integrate(pl_world *w, double dt);
void pl__apply_motion_laws(pl_world *w, double t, double dt);

/* Time step */
void pl__compute_dt(pl_world *w);
/* Largest eigenvalue of a symmetric 3 x 3 matrix (timestep.c: the polygon face mode). */
double pl__sym3_max_eig(double a11, double a22, double a33, double a12, double a13, double a23);

/* Bonds, heat and wear (bond.c, heat.c): bond forces after the contacts; heat and wear of
   the step's contacts; removal of worn grains after the step; the bonds' stiffest body for
   the critical step (lowers *dt and names the body and kind when it is smaller) */
void pl__bond_forces(pl_world *w, double dt);
double pl__bond_energy(const pl_world *w);
void pl__bond_dt_limit(const pl_world *w, double *dt, int *body, const char **kind);
pl_status pl__heat_wear(pl_world *w, double dt);
void pl__wear_remove(pl_world *w);

/* Guards: returns PL_OK or PL_ERR_UNSTABLE with message */
pl_status pl__check_guards(pl_world *w);

/* Energy */
double pl__kinetic_energy(const pl_world *w);
double pl__elastic_energy(const pl_world *w);
/* Work done on the system up to the reported time t_n (e_external less the last half step). */
double pl__external_work(const pl_world *w);
double pl__gravitational_energy(const pl_world *w);


/* Velocity of a servo-controlled body for this step (servo_drive.c). */
pl_vec2 pl__servo_velocity(pl_world *w, int i);
#endif
