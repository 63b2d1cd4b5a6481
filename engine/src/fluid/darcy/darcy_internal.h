/* Private layout of the Darcy pore-fluid model (seed 000, ch. 3). The fluid model does not
 * depend on the world layout except in fluid_world.c / fluid_hook.c: mesh, assembly, solver,
 * porosity and force code work on the plain structs below so that unit tests can drive them
 * without a world. */
#ifndef PL_FLUID_INTERNAL_H
#define PL_FLUID_INTERNAL_H

#include "porelab/core.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include "mesh/mesh.h"
#include <cholmod.h>
#include <stdint.h>

#define PL_FL_MSG 512
#define PL_FL_PI 3.14159265358979323846

/* -------------------------------------------------------------------- input */



enum { PL_FL_LINE_HEAD = 0, PL_FL_LINE_FLUX = 1 };

typedef struct pl_fl_line {
    pl_vec2 a, b;
    double value;       /* pressure head (m) or inflow flux (m/s) */
    int kind;           /* PL_FL_LINE_* */
} pl_fl_line;

/* ------------------------------------------------------------------- system */

typedef struct pl_fl_system {
    /* full symmetric matrix pattern over all nodes (compressed columns, both triangles) */
    int32_t *colp, *rowi;
    int nnz;
    double *kval;       /* conductance (admittance, eq. 3.11) */
    double *mval;       /* mass: consistent or lumped (diagonal only) */
    double *mlump;      /* nn lumped mass (A/3 per triangle), for the explicit method */
    int32_t *emap;      /* 9 * ne positions of element entries in the full pattern */
    int32_t *diag;      /* nn positions of diagonal entries */
    /* boundary conditions */
    uint8_t *is_dir;    /* nn */
    double *dir_head;   /* nn prescribed total head (valid where is_dir) */
    int32_t *dir_line;  /* nn: line index that prescribed the node, or -1 */
    double *fload;      /* nn nodal inflow from flux lines (m^2/s) */
    int32_t *free_index;/* nn: index among free nodes, or -1 */
    int32_t *free_node; /* nf */
    int nf;
    /* reduced SPD matrix (upper triangle) for CHOLMOD and map full -> reduced */
    cholmod_common cc;
    int cc_started;
    cholmod_sparse *A;
    int32_t *amap;      /* nnz: index into A->x or -1 */
    cholmod_factor *L;
    cholmod_dense *rhs, *sol, *wy, *we;
    int analysed, factorised;
    double fact_c, fact_theta; /* coefficients of the factorised matrix (c M + theta K) */
    double *work;       /* nn */
} pl_fl_system;

/* ---------------------------------------------------------------- the model */

/* Parameters resolved from the world flags before each update. */
typedef struct pl_fl_params {
    int on;
    int first_step_static;
    int perm_mode;          /* 0 uniform, 1 from porosity, 2 per-element user values */
    double perm_low, perm_high; /* m/s (or m^2 when perm_units = 1) */
    int solve_every;
    double density;         /* kg/m^3 */
    double storage;         /* specific storage S, 1/m */
    double viscosity;       /* Pa s */
    int perm_units;         /* 0 hydraulic conductivity m/s, 1 intrinsic permeability m^2 */
    int method;             /* 0 backward Euler, 1 Crank-Nicolson, 2 explicit, 3 static */
    int mass_consistent;    /* 0 lumped, 1 consistent */
    int porosity_method;    /* 0 exact clipping, 1 pixellation */
    int pixels;             /* pixels along the longer side of an element's box */
    int porosity_map;       /* 0 areal (2D), 1 2D->3D mapping of DESIGN §3 */
    int kc_mode;            /* 0 interpolate between low and high, 1 clamp C1 e^3/(1+e) */
    double kc_c1;
    int drag;               /* 1 add interphase drag */
    double explicit_safety; /* fraction of the stability limit used by the explicit method */
    pl_vec2 gravity;        /* m/s^2 */
    double g;               /* |gravity| or standard gravity when zero */
    pl_vec2 up;             /* unit vector opposite to gravity (or +y) */
    int geometry_flag, pressures_flag;
    /* pore pressure from skeleton volume change (fluid_consolidation.c, docs/soil.md) */
    int force_reuse;        /* 1: fluid forces computed at fluid updates and reused in between */
    int consolidation;      /* 1: (S + n rho g / K_f) dh/dt - div(D grad h) = -div(v_s) */
    double bulk_modulus;    /* K_f, Pa; <= 0: incompressible fluid */
    int stagger_check;      /* FLUID_STAGGER_CHECK (darcy_stagger.c) */
    int porosity_every;     /* grain steps between porosity updates; 0: every fluid update */
} pl_fl_params;

