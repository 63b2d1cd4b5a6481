/* Time integration and boundary motion laws.
 *
 * Dynamic bodies: damped central difference (seed 003 eqs. 2.27-2.30; seed 000 eq. 2.5):
 *   v(t+dt/2) = [v(t-dt/2) (1 - c dt/2m) + (F + m g) dt/m] / (1 + c dt/2m),  c = C + alpha m
 *   x(t+dt)   = x(t) + v(t+dt/2) dt
 * and the same for rotation with C* + alpha I. The optional non-viscous damping of seed 002
 * (eqs. 24-29) reduces each component of the resultant force by lambda |F_i| against the
 * velocity. Prescribed bodies follow their law: constant velocity (MIMES set_velocity), a
 * sinusoid (shaking table) or a servo holding a force (seed 003 eqs. 5.11-5.12).
 *
 * The same pass tallies the energy dissipated by contact dashpots and Coulomb sliding (work of
 * those force parts with the mid-step velocities, see docs/method-dem.md), clears those parts
 * for the next step and notes the first body whose state became non-finite (for the guards). */
#include "dem/world_internal.h"
#include <math.h>

static double sgn(double x) { return (x > 0) - (x < 0); }

/* A body on a linear guide keeps only its velocity along the guide (the guide's force, across
   it, does no work). Guided bodies have inv_inertia 0 (fixed rotation), which the caller tests
   first so that free bodies do not read their law. */
static inline void guide_velocity(const pl_world *w, int i, pl_vec2 *v) {
    const pl_vec2 u = w->law[i].guide;
    if (u.x == 0 && u.y == 0) return;
    const double s = v->x * u.x + v->y * u.y;
    *v = (pl_vec2){s * u.x, s * u.y};
}

/* Power of the models' load on body i (world/models.c) at velocity vm, spin wm. */
static inline double model_power(const pl_world *w, int i, pl_vec2 vm, double wm) {
    return w->ext_force[i].x * vm.x + w->ext_force[i].y * vm.y + w->ext_moment[i] * wm;
}

/* Raised-cosine ramp of a sinusoid at time t: envelope e and its first two time derivatives
   (e = 1, 0, 0 without a ramp or between the ramps). */
static void ramp_envelope(const pl_motion *m, double t, double *e, double *de, double *dde) {
    *e = 1;
    *de = *dde = 0;
    if (!(m->ramp > 0)) return;
    const double tau = t - m->t_start, left = m->t_stop - t; /* left infinite without an end */
    const double k = M_PI / m->ramp;
    double x, sgn_d;
    if (tau < m->ramp) { x = tau; sgn_d = 1; }
    else if (left < m->ramp) { x = left; sgn_d = -1; }
    else return;
    *e = 0.5 * (1 - cos(M_PI * x / m->ramp));
    *de = sgn_d * 0.5 * k * sin(k * x);
    *dde = 0.5 * k * k * cos(k * x);
}

/* Position factor of a sinusoid at time t (clamped to its interval): e(t) sin(2 pi f tau). */
static double sinusoid_at(const pl_motion *m, double t) {
    double e, de, dde;
    ramp_envelope(m, t, &e, &de, &dde);
    return e * sin(2 * M_PI * m->frequency * (t - m->t_start));
}

int pl__law_acceleration(const pl_motion *m, double t, pl_vec2 *acc) {
    *acc = (pl_vec2){0, 0};
    if (m->law == PL_LAW_CONSTANT) return 1;
    if (m->law != PL_LAW_SINUSOID) return 0;
    if (t < m->t_start || t > m->t_stop) return 1;
    /* x = A e(tau) sin(w tau): x'' = A (e'' sin + 2 e' w cos - e w^2 sin) */
    const double tau = t - m->t_start, om = 2 * M_PI * m->frequency;
    double e, de, dde;
    ramp_envelope(m, t, &e, &de, &dde);
    const double s = sin(om * tau), c = cos(om * tau);
    const double f = dde * s + 2 * de * om * c - e * om * om * s;
    *acc = (pl_vec2){m->amplitude.x * f, m->amplitude.y * f};
    return 1;
}

