/* The fluid model seen from the world: public API of porelab/fluid.h (quads, lines, solves,
 * queries) and the per-step hook (fluid_hook.h) that couples the Darcy field to the grains
 * (seed 000 §3.3, Fig. 3-1; DESIGN §2 step 2). */
#include "core/alloc.h"
#include "world/model.h"
#include "fluid/darcy/darcy_internal.h"
#include "fluid/darcy/darcy_world.h"
#include "fluid/darcy/darcy_model.h"
#include "porelab/darcy.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


pl_fl_params pl_fl_default_params(void) {
    pl_fl_params p;
    memset(&p, 0, sizeof p);
    p.on = 1;
    p.perm_low = 0.001;
    p.perm_high = 5.0;
    p.solve_every = 1;
    p.density = 1000;
    p.storage = 1e-4;
    p.viscosity = 1e-3;
    p.explicit_safety = 0.9;
    p.pixels = 16;
    p.porosity_map = 1;
    p.kc_c1 = 1e-2;
    p.drag = 1;
    p.gravity = (pl_vec2){0, -9.81};
    p.g = 9.81;
    p.up = (pl_vec2){0, 1};
    return p;
}

/* The resolved parameters of one update: the typed def (one storage with the MIMES flags) plus
   gravity. Read by row offset, never by name. */
void pl__fluid_read_params(pl_world *w, pl_fl_params *p) {
    pl_darcy_def d;
    pl_world_get_darcy(w, &d);
    *p = pl_fl_default_params();
    p->on = d.on;
    p->first_step_static = d.first_step_static;
    p->perm_mode = d.perm_mode;
    p->perm_low = d.perm_low;
    p->perm_high = d.perm_high;
    p->solve_every = d.solve_every;
    p->density = d.density;
    p->storage = d.storage;
    p->viscosity = d.viscosity;
    p->perm_units = d.perm_units;
    p->method = d.method;
    p->mass_consistent = d.mass_consistent;
    p->explicit_safety = d.explicit_safety;
    p->porosity_method = d.porosity_method;
    p->pixels = d.pixels;
    p->porosity_map = d.porosity_map;
    p->kc_mode = d.kc_mode;
    p->kc_c1 = d.kc_c1;
    p->drag = d.drag;
    p->geometry_flag = d.geometry_flag;
    p->pressures_flag = d.pressures_flag;
    p->consolidation = d.consolidation;
    p->force_reuse = d.force_reuse;
    p->bulk_modulus = d.bulk_modulus;
    p->porosity_every = d.porosity_every;
    p->stagger_check = d.stagger_check;
    p->gravity = pl__world_gravity(w);
    double g = hypot(p->gravity.x, p->gravity.y);
    if (g > 0) {
        p->g = g;
        p->up = (pl_vec2){-p->gravity.x / g, -p->gravity.y / g};
    } else {
        p->g = 9.80665; /* heads still convert with standard gravity; z = 0 */
        p->up = (pl_vec2){0, 1};
    }
}

pl_fl_bodies pl__fluid_world_bodies(const pl_world *w) {
    const pl_grain_view g = pl__world_grains(w);
    pl_fl_bodies b;
    b.n = g.n;
    b.shape = g.shape;
    b.pos = g.pos;
    b.radius = g.radius;
    b.vert_offset = g.vert_offset;
    b.vert_count = g.vert_count;
    b.verts = g.verts;
    return b;
}

/* The world's Darcy model, attached on first use (the first fluid quad or line). */
static struct pl_fluid *model(pl_world *w) {
    struct pl_fluid *f = pl__darcy(w);
    if (f) return f;
    f = pl__darcy_new();
    if (!f) return NULL;
    if (pl__world_attach(w, &pl_darcy_class, f) != PL_OK) {
        pl__darcy_destroy(f);
        return NULL;
    }
    return f;
}

/* ---------------------------------------------------------------- parameters */

pl_status pl_world_set_darcy(pl_world *w, const pl_darcy_def *def) {
    int n = 0;
    const pl_param *t = pl_darcy_param_table(&n);
    double v[64];
    for (int k = 0; k < n && k < 64; k++) v[k] = pl_param_read(&t[k], def);
    return pl__world_set_flag_values(w, &pl_darcy_class, v, "darcy");
}

