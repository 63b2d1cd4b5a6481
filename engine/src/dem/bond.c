/* Cohesive bonds between discs (seed 002 §3; porelab/bonds.h, docs/rock.md): the bond store,
 * the three laws as one kernel on plain structs (pl__bond_law), the force pass after the
 * contacts (geometry -> law -> accumulate), the bonds' part of the critical step, and the
 * queries. A bond acts in parallel with the pair's contact law, as the parallel bond of
 * Potyondy & Cundall (2004): the contact pushes where the outlines overlap, the bond carries
 * tension, shear and moment while intact; when it breaks the contact is already there, so the
 * pair goes on as an ordinary frictional contact with no jump of force or energy. */
#include "core/alloc.h"
#include "dem/world_internal.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

pl_bond_def pl_default_bond_def(void) {
    pl_bond_def d;
    memset(&d, 0, sizeof d);
    pl_params_defaults(pl_bond_params, PL_BOND_PARAM_COUNT, &d);
    d.law = PL_BOND_BRITTLE;
    return d;
}

/* ------------------------------------------------------------------ the law kernel */

/* Energy the damage law has released once the largest opening reached kappa (linear strain
   softening from (u_e, R) to (u_f, 0)): D = R u_f (kappa - u_e) / (2 (u_f - u_e)), from 0 at
   u_e to R u_f / 2 at u_f, the whole area under the curve (docs/rock.md, damage law). */
static double damage_released(double R, double ue, double uf, double kap) {
    if (kap <= ue) return 0;
    if (kap > uf) kap = uf;
    return R * uf * (kap - ue) / (2 * (uf - ue));
}

static double damage_of(double ue, double uf, double kap) {
    if (kap <= ue) return 0;
    if (kap >= uf) return 1;
    return 1 - (ue / kap) * (uf - kap) / (uf - ue);
}

/* Plastic flow with linear softening of one component: trial force f_tr = k (u - u_p) against
   the yield force R (1 - kap/u_f); returns the force and updates u_p, kap and the released
   energy. *fail is set when the softening reached u_f. */
static double plastic_component(double k, double R, double soften, double u, double *up, double *kap,
                                double *released, int *fail) {
    const double uf = soften * R / k;
    const double tr = k * (u - *up);
    const double ry = R * (1 - *kap / uf);
    if (fabs(tr) <= ry) return tr;
    /* consistency: k (|u - u_p| - dk) = R (1 - (kap + dk)/u_f)  ->  dk = (|tr| - ry) / (k - R/u_f) */
    double dk = (fabs(tr) - ry) / (k * (1 - 1 / soften));
    if (*kap + dk >= uf) {
        dk = uf - *kap;
        *fail = 1;
    }
    const double k0 = *kap, k1 = k0 + dk;
    *released += dk * R * (1 - 0.5 * (k0 + k1) / uf); /* the area under the yield line */
    *kap = k1;
    *up += tr > 0 ? dk : -dk;
    return k * (u - *up);
}