void pl__apply_motion_laws(pl_world *w, double t, double dt) {
    for (int i = 0; i < w->n; i++) {
        if (w->motion[i] != PL_MOTION_PRESCRIBED) continue;
        pl_motion *m = &w->law[i];
        switch (m->law) {
        case PL_LAW_CONSTANT:
            w->vel[i] = m->velocity;
            w->omega[i] = m->omega;
            break;
        case PL_LAW_SINUSOID: {
            /* velocity that lands exactly on the law's position at t + dt */
            const double ta = fmin(fmax(t, m->t_start), m->t_stop), tb = fmin(fmax(t + dt, m->t_start), m->t_stop);
            const double s = sinusoid_at(m, tb) - sinusoid_at(m, ta);
            w->vel[i] = (pl_vec2){m->amplitude.x * s / dt, m->amplitude.y * s / dt};
            w->omega[i] = 0;
            break;
        }
        case PL_LAW_SERVO: {
            /* err = (F_A - F_C) / F_A, v = G err limited to v_max, along the push direction
               (plus an optional drive across it and the fluid force: servo_drive.c) */
            w->vel[i] = pl__servo_velocity(w, i);
            w->omega[i] = 0;
            break;
        }
        default: break;
        }
    }
    /* hinged walls follow the others, whose velocities for this step are now known */
    for (int i = 0; i < w->n; i++) {
        if (w->motion[i] != PL_MOTION_PRESCRIBED || w->law[i].law != PL_LAW_HINGE) continue;
        const pl_motion *m = &w->law[i];
        const int f = m->follow;
        const double dx = w->pos[f].x + w->vel[f].x * dt - m->follow_x0;
        /* clockwise turn for a positive shear displacement (the top moves right) */
        const double th = m->angle0 - atan(dx / m->height);
        const double c = cos(th - m->angle0), s = sin(th - m->angle0);
        const pl_vec2 target = {m->pivot.x + c * m->rel0.x - s * m->rel0.y, m->pivot.y + s * m->rel0.x + c * m->rel0.y};
        w->vel[i] = (pl_vec2){(target.x - w->pos[i].x) / dt, (target.y - w->pos[i].y) / dt};
        w->omega[i] = (th - w->angle[i]) / dt;
    }
}