void pl_world_get_darcy(const pl_world *w, pl_darcy_def *out) {
    int n = 0;
    const pl_param *t = pl_darcy_param_table(&n);
    const double *v = pl__world_flag_values(w, &pl_darcy_class);
    for (int k = 0; k < n; k++) pl_param_write(&t[k], out, v[k]);
}

void pl__fluid_free_state(struct pl_fluid *f) {
    pl_free(f->head); pl_free(f->head_prev); pl_free(f->perm); pl_free(f->perm_assembled); pl_free(f->solid);
    pl_free(f->voidr); pl_free(f->porosity); pl_free(f->grad); pl_free(f->stamp); pl_free(f->perm_user);
    pl_free(f->pix_cnt); pl_free(f->pix_fill);
    f->pix_cnt = f->pix_fill = NULL;
    f->head = f->head_prev = f->perm = f->perm_assembled = f->solid = f->voidr = f->porosity = f->grad = NULL;
    f->perm_user = NULL;
    pl_fl_consolidation_free(f);
    f->stamp = NULL;
    f->stamp_gen = 0;
    f->ncover = 0;
    f->cover_bodies = 0;
}

/* Meshes and builds the system when the input changed. */
static pl_status ensure_built(pl_world *w) {
    struct pl_fluid *f = pl__darcy(w);
    if (!f) return pl__world_error(w, PL_ERR_STATE, "fluid: no fluid model (add a fluid quad first)");
    pl_status st;
    /* a step, a solve or a setter building now takes over what a query applied before it:
       without the query it would have applied the changed lines itself (built() below) */
    f->refresh_pending = 0;
    if (f->mesh_dirty) {
        pl__fluid_free_state(f);
        pl_fl_system_free(&f->sys);
        f->built = 0;
        st = pl_mesh_build(&f->mesh, f->quads, f->nq, f->msg, sizeof f->msg);
        if (st != PL_OK) return pl__world_error(w, st, "%s", f->msg);
        const int nn = f->mesh.nn, ne = f->mesh.ne;
        f->head = pl_calloc((size_t)nn, sizeof(double));
        f->head_prev = pl_calloc((size_t)nn, sizeof(double));
        f->perm = pl_calloc((size_t)ne, sizeof(double));
        f->perm_assembled = pl_calloc((size_t)ne, sizeof(double));
        f->solid = pl_calloc((size_t)ne, sizeof(double));
        f->voidr = pl_calloc((size_t)ne, sizeof(double));
        f->porosity = pl_calloc((size_t)ne, sizeof(double));
        f->grad = pl_calloc(2 * (size_t)ne, sizeof(double));
        f->stamp = pl_calloc((size_t)ne, sizeof(int32_t));
        if (!f->head || !f->head_prev || !f->perm || !f->perm_assembled || !f->solid || !f->voidr || !f->porosity ||
            !f->grad || !f->stamp)
            return pl__world_error(w, PL_ERR_NOMEM, "fluid: out of memory for %d nodes", nn);
        for (int e = 0; e < ne; e++) { f->voidr[e] = 99; f->porosity[e] = 0.99; f->perm_assembled[e] = -1; }
        /* initial field: pressure head 0 (seed 000 §3.9.2: zero except on the boundary) */
        for (int i = 0; i < nn; i++) f->head[i] = pl_fl_z(f, f->mesh.xy[i]);
        f->mesh_dirty = 0;
        f->bc_dirty = 1;
        f->initialised = 0;
        f->geometry_written = 0;
        f->built = 1;
    }
    if (f->bc_dirty) {
        st = pl_fl_system_build(f);
        if (st != PL_OK) return pl__world_error(w, st, "%s", f->msg[0] ? f->msg : "fluid: system build failed");
        pl_fl_apply_dirichlet(f, f->head);
        f->static_valid = 0;
        f->bc_dirty = 0;
    }
    return PL_OK;
}

pl_status pl__fluid_ensure_built(pl_world *w) { return ensure_built(w); }

