/* Critical time step (seed 003 §2.2.4.4; derivation in docs/stability.md, "The grain step").
 * Central differences are stable for omega dt < 2, reduced for a damped mode of damping ratio
 * zeta to omega dt < 2 (sqrt(1 + zeta^2) - zeta). For every dynamic body the estimate takes the
 * stiffest material pair it can meet and one contact with a fixed partner (a wall; two equal
 * bodies pressed together give the same estimate with the pair's relative motion), and bounds
 * the highest frequency omega^2 = lambda_max(M^-1 K) of the body's generalised coordinates
 * (x, y, theta), M = diag(m, m, I), K the contact's stiffness:
 *   disc, normal       k_N / m (the normal force passes through the centre)
 *   disc, tangential   k_S (1/m + a^2/I) with a = r the lever arm of the shear force: the
 *                      sticking contact couples sliding and turning (3 k_S / m for a solid
 *                      disc, not 2 k_S / m for turning alone); with rolling resistance the
 *                      rolling spring k_S R^2 (R <= r) adds k_S R^2 / I
 *   polygon            for each edge of length L at distance h from the centroid (foot of the
 *                      perpendicular at offset c from the edge's middle), the edge pressed flat
 *                      on a wall, the stiffest contact the area law makes (contact_polygon.c:
 *                      F = k_N A / l_c with l_c = h): normal spring k_f = k_N L / h at lever c,
 *                      tangential spring k_S L / h at lever h, rocking spring k_N L^3 / (12 h);
 *                      lambda_max of that 3 x 3 problem, exactly.
 * Damping ratios: a pair given a restitution has zeta from e (for polygons the area law's
 * cutoff-corrected zeta', contact_polygon.c); a pair given a dashpot c_N has
 * zeta = c_N / (2 sqrt(m* k_N)) with m* the reduced mass of the body and the lightest dynamic
 * body it can meet (the body's own mass against walls only), the mass the restitution's zeta
 * is defined with (neighbor.c: c_N = 2 zeta sqrt(m* k_N)), so that the same damping given
 * either way gets the same step. The tangential dashpot c_S = c_N k_S / k_N (or given) damps
 * the tangential mode with zeta_t = c_S / (2 sqrt(k_S m_t)), m_t = 1 / (1/m + a^2/I); a polygon's
 * modes are coupled, so its step takes the largest of its normal, tangential and rocking
 * damping ratios. The step is dt_safety times the smallest limit, capped by MAX_DT_CR. */
#include "dem/world_internal.h"
#include "dem/contact_polygon.h"
#include "core/alloc.h"
#include <math.h>
#include <stdlib.h>

static double damped_limit(double m, double k, double zeta) {
    if (!(k > 0) || !(m > 0)) return INFINITY;
    return 2 * sqrt(m / k) * (sqrt(1 + zeta * zeta) - zeta);
}

/* Largest eigenvalue of the symmetric 3 x 3 matrix [[a11 a12 a13] [a12 a22 a23] [a13 a23 a33]]
 * (trigonometric solution of the characteristic cubic, Smith 1961). */
double pl__sym3_max_eig(double a11, double a22, double a33, double a12, double a13, double a23) {
    const double p1 = a12 * a12 + a13 * a13 + a23 * a23;
    const double q = (a11 + a22 + a33) / 3;
    if (p1 <= 1e-300) return fmax(a11, fmax(a22, a33));
    const double b11 = a11 - q, b22 = a22 - q, b33 = a33 - q;
    const double p2 = b11 * b11 + b22 * b22 + b33 * b33 + 2 * p1;
    const double p = sqrt(p2 / 6);
    const double det = b11 * (b22 * b33 - a23 * a23) - a12 * (a12 * b33 - a23 * a13) + a13 * (a12 * a23 - b22 * a13);
    double r = det / (2 * p * p * p);
    r = r < -1 ? -1 : r > 1 ? 1 : r;
    return q + 2 * p * cos(acos(r) / 3);
}

/* Highest frequency squared of a polygon on its stiffest face, and the largest damping ratio
 * among that face's normal, tangential and rocking dashpots (contact_polygon.c:
 * c = 2 zeta' sqrt(m* k_f) or c_N given, c_S = c k_S / k_N, couple c L^2 / 12) in *zeta.
 * zcut: the cutoff-corrected zeta' of the restitution pairs; zdash: c_N / (2 sqrt(m* k_N)) of
 * the dashpot pairs (on the face spring k_f it is zdash sqrt(k_N / k_f)). */
