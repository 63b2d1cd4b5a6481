/* Cundall-Strack contact law of discs with discs and with wall segments (seed 003 §2.2.4.2,
 * eqs. 2.7-2.20), written as inline kernels for the narrow-phase loop (contact_dispatch.c):
 *   normal:  F_n = k_N delta - c_N v_n   (linear spring on the overlap delta, dashpot)
 *   shear:   S <- S - k_S v_t dt  (incremental spring, history kept while the contact lasts)
 *            D_S = -c_S v_t;  Coulomb (eq. 2.17): |S| <= mu k_N delta + c; when exceeded S is
 *            set to the limit with its sign and the shear dashpot is off (sliding). With shear
 *            damping the seed's limit is on the sum, |S + D_S| <= S_max (text below eq. 2.19):
 *            when the spring is below the limit but the sum is not, D_S is cut to the remainder.
 * The contact lasts while the outlines overlap; the spring-plus-dashpot normal force may turn
 * slightly tensile just before separation, as in the seed (this keeps the analytic
 * restitution e = exp(-pi zeta / sqrt(1 - zeta^2))).
 * Conventions: the normal n points from a to b, the tangent t = (-n.y, n.x); the force on b is
 * +F = F_n n + F_t t, on a it is -F. The normal part passes through both centres, so the moment
 * about a centre at distance l from the contact point is -l F_t (eq. 2.20).
 * Rolling resistance (material `rolling` = mu_r > 0; Iwashita & Oda 1998, the elastic-plastic
 * "type C" of Ai et al. 2011 without its dashpot): M_r <- M_r - k_r (omega_b - omega_a) dt with
 * k_r = k_S R^2, R = r_a r_b / (r_a + r_b) (a disc's radius on a wall), |M_r| <= mu_r R F_n
 * (elastic normal force); +M_r on b, -M_r on a. Its spring energy joins the shear spring's, so
 * the friction tally (integrate.c) also counts what the rolling limit dissipates.
 * For the exact energy tallies (integrate.c) the dashpot and tangential-spring parts are also
 * summed per body. */
#ifndef PL_CONTACT_DISC_H
#define PL_CONTACT_DISC_H
#include "dem/contact_out.h"
#include <math.h>

/* Body arrays hoisted out of the world once per step (no aliasing reloads in the loop). */
typedef struct pl_disc_ctx {
    const pl_vec2 *restrict pos, *restrict vel;
    const double *restrict omega, *restrict radius;
    pl_vec2 *restrict force;
    double *restrict torque;
    pl_tally *restrict tally;
    int track;
    double e_shear, e_normal;
    double worst_ratio;
    int worst_a, worst_b;
} pl_disc_ctx;

static inline __attribute__((always_inline)) void pl__apply(pl_disc_ctx *c, const pl_contact_out *o, int a, int b) {
    pl__apply_end(c->force, c->torque, c->tally, c->track, &o->add, b, 1);
    pl__apply_end(c->force, c->torque, c->tally, c->track, &o->add, a, 0);
}

/* The sums over pairs (spring energies, the worst overlap), in pair order. */
static inline __attribute__((always_inline)) void pl__account_law(pl_disc_ctx *c, const pl_contact_out *o, int a,
                                                                   int b) {
    c->e_shear += o->es;
    c->e_normal += o->en;
    if (o->ratio > c->worst_ratio) {
        c->worst_ratio = o->ratio;
        c->worst_a = a;
        c->worst_b = b;
    }
}

static inline void pl__untouch(pl_pair *p) {
    if (!p->touching) return; /* most listed pairs stay apart: do not rewrite them */
    p->touching = 0;
    p->fs = 0;
    p->mr = 0;
    p->fn = 0;
    p->ft = 0;
    p->overlap = 0;
    p->elastic = 0;
}

static inline double pl__cross2(pl_vec2 r, pl_vec2 f) { return r.x * f.y - r.y * f.x; }