/* Candidate (body, element) pair with the solid area of the body inside the element. A piece
   with outside = 1 is instead the part of a body pressed into a wall at the mesh's edge that lies
   beyond the mesh boundary, folded into the boundary element it crosses (darcy_porosity.c,
   docs/fluid.md §6.1): the fluid treats it as if the mesh went on, so that the grain's buoyancy,
   drag and skeleton flux are those of its whole area. */
typedef struct pl_fl_cover {
    int32_t body, elem;
    double area;
    int32_t outside;
} pl_fl_cover;

/* A body whose part beyond the mesh boundary reaches no deeper than this fraction of its
   thickness across that boundary is a grain pressed into a wall at the mesh's edge (a contact
   overlap: its outside part is folded into the mesh); a body reaching deeper crosses the
   boundary as a solid (piston, lid, wall slab: the mesh boundary is its seal, p = 0 beyond). */
#define PL_FL_EDGE_SLIVER 0.1
/* At most this many boundary elements share the part of one such grain beyond the boundary. */
#define PL_FL_EDGE_MAX 16

/* Geometry of the bodies as the fluid sees them (copied or pointed from the world). */
typedef struct pl_fl_bodies {
    int n;
    const uint8_t *shape;       /* pl_shape_type */
    const pl_vec2 *pos;         /* centroid */
    const double *radius;       /* disc radius / bounding radius */
    const int32_t *vert_offset, *vert_count;
    const pl_vec2 *verts;       /* world vertices */
} pl_fl_bodies;

