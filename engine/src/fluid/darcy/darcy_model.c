/* The Darcy model under the world's model interface (world/model.h): the per-step coupling
 * (seed 000 §3.3, Fig. 3-1; DESIGN §2 step 2). Every FLUID_SOLVE_TIMESTEPS grain steps the
 * fluid is updated (porosity -> permeability -> assembly -> solve: advance); every grain step
 * the fluid force and moment of the current field are given for each body the world asks for
 * (loads). FLUIDS_ON = 0 does no fluid work at all. */
#include "core/alloc.h"
#include "fluid/darcy/darcy_internal.h"
#include "fluid/darcy/darcy_snapshot.h"
#include "fluid/darcy/darcy_world.h"
#include "fluid/darcy/darcy_model.h"
#include <stdlib.h>

/* FLUIDS_ON is row 0 of the Darcy parameter table (darcy_params.c), so flag value 0 of the
   class's flag block */
static int darcy_on(const pl_world *w) { return pl__world_flag_values(w, &pl_darcy_class)[0] != 0; }

pl_status pl__darcy_advance(void *self, pl_world *w, const pl_grain_view *g, double dt) {
    struct pl_fluid *f = self;
    if (!darcy_on(w)) return PL_OK; /* FLUIDS_ON = 0: no fluid work at all */
    pl_status st;
    f->out_time = g->time + dt; /* a solve in this step gives the field at its end */
    f->geom_since++;
    if (!f->initialised || f->mesh_dirty || f->bc_dirty || f->refresh_pending) {
        f->refresh_pending = 0;
        pl__fluid_read_params(w, &f->par);
        /* FIRST_STEP_STATIC (seed 000 §3.9.3): static field first; otherwise one transient step
           from the boundary values (eq. 3.18 with phi(0) = phi_bc) */
        /* with FLUID_CONSOLIDATION the fluid's compressibility is storage too */
        const int no_storage = f->par.storage <= 0 && !(f->par.consolidation && f->par.bulk_modulus > 0);
        st = pl__fluid_update(w, f->par.first_step_static ? 0 : dt,
                              f->par.first_step_static || no_storage || f->par.method == 3);
        if (st != PL_OK) return st;
        f->initialised = 1;
        f->steps_since = 0;
        f->time_since = 0;
    } else {
        f->steps_since++;
        if (f->steps_since > 0) f->time_since += dt; /* 0: the step a query's static solve stood for */
        if (f->steps_since >= f->par.solve_every) {
            st = pl__fluid_stagger_check(w, f, g, dt);
            if (st != PL_OK) return st;
            st = pl__fluid_update(w, f->time_since, 0);
            if (st != PL_OK) return st;
            f->steps_since = 0;
            f->time_since = 0;
        }
    }
    return PL_OK;
}

/* Forces on every body the world asks for, every grain step, from the current field (or, with
   FLUID_FORCE_REUSE, computed at fluid updates and reused until the next one, for the dynamic
   bodies; a servo wall's is always fresh). */
pl_status pl__darcy_loads(void *self, pl_world *w, const pl_grain_view *g, double dt, pl_vec2 *force,
                             double *moment) {
    (void)dt;
    struct pl_fluid *f = self;
    if (!darcy_on(w)) return PL_OK;
    double t0 = pl_fl_now();
    pl_fl_bodies b = pl__fluid_world_bodies(w);
    int reuse = f->par.force_reuse && f->steps_since != 0;
    if (f->par.force_reuse && f->fcache_cap < g->n) {
        int nc = g->n + 64;
        double *p = pl_realloc(f->fcache, sizeof(double) * 3 * (size_t)nc);
        if (!p) return pl__world_error(w, PL_ERR_NOMEM, "fluid: out of memory for the reused forces");
        f->fcache = p;
        f->fcache_cap = nc;
    }
    if (f->par.force_reuse && f->fcache_n < g->n) reuse = 0; /* new bodies: recompute all */
    for (int i = 0; i < g->n; i++) {
        if (f->par.force_reuse && !reuse) f->fcache[3 * i] = f->fcache[3 * i + 1] = f->fcache[3 * i + 2] = 0;
        if (!g->wants_load[i]) continue;
        pl_vec2 F = {0, 0};
        double M = 0;
        if (g->motion[i] != PL_MOTION_DYNAMIC) { /* a servo wall counting the water's force */
            pl_fl_body_force(f, &b, i, &F, &M);
        } else if (reuse) {
            F.x = f->fcache[3 * i];
            F.y = f->fcache[3 * i + 1];
            M = f->fcache[3 * i + 2];
        } else {
            pl_fl_body_force(f, &b, i, &F, &M);
            if (f->par.force_reuse) {
                f->fcache[3 * i] = F.x;
                f->fcache[3 * i + 1] = F.y;
                f->fcache[3 * i + 2] = M;
            }
        }
        force[i].x += F.x;
        force[i].y += F.y;
        moment[i] += M;
    }
    if (f->par.force_reuse && !reuse) f->fcache_n = g->n;
    f->stats.t_forces += pl_fl_now() - t0;
    return PL_OK;
}

struct pl_fluid *pl__darcy_new(void) {
    struct pl_fluid *f = pl_calloc(1, sizeof *f);
    if (!f) return NULL;
    f->mesh_dirty = 1;
    f->par = pl_fl_default_params();
    snprintf(f->geometry_file, sizeof f->geometry_file, "geometry.flu");
    snprintf(f->pressures_file, sizeof f->pressures_file, "pressures.flu");
    return f;
}

void *pl__darcy_create(void) { return pl__darcy_new(); }

void pl__darcy_destroy(void *self) {
    struct pl_fluid *f = self;
    if (!f) return;
    pl__fluid_free_state(f);
    pl_fl_system_free(&f->sys);
    pl_mesh_free(&f->mesh);
    pl_free(f->fcache); pl_free(f->quads); pl_free(f->lines); pl_free(f->cover); pl_free(f->body_cover_start); pl_free(f->cover_xyr); pl_free(f->pix_pair);
    pl_free(f);
}

uint64_t pl__darcy_hash(const void *self, uint64_t h) { return pl__fluid_hash(self, h); }
void *pl__darcy_snapshot(const void *self, size_t *bytes) { return pl__fluid_snapshot(self, bytes); }
pl_status pl__darcy_restore(void *self, pl_world *w, const void *snap) {
    return pl__fluid_restore(w, self, snap);
}
void pl__darcy_snapshot_free(void *snap) {
    pl_fl_snapshot *z = snap;
    pl__fluid_snapshot_free(&z);
}
pl_status pl__darcy_save(const void *self, pl_image *img) { return pl__fluid_save(self, img); }
pl_status pl__darcy_load(void *self, pl_world *w, pl_image *img) { return pl__fluid_load(w, self, img); }
double pl__darcy_cost(const void *self, long *calls) {
    const struct pl_fluid *f = self;
    if (calls) *calls = f->stats.updates;
    return f->stats.t_porosity + f->stats.t_assembly + f->stats.t_factor + f->stats.t_solve + f->stats.t_forces;
}

