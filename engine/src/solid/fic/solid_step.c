/* One explicit step of the solid (seed 002 eqs. 97-98, 114-118): central differences with the
 * lumped mass, centred mass-proportional damping, prescribed-velocity sets with their
 * reactions, edge tractions (fixed direction plus a following pressure), gravity; the energy
 * ledger; and the grain-edge contact kernel (eqs. 105-109). */
#include "solid/fic/solid_internal.h"
#include "core/alloc.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* External nodal forces at the current configuration: tractions and gravity. */
static void external_forces(const pl_sf *s, double *fe) {
    for (int i = 0; i < s->nn; i++) {
        fe[2 * i] = s->m[i] * s->gravity.x;
        fe[2 * i + 1] = s->m[i] * s->gravity.y;
    }
    const double *xy = s->def.large_strain ? s->x : s->X;
    for (int k = 0; k < s->ntrac; k++) {
        const pl_sf_traction *t = &s->trac[k];
        const double ex = xy[2 * t->b] - xy[2 * t->a], ey = xy[2 * t->b + 1] - xy[2 * t->a + 1];
        const double L = hypot(ex, ey);
        /* outward normal of a CCW boundary edge: (ey, -ex) / L; pressure pushes along -n */
        const double fx = (t->tx * L - t->pn * ey) / 2, fy = (t->ty * L + t->pn * ex) / 2;
        fe[2 * t->a] += fx;
        fe[2 * t->a + 1] += fy;
        fe[2 * t->b] += fx;
        fe[2 * t->b + 1] += fy;
    }
}

pl_status pl_sf_step(pl_sf *s, double dt, const double *fext) {
    if (!(dt > 0)) return PL_OK;
    if (dt > s->dt_crit) {
        const int e = s->dt_elem;
        const int32_t *c = &s->conn[(size_t)e * s->nen];
        snprintf(s->err, sizeof s->err,
                 "solid: the time step %.4g s exceeds the critical step %.4g s of element %d (near (%.4g, %.4g) "
                 "m) at t = %.6g s: central differences would blow up. Set dt <= %.4g s (or dt = 0 for the "
                 "automatic step, which includes the solid)",
                 dt, s->dt_crit, e + 1, s->x[2 * c[0]], s->x[2 * c[0] + 1], s->time, 0.9 * s->dt_crit);
        return PL_ERR_UNSTABLE;
    }
    const int fic = s->def.formulation == PL_SOLID_FIC_EXPLICIT || s->def.formulation == PL_SOLID_FIC_SEMI_IMPLICIT;
    if (fic && ((s->def.formulation == PL_SOLID_FIC_SEMI_IMPLICIT && !s->chol) ||
                (s->def.formulation == PL_SOLID_FIC_EXPLICIT && s->fic_rho == 0))) {
        pl_status st = pl_sf_fic_prepare(s);
        if (st != PL_OK) return st;
    }
    const int nn = s->nn;
    double *fe = s->f;
    external_forces(s, fe);
    if (fext)
        for (int k = 0; k < 2 * nn; k++) fe[k] += fext[k];
    const double c = s->def.damping;
    for (int k = 0; k < s->nsets; k++) s->sets[k].reaction[0] = s->sets[k].reaction[1] = 0;
    double wext = 0, wint = 0, wdamp = 0, wcont = 0, ke = 0;
    for (int i = 0; i < nn; i++) {
        for (int d = 0; d < 2; d++) {
            const int k = 2 * i + d;
            const double vold = s->v[k];
            double vnew;
            const double F = fe[k] - s->f_prev[k];
            if (s->fix[i] & (1 << d)) {
                vnew = s->vpres[k];
            } else {
                vnew = ((1 - 0.5 * c * dt) * vold + dt * F / s->m[i]) / (1 + 0.5 * c * dt);
            }
            const double vmid = 0.5 * (vold + vnew);
            wext += fe[k] * vmid * dt;
            wint += s->f_prev[k] * vmid * dt;
            if (fext) wcont += fext[k] * vmid * dt;
            if (!(s->fix[i] & (1 << d))) wdamp += c * s->m[i] * vmid * vmid * dt;
            else {
                /* the support's force on the solid: what the node needs beyond F */
                const double R = s->m[i] * (vnew - vold) / dt - F;
                wext += R * vmid * dt;
                s->fe_prev[k] = R; /* reaction at this node, summed into the sets below */
            }
            ke += 0.5 * s->m[i] * vmid * vmid;
            s->v[k] = vnew;
            s->du[k] = dt * vnew;
            s->x[k] += s->du[k];
        }
    }
    for (int k = 0; k < s->nsets; k++) {
        pl_sf_set *st = &s->sets[k];
        for (int q = 0; q < st->n; q++) {
            const int i = st->nodes[q];
            if (st->mask & 1) st->reaction[0] += s->fe_prev[2 * i];
            if (st->mask & 2) st->reaction[1] += s->fe_prev[2 * i + 1];
        }
    }
    s->e.kinetic = ke;
    s->e.external += wext;
    s->e.internal += wint;
    s->e.damping += wdamp;
    s->e.contact += wcont;
    pl_status st = pl_sf_internal_force(s, s->du, s->f_prev);
    if (st != PL_OK) return st;
    s->time += dt;
    s->step++;
    for (int k = 0; k < 2 * nn; k++)
        if (!isfinite(s->x[k]) || !isfinite(s->v[k])) {
            snprintf(s->err, sizeof s->err,
                     "solid: node %d has a non-finite position or velocity at t = %.6g s (step %lld); the step "
                     "%.4g s is %.3g times the critical step %.4g s",
                     k / 2 + 1, s->time, (long long)s->step, dt, dt / s->dt_crit, s->dt_crit);
            return PL_ERR_UNSTABLE;
        }
    /* updated Lagrangian: the element bound follows the deformation (every 50 steps) */
    if (s->def.large_strain && s->step % 50 == 0) {
        double dmin = INFINITY;
        int emin = -1;
        for (int e = 0; e < s->ne; e++) {
            const double d = pl_sf_element_dt(s, e, s->x);
            if (!(d > 0)) {
                snprintf(s->err, sizeof s->err,
                         "solid: element %d has turned inside out at t = %.6g s (updated Lagrangian); the load "
                         "or the tool speed is too large for this mesh",
                         e + 1, s->time);
                return PL_ERR_UNSTABLE;
            }
            if (d < dmin) dmin = d, emin = e;
        }
        s->dt_crit = dmin;
        s->dt_elem = emin;
    }
    return PL_OK;
}