void pl__bond_law(const pl_bond_def *L, pl_bond *b, double un, double ut, double rot, double hw, pl_bond_eval *e) {
    memset(e, 0, sizeof *e);
    const double kn = L->kn, kt = L->kt, kr = L->kr;
    double N = 0, S = 0, en = 0, es = 0;
    int broke = 0;
    switch (L->law) {
    case PL_BOND_PLASTIC: {
        int fn = 0, ft = 0;
        if (un - b->up_n > 0) {
            N = plastic_component(kn, L->rn, L->soften, un, &b->up_n, &b->kap_n, &e->released, &fn);
        } else {
            N = kn * (un - b->up_n); /* compression: elastic */
        }
        S = kt > 0 ? plastic_component(kt, L->rt, L->soften, ut, &b->up_t, &b->kap_t, &e->released, &ft) : 0;
        en = 0.5 * N * N / kn;
        es = kt > 0 ? 0.5 * S * S / kt : 0;
        broke = fn ? PL_BOND_BROKEN_TENSION : (ft ? PL_BOND_BROKEN_SHEAR : 0);
        break;
    }
    case PL_BOND_DAMAGE: {
        const double ue = L->rn / kn, uf = L->soften * ue;
        if (un > b->kap_n) {
            e->released += damage_released(L->rn, ue, uf, un) - damage_released(L->rn, ue, uf, b->kap_n);
            b->kap_n = un;
        }
        b->om_n = damage_of(ue, uf, b->kap_n);
        N = un > 0 ? (1 - b->om_n) * kn * un : kn * un; /* compression carried undamaged */
        en = 0.5 * N * un;
        if (b->kap_n >= uf) broke = PL_BOND_BROKEN_TENSION;
        if (L->tension_only || !(kt > 0)) {
            S = kt * ut;
            es = kt > 0 ? 0.5 * S * S / kt : 0;
            if (!broke && fabs(S) > L->rt) broke = PL_BOND_BROKEN_SHEAR;
        } else {
            const double ve = L->rt / kt, vf = L->soften * ve, a = fabs(ut);
            if (a > b->kap_t) {
                e->released += damage_released(L->rt, ve, vf, a) - damage_released(L->rt, ve, vf, b->kap_t);
                b->kap_t = a;
            }
            b->om_t = damage_of(ve, vf, b->kap_t);
            S = (1 - b->om_t) * kt * ut;
            es = 0.5 * S * ut;
            if (!broke && b->kap_t >= vf) broke = PL_BOND_BROKEN_SHEAR;
        }
        break;
    }
    default: { /* brittle */
        N = kn * un;
        S = kt * ut;
        en = 0.5 * N * un;
        es = 0.5 * S * ut;
        /* beam: the largest normal stress of the bond section, N/A + |M| R/I with A = 2R,
           I = (2R)^3/12, times A: N + 3|M|/R (Potyondy & Cundall 2004) */
        const double Ne = L->beam && hw > 0 ? N + 3 * fabs(kr * rot) / hw : N;
        if (L->combined) {
            const double x = (Ne > 0 ? Ne : 0) / L->rn, y = S / L->rt;
            if (x * x + y * y > 1) broke = PL_BOND_BROKEN_COMBINED;
        } else if (Ne > L->rn) {
            broke = PL_BOND_BROKEN_TENSION;
        } else if (fabs(S) > L->rt) {
            broke = PL_BOND_BROKEN_SHEAR;
        }
        break;
    }
    }
    const double M = kr * rot;
    const double er = 0.5 * M * rot;
    if (broke) {
        /* the bond lets go at once: what it still stored is released with it */
        e->released += en + es + er;
        N = S = 0;
        e->elastic = 0;
        e->n = e->s = e->m = 0;
    } else {
        e->n = N;
        e->s = S;
        e->m = M;
        e->elastic = en + es + er;
    }
    e->broke = broke;
    b->n = e->n;
    b->s = e->s;
    b->m = e->m;
    b->un = un;
    b->elastic = e->elastic;
    b->dissipated += e->released;
}

/* ------------------------------------------------------------------ store */

static int grow(void **p, int *cap, int need, size_t elem) {
    if (need <= *cap) return 1;
    int c = *cap ? *cap : 64;
    while (c < need) c *= 2;
    void *q = pl_realloc(*p, (size_t)c * elem);
    if (!q) return 0;
    *p = q;
    *cap = c;
    return 1;
}

static int find_law(const pl_world *w, int ma, int mb) {
    if (ma > mb) {
        const int t = ma;
        ma = mb;
        mb = t;
    }
    for (int k = 0; k < w->bond_law_n; k++)
        if (w->bond_laws[k].ma == ma && w->bond_laws[k].mb == mb) return k;
    return -1;
}

