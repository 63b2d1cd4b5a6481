/* The world facade: creation, errors, the step loop and simple queries. One step: neighbour
 * list, contact forces, the attached models (advance, loads into the external-force column),
 * motion laws, integration, guards (DESIGN §2). */
#include "world/world_layer.h"
#include "core/alloc.h"
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

pl_world_def pl_default_world_def(void) {
    pl_world_def d;
    memset(&d, 0, sizeof d);
    d.gravity = (pl_vec2){0, -9.81};
    d.dt = 0;
    d.dt_safety = 0.1;
    d.max_dt = 0;
    d.max_overlap_ratio = 0.5;
    d.energy_surge_ratio = 10;
    d.guard_interval = 1;
    d.track_energy = 1;
    return d;
}

pl_status pl__error(const pl_world *w, pl_status s, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(w->error, PL_ERR_LEN, fmt, ap);
    va_end(ap);
    return s;
}

const char *pl_world_last_error(const pl_world *w) { return w ? w->error : "no world"; }

pl_world *pl_world_create(const pl_world_def *def) {
    pl_world *w = pl_calloc(1, sizeof *w);
    if (!w) return NULL;
    w->error = pl_calloc(PL_ERR_LEN, 1);
    if (!w->error) {
        pl_free(w);
        return NULL;
    }
    w->def = def ? *def : pl_default_world_def();
    if (w->def.dt_safety <= 0) w->def.dt_safety = 0.1;
    if (w->def.guard_interval < 1) w->def.guard_interval = 1;
    if (w->def.max_overlap_ratio <= 0) w->def.max_overlap_ratio = 0.5;
    if (w->def.energy_surge_ratio <= 1) w->def.energy_surge_ratio = 10;
    w->need_rebuild = 1;
    w->nonfinite_body = -1;
    pl__flags_init(w);
    if (!w->flag_values) {
        pl_free(w->error);
        pl_free(w);
        return NULL;
    }
    return w;
}

void pl_world_destroy(pl_world **wp) {
    if (!wp || !*wp) return;
    pl_world *w = *wp;
    pl__models_destroy(w);
    pl_free(w->ext_force); pl_free(w->ext_moment); pl_free(w->wants_load);
    pl_free(w->materials);
    pl_free(w->pair_params);
    pl_free(w->pair_overrides);
    pl_free(w->pos); pl_free(w->vel); pl_free(w->force);
    pl_free(w->angle); pl_free(w->omega); pl_free(w->torque);
    pl_free(w->mass); pl_free(w->inv_mass); pl_free(w->inertia); pl_free(w->inv_inertia);
    pl_free(w->radius); pl_free(w->area); pl_free(w->shape); pl_free(w->motion);
    pl_free(w->material); pl_free(w->user_id); pl_free(w->law); pl_free(w->load); pl_free(w->load_moment);
    pl_free(w->x0); pl_free(w->tally); pl_free(w->vert_offset); pl_free(w->vert_count);
    pl_free(w->verts_local); pl_free(w->verts_world);
    pl_free(w->pairs); pl_free(w->pairs_scratch);
    pl__parallel_free(w);
    pl_free(w->pos_at_build); pl_free(w->angle_at_build);
    pl_free(w->temperature); pl_free(w->heat); pl_free(w->wear); pl_free(w->removed_at);
    pl_free(w->temp_hold); pl_free(w->removed); pl_free(w->heat_step); pl_free(w->bonds); pl_free(w->bond_laws); pl_free(w->thermal);
    pl_free(w->cell_start); pl_free(w->cell_items); pl_free(w->body_cell); pl_free(w->cursor);
    pl_free(w->is_large); pl_free(w->large_list); pl_free(w->cand);
    pl_free(w->flag_values);
    pl_free(w->error);
    pl_free(w);
    *wp = NULL;
}

double pl_world_time(const pl_world *w) { return w->time; }
int64_t pl_world_step_count(const pl_world *w) { return w->step; }

double pl_world_dt(pl_world *w) {
    if (w->dt <= 0) pl__compute_dt(w), pl__models_limit_dt(w);
    return w->dt;
}

pl_dt_report pl_world_dt_report(pl_world *w) {
    /* also when a fixed step was set before any estimate was made (the report is then empty) */
    if (w->dt <= 0 || w->dt_report.dt != w->dt) pl__compute_dt(w), pl__models_limit_dt(w);
    return w->dt_report;
}

/* Energy reference: taken at the first step and again whenever the scene changes the world
   between steps (new bodies, new velocities), so the balance measures the integration only. */
static void init_energy_reference(pl_world *w) {
    /* evaluate the contacts once without advancing (dt = 0 leaves the shear history as it
       is) so that energy stored in overlaps present at the start is counted */
    if (pl__neighbor_update(w) == PL_OK) {
        pl__compute_contact_forces(w, 0);
        memset(w->tally, 0, (size_t)w->n * sizeof *w->tally);
        w->e_bond = pl__bond_energy(w);
    }
    w->e_supply0 = pl__kinetic_energy(w) + pl__elastic_energy(w);
    w->pe0 = pl__gravitational_energy(w);
    w->ext0 = w->e_external;
    w->e_initial = w->e_supply0 + w->pe0 + w->e_damped + w->e_friction + w->e_fracture - pl__external_work(w);
    w->energy_initialised = 1;
}

pl_status pl_world_prepare(pl_world *w) {
    for (int k = 0; k < w->model_n; k++) {
        const pl_model_slot *m = &w->models[k];
        if (!m->cls->prepare) continue;
        pl_status st = m->cls->prepare(m->self, w);
        if (st != PL_OK) return st;
    }
    return PL_OK;
}

pl_status pl_world_step(pl_world *w, int nsteps) {
    if (nsteps < 0) return pl__error(w, PL_ERR_ARG, "step: the step count must be >= 0 (got %d)", nsteps);
    if (w->dt <= 0) pl__compute_dt(w), pl__models_limit_dt(w);
    if (w->dt <= 0 || !isfinite(w->dt))
        return pl__error(w, PL_ERR_STATE, "step: no valid time step (add a dynamic body, or set dt > 0)");
    if (w->pair_params_dirty) pl__update_pair_params(w);
    if (w->classify_dirty) { /* bodies added or changed: not piled on one spot */
        pl_status st = pl__check_crowding(w);
        if (st != PL_OK) return st;
    }
    if (!w->energy_initialised) init_energy_reference(w);
    const double dt = w->dt;
    for (int s = 0; s < nsteps; s++) {
        pl_status st = pl__neighbor_update(w);
        if (st != PL_OK) return st;
        for (int i = 0; i < w->n; i++) {
            w->force[i] = w->load[i];
            w->torque[i] = w->load_moment[i];
        }
        pl__compute_contact_forces(w, dt);
        if (w->bond_intact) pl__bond_forces(w, dt);
        if (w->heat_on) {
            st = pl__heat_wear(w, dt);
            if (st != PL_OK) return st;
        }
        st = pl__models_step(w, dt);
        if (st != PL_OK) return st;
        pl__apply_motion_laws(w, w->time, dt);
        pl__integrate(w, dt);
        w->time += dt;
        w->step++;
        if (w->wear_remove) pl__wear_remove(w);
        if ((w->step % w->def.guard_interval) == 0 || s == nsteps - 1) {
            st = pl__check_guards(w);
            if (st != PL_OK) return st;
        }
    }
    return PL_OK;
}