/* ---------------------------------------------------------------- contact */

double pl_sf_node_temperature(const pl_sf *s, int i) {
    if (!s->heat) return NAN;
    const double C = s->m[i] * s->thermal.heat_capacity;
    return C > 0 ? s->t0 + s->heat[i] / C : s->t0;
}

/* Frictional heat and Archard wear of one sliding point (the laws of the grains' contacts,
   dem/heat.c, docs/rock.md): Q = fraction |F_t v_t| dt, half to the element side spread to the
   edge's nodes by the shape weights (1 - t, t) (b < 0: node a alone), half to the grain; the
   element side wears dV = k F_n |v_t| dt / H(T) at each node by its weight. */
static void slide_heat(const pl_sf *s, int a, int b, double t, double Fn, double Ft, double vt, double dt,
                       pl_sf_contact_out *out) {
    if (!s->heat) return;
    const double Q = s->heat_fraction * fabs(Ft * vt) * dt, W = Fn > 0 ? Fn * fabs(vt) * dt : 0;
    const double wa = b < 0 ? 1 : 1 - t;
    out->heat_grain += 0.5 * Q;
    out->wear_work += W;
    const int nodes[2] = {a, b};
    const double wt[2] = {wa, 1 - wa};
    for (int k = 0; k < 2; k++) {
        if (nodes[k] < 0 || wt[k] == 0) continue;
        const int i = nodes[k];
        s->heat[i] += 0.5 * Q * wt[k];
        if (s->thermal.wear > 0)
            s->wear[i] += wt[k] * s->thermal.wear * W / pl_thermal_hardness(&s->thermal, pl_sf_node_temperature(s, i));
    }
}