static double polygon_face_lambda(const pl_world *w, int i, double kn, double ks, double zcut, double zdash,
                                  double *zeta) {
    const int nv = w->vert_count[i];
    const pl_vec2 *v = &w->verts_local[w->vert_offset[i]];
    const double m = w->mass[i], I = w->inertia[i];
    double best = 0, zbest = zcut;
    for (int k = 0; k < nv; k++) {
        const pl_vec2 p0 = v[k], p1 = v[k + 1 < nv ? k + 1 : 0];
        const double ex = p1.x - p0.x, ey = p1.y - p0.y, L = sqrt(ex * ex + ey * ey);
        if (!(L > 0)) continue;
        const double tx = ex / L, ty = ey / L;
        /* the local outline is about the centroid: h = |p0 x t|, c = offset of the edge's
           middle along t from the foot of the perpendicular */
        const double h = fmax(fabs(p0.x * ty - p0.y * tx), 0.05 * w->radius[i]); /* l_c's floor */
        const double c = 0.5 * ((p0.x + p1.x) * tx + (p0.y + p1.y) * ty);
        const double kf = kn * L / h, kt = ks * L / h, kr = kn * L * L * L / (12 * h);
        double lam;
        if (I > 0 && !(w->inv_inertia[i] == 0 && w->law[i].fixed_rotation)) {
            const double sm = 1 / sqrt(m), si = 1 / sqrt(I);
            lam = pl__sym3_max_eig(kf / m, kt / m, (kf * c * c + kt * h * h + kr) / I, 0, kf * c * sm * si,
                                   -kt * h * sm * si);
        } else {
            lam = kf / m; /* does not turn: the normal spring alone */
        }
        if (lam > best) {
            best = lam;
            const double zn = fmax(zcut, zdash * sqrt(kn / kf));
            const double mt = 1 / (1 / m + (I > 0 ? h * h / I : 0));
            const double zt = ks > 0 ? zn * sqrt(ks / kn) * sqrt(m / mt) : 0;
            const double zr = I > 0 ? zn * L * sqrt(m / (12 * I)) : 0;
            zbest = fmax(zn, fmax(zt, zr));
        }
    }
    *zeta = zbest;
    return best;
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
        /* tangential damping: zs, the largest zeta sqrt(k_S / k_N) of a's restitution pairs;
           csk, the largest c_S / sqrt(k_S) of its dashpot pairs; zcut, the largest area-law
           zeta' (contact_polygon.c) */
        double *zs = pl_calloc((size_t)nm, sizeof *zs), *csk = pl_calloc((size_t)nm, sizeof *csk);
        double *zcut = pl_calloc((size_t)nm, sizeof *zcut);
        /* the two lightest dynamic bodies of each material (the lightest's index in arg1) */
        double *min1 = pl_malloc((size_t)nm * sizeof *min1), *min2 = pl_malloc((size_t)nm * sizeof *min2);
        double *light = pl_malloc((size_t)nm * sizeof *light);
        int *arg1 = pl_malloc((size_t)nm * sizeof *arg1);
        if (used && kn && ks && cn && zeta && roll && zs && csk && zcut && min1 && min2 && light && arg1) {
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
                    if (p->zeta >= 0 && p->kn > 0) {
                        zs[a] = fmax(zs[a], p->zeta * sqrt(p->ks / p->kn));
                        zcut[a] = fmax(zcut[a], pl__polygon_cutoff_zeta(p->zeta));
                    }
                    if (p->zeta < 0 && p->ks > 0) csk[a] = fmax(csk[a], p->cs / sqrt(p->ks));
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
                if (w->shape[i] == PL_SHAPE_POLYGON && w->vert_count[i] >= 3) {
                    double zp;
                    const double lam = polygon_face_lambda(w, i, kn[m], ks[m], zcut[m], cn[m] / (2 * sqrt(mred)), &zp);
                    const double dtp = lam > 0 ? damped_limit(1, lam, zp) : INFINITY;
                    if (dtp < r.dt_critical) {
                        r.dt_critical = dtp;
                        r.limiting_body = i;
                        r.limit_kind = "polygon face";
                    }
                    continue;
                }
                const double dtt = damped_limit(mass, kn[m], z);
                if (dtt < r.dt_critical) {
                    r.dt_critical = dtt;
                    r.limiting_body = i;
                    r.limit_kind = "translation";
                }
                if (w->inv_inertia[i] == 0 && w->law[i].fixed_rotation) continue; /* does not turn */
                if (!(ks[m] > 0) || !(w->inertia[i] > 0)) continue;
                /* the shear spring at the rim couples sliding and turning; the rolling spring
                   (k_S R^2, R <= r) adds to the turning */
                const double rr = w->radius[i], I = w->inertia[i];
                const double lam = ks[m] * (1 / mass + rr * rr / I) + (roll[m] > 0 ? ks[m] * rr * rr / I : 0);
                const double mt = 1 / (1 / mass + rr * rr / I);
                const double zt = fmax(zs[m] * sqrt(mred / mt), csk[m] / (2 * sqrt(mt)));
                const double dtr = damped_limit(1, lam, zt);
                if (dtr < r.dt_critical) {
                    r.dt_critical = dtr;
                    r.limiting_body = i;
                    r.limit_kind = "rotation";
                }
            }
        }
        pl_free(used); pl_free(kn); pl_free(ks); pl_free(cn); pl_free(zeta); pl_free(roll);
        pl_free(zs); pl_free(csk); pl_free(zcut);
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
