/* Cundall-Strack contact law (seed 003 §2.2.4.2, eqs. 2.7-2.20):
 *   normal:  N = k_N delta (linear spring on the overlap delta) + D_N = c_N d(delta)/dt
 *   shear:   S += k_S ds  (incremental spring, history kept while the contact lasts)
 *            D_S = c_S ds/dt,  Coulomb: |S| <= mu N + c  (eq. 2.17); when sliding, S is set
 *            to the limit with its sign and the shear dashpot is off.
 * The contact lasts while the outlines overlap; the spring-plus-dashpot normal force may
 * turn slightly tensile just before separation, as in the seed (this keeps the analytic
 * restitution e = exp(-pi zeta / sqrt(1 - zeta^2))).
 * Conventions: the normal n points from a to b, the tangent t = (-n.y, n.x); the force on
 * b is +F = F_n n + F_t t, on a it is -F. Moments about the centroids. */
#include "dem/contact_disc.h"
#include <math.h>

static inline double cross2(pl_vec2 r, pl_vec2 f) { return r.x * f.y - r.y * f.x; }

/* Shared tail of both laws: given the geometry at the contact, the relative velocity of b's
   material point with respect to a's, and the effective mass, evaluate forces and apply. */
static inline __attribute__((always_inline)) void apply_law(pl_world *w, pl_pair *p, const pl_pair_params *pp,
                                                             double dt, int a, int b, pl_vec2 n, double delta,
                                                             pl_vec2 point, pl_vec2 vrel, double rmin) {
    const pl_vec2 t = {-n.y, n.x};
    const double vn = vrel.x * n.x + vrel.y * n.y; /* < 0 while approaching */
    const double vt = vrel.x * t.x + vrel.y * t.y;
    const double cn = p->cn, cs = p->cs;
    const double fn_el = pp->kn * delta;
    const double fn_d = -cn * vn;
    const double fn = fn_el + fn_d;
    /* shear: the spring force on b opposes b's sliding relative to a */
    double fs = p->fs - pp->ks * vt * dt;
    double fd = -cs * vt;
    const double smax = pp->friction * fn_el + pp->cohesion;
    if (fabs(fs) > smax) {
        const double lim = smax > 0 ? smax : 0;
        fs = fs > 0 ? lim : -lim;
        fd = 0;
    }
    p->fs = fs;
    const double ft = fs + fd;
    p->fn = fn;
    p->ft = ft;
    p->overlap = delta;
    p->normal = n;
    p->point = point;
    p->touching = 1;
    const double es = 0.5 * fs * fs * pp->inv_ks;
    p->elastic = 0.5 * fn_el * delta + es;
    w->e_shear += es;
    const pl_vec2 F = {fn * n.x + ft * t.x, fn * n.y + ft * t.y};
    const pl_vec2 ra = {point.x - w->pos[a].x, point.y - w->pos[a].y};
    const pl_vec2 rb = {point.x - w->pos[b].x, point.y - w->pos[b].y};
    w->force[b].x += F.x;
    w->force[b].y += F.y;
    w->force[a].x -= F.x;
    w->force[a].y -= F.y;
    w->torque[b] += cross2(rb, F);
    w->torque[a] -= cross2(ra, F);
    /* split for the energy tallies: dashpot part and tangential spring part */
    const pl_vec2 Fd = {fn_d * n.x + fd * t.x, fn_d * n.y + fd * t.y};
    const pl_vec2 Fs = {fs * t.x, fs * t.y};
    w->fdamp[b].x += Fd.x;
    w->fdamp[b].y += Fd.y;
    w->fdamp[a].x -= Fd.x;
    w->fdamp[a].y -= Fd.y;
    w->tdamp[b] += cross2(rb, Fd);
    w->tdamp[a] -= cross2(ra, Fd);
    w->fshear[b].x += Fs.x;
    w->fshear[b].y += Fs.y;
    w->fshear[a].x -= Fs.x;
    w->fshear[a].y -= Fs.y;
    w->tshear[b] += cross2(rb, Fs);
    w->tshear[a] -= cross2(ra, Fs);
    const double ratio = delta / rmin;
    if (ratio > w->worst_overlap_ratio) {
        w->worst_overlap_ratio = ratio;
        w->worst_a = a;
        w->worst_b = b;
    }
}