static void contact_at(const pl_sf *s, pl_vec2 c, pl_vec2 vc, double omega, double r, double dt, pl_vec2 q,
                       pl_vec2 n, double delta, int a, int b, double t, double *fsolid, pl_sf_contact_out *out) {
    const pl_solid_def *d = &s->def;
    /* velocities: disc surface point, edge point (linear shape functions of the edge) */
    const double vdx = vc.x + omega * r * n.y, vdy = vc.y - omega * r * n.x;
    const double vqx = (1 - t) * s->v[2 * a] + t * s->v[2 * b], vqy = (1 - t) * s->v[2 * a + 1] + t * s->v[2 * b + 1];
    const double rx = vdx - vqx, ry = vdy - vqy;
    const double vn = rx * n.x + ry * n.y;
    /* eq. 105: elastic plus viscous part, not clipped (as the grains' own dashpot), so that an
       impact has the restitution of the linear spring-dashpot; friction sees |F_n| */
    const double Fn = d->contact_stiffness * delta - d->contact_damping * vn;
    const pl_vec2 tt = {-n.y, n.x};
    const double vt = rx * tt.x + ry * tt.y;
    const double Ft = -d->friction * fabs(Fn) * tanh(vt / d->slip_velocity);
    const double Fx = Fn * n.x + Ft * tt.x, Fy = Fn * n.y + Ft * tt.y;
    out->fx += Fx;
    out->fy += Fy;
    /* arm from the centre to the contact point: -r n */
    out->m += -r * n.x * Fy + r * n.y * Fx;
    out->touching = 1;
    if (delta > out->overlap) out->overlap = delta;
    out->e_dashpot += d->contact_damping * vn * vn * dt;
    out->e_friction += fabs(Ft * vt) * dt;
    slide_heat(s, a, b, t, Fn, Ft, vt, dt, out);
    (void)q;
    if (fsolid) {
        fsolid[2 * a] -= (1 - t) * Fx;
        fsolid[2 * a + 1] -= (1 - t) * Fy;
        fsolid[2 * b] -= t * Fx;
        fsolid[2 * b + 1] -= t * Fy;
    }
}

/* A candidate contact of one disc with one boundary feature. */
typedef struct cand {
    int a, b, edge;
    double t, delta;
    pl_vec2 n, q;
} cand;

void pl_sf_disc_contact(const pl_sf *s, pl_vec2 c, pl_vec2 vc, double omega, double r, double dt, double *fsolid,
                        pl_sf_contact_out *out) {
    memset(out, 0, sizeof *out);
    const double *x = s->x;
    cand cs[16];
    int nc = 0;
    for (int k = 0; k < s->nbedge && nc < 16; k++) {
        const int a = s->bedge[2 * k], b = s->bedge[2 * k + 1];
        const double ax = x[2 * a], ay = x[2 * a + 1], ex = x[2 * b] - ax, ey = x[2 * b + 1] - ay;
        /* quick reject on the edge's box */
        const double lx = fmin(ax, ax + ex) - r, hx = fmax(ax, ax + ex) + r;
        const double ly = fmin(ay, ay + ey) - r, hy = fmax(ay, ay + ey) + r;
        if (c.x < lx || c.x > hx || c.y < ly || c.y > hy) continue;
        const double l2 = ex * ex + ey * ey;
        const double t = ((c.x - ax) * ex + (c.y - ay) * ey) / l2;
        /* outside distance along the outward normal (ey, -ex)/L */
        const double L = sqrt(l2);
        const double side = ((c.x - ax) * ey - (c.y - ay) * ex) / L;
        if (side <= -r) continue;
        if (t > 0 && t < 1) {
            /* face contact: centre beside the edge, on its outer side */
            if (side <= 0 || side >= r) continue;
            cs[nc++] = (cand){a, b, k, t, r - side, {ey / L, -ex / L}, {ax + t * ex, ay + t * ey}};
        } else if (t <= 0) {
            /* vertex a (counted by the edge that starts at a) when the centre lies past the end
               of the previous edge too: a convex corner */
            const double dx = c.x - ax, dy = c.y - ay, dist = hypot(dx, dy);
            if (dist >= r || dist <= 0) continue;
            int ok = 1;
            for (int k2 = 0; k2 < s->nbedge; k2++) {
                if (s->bedge[2 * k2 + 1] != a) continue;
                const int p0 = s->bedge[2 * k2];
                const double px = x[2 * p0], py = x[2 * p0 + 1], fx = ax - px, fy = ay - py;
                /* the same arithmetic as that edge's own face test, so exactly one of them counts */
                const double tp = ((c.x - px) * fx + (c.y - py) * fy) / (fx * fx + fy * fy);
                if (tp < 1) ok = 0;
                break;
            }
            if (!ok) continue;
            cs[nc++] = (cand){a, b, k, 0, r - dist, {dx / dist, dy / dist}, {ax, ay}};
        }
    }
    /* one contact per stretch of boundary: where two candidates share a node (a slightly
       concave kink of the deformed surface), only the deeper one acts, so that the contact
       stiffness does not double at a node */
    for (int i = 0; i < nc; i++) {
        int keep = 1;
        for (int j = 0; j < nc && keep; j++) {
            if (j == i) continue;
            const int share = cs[i].a == cs[j].a || cs[i].a == cs[j].b || cs[i].b == cs[j].a || cs[i].b == cs[j].b;
            if (share && (cs[j].delta > cs[i].delta || (cs[j].delta == cs[i].delta && j < i))) keep = 0;
        }
        if (keep)
            contact_at(s, c, vc, omega, r, dt, cs[i].q, cs[i].n, cs[i].delta, cs[i].a, cs[i].b, cs[i].t, fsolid, out);
    }
}