/* End of a contact (the outlines no longer overlap at this evaluation). The normal dashpot acts
   on the rate of the overlap, F_d = c d(delta)/dt; between evaluations it sees the half-step
   velocity (delta_n - delta_{n-1})/dt, so over a contact it gives the telescoping impulse
   c (delta_last - delta_before) and needs both ends at zero overlap to be the analytic zero
   (the overlap-end contact). The onset is clipped in pl__disc_law; here the last increment,
   from delta_last to 0, is given as one pull c delta_last / dt along the last normal, instead of
   depending on where in the step the outlines parted. Without it the restitution of a damped
   impact varied with the contact's phase within a step by up to 2 zeta omega dt (-1.55 % at
   zeta = 0.3, 0.01 x critical). wall: the segment's index or -1. The additions go to o. */
static inline __attribute__((always_inline)) void pl__release(pl_disc_ctx *c, pl_pair *p, double dt, int a, int b,
                                                               int wall, pl_contact_out *o, int apply) {
    o->add.flags = 0;
    /* dt = 0 is the energy reference's evaluation without a step (world.c): the release and its
       pull belong to the next real step, so the pair is left as it is */
    if (!p->touching || dt <= 0) return;
    if (p->cn > 0 && p->overlap > 0) {
        const double fn = -p->cn * p->overlap / dt; /* on b along n: a pull */
        const pl_vec2 n = p->normal;
        const pl_vec2 F = {fn * n.x, fn * n.y};
        o->add.flags = PL_OUT_F | PL_OUT_FD;
        o->add.tqa = o->add.tqb = o->add.dma = o->add.dmb = 0;
        o->add.fx = o->add.dfx = F.x;
        o->add.fy = o->add.dfy = F.y;
        if (wall >= 0) {
            const pl_vec2 rw = {p->point.x - c->pos[wall].x, p->point.y - c->pos[wall].y};
            const double mw = (wall == b ? 1 : -1) * pl__cross2(rw, F);
            if (wall == b) o->add.flags |= PL_OUT_TQB | PL_OUT_DMB, o->add.tqb = o->add.dmb = mw;
            else o->add.flags |= PL_OUT_TQA | PL_OUT_DMA, o->add.tqa = o->add.dma = mw;
        }
        if (apply) pl__apply(c, o, a, b);
    }
    pl__untouch(p);
}

/* Evaluates the law for a touching pair. vn, vt: relative velocity of b's material point with
   respect to a's. arm_a, arm_b: distances from the disc centres to the contact point (the
   moment is then -arm F_t). A wall is not centred on the line of the normal force: pass its
   lever vector (contact point - wall centroid) in wall_r and its end (0: a, 1: b) in wall_end,
   or wall_r = NULL for two discs. wrel = omega_b - omega_a and reff = R of the rolling law.
   Updates the pair's history and puts the additions to the bodies in o; with apply, also adds
   them to bodies a and b and to the sums over pairs at once (the serial loop). */
