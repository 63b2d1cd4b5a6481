/* Cohesive bonds between discs and the solid's boundary edges (docs/solids.md): the grains'
 * bond law (porelab/bonds.h, pl_bond_law_eval: the kernel of the disc-disc bonds) on the
 * opening, slip and rotation of a disc relative to a material point of an edge. The forces on
 * the edge's nodes are the derivatives of the bond's energy with respect to their positions,
 * so that the bond stores and returns energy exactly and the total moment vanishes. */
#include "solid/fic/solid_internal.h"
#include <math.h>
#include <string.h>

static double wrap_angle(double a) {
    while (a > M_PI) a -= 2 * M_PI;
    while (a <= -M_PI) a += 2 * M_PI;
    return a;
}

int pl_sf_bond_make(const pl_sf *s, int grain, pl_vec2 c, double theta, double r, double gap, pl_sf_bond *bd) {
    const double *x = s->x;
    int best = -1;
    double bt = 0, bside = 0, bgap = INFINITY;
    for (int k = 0; k < s->nbedge; k++) {
        const int a = s->bedge[2 * k], b = s->bedge[2 * k + 1];
        const double ax = x[2 * a], ay = x[2 * a + 1], ex = x[2 * b] - ax, ey = x[2 * b + 1] - ay;
        const double l2 = ex * ex + ey * ey, L = sqrt(l2);
        const double t = ((c.x - ax) * ex + (c.y - ay) * ey) / l2;
        if (!(t > 0 && t < 1)) continue;
        const double side = ((c.x - ax) * ey - (c.y - ay) * ex) / L; /* centre's distance outside */
        if (side <= 0) continue;
        const double g = fabs(side - r);
        if (side - r > gap || g >= bgap) continue;
        best = k, bt = t, bside = side, bgap = g;
    }
    if (best < 0) return 0;
    memset(bd, 0, sizeof *bd);
    bd->grain = grain;
    bd->a = s->bedge[2 * best];
    bd->b = s->bedge[2 * best + 1];
    bd->state = PL_BOND_INTACT;
    bd->t0 = bt;
    bd->d0 = bside;
    const double ex = x[2 * bd->b] - x[2 * bd->a], ey = x[2 * bd->b + 1] - x[2 * bd->a + 1];
    bd->th0 = theta - atan2(ey, ex);
    bd->broken_time = -1;
    return 1;
}

double pl_sf_bond_force(const pl_sf *s, const pl_bond_def *L, pl_sf_bond *bd, pl_vec2 c, double theta, double r,
                        double *fsolid, pl_sf_contact_out *out) {
    if (bd->state != PL_BOND_INTACT) return 0;
    const double *x = s->x;
    const int a = bd->a, b = bd->b;
    const double t0 = bd->t0;
    const double ax = x[2 * a], ay = x[2 * a + 1], ex = x[2 * b] - ax, ey = x[2 * b + 1] - ay;
    const double len = hypot(ex, ey);
    const pl_vec2 e = {ex / len, ey / len}, n = {e.y, -e.x}; /* tangent, outward normal */
    const double qx = ax + t0 * ex, qy = ay + t0 * ey;
    const double dx = c.x - qx, dy = c.y - qy;
    const double side = dx * n.x + dy * n.y, slip = dx * e.x + dy * e.y;
    const double un = side - bd->d0, ut = slip;
    const double rot = wrap_angle(theta - atan2(ey, ex) - bd->th0);
    pl_bond_result res;
    pl_bond_law_eval(L, &bd->h, un, ut, rot, r, &res);
    bd->un = un, bd->ut = ut;
    bd->n = res.n, bd->s = res.s, bd->m = res.m, bd->elastic = res.elastic;
    if (res.broke) {
        bd->state = res.broke;
        return res.released;
    }
    const double N = res.n, S = res.s, M = res.m;
    /* on the disc: -dE/dc = -N n - S e, and -dE/dtheta = -M */
    const double Fx = -N * n.x - S * e.x, Fy = -N * n.y - S * e.y;
    out->fx += Fx;
    out->fy += Fy;
    out->m -= M;
    out->touching = 1;
    out->spring += res.elastic;
    if (fsolid) {
        /* on the edge: the opposite force at q (shape weights 1 - t0, t0) and the couple
           T = -dE/dphi = -N slip + S side + M on the edge's direction phi, applied as +-T/len
           along the edge's left normal (-n) at b and a */
        const double T = -N * slip + S * side + M;
        const double cx = -T / len * n.x, cy = -T / len * n.y;
        fsolid[2 * a] += -(1 - t0) * Fx - cx;
        fsolid[2 * a + 1] += -(1 - t0) * Fy - cy;
        fsolid[2 * b] += -t0 * Fx + cx;
        fsolid[2 * b + 1] += -t0 * Fy + cy;
    }
    return res.released;
}