static pl_status write_outputs(pl_world *w) {
    struct pl_fluid *f = pl__darcy(w);
    if (f->par.geometry_flag && !f->geometry_written) {
        pl_status st = pl_world_fluid_write_geometry(w, f->geometry_file);
        if (st != PL_OK) return st;
        f->geometry_written = 1;
    }
    if (f->par.pressures_flag) {
        if (!f->pressures_started) {
            pl_status st = pl_world_fluid_append_pressures_header(w, f->pressures_file);
            if (st != PL_OK) return st;
            f->pressures_started = 1;
        }
        return pl_world_fluid_append_pressures(w, f->pressures_file);
    }
    return PL_OK;
}

/* One fluid update: porosity, permeability, assembly, solve (static when dt <= 0). */
pl_status pl__fluid_update(pl_world *w, double dt, int is_static) {
    struct pl_fluid *f = pl__darcy(w);
    pl__fluid_read_params(w, &f->par);
    /* gravity or density changes move the prescribed total heads */
    pl_status st = ensure_built(w);
    if (st != PL_OK) return st;
    /* the pieces of the grains in the elements: at every update, or with
       FLUID_POROSITY_TIMESTEPS = P every P grain steps (and whenever bodies were added, the mesh
       was rebuilt or the solve is static); in between the last pieces stand */
    const pl_grain_view g = pl__world_grains(w);
    const int lagged = f->par.porosity_every > 0 && !is_static && f->initialised && f->cover_bodies == g.n &&
                       f->geom_since < f->par.porosity_every;
    if ((f->par.perm_mode == 1 || f->par.drag || f->par.consolidation) && !lagged) {
        pl_fl_bodies b = pl__fluid_world_bodies(w);
        st = pl_fl_update_porosity(f, &b);
        if (st != PL_OK) return pl__world_error(w, st, "fluid: out of memory in the porosity update");
        f->geom_since = 0;
    }
    if (f->par.consolidation) {
        /* pore pressure from skeleton volume change (fluid_consolidation.c) */
        pl_fl_bodies b = pl__fluid_world_bodies(w);
        st = pl_fl_consolidation_alloc(f);
        if (st == PL_OK)
            st = is_static || !(dt > 0) ? pl_fl_consolidation_reset(f, &b, g.angle)
                                         : pl_fl_consolidation_source(f, &b, g.angle, dt);
        if (st != PL_OK) return pl__world_error(w, st, "fluid: out of memory in the consolidation source");
        pl_fl_consolidation_storage(f);
    } else if (f->src_active) {
        f->src_active = 0;
        f->static_valid = 0;
    }
    /* accelerating frame: the acceleration of its body at the time the solution stands for */
    const pl_vec2 acc0 = f->frame_acc;
    f->frame_acc = (pl_vec2){0, 0};
    if (f->frame_body_plus1 > 0 && f->frame_body_plus1 <= g.n)
        pl__world_body_acceleration(w, f->frame_body_plus1 - 1, is_static ? g.time : f->out_time, &f->frame_acc);
    if (f->frame_acc.x != acc0.x || f->frame_acc.y != acc0.y) f->static_valid = 0;
    if (f->par.perm_mode == 2 && !f->perm_user)
        return pl__world_error(w, PL_ERR_STATE,
                         "fluid: FLUID_PERM = 2 needs per-element permeabilities (fluid_set_element_permeability)");
    pl_fl_update_permeability(f);
    if (f->k_dirty) {
        double t0 = pl_fl_now();
        pl_fl_assemble(f);
        f->stats.t_assembly += pl_fl_now() - t0;
    }
    st = is_static ? pl_fl_solve_static(f) : pl_fl_advance(f, dt);
    if (st != PL_OK) return pl__world_error(w, st, "%s", f->msg);
    pl_fl_update_gradients(f);
    f->stats.updates++;
    return write_outputs(w);
}

/* ------------------------------------------------------------------ API */

pl_fluid_quad_def pl_default_fluid_quad_def(void) {
    pl_fluid_quad_def d;
    memset(&d, 0, sizeof d);
    d.corners[0] = (pl_vec2){0, 0};
    d.corners[1] = (pl_vec2){1, 0};
    d.corners[2] = (pl_vec2){1, 1};
    d.corners[3] = (pl_vec2){0, 1};
    d.ndivx = 4;
    d.ndivy = 4;
    d.id = -1;
    d.anisotropy = 1;
    return d;
}

