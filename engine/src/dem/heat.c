/* Frictional heat, conduction and Archard wear of the contacts (seed 002 §4; porelab/bonds.h,
 * docs/rock.md), one pass over the step's contacts after the contact and bond forces:
 *   friction heat   Q = |F_t v_t| on every sliding disc contact (disc-disc, disc-wall), a
 *                   fraction alpha of it to heat, half to each body;
 *   conduction      Q_ij = H_ij (T_j - T_i), H = k_th w / d x 1 m through touching disc pairs
 *                   (w the overlap chord) and intact bonds (w = 2 min(r_a, r_b)), explicit;
 *   wear            dV_i = k_i F_n |v_t| dt / H_i(T_i) on both bodies of a sliding contact.
 * Worn-away discs leave the world after the step (pl__wear_remove). */
#include "core/alloc.h"
#include "dem/world_internal.h"
#include <math.h>
#include <string.h>

void pl__bond_release_body(pl_world *w, int body); /* bond.c */

pl_thermal_def pl_default_thermal_def(void) {
    pl_thermal_def d;
    memset(&d, 0, sizeof d);
    pl_params_defaults(pl_thermal_params, PL_THERMAL_PARAM_COUNT, &d);
    return d;
}

static const pl_thermal_def *thermal_of(const pl_world *w, int material) {
    static const pl_thermal_def *dflt = NULL;
    static pl_thermal_def d0;
    if (material < w->thermal_n && w->thermal[material].set) return &w->thermal[material].def;
    if (!dflt) {
        d0 = pl_default_thermal_def();
        dflt = &d0;
    }
    return dflt;
}

pl_status pl_world_set_thermal(pl_world *w, int material, const pl_thermal_def *def) {
    if (!def) return pl__error(w, PL_ERR_ARG, "thermal: no definition");
    if (material < 0 || material >= w->material_count)
        return pl__error(w, PL_ERR_ARG, "thermal: material index must be in 0..%d (got %d)", w->material_count - 1,
                         material);
    char msg[512];
    if (pl_params_check_all(pl_thermal_params, PL_THERMAL_PARAM_COUNT, def, "thermal", msg, sizeof msg) != PL_OK)
        return pl__error(w, PL_ERR_ARG, "%s", msg);
    if (material >= w->thermal_cap) {
        const int cap = w->material_count > 8 ? w->material_count : 8;
        pl_thermal *t = pl_realloc(w->thermal, (size_t)cap * sizeof *t);
        if (!t) return pl__error(w, PL_ERR_NOMEM, "thermal: out of memory");
        w->thermal = t;
        w->thermal_cap = cap;
    }
    while (w->thermal_n <= material) {
        memset(&w->thermal[w->thermal_n], 0, sizeof *w->thermal);
        w->thermal_n++;
    }
    w->thermal[material].set = 1;
    w->thermal[material].def = *def;
    return PL_OK;
}

pl_status pl_world_enable_heat(pl_world *w, double fraction, double t0) {
    if (!(fraction >= 0 && fraction <= 1))
        return pl__error(w, PL_ERR_ARG, "heat: fraction must be in [0, 1] (got %g)", fraction);
    if (!(t0 > 0) || !isfinite(t0))
        return pl__error(w, PL_ERR_ARG, "heat: initial temperature must be > 0 K (got %g)", t0);
    w->heat_fraction = fraction;
    w->heat_t0 = t0;
    if (!w->heat_on)
        for (int i = 0; i < w->n; i++) {
            w->temperature[i] = t0;
            w->heat[i] = 0;
            w->temp_hold[i] = 0;
        }
    w->heat_on = 1;
    return PL_OK;
}

pl_status pl_world_set_body_temperature(pl_world *w, int i, double t, int hold) {
    if (!w->heat_on) return pl__error(w, PL_ERR_STATE, "set_temperature: heat is off (switch it on with heat{...} first)");
    if (i < 0 || i >= w->n) return pl__error(w, PL_ERR_ARG, "set_temperature: body index must be in 0..%d (got %d)", w->n - 1, i);
    if (!(t > 0) || !isfinite(t))
        return pl__error(w, PL_ERR_ARG, "set_temperature: temperature must be > 0 K (got %g)", t);
    w->temperature[i] = t;
    w->temp_hold[i] = hold != 0;
    return PL_OK;
}

double pl_world_body_temperature(const pl_world *w, int i) {
    return w->heat_on && i >= 0 && i < w->n ? w->temperature[i] : NAN;
}
double pl_world_body_heat(const pl_world *w, int i) { return w->heat_on && i >= 0 && i < w->n ? w->heat[i] : 0; }

int pl_world_copy_temperatures(const pl_world *w, double *out, int cap) {
    if (!w->heat_on) return 0;
    const int c = cap < w->n ? cap : w->n;
    for (int i = 0; i < c; i++) out[i] = w->temperature[i];
    return c;
}

double pl_thermal_hardness(const pl_thermal_def *d, double T) { return pl__hardness(d, T); }