static inline void untouch(pl_pair *p) {
    if (!p->touching) return; /* most listed pairs stay apart: do not rewrite them */
    p->touching = 0;
    p->fs = 0;
    p->fn = 0;
    p->ft = 0;
    p->overlap = 0;
    p->elastic = 0;
}

void pl__contact_disc_disc(pl_world *w, pl_pair *p, const pl_pair_params *pp, double dt) {
    const int a = p->a, b = p->b;
    const double dx = w->pos[b].x - w->pos[a].x, dy = w->pos[b].y - w->pos[a].y;
    const double ra = w->radius[a], rb = w->radius[b], rs = ra + rb;
    const double d2 = dx * dx + dy * dy;
    if (d2 >= rs * rs) {
        untouch(p);
        return;
    }
    const double d = sqrt(d2), id = d > 0 ? 1.0 / d : 0;
    const pl_vec2 n = d > 0 ? (pl_vec2){dx * id, dy * id} : (pl_vec2){0, 1};
    const double delta = rs - d;
    /* contact point: midpoint of the overlap along the line of centres (seed 003 §2.2.4.2) */
    const double la = ra - 0.5 * delta, lb = rb - 0.5 * delta;
    const pl_vec2 point = {w->pos[a].x + la * n.x, w->pos[a].y + la * n.y};
    /* velocities of the material points at the contact (omega x r, r = +la n for a, -lb n for b) */
    const pl_vec2 va = {w->vel[a].x - w->omega[a] * la * n.y, w->vel[a].y + w->omega[a] * la * n.x};
    const pl_vec2 vb = {w->vel[b].x + w->omega[b] * lb * n.y, w->vel[b].y - w->omega[b] * lb * n.x};
    const pl_vec2 vrel = {vb.x - va.x, vb.y - va.y};
    apply_law(w, p, pp, dt, a, b, n, delta, point, vrel, ra < rb ? ra : rb);
}

void pl__contact_disc_segment(pl_world *w, pl_pair *p, const pl_pair_params *pp, double dt) {
    const int s = p->swapped ? p->a : p->b; /* the wall */
    const int c = p->swapped ? p->b : p->a; /* the disc */
    const pl_vec2 *v = &w->verts_world[w->vert_offset[s]];
    const pl_vec2 A = v[0], B = v[1], P = w->pos[c];
    const double ex = B.x - A.x, ey = B.y - A.y, l2 = ex * ex + ey * ey;
    double u = ((P.x - A.x) * ex + (P.y - A.y) * ey) / l2;
    u = u < 0 ? 0 : (u > 1 ? 1 : u);
    const pl_vec2 Q = {A.x + u * ex, A.y + u * ey};
    const double dx = P.x - Q.x, dy = P.y - Q.y, d2 = dx * dx + dy * dy;
    const double r = w->radius[c];
    if (d2 >= r * r) {
        untouch(p);
        return;
    }
    const double d = sqrt(d2);
    /* normal from the wall towards the disc; a centre exactly on the wall uses the wall's
       left-hand normal */
    pl_vec2 n = d > 0 ? (pl_vec2){dx / d, dy / d} : (pl_vec2){-ey / sqrt(l2), ex / sqrt(l2)};
    const double delta = r - d;
    const double lc = r - 0.5 * delta;
    const pl_vec2 point = {P.x - lc * n.x, P.y - lc * n.y};
    /* wall material point velocity at the contact point */
    const pl_vec2 rw = {point.x - w->pos[s].x, point.y - w->pos[s].y};
    const pl_vec2 vw = {w->vel[s].x - w->omega[s] * rw.y, w->vel[s].y + w->omega[s] * rw.x};
    const pl_vec2 vc = {w->vel[c].x + w->omega[c] * lc * n.y, w->vel[c].y - w->omega[c] * lc * n.x};
    if (!p->swapped) {
        /* a = disc, b = wall: flip to keep n from a to b */
        const pl_vec2 nab = {-n.x, -n.y};
        const pl_vec2 vrel = {vw.x - vc.x, vw.y - vc.y};
        apply_law(w, p, pp, dt, c, s, nab, delta, point, vrel, r);
    } else {
        const pl_vec2 vrel = {vc.x - vw.x, vc.y - vw.y};
        apply_law(w, p, pp, dt, s, c, n, delta, point, vrel, r);
    }
}