int pl_world_add_fluid_quad(pl_world *w, const pl_fluid_quad_def *def) {
    if (!def) return pl__world_error(w, PL_ERR_ARG, "add_fluid_quad: no definition given");
    struct pl_fluid *f = model(w);
    if (!f) return pl__world_error(w, PL_ERR_NOMEM, "add_fluid_quad: out of memory");
    pl_mesh_quad q;
    memset(&q, 0, sizeof q); /* padding too (restart files) */
    for (int k = 0; k < 4; k++) q.c[k] = def->corners[k];
    q.ndivx = def->ndivx;
    q.ndivy = def->ndivy;
    if (def->id >= 0) q.id = def->id;
    else { /* automatic: one more than the largest id in use */
        q.id = 0;
        for (int k = 0; k < f->nq; k++)
            if (f->quads[k].id >= q.id) q.id = f->quads[k].id + 1;
    }
    q.anisotropy = def->anisotropy;
    for (int k = 0; k < f->nq; k++)
        if (f->quads[k].id == q.id)
            return pl__world_error(w, PL_ERR_ARG, "add_fluid_quad: id %d is already used by fluid quad %d", q.id, k);
    /* validate this quad alone now so that the error names the call */
    pl_mesh tmp = {0};
    char msg[PL_FL_MSG];
    pl_mesh_quad one = q;
    if (q.ndivx >= 1 && q.ndivy >= 1 && q.ndivx <= 4096 && q.ndivy <= 4096) { one.ndivx = 1; one.ndivy = 1; }
    pl_status st = pl_mesh_build(&tmp, &one, 1, msg, sizeof msg);
    pl_mesh_free(&tmp);
    if (st != PL_OK) {
        /* report with the real index and divisions */
        if (q.ndivx < 1 || q.ndivy < 1 || q.ndivx > 4096 || q.ndivy > 4096)
            return pl__world_error(w, PL_ERR_ARG, "add_fluid_quad (id %d): ndivx and ndivy must be 1..4096 (got %d, %d)",
                             q.id, q.ndivx, q.ndivy);
        return pl__world_error(w, st, "add_fluid_quad: %s", msg);
    }
    if (f->nq == f->qcap) {
        int nc = f->qcap ? 2 * f->qcap : 8;
        pl_mesh_quad *p = pl_realloc(f->quads, sizeof(pl_mesh_quad) * (size_t)nc);
        if (!p) return pl__world_error(w, PL_ERR_NOMEM, "add_fluid_quad: out of memory");
        f->quads = p;
        f->qcap = nc;
    }
    f->quads[f->nq] = q;
    f->mesh_dirty = 1;
    return f->nq++;
}

pl_status pl_world_change_fluid_id(pl_world *w, int old_id, int new_id) {
    struct pl_fluid *f = pl__darcy(w);
    int at = -1;
    for (int k = 0; f && k < f->nq; k++) {
        if (f->quads[k].id == new_id && new_id != old_id)
            return pl__world_error(w, PL_ERR_ARG, "change_fluid_id: id %d is already used", new_id);
        if (f->quads[k].id == old_id) at = k;
    }
    if (at < 0) return pl__world_error(w, PL_ERR_ARG, "change_fluid_id: no fluid quad has id %d", old_id);
    f->quads[at].id = new_id;
    return PL_OK;
}

int pl_world_fluid_quad_count(const pl_world *w) { return pl__darcy(w) ? pl__darcy(w)->nq : 0; }

static int add_line(pl_world *w, pl_vec2 a, pl_vec2 b, double value, int kind, const char *fn) {
    if (!isfinite(a.x) || !isfinite(a.y) || !isfinite(b.x) || !isfinite(b.y) || !isfinite(value))
        return pl__world_error(w, PL_ERR_ARG, "%s: coordinates and value must be finite", fn);
    struct pl_fluid *f = model(w);
    if (!f) return pl__world_error(w, PL_ERR_NOMEM, "%s: out of memory", fn);
    if (f->nl == f->lcap) {
        int nc = f->lcap ? 2 * f->lcap : 8;
        pl_fl_line *p = pl_realloc(f->lines, sizeof(pl_fl_line) * (size_t)nc);
        if (!p) return pl__world_error(w, PL_ERR_NOMEM, "%s: out of memory", fn);
        f->lines = p;
        f->lcap = nc;
    }
    pl_fl_line *l = &f->lines[f->nl];
    memset(l, 0, sizeof *l); /* padding too: restart files of the same state are the same bytes */
    l->a = a;
    l->b = b;
    l->value = value;
    l->kind = kind;
    f->bc_dirty = 1;
    return f->nl++;
}