pl_status pl_world_body_contact_heat(pl_world *w, int i, double q, double fn_s) {
    if (i < 0 || i >= w->n)
        return pl__error(w, PL_ERR_ARG, "contact heat: body index must be in 0..%d (got %d)", w->n - 1, i);
    if (!(q >= 0) || !(fn_s >= 0) || !isfinite(q) || !isfinite(fn_s))
        return pl__error(w, PL_ERR_ARG, "contact heat: heat and wear work must be finite and >= 0 (got %g J, %g N m)",
                         q, fn_s);
    if (!w->heat_on || (w->removed && w->removed[i])) return PL_OK;
    const pl_thermal_def *t = thermal_of(w, w->material[i]);
    const double C = w->mass[i] * t->heat_capacity;
    w->heat[i] += q;
    if (!w->temp_hold[i] && C > 0) w->temperature[i] += q / C;
    if (w->wear_on && t->wear > 0) w->wear[i] += t->wear * fn_s / pl__hardness(t, w->temperature[i]);
    return PL_OK;
}

pl_status pl_world_enable_wear(pl_world *w, int remove) {
    if (!w->heat_on) return pl__error(w, PL_ERR_STATE, "wear: switch heat on first (the hardness H(T) needs temperatures)");
    w->wear_on = 1;
    w->wear_remove = remove != 0;
    return PL_OK;
}

double pl_world_body_wear(const pl_world *w, int i) { return w->wear_on && i >= 0 && i < w->n ? w->wear[i] : 0; }

int pl_world_body_removed(const pl_world *w, int i, double *time) {
    if (i < 0 || i >= w->n || !w->removed[i]) return 0;
    if (time) *time = w->removed_at[i];
    return 1;
}
int pl_world_removed_count(const pl_world *w) { return w->removed_n; }

/* Conductance of a contact of width wid over the centre distance d between materials with
   conductivities ka, kb (harmonic mean), per metre of thickness: W/K. */
static double conductance(double ka, double kb, double wid, double d) {
    if (!(ka > 0) || !(kb > 0) || !(d > 0)) return 0;
    return 2 * ka * kb / (ka + kb) * wid / d;
}

static inline pl_vec2 point_velocity(const pl_world *w, int i, pl_vec2 p) {
    const double rx = p.x - w->pos[i].x, ry = p.y - w->pos[i].y;
    return (pl_vec2){w->vel[i].x - w->omega[i] * ry, w->vel[i].y + w->omega[i] * rx};
}