static inline __attribute__((always_inline)) void pl__disc_law(pl_disc_ctx *c, pl_pair *p, const pl_pair_params *pp,
                                                                double dt, int a, int b, pl_vec2 n, double delta,
                                                                pl_vec2 point, double vn, double vt, double arm_a,
                                                                double arm_b, double rmin, const pl_vec2 *wall_r,
                                                                int wall_end, double wrel, double reff,
                                                                pl_contact_out *o, int apply) {
    const double fn_el = pp->kn * delta;
    /* onset: the outlines met during the last step; the dashpot sees only the overlap built
       since then, c delta / dt, not the whole step's approach c |v_n| (see pl__release) */
    double vd = vn;
    if (!p->touching && vn * dt < -delta) vd = -delta / dt;
    const double fn_d = -p->cn * vd;
    const double fn = fn_el + fn_d;
    double fs = p->fs - pp->ks * vt * dt;
    double fd = -p->cs * vt;
    const double smax = pp->friction * fn_el + pp->cohesion;
    if (fabs(fs) > smax) {
        const double lim = smax > 0 ? smax : 0;
        fs = fs > 0 ? lim : -lim;
        fd = 0;
    } else if (fabs(fs + fd) > smax) {
        /* seed 003, text below eq. 2.19: with shear damping the limit is |S + D_S| <= S_max;
           the spring keeps its (sub-limit) history and the dashpot gives what is left */
        fd = (fs + fd > 0 ? smax : -smax) - fs;
    }
    const double ft = fs + fd;
    double es = 0.5 * fs * fs * pp->inv_ks;
    const double en = 0.5 * fn_el * delta;
    uint32_t flags = PL_OUT_F | PL_OUT_FD | PL_OUT_FS | PL_OUT_TQA | PL_OUT_TQB | PL_OUT_DMA | PL_OUT_DMB | PL_OUT_LAW;
    if (pp->rolling > 0) {
        const double kr = pp->ks * reff * reff;
        const double mmax = pp->rolling * reff * (fn_el > 0 ? fn_el : 0);
        double mr = p->mr - kr * wrel * dt;
        if (fabs(mr) > mmax) mr = mr > 0 ? mmax : -mmax;
        p->mr = mr;
        if (kr > 0) es += 0.5 * mr * mr / kr;
        flags |= PL_OUT_ROLL;
        o->add.mr = mr;
    }
    p->fs = fs;
    p->fn = fn;
    p->ft = ft;
    p->overlap = delta;
    p->normal = n;
    p->point = point;
    p->touching = 1;
    p->elastic = en + es;
    o->es = es;
    o->en = en;
    const pl_vec2 t = {-n.y, n.x};
    o->add.fx = fn * n.x + ft * t.x;
    o->add.fy = fn * n.y + ft * t.y;
    o->add.dfx = fn_d * n.x + fd * t.x;
    o->add.dfy = fn_d * n.y + fd * t.y;
    o->add.sfx = fs * t.x;
    o->add.sfy = fs * t.y;
    if (wall_r) {
        /* moment on the wall from +F (wall b) or -F (wall a) about its centroid */
        const pl_vec2 F = {o->add.fx, o->add.fy}, Fd = {o->add.dfx, o->add.dfy}, Fs = {o->add.sfx, o->add.sfy};
        const double sgn = wall_end == 1 ? 1 : -1;
        const double tw = sgn * pl__cross2(*wall_r, F), tk = -((wall_end == 1 ? arm_a : arm_b) * ft);
        const double dw = sgn * pl__cross2(*wall_r, Fd), dk = -((wall_end == 1 ? arm_a : arm_b) * fd);
        const double sw = sgn * pl__cross2(*wall_r, Fs), sk = -((wall_end == 1 ? arm_a : arm_b) * fs);
        if (wall_end == 1) o->add.tqb = tw, o->add.tqa = tk, o->add.dmb = dw, o->add.dma = dk, o->add.smb = sw, o->add.sma = sk;
        else o->add.tqa = tw, o->add.tqb = tk, o->add.dma = dw, o->add.dmb = dk, o->add.sma = sw, o->add.smb = sk;
    } else {
        o->add.tqa = -(arm_a * ft);
        o->add.tqb = -(arm_b * ft);
        o->add.dma = -(arm_a * fd);
        o->add.dmb = -(arm_b * fd);
        o->add.sma = -(arm_a * fs);
        o->add.smb = -(arm_b * fs);
    }
    o->ratio = delta / rmin;
    o->add.flags = flags;
    if (apply) {
        pl__apply(c, o, a, b);
        pl__account_law(c, o, a, b);
    }
}