pl_status pl_bond_def_check(pl_bond_def *d, const char *who, char *msg, size_t len) {
    if ((int)d->law < PL_BOND_BRITTLE || (int)d->law > PL_BOND_DAMAGE) {
        snprintf(msg, len, "%s: law must be brittle (0), plastic (1) or damage (2) (got %d)", who, (int)d->law);
        return PL_ERR_ARG;
    }
    if (pl_params_check_all(pl_bond_params, PL_BOND_PARAM_COUNT, d, who, msg, len) != PL_OK) return PL_ERR_ARG;
    if (!(d->kn > 0) || !(d->rn > 0) || !(d->rt > 0)) {
        snprintf(msg, len, "%s: kn, rn and rt must be > 0 (got kn = %g N/m, rn = %g N, rt = %g N)", who, d->kn, d->rn,
                 d->rt);
        return PL_ERR_ARG;
    }
    if (d->kt < 0) d->kt = 0.5 * d->kn;
    if (d->law != PL_BOND_BRITTLE && !(d->kt > 0)) {
        snprintf(msg, len, "%s: the plastic and damage laws need kt > 0", who);
        return PL_ERR_ARG;
    }
    return PL_OK;
}

/* The law for a bond held by another model: its history in a pl_bond_history. */
void pl_bond_law_eval(const pl_bond_def *def, pl_bond_history *h, double un, double ut, double rot, double hw,
                      pl_bond_result *out) {
    pl_bond b;
    memset(&b, 0, sizeof b);
    b.up_n = h->up_n, b.up_t = h->up_t, b.kap_n = h->kap_n, b.kap_t = h->kap_t;
    b.om_n = h->om_n, b.om_t = h->om_t, b.dissipated = h->dissipated;
    pl_bond_eval e;
    pl__bond_law(def, &b, un, ut, rot, hw, &e);
    h->up_n = b.up_n, h->up_t = b.up_t, h->kap_n = b.kap_n, h->kap_t = b.kap_t;
    h->om_n = b.om_n, h->om_t = b.om_t, h->dissipated = b.dissipated;
    *out = (pl_bond_result){e.n, e.s, e.m, e.elastic, e.released, e.broke};
}

pl_status pl_world_set_bond_law(pl_world *w, int ma, int mb, const pl_bond_def *def) {
    if (!def) return pl__error(w, PL_ERR_ARG, "bond law: no definition");
    if (ma < 0 || mb < 0 || ma >= w->material_count || mb >= w->material_count)
        return pl__error(w, PL_ERR_ARG, "bond law: material indices must be in 0..%d (got %d, %d)", w->material_count - 1,
                         ma, mb);
    if ((int)def->law < PL_BOND_BRITTLE || (int)def->law > PL_BOND_DAMAGE)
        return pl__error(w, PL_ERR_ARG, "bond law: law must be brittle (0), plastic (1) or damage (2) (got %d)",
                         (int)def->law);
    char msg[512], who[64];
    snprintf(who, sizeof who, "bond law (materials %d, %d)", ma, mb);
    pl_bond_def d = *def;
    if (pl_bond_def_check(&d, who, msg, sizeof msg) != PL_OK) return pl__error(w, PL_ERR_ARG, "%s", msg);
    int k = find_law(w, ma, mb);
    if (k < 0) {
        if (!grow((void **)&w->bond_laws, &w->bond_law_cap, w->bond_law_n + 1, sizeof *w->bond_laws))
            return pl__error(w, PL_ERR_NOMEM, "bond law: out of memory");
        k = w->bond_law_n++;
    }
    w->bond_laws[k].ma = ma < mb ? ma : mb;
    w->bond_laws[k].mb = ma < mb ? mb : ma;
    w->bond_laws[k].def = d;
    return PL_OK;
}

/* A bond changes the critical step and the energy reference */
static void bonds_changed(pl_world *w) {
    if (!(w->def.dt > 0)) w->dt = 0;
    w->energy_initialised = 0;
}

static int already_bonded(const pl_world *w, int a, int b) {
    for (int k = 0; k < w->bond_n; k++)
        if (w->bonds[k].a == a && w->bonds[k].b == b && w->bonds[k].state == PL_BOND_INTACT) return 1;
    return 0;
}

