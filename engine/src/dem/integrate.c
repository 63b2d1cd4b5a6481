/* Time integration and boundary motion laws.
 *
 * Dynamic bodies: damped central difference (seed 003 eqs. 2.27-2.30; seed 000 eq. 2.5):
 *   v(t+dt/2) = [v(t-dt/2) (1 - c dt/2m) + (F + m g) dt/m] / (1 + c dt/2m),  c = C + alpha m
 *   x(t+dt)   = x(t) + v(t+dt/2) dt
 * and the same for rotation with C* + alpha I. The optional non-viscous damping of seed 002
 * (eqs. 24-29) reduces each component of the resultant force by lambda |F_i| against the
 * velocity. Prescribed bodies follow their law: constant velocity (MIMES set_velocity), a
 * sinusoid (shaking table) or a servo holding a force (seed 003 eqs. 5.11-5.12). */
#include "dem/world_internal.h"
#include <math.h>

static double sgn(double x) { return (x > 0) - (x < 0); }

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
            const double w2 = 2 * M_PI * m->frequency;
            const double s = sin(w2 * (tb - m->t_start)) - sin(w2 * (ta - m->t_start));
            w->vel[i] = (pl_vec2){m->amplitude.x * s / dt, m->amplitude.y * s / dt};
            w->omega[i] = 0;
            break;
        }
        case PL_LAW_SERVO: {
            /* err = (F_A - F_C) / F_A, v = G err limited to v_max, along the push direction */
            const double fc = -(w->force[i].x * m->servo_dir.x + w->force[i].y * m->servo_dir.y);
            const double err = (m->servo_target - fc) / m->servo_target;
            double v = m->servo_gain * err;
            if (fabs(v) > m->servo_vmax) v = m->servo_vmax * sgn(v);
            w->vel[i] = (pl_vec2){v * m->servo_dir.x, v * m->servo_dir.y};
            w->omega[i] = 0;
            break;
        }
        default: break;
        }
    }
}

/* Energy dissipated by the contact dashpots and by Coulomb sliding over one step, from the work
   of those force parts with the mid-step velocities (the same identity the central difference
   satisfies for kinetic energy, so the balance closes to the scheme's own accuracy):
     D_damp = -sum_i (F_damp,i . v_mid,i + M_damp,i w_mid,i) dt
     D_fric = -sum_i (F_shear,i . v_mid,i + M_shear,i w_mid,i) dt - (E_shear,n - E_shear,n-1)  */
static inline void tally_contact_dissipation(pl_world *w, int i, pl_vec2 vm, double wm, double dt, double *damped,
                                             double *work_shear) {
    *damped -= (w->fdamp[i].x * vm.x + w->fdamp[i].y * vm.y + w->tdamp[i] * wm) * dt;
    *work_shear += (w->fshear[i].x * vm.x + w->fshear[i].y * vm.y + w->tshear[i] * wm) * dt;
}

void pl__integrate(pl_world *w, double dt) {
    const pl_vec2 g = w->def.gravity;
    const double C = w->def.global_c, Cr = w->def.global_c_rot, alpha = w->def.rayleigh_alpha;
    const double lam = w->def.local_damping;
    double damped = 0, external = 0, work_shear = 0;
    for (int i = 0; i < w->n; i++) {
        if (w->motion[i] == PL_MOTION_FIXED) continue;
        if (w->motion[i] == PL_MOTION_PRESCRIBED || w->inv_mass[i] == 0) {
            tally_contact_dissipation(w, i, w->vel[i], w->omega[i], dt, &damped, &work_shear);
            w->pos[i].x += w->vel[i].x * dt;
            w->pos[i].y += w->vel[i].y * dt;
            w->angle[i] += w->omega[i] * dt;
            if (w->vert_count[i]) pl__update_world_vertices(w, i);
            continue;
        }
        const double m = w->mass[i], I = w->inertia[i];
        pl_vec2 F = {w->force[i].x + m * g.x, w->force[i].y + m * g.y};
        double T = w->torque[i];
        const pl_vec2 v0 = w->vel[i];
        const double w0 = w->omega[i];
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
        const double a = 1 - c * dt / (2 * m), b = 1 / (1 + c * dt / (2 * m));
        const pl_vec2 v1 = {(v0.x * a + F.x * dt / m) * b, (v0.y * a + F.y * dt / m) * b};
        double w1 = w0;
        if (I > 0) {
            const double cr = Cr + alpha * I;
            const double ar = 1 - cr * dt / (2 * I), br = 1 / (1 + cr * dt / (2 * I));
            w1 = (w0 * ar + T * dt / I) * br;
        }
        const pl_vec2 vm = {0.5 * (v0.x + v1.x), 0.5 * (v0.y + v1.y)};
        const double wm = 0.5 * (w0 + w1);
        damped += (c * (vm.x * vm.x + vm.y * vm.y) - (Fl.x * vm.x + Fl.y * vm.y)) * dt;
        if (I > 0) damped += ((Cr + alpha * I) * wm * wm - Tl * wm) * dt;
        external += (w->load[i].x * vm.x + w->load[i].y * vm.y + w->load_moment[i] * wm) * dt;
        tally_contact_dissipation(w, i, vm, wm, dt, &damped, &work_shear);
        w->vel[i] = v1;
        w->omega[i] = w1;
        w->pos[i].x += v1.x * dt;
        w->pos[i].y += v1.y * dt;
        w->angle[i] += w1 * dt;
        if (w->vert_count[i]) pl__update_world_vertices(w, i);
    }
    w->e_damped += damped;
    w->e_friction += -work_shear - (w->e_shear - w->e_shear_prev);
    w->e_external += external;
}