int pl_world_add_fluid_bc(pl_world *w, pl_vec2 a, pl_vec2 b, double pressure_head) {
    return add_line(w, a, b, pressure_head, PL_FL_LINE_HEAD, "add_fluid_bc");
}

int pl_world_add_fluid_flux(pl_world *w, pl_vec2 a, pl_vec2 b, double inflow) {
    return add_line(w, a, b, inflow, PL_FL_LINE_FLUX, "add_fluid_flux");
}

pl_status pl_world_clear_fluid_bcs(pl_world *w) {
    if (!pl__darcy(w)) return PL_OK;
    pl__darcy(w)->nl = 0;
    pl__darcy(w)->bc_dirty = 1;
    return PL_OK;
}

pl_status pl_world_fluid_solve_static(pl_world *w) {
    if (!pl__darcy(w)) return pl__world_error(w, PL_ERR_STATE, "fluid_solve_static: no fluid model (add a fluid quad first)");
    pl_status st = pl__fluid_update(w, 0, 1);
    if (st == PL_OK) {
        pl__darcy(w)->initialised = 1;
        pl__darcy(w)->steps_since = 0;
        pl__darcy(w)->time_since = 0;
    }
    return st;
}

pl_status pl_world_fluid_advance(pl_world *w, double dt) {
    if (!pl__darcy(w)) return pl__world_error(w, PL_ERR_STATE, "fluid_advance: no fluid model (add a fluid quad first)");
    if (!(dt > 0) || !isfinite(dt)) return pl__world_error(w, PL_ERR_ARG, "fluid_advance: dt must be > 0 (got %g)", dt);
    pl_status st = pl__fluid_update(w, dt, 0);
    if (st == PL_OK) pl__darcy(w)->initialised = 1;
    return st;
}

pl_status pl_world_fluid_set_frame(pl_world *w, int body) {
    if (!pl__darcy(w)) return pl__world_error(w, PL_ERR_STATE, "fluid_frame: no fluid model (add a fluid quad first)");
    if (body < 0) {
        pl__darcy(w)->frame_body_plus1 = 0;
        return PL_OK;
    }
    const int nb = pl__world_grains(w).n;
    if (body >= nb) return pl__world_error(w, PL_ERR_ARG, "fluid_frame: no body %d (the world has %d)", body, nb);
    pl_vec2 a;
    if (!pl__world_body_acceleration(w, body, pl__world_time(w), &a))
        return pl__world_error(w, PL_ERR_ARG,
                         "fluid_frame: body %d must move by a prescribed law with a known acceleration (shake, or a "
                         "constant velocity); give it its motion first",
                         body);
    pl__darcy(w)->frame_body_plus1 = body + 1;
    return PL_OK;
}

pl_status pl_world_fluid_set_pressure_head(pl_world *w, double psi) {
    if (!pl__darcy(w)) return pl__world_error(w, PL_ERR_STATE, "fluid_set_pressure_head: no fluid model");
    pl__fluid_read_params(w, &pl__darcy(w)->par);
    pl_status st = ensure_built(w);
    if (st != PL_OK) return st;
    struct pl_fluid *f = pl__darcy(w);
    for (int i = 0; i < f->mesh.nn; i++) f->head[i] = psi + pl_fl_z(f, f->mesh.xy[i]);
    pl_fl_apply_dirichlet(f, f->head);
    pl_fl_update_gradients(f);
    f->static_valid = 0;
    f->initialised = 1;
    return PL_OK;
}