static int push_bond(pl_world *w, int a, int b, int law) {
    if (!grow((void **)&w->bonds, &w->bond_cap, w->bond_n + 1, sizeof *w->bonds))
        return pl__error(w, PL_ERR_NOMEM, "bond: out of memory");
    pl_bond *q = &w->bonds[w->bond_n];
    memset(q, 0, sizeof *q);
    q->a = a;
    q->b = b;
    q->law = law;
    q->state = PL_BOND_INTACT;
    q->d0 = hypot(w->pos[b].x - w->pos[a].x, w->pos[b].y - w->pos[a].y);
    q->broken_step = -1;
    q->broken_time = -1;
    w->bond_intact++;
    return w->bond_n++;
}

int pl_world_add_bond(pl_world *w, int a, int b) {
    if (a < 0 || b < 0 || a >= w->n || b >= w->n || a == b)
        return pl__error(w, PL_ERR_ARG, "bond: body indices must be two different bodies in 0..%d (got %d, %d)", w->n - 1,
                         a, b);
    if (a > b) {
        const int t = a;
        a = b;
        b = t;
    }
    if (w->shape[a] != PL_SHAPE_DISC || w->shape[b] != PL_SHAPE_DISC)
        return pl__error(w, PL_ERR_ARG, "bond: bodies %d and %d must both be discs (bonds join discs only)", a, b);
    if (w->removed && (w->removed[a] || w->removed[b]))
        return pl__error(w, PL_ERR_ARG, "bond: body %d or %d was removed by wear", a, b);
    const int law = find_law(w, w->material[a], w->material[b]);
    if (law < 0)
        return pl__error(w, PL_ERR_ARG, "bond: no bond law for the materials of bodies %d and %d (set one with bond_law)",
                         a, b);
    if (already_bonded(w, a, b)) return pl__error(w, PL_ERR_ARG, "bond: bodies %d and %d are already bonded", a, b);
    const int k = push_bond(w, a, b, law);
    if (k >= 0) bonds_changed(w);
    return k;
}

/* Sort key of a disc pair for the duplicate check of pl_world_bond_touching. */
static int cmp_pair(const void *x, const void *y) {
    const int64_t *a = x, *b = y;
    return (*a > *b) - (*a < *b);
}

int pl_world_bond_touching(pl_world *w, double gap) {
    if (!(gap >= 0) || !isfinite(gap)) return pl__error(w, PL_ERR_ARG, "bond_touching: gap must be >= 0 m (got %g)", gap);
    if (w->bond_law_n == 0) return pl__error(w, PL_ERR_ARG, "bond_touching: no bond law set (set one with bond_law)");
    /* the discs near each other: the neighbour list, built once more with a skin of at least
       the gap when its own is smaller; the next step builds it again with its own skin */
    w->need_rebuild = 1;
    pl_status st = pl__neighbor_update(w);
    if (st == PL_OK && gap > w->skin) {
        const double skin = w->def.skin;
        w->def.skin = gap;
        w->classify_dirty = 1;
        w->need_rebuild = 1;
        st = pl__neighbor_update(w);
        w->def.skin = skin;
        w->classify_dirty = 1;
    }
    w->need_rebuild = 1;
    if (st != PL_OK) return st;
    /* intact bonds already there, sorted, to skip */
    int64_t *have = pl_malloc((size_t)(w->bond_n > 0 ? w->bond_n : 1) * sizeof *have);
    if (!have) return pl__error(w, PL_ERR_NOMEM, "bond_touching: out of memory");
    int nh = 0;
    for (int k = 0; k < w->bond_n; k++)
        if (w->bonds[k].state == PL_BOND_INTACT) have[nh++] = (int64_t)w->bonds[k].a * w->n + w->bonds[k].b;
    qsort(have, (size_t)nh, sizeof *have, cmp_pair);
    int made = 0;
    for (int k = 0; k < w->pair_n; k++) {
        const pl_pair *p = &w->pairs[k];
        const int a = p->a, b = p->b;
        if (w->shape[a] != PL_SHAPE_DISC || w->shape[b] != PL_SHAPE_DISC) continue;
        if (w->removed[a] || w->removed[b]) continue;
        const double d = hypot(w->pos[b].x - w->pos[a].x, w->pos[b].y - w->pos[a].y);
        if (d - w->radius[a] - w->radius[b] > gap) continue;
        const int law = find_law(w, w->material[a], w->material[b]);
        if (law < 0) continue;
        const int64_t key = (int64_t)a * w->n + b;
        if (nh > 0 && bsearch(&key, have, (size_t)nh, sizeof key, cmp_pair)) continue;
        if (push_bond(w, a, b, law) < 0) {
            pl_free(have);
            return PL_ERR_NOMEM;
        }
        made++;
    }
    pl_free(have);
    if (made) bonds_changed(w);
    return made;
}