void pl__integrate(pl_world *w, double dt) {
    const pl_vec2 g = w->def.gravity;
    const double C = w->def.global_c, Cr = w->def.global_c_rot, alpha = w->def.rayleigh_alpha;
    const double lam = w->def.local_damping;
    const int plain = C == 0 && Cr == 0 && alpha == 0 && lam == 0;
    double damped = 0, external = 0, work_shear = 0, ext_half = 0;
    int bad = -1;
    /* the neighbour list is rebuilt when some body has moved (or turned) by half the skin */
    const double lim = 0.5 * w->skin, lim2 = lim * lim;
    int moved = 0;
    pl_vec2 *restrict pos = w->pos, *restrict vel = w->vel;
    pl_tally *restrict tl = w->tally;
    const int track = w->def.track_energy;
    /* the models' external-force column of this step (world/models.c) */
    const int models = w->model_n > 0 && w->ext_force && w->ext_cap >= w->n;
    for (int i = 0; i < w->n; i++) {
        const int motion = w->motion[i];
        if (motion == PL_MOTION_FIXED) {
            /* no work at rest; clear the parts so they do not pile up if the body is released */
            tl[i] = (pl_tally){0, 0, 0, 0, 0, 0};
            continue;
        }
        pl_vec2 vm;
        double wm;
        if (motion == PL_MOTION_PRESCRIBED || w->inv_mass[i] == 0) {
            vm = vel[i];
            wm = w->omega[i];
            /* the force on a kinematic body is the reaction of what it pushes: its work on
               the system is minus its power */
            external -= (w->force[i].x * vm.x + w->force[i].y * vm.y + w->torque[i] * wm) * dt;
            if (models && motion == PL_MOTION_DYNAMIC && w->wants_load[i]) /* a massless body: in and out */
                external += model_power(w, i, vm, wm) * dt;
            pos[i].x += vm.x * dt;
            pos[i].y += vm.y * dt;
            w->angle[i] += wm * dt;
            if (w->vert_count[i]) pl__update_world_vertices(w, i);
        } else {
            const double im = w->inv_mass[i], ii = w->inv_inertia[i];
            const pl_vec2 v0 = vel[i];
            /* a guided body (fixed_rotation) has ii = 0 and is held at omega = 0 */
            const double w0 = ii == 0 && w->law[i].fixed_rotation ? 0 : w->omega[i];
            pl_vec2 v1;
            double w1;
            if (plain) {
                v1.x = v0.x + (w->force[i].x * im + g.x) * dt;
                v1.y = v0.y + (w->force[i].y * im + g.y) * dt;
                if (ii == 0) guide_velocity(w, i, &v1);
                w1 = w0 + w->torque[i] * ii * dt;
                vm = (pl_vec2){0.5 * (v0.x + v1.x), 0.5 * (v0.y + v1.y)};
                wm = 0.5 * (w0 + w1);
            } else {
                const double m = w->mass[i], I = w->inertia[i];
                pl_vec2 F = {w->force[i].x + m * g.x, w->force[i].y + m * g.y};
                double T = w->torque[i];
                pl_vec2 Fl = {0, 0};
                double Tl = 0;
                if (lam > 0) {
                    Fl.x = -lam * fabs(F.x) * sgn(v0.x);
                    Fl.y = -lam * fabs(F.y) * sgn(v0.y);
                    Tl = -lam * fabs(T) * sgn(w0);
                    F.x += Fl.x;
                    F.y += Fl.y;
                    T += Tl;
                }
                const double c = C + alpha * m;
                const double a = 1 - c * dt * 0.5 * im, b = 1 / (1 + c * dt * 0.5 * im);
                v1 = (pl_vec2){(v0.x * a + F.x * dt * im) * b, (v0.y * a + F.y * dt * im) * b};
                if (ii == 0) guide_velocity(w, i, &v1);
                w1 = w0;
                if (I > 0) {
                    const double cr = Cr + alpha * I;
                    const double ar = 1 - cr * dt * 0.5 * ii, br = 1 / (1 + cr * dt * 0.5 * ii);
                    w1 = (w0 * ar + T * dt * ii) * br;
                }
                vm = (pl_vec2){0.5 * (v0.x + v1.x), 0.5 * (v0.y + v1.y)};
                wm = 0.5 * (w0 + w1);
                damped += (c * (vm.x * vm.x + vm.y * vm.y) - (Fl.x * vm.x + Fl.y * vm.y)) * dt;
                if (I > 0) damped += ((Cr + alpha * I) * wm * wm - Tl * wm) * dt;
            }
            /* work of the point loads and of the models' loads (world/models.c) with the mid-step
               velocity: m (v1 - v0) = F dt dotted with (v0 + v1) / 2 gives
               m (v1^2 - v0^2) / 2 = F . vm dt exactly, so a load's work equals the change of the
               kinetic energy at the staggered half steps (and, with springs, of kinetic + elastic
               energy to O(dt^2), bounded); the start-of-step velocity v0 would miss
               m |v1 - v0|^2 / 2 per step. Summed, this is the trapezoidal work up to t_n plus
               F_n . v1 dt / 2 (kept in e_ext_half, which the report at t_n takes off) */
            if (w->any_load) {
                external += (w->load[i].x * vm.x + w->load[i].y * vm.y + w->load_moment[i] * wm) * dt;
                ext_half += (w->load[i].x * v1.x + w->load[i].y * v1.y + w->load_moment[i] * w1) * 0.5 * dt;
            }
            if (models && w->wants_load[i]) {
                external += model_power(w, i, vm, wm) * dt;
                ext_half += model_power(w, i, v1, w1) * 0.5 * dt;
            }
            vel[i] = v1;
            w->omega[i] = w1;
            pos[i].x += v1.x * dt;
            pos[i].y += v1.y * dt;
            w->angle[i] += w1 * dt;
            if (bad < 0 && !isfinite(v1.x + v1.y + w1 + pos[i].x + pos[i].y)) bad = i;
            if (w->vert_count[i]) pl__update_world_vertices(w, i);
        }
        if (!moved) {
            const double dx = pos[i].x - w->pos_at_build[i].x, dy = pos[i].y - w->pos_at_build[i].y;
            const double d2 = dx * dx + dy * dy;
            if (w->shape[i] == PL_SHAPE_DISC) {
                moved = d2 > lim2;
            } else {
                /* a turning outline sweeps up to |dtheta| x bounding radius more:
                   |dx| + rot > lim  <=>  |dx| > lim - rot (no square root) */
                const double rot = fabs(w->angle[i] - w->angle_at_build[i]) * w->radius[i];
                moved = rot >= lim || d2 > (lim - rot) * (lim - rot);
            }
        }
        if (track) {
            damped -= (tl[i].dfx * vm.x + tl[i].dfy * vm.y + tl[i].dm * wm) * dt;
            work_shear += (tl[i].sfx * vm.x + tl[i].sfy * vm.y + tl[i].sm * wm) * dt;
            tl[i] = (pl_tally){0, 0, 0, 0, 0, 0};
        }
    }
    w->e_damped += damped;
    if (track) w->e_friction += -work_shear - (w->e_shear - w->e_shear_prev);
    w->e_external += external;
    w->e_ext_half = ext_half;
    if (bad >= 0 && w->nonfinite_body < 0) w->nonfinite_body = bad;
    if (moved) w->need_rebuild = 1;
}