pl_status pl_world_fluid_set_element_permeability(pl_world *w, const double *k, int count) {
    if (!pl__darcy(w)) return pl__world_error(w, PL_ERR_STATE, "fluid_set_element_permeability: no fluid model");
    pl__fluid_read_params(w, &pl__darcy(w)->par);
    pl_status st = ensure_built(w);
    if (st != PL_OK) return st;
    struct pl_fluid *f = pl__darcy(w);
    if (count != f->mesh.ne)
        return pl__world_error(w, PL_ERR_ARG, "fluid_set_element_permeability: %d values given for %d triangles", count,
                         f->mesh.ne);
    for (int e = 0; e < count; e++)
        if (!(k[e] > 0) || !isfinite(k[e]))
            return pl__world_error(w, PL_ERR_ARG, "fluid_set_element_permeability: value %d is %g; must be > 0", e, k[e]);
    if (!f->perm_user) f->perm_user = pl_malloc(sizeof(double) * (size_t)count);
    if (!f->perm_user) return pl__world_error(w, PL_ERR_NOMEM, "fluid_set_element_permeability: out of memory");
    memcpy(f->perm_user, k, sizeof(double) * (size_t)count);
    return PL_OK;
}

/* ---------------------------------------------------------------- queries */

/* Prepare (the world's explicit build step, pl_world_prepare): meshes, applies changed boundary
   lines and, with FLUIDS_ON and FIRST_STEP_STATIC, computes the static solution the first step
   will use (so that a frame at t = 0 shows it). The hosts call it before reading the field;
   the queries below only read. */
pl_status pl__darcy_prepare(void *self, pl_world *w) {
    struct pl_fluid *f = self;
    if (f->mesh_dirty || f->bc_dirty) {
        /* preparing must not change what the next step does: when it rebuilds changed boundary
           conditions, the next step still makes the update the stepping makes after a change
           (darcy_model.c), as it would without the prepare */
        const int bcs_only = !f->mesh_dirty && f->initialised;
        pl__fluid_read_params(w, &f->par);
        pl_status st = ensure_built(w);
        if (st != PL_OK) return st;
        if (bcs_only) f->refresh_pending = 1;
    }
    const double *flags = pl__world_flag_values(w, &pl_darcy_class);
    if (!f->initialised && flags[0] != 0 && flags[1] != 0) { /* FLUIDS_ON, FIRST_STEP_STATIC */
        pl_status st = pl__fluid_update(w, 0, 1);
        if (st != PL_OK) return st; /* message in last_error; the field stays */
        f->initialised = 1;
        /* the stepping would have made this static solve at the first step and counted
           from there: start one step behind so that the later updates fall on the same steps
           whether or not a prepare (e.g. for a frame at t = 0) came first (docs/soil.md §7) */
        f->steps_since = -1;
        f->geom_since = -1; /* likewise the cuts of the pieces (FLUID_POROSITY_TIMESTEPS) */
        f->time_since = 0;
    }
    return PL_OK;
}

/* The model when its mesh and system are built (after a prepare or a step), else NULL. */
static const struct pl_fluid *built(const pl_world *w) {
    const struct pl_fluid *f = pl__darcy(w);
    return f && f->built && !f->mesh_dirty && f->head ? f : NULL;
}

int pl_world_fluid_node_count(const pl_world *w) {
    const struct pl_fluid *f = built(w);
    return f ? f->mesh.nn : 0;
}

int pl_world_fluid_triangle_count(const pl_world *w) {
    const struct pl_fluid *f = built(w);
    return f ? f->mesh.ne : 0;
}

int pl_world_fluid_copy_nodes(const pl_world *w, pl_vec2 *out, int cap) {
    const struct pl_fluid *f = built(w);
    if (!f) return 0;
    int n = f->mesh.nn < cap ? f->mesh.nn : cap;
    memcpy(out, f->mesh.xy, sizeof(pl_vec2) * (size_t)(n > 0 ? n : 0));
    return n;
}

int pl_world_fluid_copy_triangles(const pl_world *w, int *out, int cap) {
    const struct pl_fluid *f = built(w);
    if (!f) return 0;
    int n = f->mesh.ne < cap ? f->mesh.ne : cap;
    for (int k = 0; k < 3 * n; k++) out[k] = f->mesh.tri[k];
    return n;
}