int pl_world_bond_total(const pl_world *w) { return w->bond_n; }
int pl_world_bond_count(const pl_world *w) { return w->bond_intact; }

static void break_bond(pl_world *w, pl_bond *q, int why) {
    q->state = why;
    q->broken_step = w->step + 1; /* the step count once this step is done */
    q->broken_time = w->time;
    q->n = q->s = q->m = 0;
    q->elastic = 0;
    w->bond_intact--;
}

/* Bonds of a worn-away grain (heat.c). */
void pl__bond_release_body(pl_world *w, int body);
void pl__bond_release_body(pl_world *w, int body) {
    for (int k = 0; k < w->bond_n; k++) {
        pl_bond *q = &w->bonds[k];
        if (q->state != PL_BOND_INTACT || (q->a != body && q->b != body)) continue;
        w->e_fracture += q->elastic;
        q->dissipated += q->elastic;
        break_bond(w, q, PL_BOND_BROKEN_REMOVED);
    }
}

/* ------------------------------------------------------------------ forces */

void pl__bond_forces(pl_world *w, double dt) {
    double stored = 0;
    const pl_vec2 *pos = w->pos, *vel = w->vel;
    const double *om = w->omega, *rad = w->radius;
    const int track = w->def.track_energy;
    for (int k = 0; k < w->bond_n; k++) {
        pl_bond *q = &w->bonds[k];
        if (q->state != PL_BOND_INTACT) continue;
        const int a = q->a, b = q->b;
        /* geometry: normal, opening, arms, relative slip and rotation of the step */
        const double dx = pos[b].x - pos[a].x, dy = pos[b].y - pos[a].y;
        const double d = sqrt(dx * dx + dy * dy);
        const pl_vec2 n = d > 0 ? (pl_vec2){dx / d, dy / d} : (pl_vec2){0, 1};
        const pl_vec2 t = {-n.y, n.x};
        const double ra = rad[a], rb = rad[b];
        const double la = d * ra / (ra + rb), lb = d * rb / (ra + rb);
        const double vt = (vel[b].x - vel[a].x) * t.x + (vel[b].y - vel[a].y) * t.y - la * om[a] - lb * om[b];
        q->ut += vt * dt;
        q->rot += (om[b] - om[a]) * dt;
        /* law */
        pl_bond_eval e;
        pl__bond_law(&w->bond_laws[q->law].def, q, d - q->d0, q->ut, q->rot, fmin(ra, rb), &e);
        w->e_fracture += e.released;
        if (e.broke) {
            break_bond(w, q, e.broke);
            continue;
        }
        /* accumulate: -N n - S t on b, the opposite on a; moments of S about the centres and -M */
        const pl_vec2 F = {-e.n * n.x - e.s * t.x, -e.n * n.y - e.s * t.y};
        w->force[b].x += F.x;
        w->force[b].y += F.y;
        w->force[a].x -= F.x;
        w->force[a].y -= F.y;
        w->torque[a] += la * e.s + e.m;
        w->torque[b] += lb * e.s - e.m;
        stored += e.elastic;
    }
    (void)track;
    w->e_bond = stored;
}

double pl__bond_energy(const pl_world *w) {
    double e = 0;
    for (int k = 0; k < w->bond_n; k++)
        if (w->bonds[k].state == PL_BOND_INTACT) e += w->bonds[k].elastic;
    return e;
}