/* Normal spring-dashpot and regularised Coulomb friction at point q of a grain (centroid c,
   velocity vc, spin omega) pressed along n (unit, pointing from the solid into the grain) by
   delta; the solid side is the point with shape weights (1 - t, t) on nodes a, b (b < 0: the
   node a alone). Force and moment on the grain into out, the opposite into fsolid. */
static void point_contact(const pl_sf *s, pl_vec2 c, pl_vec2 vc, double omega, double dt, pl_vec2 q, pl_vec2 n,
                          double delta, int a, int b, double t, double *fsolid, pl_sf_contact_out *out) {
    const pl_solid_def *d = &s->def;
    const double vgx = vc.x - omega * (q.y - c.y), vgy = vc.y + omega * (q.x - c.x);
    double vsx = s->v[2 * a], vsy = s->v[2 * a + 1];
    if (b >= 0) {
        vsx = (1 - t) * vsx + t * s->v[2 * b];
        vsy = (1 - t) * vsy + t * s->v[2 * b + 1];
    }
    const double rx = vgx - vsx, ry = vgy - vsy;
    const double vn = rx * n.x + ry * n.y;
    const double Fn = d->contact_stiffness * delta - d->contact_damping * vn;
    const pl_vec2 tt = {-n.y, n.x};
    const double vt = rx * tt.x + ry * tt.y;
    const double Ft = -d->friction * fabs(Fn) * tanh(vt / d->slip_velocity);
    const double Fx = Fn * n.x + Ft * tt.x, Fy = Fn * n.y + Ft * tt.y;
    out->fx += Fx;
    out->fy += Fy;
    out->m += (q.x - c.x) * Fy - (q.y - c.y) * Fx;
    out->touching = 1;
    if (delta > out->overlap) out->overlap = delta;
    out->spring += 0.5 * d->contact_stiffness * delta * delta;
    out->e_dashpot += d->contact_damping * vn * vn * dt;
    out->e_friction += fabs(Ft * vt) * dt;
    slide_heat(s, a, b, t, Fn, Ft, vt, dt, out);
    if (fsolid) {
        if (b < 0) {
            fsolid[2 * a] -= Fx;
            fsolid[2 * a + 1] -= Fy;
        } else {
            fsolid[2 * a] -= (1 - t) * Fx;
            fsolid[2 * a + 1] -= (1 - t) * Fy;
            fsolid[2 * b] -= t * Fx;
            fsolid[2 * b + 1] -= t * Fy;
        }
    }
}