static double head_ref(const struct pl_fluid *f) {
    double s = 0;
    int n = 0;
    for (int i = 0; i < f->mesh.nn; i++)
        if (f->sys.is_dir && f->sys.is_dir[i]) { s += f->head[i]; n++; }
    if (n == 0)
        for (int i = 0; i < f->mesh.nn; i++) { s += f->head[i]; n++; }
    return n ? s / n : 0;
}

int pl_world_fluid_copy_node_field(const pl_world *w, pl_fluid_node_field field, double *out, int cap) {
    const struct pl_fluid *f = built(w);
    if (!f) return 0;
    int n = f->mesh.nn < cap ? f->mesh.nn : cap;
    double rg = f->par.density * f->par.g, href = head_ref(f);
    for (int i = 0; i < n; i++) {
        double z = pl_fl_z(f, f->mesh.xy[i]);
        switch (field) {
        case PL_FLUID_HEAD: out[i] = f->head[i]; break;
        case PL_FLUID_PRESSURE_HEAD: out[i] = f->head[i] - z; break;
        case PL_FLUID_PRESSURE: out[i] = rg * (f->head[i] - z); break;
        case PL_FLUID_EXCESS_PRESSURE: out[i] = rg * (f->head[i] - href); break;
        default: return 0;
        }
    }
    return n;
}

int pl_world_fluid_copy_element_field(const pl_world *w, pl_fluid_element_field field, double *out, int cap) {
    const struct pl_fluid *f = built(w);
    if (!f) return 0;
    int n = f->mesh.ne < cap ? f->mesh.ne : cap;
    /* Darcy flux q = -D (grad h + a/g): in a shaking table's frame (pl_world_fluid_set_frame)
       the part of grad h that accelerates the water drives no flow (as for the drag) */
    const pl_vec2 fa = pl_fl_frame_gradient(f);
    for (int e = 0; e < n; e++) {
        double kx = f->perm[e], ky = f->perm[e] * f->quads[f->mesh.tri_quad[e]].anisotropy;
        switch (field) {
        case PL_FLUID_VELOCITY_X: out[e] = -kx * (f->grad[2 * e] + fa.x); break;
        case PL_FLUID_VELOCITY_Y: out[e] = -ky * (f->grad[2 * e + 1] + fa.y); break;
        case PL_FLUID_POROSITY: out[e] = f->porosity[e]; break;
        case PL_FLUID_VOID_RATIO: out[e] = f->voidr[e]; break;
        case PL_FLUID_PERM_X: out[e] = kx; break;
        case PL_FLUID_PERM_Y: out[e] = ky; break;
        case PL_FLUID_SOLID_AREA: out[e] = f->solid[e]; break;
        default: return 0;
        }
    }
    return n;
}

int pl_world_fluid_pressure_at(const pl_world *w, pl_vec2 p, double *pressure, double *head) {
    const struct pl_fluid *f = built(w);
    if (!f) {
        if (pressure) *pressure = 0;
        if (head) *head = NAN;
        return 0;
    }
    return pl_fl_pressure_at(f, p, pressure, head) >= 0;
}

double pl_world_fluid_line_inflow(const pl_world *w, int line) {
    const struct pl_fluid *f = built(w);
    if (!f || line < 0 || line >= f->nl) return NAN;
    return pl_fl_line_inflow(f, line);
}

pl_status pl_world_fluid_body_force(const pl_world *w, int body, pl_vec2 *force, double *moment) {
    const struct pl_fluid *f = built(w);
    if (!f) return pl__world_error(w, PL_ERR_STATE, "fluid_body_force: no fluid model");
    const int nb = pl__world_grains(w).n;
    if (body < 0 || body >= nb)
        return pl__world_error(w, PL_ERR_ARG, "fluid_body_force: body %d does not exist (0..%d)", body, nb - 1);
    pl_fl_bodies b = pl__fluid_world_bodies(w);
    pl_vec2 F = {0, 0};
    double M = 0;
    pl_fl_body_force(f, &b, body, &F, &M);
    if (force) *force = F;
    if (moment) *moment = M;
    return PL_OK;
}

pl_status pl_world_fluid_stats(const pl_world *w, pl_fluid_stats *out) {
    if (!pl__darcy(w)) {
        memset(out, 0, sizeof *out);
        return PL_ERR_STATE;
    }
    *out = pl__darcy(w)->stats;
    return PL_OK;
}