struct pl_fluid {
    /* input */
    pl_mesh_quad *quads; int nq, qcap;
    pl_fl_line *lines; int nl, lcap;
    int mesh_dirty;             /* quads changed: remesh */
    int bc_dirty;               /* lines changed: re-apply, re-analyse */
    /* mesh and system */
    pl_mesh mesh;
    pl_fl_system sys;
    int built;
    /* state */
    double *head;               /* nn total head h = p/(rho g) + z, m */
    double *head_prev;
    double *perm;               /* ne isotropic conductivity (before anisotropy), m/s */
    double *perm_user;          /* ne user values (perm_mode 2) or NULL */
    double *perm_assembled;     /* ne conductivity in the assembled matrix */
    double *solid;              /* ne solid area of each element, m^2 */
    double *voidr;              /* ne void ratio after clamping (2D areal) */
    double *porosity;           /* ne porosity used for permeability (after mapping) */
    double *grad;               /* 2 * ne total-head gradient */
    pl_fl_cover *cover; int ncover, cover_cap;
    int32_t *stamp; int32_t stamp_gen; /* ne: last body generation that met the element */
    int32_t *pix_cnt, *pix_fill, *pix_pair; int pix_cap; /* pixellation scratch */
    int32_t *body_cover_start;  /* n+1 per body ranges into cover (sorted by body) */
    int cover_bodies;           /* bodies known to the last porosity update */
    double *cover_xyr;          /* 3 * cover_bodies: x, y, radius of each body at the last
                                   porosity update: its covers are current while these match */
    int body_cap;
    int k_dirty;                /* permeabilities changed since the last assembly */
    int have_solution;          /* head holds a solution for the current system */
    int static_valid;           /* head is the static solution of the current matrix and BCs */
    int initialised;            /* first fluid step done */
    int refresh_pending;        /* BCs rebuilt by a query: the next step still makes the update
                                   that a change of boundary conditions asks for */
    int64_t steps_since;        /* grain steps since the last solve */
    int64_t geom_since;         /* grain steps since the last porosity update (FLUID_POROSITY_TIMESTEPS) */
    double time_since;          /* time since the last solve, s */
    double time;                /* fluid time, s */
    double out_time;            /* time written with the pressures (end of the fluid step), s */
    pl_fl_params par;
    pl_fl_params assembled_par; /* parameters used for the assembled matrix */
    /* outputs */
    char geometry_file[256], pressures_file[256];
    int geometry_written;
    int pressures_started;
    pl_fluid_stats stats;
    char msg[PL_FL_MSG];
    /* consolidation coupling (fluid_consolidation.c): all NULL / 0 while FLUID_CONSOLIDATION = 0 */
    double *src;                /* nn volume source -div(v_s) per node (weak form), m^2/s */
    double *stor;               /* ne specific storage per element S + n rho g / K_f, 1/m */
    double *stor_assembled;     /* ne storage in the assembled mass matrix */
    pl_vec2 *ref_pos;           /* body centroids at the last fluid update, m */
    double *ref_ang;            /* body angles at the last fluid update, rad */
    int ref_n, ref_cap;         /* bodies with a reference position */
    double *vbar;               /* 2 ne mean skeleton velocity per element (last update), m/s */
    int32_t *elem_bedge;        /* 3 ne: boundary edges of each element (-1: none) */
    double *bchord;             /* nbe length of each boundary edge covered by solids, m */
    int src_active;             /* src holds a nonzero source for the next solve */
    double t_source;            /* time spent computing the source, s */
    double last_src_abs;        /* sum |src| of the last update, m^2/s */
    double *fcache;             /* 3 per body: fluid force x, y and moment of the last update */
    /* accelerating frame (pl_world_fluid_set_frame): the pore water shares the acceleration of a
       prescribed body, Darcy's law q = -D (grad h + a/g) (u-p approximation) */
    int frame_body_plus1;       /* that body's index + 1; 0: none */
    pl_vec2 frame_acc;          /* its acceleration at the last update, m/s^2 */
    int fcache_n, fcache_cap;   /* bodies with a cached force */
};

/* assembly and solution (fluid_system.c, fluid_solve.c) */
pl_status pl_fl_system_build(struct pl_fluid *f);         /* pattern, BCs, analysis */
void pl_fl_system_free(pl_fl_system *s);
void pl_fl_assemble(struct pl_fluid *f);                  /* values from f->perm */
pl_status pl_fl_solve_static(struct pl_fluid *f);
pl_status pl_fl_advance(struct pl_fluid *f, double dt);   /* transient step of length dt */
void pl_fl_apply_dirichlet(struct pl_fluid *f, double *h);
double pl_fl_explicit_dt_limit(const struct pl_fluid *f);
/* the staggering limit of the undrained coupling (darcy_stagger.c) */
struct pl_world;
struct pl_grain_view;
pl_status pl__fluid_stagger_check(struct pl_world *w, struct pl_fluid *f, const struct pl_grain_view *g,
                                  double dt);
/* Net inflow (m^2/s per unit thickness) through the nodes a head line prescribes. */
double pl_fl_line_inflow(const struct pl_fluid *f, int line);

/* Adds the frame load -int grad N_i . D a/g dA of an accelerating frame to r (nn). */
void pl_fl_add_frame_load(const struct pl_fluid *f, double *r);

/* porosity and permeability (fluid_porosity.c) */
pl_status pl_fl_update_porosity(struct pl_fluid *f, const pl_fl_bodies *b);
void pl_fl_update_permeability(struct pl_fluid *f);
/* Grain pressed into a wall at the mesh's edge (docs/fluid.md §6.1): the boundary elements whose
   boundary edges the body (disc c, r when v is NULL, else convex polygon v, n, counter-clockwise)
   crosses, and the body's length on those edges (wt), at most cap of them; returns their number,
   0 when it crosses no boundary edge or crosses one deeper than PL_FL_EDGE_SLIVER of its
   thickness (a solid: piston, lid, wall slab). */
