/* Critical time step (seed 003 §2.2.4.4): 2 sqrt(m/k) for a mass on a spring, reduced for a
 * damped spring to (2/omega)(sqrt(1 + zeta^2) - zeta) (central difference with damping).
 * The estimate takes, for every dynamic body, the stiffest material pair it can meet,
 * translational (k_N, mass m) and rotational (k r^2 about the centroid, inertia I, with k_S for
 * discs whose contacts act at the rim and max(k_N, k_S) for polygons whose corners carry
 * normal forces off the centroid). The step is dt_safety times the smallest of these,
 * capped by MAX_DT_CR.
 * Damping ratio: a pair given a restitution has zeta from e; a pair given a dashpot c_N has
 * zeta = c_N / (2 sqrt(m* k_N)) with m* the reduced mass of the body and the lightest dynamic
 * body it can meet (the body's own mass against walls only), the mass the restitution's zeta
 * is defined with (neighbor.c: c_N = 2 zeta sqrt(m* k_N)), so that the same damping given
 * either way gets the same step. */
#include "dem/world_internal.h"
#include "core/alloc.h"
#include <math.h>
#include <stdlib.h>

static double damped_limit(double m, double k, double zeta) {
    if (!(k > 0) || !(m > 0)) return INFINITY;
    return 2 * sqrt(m / k) * (sqrt(1 + zeta * zeta) - zeta);
}

void pl__compute_dt(pl_world *w) {
    if (w->pair_params_dirty) pl__update_pair_params(w);
    const int nm = w->material_count;
    pl_dt_report r = {0};
    r.dt_critical = INFINITY;
    r.limiting_body = -1;
    r.limit_kind = "none";
    if (nm > 0) {
        uint8_t *used = pl_calloc((size_t)nm, 1);
        double *kn = pl_calloc((size_t)nm, sizeof *kn), *ks = pl_calloc((size_t)nm, sizeof *ks);
        double *cn = pl_calloc((size_t)nm, sizeof *cn), *zeta = pl_calloc((size_t)nm, sizeof *zeta);
        double *roll = pl_calloc((size_t)nm, sizeof *roll);
        /* the two lightest dynamic bodies of each material (the lightest's index in arg1) */
        double *min1 = pl_malloc((size_t)nm * sizeof *min1), *min2 = pl_malloc((size_t)nm * sizeof *min2);
        double *light = pl_malloc((size_t)nm * sizeof *light);
        int *arg1 = pl_malloc((size_t)nm * sizeof *arg1);
        if (used && kn && ks && cn && zeta && roll && min1 && min2 && light && arg1) {
            for (int a = 0; a < nm; a++) {
                min1[a] = min2[a] = light[a] = INFINITY;
                arg1[a] = -1;
            }
            for (int i = 0; i < w->n; i++) {
                const int a = w->material[i];
                used[a] = 1;
                if (w->motion[i] != PL_MOTION_DYNAMIC || !(w->mass[i] > 0)) continue;
                if (w->mass[i] < min1[a]) {
                    min2[a] = min1[a];
                    min1[a] = w->mass[i];
                    arg1[a] = i;
                } else if (w->mass[i] < min2[a]) {
                    min2[a] = w->mass[i];
                }
            }
            /* cn[a]: the largest c_N / sqrt(k_N) of a's dashpot pairs (its damping ratio is
               that over 2 sqrt(m*)); light[a]: the lightest dynamic body of another material
               that a can meet (its own material is looked at per body, without the body) */
            for (int a = 0; a < nm; a++)
                for (int b = 0; b < nm; b++) {
                    if (!used[b]) continue;
                    const pl_pair_params *p = pl__pair_params(w, a, b);
                    kn[a] = fmax(kn[a], p->kn);
                    ks[a] = fmax(ks[a], p->ks);
                    if (p->zeta < 0 && p->kn > 0) cn[a] = fmax(cn[a], p->cn / sqrt(p->kn));
                    zeta[a] = fmax(zeta[a], p->zeta);
                    roll[a] = fmax(roll[a], p->rolling);
                    if (b != a) light[a] = fmin(light[a], min1[b]);
                }
            for (int i = 0; i < w->n; i++) {
                if (w->motion[i] != PL_MOTION_DYNAMIC || !(w->mass[i] > 0)) continue;
                const int m = w->material[i];
                const double mass = w->mass[i];
                const double partner = fmin(light[m], i == arg1[m] ? min2[m] : min1[m]);
                const double mred = isfinite(partner) ? mass * partner / (mass + partner) : mass;
                const double z = fmax(zeta[m], cn[m] / (2 * sqrt(mred)));
                const double dtt = damped_limit(mass, kn[m], z);
                if (dtt < r.dt_critical) {
                    r.dt_critical = dtt;
                    r.limiting_body = i;
                    r.limit_kind = "translation";
                }
                if (w->inv_inertia[i] == 0 && w->law[i].fixed_rotation) continue; /* does not turn */
                const double rr = w->radius[i];
                /* a disc with rolling resistance has the rolling spring (k_S R^2, R <= r) beside
                   the shear spring's k_S r^2 */
                const double kdisc = roll[m] > 0 ? 2 * ks[m] : ks[m];
                const double krot = (w->shape[i] == PL_SHAPE_DISC ? kdisc : fmax(kn[m], ks[m])) * rr * rr;
                const double dtr = damped_limit(w->inertia[i], krot, 0);
                if (dtr < r.dt_critical) {
                    r.dt_critical = dtr;
                    r.limiting_body = i;
                    r.limit_kind = "rotation";
                }
            }
        }
        pl_free(used); pl_free(kn); pl_free(ks); pl_free(cn); pl_free(zeta); pl_free(roll);
        pl_free(min1); pl_free(min2); pl_free(light); pl_free(arg1);
    }
    pl__bond_dt_limit(w, &r.dt_critical, &r.limiting_body, &r.limit_kind);
    if (w->def.dt > 0) {
        r.dt = w->def.dt;
        r.fixed = 1;
    } else {
        r.dt = isfinite(r.dt_critical) ? w->def.dt_safety * r.dt_critical : INFINITY;
        if (w->def.max_dt > 0 && r.dt > w->def.max_dt) {
            r.dt = w->def.max_dt;
            r.capped = 1;
        }
        if (!isfinite(r.dt)) r.dt = 0;
    }
    w->dt_report = r;
    w->dt = r.dt;
}
