/* The per-step coupling hook (seed 000 §3.3, Fig. 3-1; DESIGN §2 step 2): every
 * FLUID_SOLVE_TIMESTEPS grain steps the fluid is updated (porosity -> permeability -> assembly ->
 * solve); every grain step the fluid force and moment of the current field are added to the
 * dynamic bodies. FLUIDS_ON = 0 returns at once. */
#include "fluid/fluid_hook.h"
#include "fluid/fluid_internal.h"
#include "fluid/fluid_world.h"
#include <stdlib.h>

pl_status pl__fluid_step(pl_world *w, double dt) {
    struct pl_fluid *f = w->fluid;
    if (!f) return PL_OK;
    if (pl__fluid_flag(w, "FLUIDS_ON", 0) == 0) return PL_OK; /* FLUIDS_ON = 0: no fluid work at all */
    pl_status st;
    f->out_time = w->time + dt; /* a solve in this step gives the field at its end */
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
            st = pl__fluid_update(w, f->time_since, 0);
            if (st != PL_OK) return st;
            f->steps_since = 0;
            f->time_since = 0;
        }
    }
    /* forces on every dynamic body, every grain step, from the current field (or, with
       FLUID_FORCE_REUSE, computed at fluid updates and reused until the next one) */
    double t0 = pl_fl_now();
    pl_fl_bodies b = pl__fluid_world_bodies(w);
    double work = 0;
    int reuse = f->par.force_reuse && f->steps_since != 0;
    if (f->par.force_reuse && f->fcache_cap < w->n) {
        int nc = w->n + 64;
        double *p = realloc(f->fcache, sizeof(double) * 3 * (size_t)nc);
        if (!p) return PL_ERR_NOMEM;
        f->fcache = p;
        f->fcache_cap = nc;
    }
    if (f->par.force_reuse && f->fcache_n < w->n) reuse = 0; /* new bodies: recompute all */
    for (int i = 0; i < w->n; i++) {
        if (f->par.force_reuse && !reuse) f->fcache[3 * i] = f->fcache[3 * i + 1] = f->fcache[3 * i + 2] = 0;
        if (w->motion[i] != PL_MOTION_DYNAMIC) continue;
        if (w->shape[i] != PL_SHAPE_DISC && w->shape[i] != PL_SHAPE_POLYGON) continue;
        pl_vec2 F = {0, 0};
        double M = 0;
        if (reuse) {
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
        w->force[i].x += F.x;
        w->force[i].y += F.y;
        w->torque[i] += M;
        work += (F.x * w->vel[i].x + F.y * w->vel[i].y + M * w->omega[i]) * dt;
    }
    if (f->par.force_reuse && !reuse) f->fcache_n = w->n;
    w->e_external += work;
    f->stats.t_forces += pl_fl_now() - t0;
    return PL_OK;
}

void pl__fluid_free(struct pl_fluid *f) {
    if (!f) return;
    pl__fluid_free_state(f);
    pl_fl_system_free(&f->sys);
    pl_fl_mesh_free(&f->mesh);
    free(f->fcache); free(f->quads); free(f->lines); free(f->cover); free(f->body_cover_start); free(f->cover_xyr); free(f->pix_pair);
    free(f);
}

