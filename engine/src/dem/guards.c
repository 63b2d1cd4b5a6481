/* Bodies are numbered from 1 in messages, as scenes number them (the C API indexes from 0).
 * Stability guards: stop a run that goes unstable with a message naming what, where, when,
 * the likely cause and the time step that would be safe. Checked after each step:
 *   - non-finite position or velocity of a dynamic body,
 *   - an overlap beyond max_overlap_ratio of the smaller radius,
 *   - (every 50 steps) kinetic energy above energy_surge_ratio times all the energy that could have become
 *     kinetic (initial kinetic + elastic, gravitational energy released, work supplied),
 *   - (every 10 steps) a servo wall whose gain overshoots: the servo (seed 003 eqs. 5.11-5.12)
 *     moves v = G (F_t - F) / F_t, so the force error changes by a factor 1 - G k dt / F_t per
 *     step with k the stiffness behind the wall; with k bounded by the sum of the normal
 *     springs of its contacts the update is stable for G k dt / F_t < 2 (docs/stability.md). */
#include "dem/world_internal.h"
#include <math.h>
#include <stdio.h>

static const char *shape_name(int s) {
    return s == PL_SHAPE_DISC ? "disc" : s == PL_SHAPE_POLYGON ? "polygon" : "wall";
}

static void advice(pl_world *w, char *buf, size_t len) {
    const double dt = w->dt;
    pl_dt_report saved = w->dt_report;
    const double dt_user = w->def.dt;
    w->def.dt = 0;
    pl__compute_dt(w);
    const pl_dt_report r = w->dt_report;
    w->def.dt = dt_user;
    w->dt_report = saved;
    w->dt = dt;
    if (isfinite(r.dt_critical) && dt > 0.5 * r.dt_critical)
        snprintf(buf, len,
                 "likely cause: the time step %.3g s is %.2g times the critical step %.3g s (body %d, %s); "
                 "a safe step is %.3g s (set dt = 0 for automatic, or dt <= %.3g)",
                 dt, dt / r.dt_critical, r.dt_critical, r.limiting_body + 1, r.limit_kind, 0.1 * r.dt_critical,
                 0.1 * r.dt_critical);
    else
        snprintf(buf, len,
                 "likely cause: bodies driven into each other faster than the springs can push back "
                 "(stiffness too low for the loads or velocities, or bodies created overlapping); "
                 "the time step %.3g s is below the critical step %.3g s, so raise kn or lower the loads/velocities",
                 dt, r.dt_critical);
}

/* The servo limit: G k dt / F_t < 2 with k the sum of the normal springs touching the wall. */
static pl_status check_servos(pl_world *w) {
    for (int i = 0; i < w->n; i++) {
        if (w->motion[i] != PL_MOTION_PRESCRIBED || w->law[i].law != PL_LAW_SERVO) continue;
        const pl_motion *m = &w->law[i];
        double k = 0;
        for (int p = 0; p < w->pair_n; p++) {
            const pl_pair *q = &w->pairs[p];
            if (q->touching && (q->a == i || q->b == i)) k += w->pair_params[q->params].kn;
        }
        const double ratio = m->servo_gain * k * w->dt / m->servo_target;
        if (!(ratio > 2)) continue;
        return pl__error(w, PL_ERR_UNSTABLE,
                         "unstable servo: body %d (servo along (%.3g, %.3g), force %.4g N) has gain %.4g m/s; "
                         "with the normal springs of its %s contacts (k = %.4g N/m) and dt = %.3g s the servo "
                         "update G k dt / F = %.3g exceeds its stability limit 2 at t = %.6g s (step %lld), so "
                         "the wall overshoots and oscillates; a safe gain is G <= F / (k dt) = %.4g m/s "
                         "(or a smaller dt)",
                         i + 1, m->servo_dir.x, m->servo_dir.y, m->servo_target, m->servo_gain,
                         "touching", k, w->dt, ratio, w->time, (long long)w->step,
                         m->servo_target / (k * w->dt));
    }
    return PL_OK;
}

pl_status pl__check_guards(pl_world *w) {
    char adv[512];
    if (w->nonfinite_body >= 0) {
        const int i = w->nonfinite_body;
        {
            advice(w, adv, sizeof adv);
            return pl__error(w, PL_ERR_UNSTABLE,
                             "unstable: body %d (%s, material '%s') has a non-finite position or velocity at "
                             "t = %.6g s (step %lld); %s",
                             i + 1, shape_name(w->shape[i]), w->materials[w->material[i]].name, w->time,
                             (long long)w->step, adv);
        }
    }
    if (w->worst_overlap_ratio > w->def.max_overlap_ratio) {
        const int a = w->worst_a, b = w->worst_b;
        advice(w, adv, sizeof adv);
        return pl__error(w, PL_ERR_UNSTABLE,
                         "unstable: bodies %d (%s) and %d (%s) overlap by %.0f%% of the smaller radius at t = %.6g s "
                         "(step %lld, limit %.0f%%) near (%.4g, %.4g); %s",
                         a + 1, shape_name(w->shape[a]), b + 1, shape_name(w->shape[b]), 100 * w->worst_overlap_ratio, w->time,
                         (long long)w->step, 100 * w->def.max_overlap_ratio, w->pos[b].x, w->pos[b].y, adv);
    }
    if (w->step % 10 == 0) {
        const pl_status st = check_servos(w);
        if (st != PL_OK) return st;
    }
    if (w->step % 50 == 0) {
        const double ke = pl__kinetic_energy(w);
        const double grav = w->pe0 - pl__gravitational_energy(w), ext = w->e_external - w->ext0;
        const double supply = w->e_supply0 + grav + ext + w->e_models;
        /* A grain nearly as dense as the water around it gains its kinetic energy from the small
           difference of two large works, gravity's and the fluid's buoyancy: the supplied energy
           is then within the tallies' round-off and splitting error of zero (or below it), and a
           surge is measured against a percent of the energy moved instead. */
        const double moved = fabs(w->e_supply0) + fabs(grav) + fabs(ext) + fabs(w->e_models);
        const double scale = fmax(fmax(fabs(supply), 1e-2 * moved), 1e-300);
        if (ke > w->def.energy_surge_ratio * scale && ke > 0) {
            /* find the fastest body to name it */
            int worst = -1;
            double vmax = -1;
            for (int i = 0; i < w->n; i++) {
                if (w->motion[i] != PL_MOTION_DYNAMIC) continue;
                const double v = w->mass[i] * (w->vel[i].x * w->vel[i].x + w->vel[i].y * w->vel[i].y);
                if (v > vmax) {
                    vmax = v;
                    worst = i;
                }
            }
            advice(w, adv, sizeof adv);
            return pl__error(w, PL_ERR_UNSTABLE,
                             "unstable: kinetic energy %.4g J exceeds %.0f times the energy supplied (%.4g J) at "
                             "t = %.6g s (step %lld); most energetic body %d at (%.4g, %.4g); %s",
                             ke, w->def.energy_surge_ratio, supply, w->time, (long long)w->step, worst + 1,
                             worst >= 0 ? w->pos[worst].x : 0, worst >= 0 ? w->pos[worst].y : 0, adv);
        }
    }
    return PL_OK;
}