void pl_sf_polygon_contact(const pl_sf *s, pl_vec2 c, pl_vec2 vc, double omega, const pl_vec2 *vert, int nv,
                           double dt, double *fsolid, pl_sf_contact_out *out) {
    memset(out, 0, sizeof *out);
    const double *x = s->x;
    double lx = INFINITY, ly = INFINITY, hx = -INFINITY, hy = -INFINITY;
    for (int k = 0; k < nv; k++) {
        lx = fmin(lx, vert[k].x), hx = fmax(hx, vert[k].x);
        ly = fmin(ly, vert[k].y), hy = fmax(hy, vert[k].y);
    }
    /* 1. grain vertices inside the solid: pushed out through the nearest boundary edge (the
       penetration measured along that edge's outward normal, at most half its length) */
    for (int v = 0; v < nv; v++) {
        const pl_vec2 P = vert[v];
        int best = -1;
        double bt = 0, bd = 0;
        pl_vec2 bn = {0, 0};
        for (int k = 0; k < s->nbedge; k++) {
            const int a = s->bedge[2 * k], b = s->bedge[2 * k + 1];
            const double ax = x[2 * a], ay = x[2 * a + 1], ex = x[2 * b] - ax, ey = x[2 * b + 1] - ay;
            const double l2 = ex * ex + ey * ey, L = sqrt(l2);
            if (P.x < fmin(ax, ax + ex) - L || P.x > fmax(ax, ax + ex) + L || P.y < fmin(ay, ay + ey) - L ||
                P.y > fmax(ay, ay + ey) + L)
                continue;
            const double tp = ((P.x - ax) * ex + (P.y - ay) * ey) / l2;
            if (tp < 0 || tp > 1) continue;
            const double side = ((P.x - ax) * ey - (P.y - ay) * ex) / L; /* > 0 outside */
            if (side >= 0 || side < -0.5 * L) continue;
            if (best < 0 || -side < bd) best = k, bd = -side, bt = tp, bn = (pl_vec2){ey / L, -ex / L};
        }
        if (best < 0) continue;
        point_contact(s, c, vc, omega, dt, P, bn, bd, s->bedge[2 * best], s->bedge[2 * best + 1], bt, fsolid, out);
    }
    /* 2. solid boundary nodes inside the (convex, counter-clockwise) grain: pushed out through
       the grain's nearest edge (a corner of the solid pressing on a face of the grain) */
    for (int k = 0; k < s->nbedge; k++) {
        const int a = s->bedge[2 * k];
        const pl_vec2 N = {x[2 * a], x[2 * a + 1]};
        if (N.x < lx || N.x > hx || N.y < ly || N.y > hy) continue;
        double dmin = INFINITY;
        pl_vec2 nmin = {0, 0};
        int inside = 1;
        for (int e = 0; e < nv && inside; e++) {
            const pl_vec2 A = vert[e], B = vert[(e + 1) % nv];
            const double ex = B.x - A.x, ey = B.y - A.y, L = hypot(ex, ey);
            const double dist = ((N.x - A.x) * (-ey) + (N.y - A.y) * ex) / L; /* > 0 inside (CCW) */
            if (dist <= 0) inside = 0;
            else if (dist < dmin) dmin = dist, nmin = (pl_vec2){ey / L, -ex / L}; /* outward of the grain */
        }
        if (!inside) continue;
        /* only at a convex corner of the solid (a left turn of more than 20 degrees): along a
           flat stretch the grain's vertices already carry the contact (pass 1) */
        const int b = s->bedge[2 * k + 1];
        int prev = -1;
        for (int k2 = 0; k2 < s->nbedge && prev < 0; k2++)
            if (s->bedge[2 * k2 + 1] == a) prev = s->bedge[2 * k2];
        if (prev < 0) continue;
        const double ux = N.x - x[2 * prev], uy = N.y - x[2 * prev + 1], wx = x[2 * b] - N.x, wy = x[2 * b + 1] - N.y;
        if (!(ux * wy - uy * wx > 0.342 * hypot(ux, uy) * hypot(wx, wy))) continue;
        /* the node pushes the grain inwards: n = -(outward normal of the grain's nearest edge) */
        point_contact(s, c, vc, omega, dt, N, (pl_vec2){-nmin.x, -nmin.y}, dmin, a, -1, 0, fsolid, out);
    }
}

/* ---------------------------------------------------------------- hash */

uint64_t pl_sf_hash(const pl_sf *s, uint64_t h) {
    const size_t N = (size_t)s->nn, I = (size_t)s->ne * s->nip;
    for (int k = 0; k < PL_SOLID_PARAM_COUNT; k++) {
        const double v = pl_param_read(&pl_solid_params[k], &s->def);
        h = pl_hash_bytes(h, &v, sizeof v);
    }
    h = pl_hash_bytes(h, s->x, sizeof *s->x * 2 * N);
    h = pl_hash_bytes(h, s->v, sizeof *s->v * 2 * N);
    h = pl_hash_bytes(h, s->p, sizeof *s->p * N);
    h = pl_hash_bytes(h, s->pi, sizeof *s->pi * 2 * N);
    h = pl_hash_bytes(h, s->gv, sizeof *s->gv * N);
    h = pl_hash_bytes(h, s->f_prev, sizeof *s->f_prev * 2 * N);
    h = pl_hash_bytes(h, s->s, sizeof *s->s * 4 * I);
    h = pl_hash_bytes(h, s->pe, sizeof *s->pe * I);
    h = pl_hash_bytes(h, s->ep, sizeof *s->ep * 4 * I);
    h = pl_hash_bytes(h, s->alpha, sizeof *s->alpha * I);
    const double e[6] = {s->e.kinetic, s->e.internal, s->e.external, s->e.damping, s->e.plastic, s->e.contact};
    h = pl_hash_bytes(h, e, sizeof e);
    h = pl_hash_bytes(h, &s->time, sizeof s->time);
    return pl_hash_bytes(h, &s->step, sizeof s->step);
}