pl_status pl__heat_wear(pl_world *w, double dt) {
    const double alpha = w->heat_fraction;
    const int wear = w->wear_on;
    double *q = w->heat_step, *hs = w->heat_step + w->n;
    memset(q, 0, (size_t)w->n * 2 * sizeof *q);
    /* contacts: friction heat, wear, conduction through the overlap */
    for (int k = 0; k < w->pair_n; k++) {
        const pl_pair *p = &w->pairs[k];
        if (!p->touching || p->kind == PL_PAIR_NONE) continue;
        const int a = p->a, b = p->b;
        const pl_pair_params *pp = &w->pair_params[p->params];
        const pl_vec2 n = p->normal, t = {-n.y, n.x};
        const pl_vec2 va = point_velocity(w, a, p->point), vb = point_velocity(w, b, p->point);
        const double vt = (vb.x - va.x) * t.x + (vb.y - va.y) * t.y;
        const int disc = p->kind == PL_PAIR_DISC_DISC || p->kind == PL_PAIR_DISC_SEGMENT;
        /* discs: the Coulomb cap mu k_n overlap + c reached; polygons (seed 004 area law): the
           contact marks it (p->pad, set in contact_polygon.c while heat is on) */
        const double smax = pp->friction * pp->kn * p->overlap + pp->cohesion;
        const int sliding = disc ? fabs(p->fs) >= smax * (1 - 1e-12) && smax > 0 : p->pad != 0;
        const pl_thermal_def *ta = thermal_of(w, w->material[a]), *tb = thermal_of(w, w->material[b]);
        if (sliding) {
            const double Q = fabs(p->ft * vt) * dt * alpha; /* J this step */
            q[a] += 0.5 * Q;
            q[b] += 0.5 * Q;
            if (wear) {
                const double s = p->fn > 0 ? p->fn * fabs(vt) * dt : 0; /* N m */
                if (ta->wear > 0) w->wear[a] += ta->wear * s / pl__hardness(ta, w->temperature[a]);
                if (tb->wear > 0) w->wear[b] += tb->wear * s / pl__hardness(tb, w->temperature[b]);
            }
        }
        if ((p->kind == PL_PAIR_POLY_DISC || p->kind == PL_PAIR_POLY_POLY) && ta->conductivity > 0 &&
            tb->conductivity > 0 && p->overlap > 0) {
            /* polygons: the contact width is the overlap area over its depth */
            const double d = hypot(w->pos[b].x - w->pos[a].x, w->pos[b].y - w->pos[a].y);
            const double H = conductance(ta->conductivity, tb->conductivity, p->area_prev / p->overlap, d);
            const double f = H * (w->temperature[b] - w->temperature[a]) * dt;
            q[a] += f;
            q[b] -= f;
            hs[a] += H;
            hs[b] += H;
        }
        if (p->kind == PL_PAIR_DISC_DISC && ta->conductivity > 0 && tb->conductivity > 0) {
            const double ra = w->radius[a], rb = w->radius[b];
            const double d = ra + rb - p->overlap;
            const double l = (d * d + ra * ra - rb * rb) / (2 * d); /* a's centre to the chord */
            const double c2 = ra * ra - l * l;
            const double H = conductance(ta->conductivity, tb->conductivity, c2 > 0 ? 2 * sqrt(c2) : 0, d);
            const double f = H * (w->temperature[b] - w->temperature[a]) * dt;
            q[a] += f;
            q[b] -= f;
            hs[a] += H;
            hs[b] += H;
        }
    }
    /* intact bonds conduct over the bond width */
    for (int k = 0; k < w->bond_n; k++) {
        const pl_bond *bd = &w->bonds[k];
        if (bd->state != PL_BOND_INTACT) continue;
        const int a = bd->a, b = bd->b;
        const pl_thermal_def *ta = thermal_of(w, w->material[a]), *tb = thermal_of(w, w->material[b]);
        if (!(ta->conductivity > 0 && tb->conductivity > 0)) continue;
        const double d = hypot(w->pos[b].x - w->pos[a].x, w->pos[b].y - w->pos[a].y);
        const double H = conductance(ta->conductivity, tb->conductivity, 2 * fmin(w->radius[a], w->radius[b]), d);
        const double f = H * (w->temperature[b] - w->temperature[a]) * dt;
        q[a] += f;
        q[b] -= f;
        hs[a] += H;
        hs[b] += H;
    }
    /* explicit update; stable while dt sum_j H_ij <= C_i (Gershgorin bound, docs/rock.md) */
    for (int i = 0; i < w->n; i++) {
        if (q[i] == 0 && hs[i] == 0) continue;
        const double C = w->mass[i] * thermal_of(w, w->material[i])->heat_capacity;
        w->heat[i] += q[i];
        if (w->temp_hold[i] || !(C > 0)) continue;
        if (dt * hs[i] > C)
            return pl__error(w, PL_ERR_UNSTABLE,
                             "heat conduction unstable at body %d, step %lld (t = %g s): dt x sum of its contact "
                             "conductances = %g J/K exceeds its heat capacity %g J/K; lower the time step below %g s, "
                             "or the conductivity, or raise the heat capacity",
                             i + 1, (long long)w->step, w->time, dt * hs[i], C, C / hs[i]);
        w->temperature[i] += q[i] / C;
    }
    return PL_OK;
}

static void remove_one(pl_world *w, int i) {
    /* the grain's motion leaves the system with it (external work out of the balance) */
    if (w->motion[i] != PL_MOTION_FIXED)
        w->e_external -= 0.5 * w->mass[i] * (w->vel[i].x * w->vel[i].x + w->vel[i].y * w->vel[i].y) +
                         0.5 * w->inertia[i] * w->omega[i] * w->omega[i];
    w->removed[i] = 1;
    w->removed_at[i] = w->time;
    w->removed_n++;
    w->motion[i] = PL_MOTION_FIXED;
    w->vel[i] = (pl_vec2){0, 0};
    w->omega[i] = 0;
    w->inv_mass[i] = w->inv_inertia[i] = 0;
    w->law[i].law = PL_LAW_CONSTANT;
    w->law[i].velocity = (pl_vec2){0, 0};
    w->law[i].omega = 0;
    pl__bond_release_body(w, i);
    w->need_rebuild = 1;
    w->classify_dirty = 1;
}

void pl__wear_remove(pl_world *w) {
    for (int i = 0; i < w->n; i++)
        if (!w->removed[i] && w->shape[i] == PL_SHAPE_DISC && w->area[i] > 0 && w->wear[i] >= w->area[i])
            remove_one(w, i);
}

pl_status pl_world_remove_body(pl_world *w, int i) {
    if (i < 0 || i >= w->n) return pl__error(w, PL_ERR_ARG, "remove: body index must be in 0..%d (got %d)", w->n - 1, i);
    if (w->shape[i] != PL_SHAPE_DISC) return pl__error(w, PL_ERR_ARG, "remove: body %d is not a disc (only discs are removed)", i);
    if (w->removed[i]) return PL_OK;
    remove_one(w, i);
    if (!(w->def.dt > 0)) w->dt = 0;
    w->energy_initialised = 0;
    return PL_OK;
}

int pl_world_body_touching(const pl_world *w, int body) {
    if (body < 0 || body >= w->n) return 0;
    int c = 0;
    for (int k = 0; k < w->pair_n; k++)
        c += w->pairs[k].touching && (w->pairs[k].a == body || w->pairs[k].b == body);
    return c;
}