/* The bonds' part of the critical step: every dynamic body with bonds is a mass on the sum of
   its bonds' springs, 2 sqrt(m / sum max(k_n, k_t)) (the Gershgorin bound of the bonded
   lattice's highest frequency, exact for a body between fixed neighbours), and turns on
   sum (k_t l^2 + k_r): 2 sqrt(I / sum(k_t l^2 + k_r)). */
void pl__bond_dt_limit(const pl_world *w, double *dt, int *body, const char **kind) {
    if (w->bond_intact == 0) return;
    double *kt = pl_calloc((size_t)w->n * 2, sizeof *kt);
    if (!kt) return;
    double *kr = kt + w->n;
    for (int k = 0; k < w->bond_n; k++) {
        const pl_bond *q = &w->bonds[k];
        if (q->state != PL_BOND_INTACT) continue;
        const pl_bond_def *L = &w->bond_laws[q->law].def;
        const double ra = w->radius[q->a], rb = w->radius[q->b];
        const double la = q->d0 * ra / (ra + rb), lb = q->d0 * rb / (ra + rb);
        const double kk = fmax(L->kn, L->kt);
        kt[q->a] += kk;
        kt[q->b] += kk;
        kr[q->a] += L->kt * la * la + L->kr;
        kr[q->b] += L->kt * lb * lb + L->kr;
    }
    for (int i = 0; i < w->n; i++) {
        if (w->motion[i] != PL_MOTION_DYNAMIC || !(w->mass[i] > 0) || !(kt[i] > 0)) continue;
        const double dtt = 2 * sqrt(w->mass[i] / kt[i]);
        if (dtt < *dt) {
            *dt = dtt;
            *body = i;
            *kind = "translation";
        }
        if (w->inv_inertia[i] == 0 || !(kr[i] > 0)) continue;
        const double dtr = 2 * sqrt(w->inertia[i] / kr[i]);
        if (dtr < *dt) {
            *dt = dtr;
            *body = i;
            *kind = "rotation";
        }
    }
    pl_free(kt);
}

/* ------------------------------------------------------------------ queries */

static void info_of(const pl_world *w, const pl_bond *q, pl_bond_info *o) {
    o->a = q->a;
    o->b = q->b;
    o->state = q->state;
    o->n = q->n;
    o->s = q->s;
    o->m = q->m;
    o->un = q->un;
    o->ut = q->ut;
    const pl_bond_def *L = &w->bond_laws[q->law].def;
    if (L->law == PL_BOND_DAMAGE) o->damage = fmax(q->om_n, q->om_t);
    else if (L->law == PL_BOND_PLASTIC) o->damage = fmax(q->kap_n / (L->soften * L->rn / L->kn),
                                                          L->kt > 0 ? q->kap_t / (L->soften * L->rt / L->kt) : 0);
    else o->damage = 0;
    if (q->state != PL_BOND_INTACT) o->damage = 1;
    o->elastic = q->elastic;
    o->dissipated = q->dissipated;
    const pl_vec2 pa = w->pos[q->a], pb = w->pos[q->b];
    const double ra = w->radius[q->a], rb = w->radius[q->b], f = ra / (ra + rb);
    o->point = (pl_vec2){pa.x + f * (pb.x - pa.x), pa.y + f * (pb.y - pa.y)};
    o->broken_step = q->broken_step;
    o->broken_time = q->broken_time;
}

int pl_world_copy_bonds(const pl_world *w, int first, pl_bond_info *out, int cap) {
    int c = 0;
    for (int k = first < 0 ? 0 : first; k < w->bond_n && c < cap; k++) info_of(w, &w->bonds[k], &out[c++]);
    return c;
}

int pl_world_broken_bonds(const pl_world *w, int64_t since, pl_bond_info *out, int cap) {
    int c = 0;
    for (int k = 0; k < w->bond_n; k++) {
        const pl_bond *q = &w->bonds[k];
        if (q->state == PL_BOND_INTACT || q->broken_step <= since) continue;
        if (cap == 0) {
            c++;
            continue;
        }
        if (c >= cap) break;
        info_of(w, q, &out[c++]);
    }
    return c;
}