int pl_fl_edge_elements(const pl_mesh *m, pl_vec2 c, double r, const pl_vec2 *v, int n, int32_t *elem, double *wt,
                        int cap);
double pl_fl_tri_disc_area(const pl_vec2 t[3], pl_vec2 c, double r);
double pl_fl_tri_poly_area(const pl_vec2 t[3], const pl_vec2 *v, int n);
double pl_fl_kc_map(const pl_fl_params *p, double e);
double pl_fl_porosity_3d(double n2d);

/* fields (fluid_field.c) */
double pl_fl_z(const struct pl_fluid *f, pl_vec2 p);     /* elevation along -gravity */
/* a/g of the accelerating frame (zero without one): Darcy's flux is q = -D (grad h + a/g) */
static inline pl_vec2 pl_fl_frame_gradient(const struct pl_fluid *f) {
    return (pl_vec2){f->frame_acc.x / f->par.g, f->frame_acc.y / f->par.g};
}
double pl_fl_node_pressure(const struct pl_fluid *f, int node);
void pl_fl_update_gradients(struct pl_fluid *f);
/* Pressure (Pa) at p; returns the element or -1 outside (pressure 0 then). */
int pl_fl_pressure_at(const struct pl_fluid *f, pl_vec2 p, double *pressure, double *head);

/* forces (fluid_forces.c) */
void pl_fl_polygon_force(const struct pl_fluid *f, const pl_vec2 *v, int n, pl_vec2 c,
                         pl_vec2 *force, double *moment);
void pl_fl_disc_force(const struct pl_fluid *f, pl_vec2 c, double r, pl_vec2 *force);
/* Pressure force and moment plus drag on body i; adds to *force, *moment. */
void pl_fl_body_force(const struct pl_fluid *f, const pl_fl_bodies *b, int i,
                      pl_vec2 *force, double *moment);

/* consolidation (fluid_consolidation.c) */
/* Allocates src/stor for the mesh (idempotent). */
pl_status pl_fl_consolidation_alloc(struct pl_fluid *f);
void pl_fl_consolidation_free(struct pl_fluid *f);
/* Per-element specific storage S_e = FLUID_STORAGE + n_e rho_f g / K_f from the current solid
   areas; marks the matrix dirty when a value changed. */
void pl_fl_consolidation_storage(struct pl_fluid *f);
/* Nodal source from the grain displacements since the reference (covers must be current);
   dt > 0 the fluid step. Moves the reference to the current positions. */
pl_status pl_fl_consolidation_source(struct pl_fluid *f, const pl_fl_bodies *b, const double *angle, double dt);
/* Reference positions := current, source := 0. */
pl_status pl_fl_consolidation_reset(struct pl_fluid *f, const pl_fl_bodies *b, const double *angle);
/* Storage coefficient used for the time term: 1 when the storage is per element (folded into
   the mass matrix), FLUID_STORAGE otherwise. */
double pl_fl_storage_factor(const struct pl_fluid *f);

/* default parameters (used when no world flag table is available) */
pl_fl_params pl_fl_default_params(void);

/* timer */
double pl_fl_now(void);

/* Cyrus-Beck: narrows [*t0, *t1] to the part of the segment a + t d inside the convex
   counter-clockwise polygon v (n vertices). Returns 0 when the segment misses it (parallel and
   outside an edge). Shared by the porosity cut and the consolidation source. */
static inline int pl_fl_clip_segment_convex(pl_vec2 a, pl_vec2 d, const pl_vec2 *v, int n, double *t0, double *t1) {
    for (int k = 0; k < n && *t0 < *t1; k++) {
        pl_vec2 p = v[k], q = v[(k + 1) % n];
        pl_vec2 e = {q.x - p.x, q.y - p.y};
        double sa = e.x * (a.y - p.y) - e.y * (a.x - p.x); /* >= 0 inside */
        double sd = e.x * d.y - e.y * d.x;
        if (sd == 0) {
            if (sa < 0) return 0;
        } else {
            double t = -sa / sd;
            if (sd > 0) { if (t > *t0) *t0 = t; }
            else if (t < *t1) *t1 = t;
        }
    }
    return 1;
}

#endif