static inline __attribute__((always_inline)) void pl__contact_disc_disc(pl_disc_ctx *c, pl_pair *p,
                                                                        const pl_pair_params *pp, double dt,
                                                                        pl_contact_out *o, int apply) {
    const int a = p->a, b = p->b;
    const pl_vec2 pa = c->pos[a], pb = c->pos[b];
    const double dx = pb.x - pa.x, dy = pb.y - pa.y;
    const double ra = c->radius[a], rb = c->radius[b], rs = ra + rb;
    const double d2 = dx * dx + dy * dy;
    if (d2 >= rs * rs) {
        pl__release(c, p, dt, a, b, -1, o, apply);
        return;
    }
    const double d = sqrt(d2), id = d > 0 ? 1.0 / d : 0;
    const pl_vec2 n = d > 0 ? (pl_vec2){dx * id, dy * id} : (pl_vec2){0, 1};
    const double delta = rs - d;
    /* contact point: middle of the overlap on the line of centres */
    const double la = ra - 0.5 * delta, lb = rb - 0.5 * delta;
    const pl_vec2 point = {pa.x + la * n.x, pa.y + la * n.y};
    /* material point velocities: v + omega x r, r = +la n for a and -lb n for b */
    const pl_vec2 va = c->vel[a], vb = c->vel[b];
    const double wa = c->omega[a] * la, wb = c->omega[b] * lb;
    const pl_vec2 vrel = {vb.x + wb * n.y - va.x + wa * n.y, vb.y - wb * n.x - va.y - wa * n.x};
    const double vn = vrel.x * n.x + vrel.y * n.y, vt = -vrel.x * n.y + vrel.y * n.x;
    pl__disc_law(c, p, pp, dt, a, b, n, delta, point, vn, vt, la, lb, ra < rb ? ra : rb, NULL, 0,
                 c->omega[b] - c->omega[a], ra * rb / rs, o, apply);
}

static inline __attribute__((always_inline)) void pl__contact_disc_segment(pl_disc_ctx *c, const pl_world *w,
                                                                           pl_pair *p, const pl_pair_params *pp,
                                                                           double dt, pl_contact_out *o, int apply) {
    const int s = p->swapped ? p->a : p->b; /* the wall */
    const int k = p->swapped ? p->b : p->a; /* the disc */
    const pl_vec2 *v = &w->verts_world[w->vert_offset[s]];
    const pl_vec2 A = v[0], B = v[1], P = c->pos[k];
    const double ex = B.x - A.x, ey = B.y - A.y, l2 = ex * ex + ey * ey;
    double u = ((P.x - A.x) * ex + (P.y - A.y) * ey) / l2;
    u = u < 0 ? 0 : (u > 1 ? 1 : u);
    const pl_vec2 Q = {A.x + u * ex, A.y + u * ey};
    const double dx = P.x - Q.x, dy = P.y - Q.y, d2 = dx * dx + dy * dy;
    const double r = c->radius[k];
    if (d2 >= r * r) {
        pl__release(c, p, dt, p->a, p->b, s, o, apply);
        return;
    }
    const double d = sqrt(d2);
    /* normal from the wall towards the disc; a centre exactly on the wall uses the wall's
       left-hand normal */
    const pl_vec2 n = d > 0 ? (pl_vec2){dx / d, dy / d} : (pl_vec2){-ey / sqrt(l2), ex / sqrt(l2)};
    const double delta = r - d;
    const double lk = r - 0.5 * delta;
    const pl_vec2 point = {P.x - lk * n.x, P.y - lk * n.y};
    /* wall material velocity at the contact point, and its lever about its centroid along t */
    const pl_vec2 rw = {point.x - c->pos[s].x, point.y - c->pos[s].y};
    const pl_vec2 vw = {c->vel[s].x - c->omega[s] * rw.y, c->vel[s].y + c->omega[s] * rw.x};
    const pl_vec2 vk = {c->vel[k].x + c->omega[k] * lk * n.y, c->vel[k].y - c->omega[k] * lk * n.x};
    if (!p->swapped) {
        /* a = disc, b = wall: n from a to b is -n; the tangent flips with it */
        const pl_vec2 nab = {-n.x, -n.y};
        const pl_vec2 vrel = {vw.x - vk.x, vw.y - vk.y};
        const double vn = vrel.x * nab.x + vrel.y * nab.y, vt = -vrel.x * nab.y + vrel.y * nab.x;
        pl__disc_law(c, p, pp, dt, k, s, nab, delta, point, vn, vt, lk, 0, r, &rw, 1, c->omega[s] - c->omega[k], r, o,
                     apply);
    } else {
        const pl_vec2 vrel = {vk.x - vw.x, vk.y - vw.y};
        const double vn = vrel.x * n.x + vrel.y * n.y, vt = -vrel.x * n.y + vrel.y * n.x;
        pl__disc_law(c, p, pp, dt, s, k, n, delta, point, vn, vt, 0, lk, r, &rw, 0, c->omega[k] - c->omega[s], r, o,
                     apply);
    }
}
#endif
