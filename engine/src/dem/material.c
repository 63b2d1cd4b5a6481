/* Materials and the combined parameters of material pairs. */
#include "dem/world_internal.h"
#include "core/alloc.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The pair tables hold material_count^2 entries (144 bytes each): 2048 materials take 600 MB. */
#define PL_MAX_MATERIALS 2048

pl_material_def pl_default_material_def(void) {
    pl_material_def d;
    memset(&d, 0, sizeof d);
    d.density = 2650;
    d.kn = 0;
    d.ks = -1;
    d.young = 0;
    d.young_overlap = 0.02;
    d.friction = 0.5;
    d.cohesion = 0;
    d.cn = 0;
    d.cs = -1;
    d.restitution = -1;
    return d;
}

pl_pair_def pl_default_pair_def(void) {
    return (pl_pair_def){-1, -1, -1, -1, -1, -1, -1, -1};
}

/* Normal stiffness of one material: given directly, or from Young's modulus by seed 003
   eq. 2.36, k_N = E l / (2R) with the chord l = 2 sqrt(R^2 - (R - d)^2) at the overlap
   d = f R: k_N = E sqrt(2f - f^2), independent of R. */
static double material_kn(const pl_material_def *m) {
    if (m->kn > 0) return m->kn;
    const double f = m->young_overlap;
    return m->young * sqrt(2 * f - f * f);
}

static double material_ks(const pl_material_def *m) {
    return m->ks >= 0 ? m->ks : (2.0 / 3.0) * material_kn(m);
}

static double series(double a, double b) { return (a + b) > 0 ? 2 * a * b / (a + b) : 0; }

/* Damping ratio giving restitution e for a linear spring-dashpot:
   e = exp(-pi zeta / sqrt(1 - zeta^2))  =>  zeta = -ln e / sqrt(pi^2 + ln^2 e). */
static double zeta_from_restitution(double e) {
    if (e >= 1) return 0;
    const double l = log(e);
    return -l / sqrt(M_PI * M_PI + l * l);
}

/* The overrides are kept as a lower triangle, row a holding the pairs (a, 0..a): its layout
   does not depend on the material count, so adding a material only appends a row. */
static size_t override_index(int a, int b) {
    if (a < b) {
        const int t = a;
        a = b;
        b = t;
    }
    return (size_t)a * (size_t)(a + 1) / 2 + (size_t)b;
}

int pl_world_add_material(pl_world *w, const pl_material_def *def) {
    if (!def || !def->name || !def->name[0])
        return pl__error(w, PL_ERR_ARG, "material: a name is required");
    if (strlen(def->name) >= sizeof w->materials[0].name)
        return pl__error(w, PL_ERR_ARG, "material '%s': name longer than 63 characters", def->name);
    if (pl_world_find_material(w, def->name) >= 0)
        return pl__error(w, PL_ERR_ARG, "material '%s' already exists", def->name);
    if (!(def->density > 0) || !isfinite(def->density))
        return pl__error(w, PL_ERR_ARG, "material '%s': density must be > 0 (got %g)", def->name, def->density);
    if (def->kn < 0 || !isfinite(def->kn))
        return pl__error(w, PL_ERR_ARG, "material '%s': kn must be > 0 N/m (got %g)", def->name, def->kn);
    if (def->kn == 0 && !(def->young > 0))
        return pl__error(w, PL_ERR_ARG, "material '%s': give kn > 0 (N/m) or young > 0 (Pa)", def->name);
    if (def->kn == 0 && !(def->young_overlap > 0 && def->young_overlap < 1))
        return pl__error(w, PL_ERR_ARG, "material '%s': young_overlap must be in (0, 1) (got %g)", def->name, def->young_overlap);
    if (!(def->friction >= 0) || !isfinite(def->friction))
        return pl__error(w, PL_ERR_ARG, "material '%s': friction must be >= 0 (got %g)", def->name, def->friction);
    if (!(def->rolling >= 0) || !isfinite(def->rolling))
        return pl__error(w, PL_ERR_ARG, "material '%s': rolling must be >= 0 (got %g)", def->name, def->rolling);
    if (!(def->cohesion >= 0) || !isfinite(def->cohesion))
        return pl__error(w, PL_ERR_ARG, "material '%s': cohesion must be finite and >= 0 (got %g)", def->name, def->cohesion);
    if (!(def->cn >= 0) || !isfinite(def->cn))
        return pl__error(w, PL_ERR_ARG, "material '%s': cn must be finite and >= 0 N s/m (got %g)", def->name, def->cn);
    if (!isfinite(def->ks) || !isfinite(def->cs) || !isfinite(def->young))
        return pl__error(w, PL_ERR_ARG, "material '%s': ks, cs and young must be finite (got %g, %g, %g)", def->name,
                         def->ks, def->cs, def->young);
    if (def->restitution >= 0 && !(def->restitution > 0 && def->restitution <= 1))
        return pl__error(w, PL_ERR_ARG, "material '%s': restitution must be in (0, 1] (got %g)", def->name, def->restitution);
    if (w->material_count >= PL_MAX_MATERIALS)
        return pl__error(w, PL_ERR_ARG, "material '%s': at most %d materials (the pair tables grow as the square "
                         "of the count)", def->name, PL_MAX_MATERIALS);
    if (w->material_count == w->material_cap) {
        /* geometric growth of the material list and of the two pair tables, which are
           allocated for material_cap^2 entries (the snapshot copies material_count^2 of each):
           adding N materials costs O(N^2) in all (it was O(N^3): both tables were rebuilt at
           the new size and every pair recombined on each add) */
        const int cap = w->material_cap ? 2 * w->material_cap : 8;
        const size_t cells = (size_t)cap * (size_t)cap;
        pl_material *m = pl_realloc(w->materials, (size_t)cap * sizeof *m);
        if (!m) return pl__error(w, PL_ERR_NOMEM, "material: out of memory");
        w->materials = m;
        pl_pair_def *ov = pl_realloc(w->pair_overrides, cells * sizeof *ov);
        if (!ov) return pl__error(w, PL_ERR_NOMEM, "material: out of memory for %d materials' pair table", cap);
        w->pair_overrides = ov;
        /* the combined table is rebuilt from scratch when next needed: no need to keep it */
        pl_free(w->pair_params);
        w->pair_params = pl_calloc(cells, sizeof *w->pair_params);
        if (!w->pair_params) return pl__error(w, PL_ERR_NOMEM, "material: out of memory for %d materials' pair table", cap);
        /* the triangle's later rows are written as materials arrive; the rest stays defined */
        const size_t used = (size_t)w->material_count * (w->material_count + 1) / 2;
        for (size_t k = used; k < cells; k++) ov[k] = pl_default_pair_def();
        w->material_cap = cap;
    }
    const int id = w->material_count;
    pl_material *m = &w->materials[id];
    memset(m, 0, sizeof *m);
    m->def = *def;
    strcpy(m->name, def->name);
    m->def.name = m->name;
    /* the new material's row of the override triangle (already at the defaults) */
    for (int j = 0; j <= id; j++) w->pair_overrides[override_index(id, j)] = pl_default_pair_def();
    w->material_count = id + 1;
    /* the combined parameters are recomputed once before the next use (pl_world_step,
       pl__compute_dt, pl_world_pair_params all check the flag), not on every add */
    w->pair_params_dirty = 1;
    w->need_rebuild = 1;
    w->dt = w->def.dt > 0 ? w->def.dt : 0; /* recompute the automatic step */
    return id;
}

int pl_world_find_material(const pl_world *w, const char *name) {
    for (int i = 0; i < w->material_count; i++)
        if (strcmp(w->materials[i].name, name) == 0) return i;
    return -1;
}

int pl_world_material_count(const pl_world *w) { return w->material_count; }

pl_material_def pl_world_material(const pl_world *w, int m) {
    if (m < 0 || m >= w->material_count) return pl_default_material_def();
    return w->materials[m].def;
}

pl_status pl_world_set_pair(pl_world *w, int a, int b, const pl_pair_def *def) {
    if (a < 0 || a >= w->material_count || b < 0 || b >= w->material_count)
        return pl__error(w, PL_ERR_ARG, "set_pair: material index out of range 0..%d (got %d, %d)",
                         w->material_count - 1, a, b);
    if (def->restitution >= 0 && !(def->restitution > 0 && def->restitution <= 1))
        return pl__error(w, PL_ERR_ARG, "set_pair: restitution must be in (0, 1] (got %g)", def->restitution);
    const double f[] = {def->kn, def->ks, def->friction, def->cohesion, def->cn, def->cs, def->restitution, def->rolling};
    for (int k = 0; k < 8; k++)
        if (!isfinite(f[k]))
            return pl__error(w, PL_ERR_ARG, "set_pair: every field must be finite (< 0 keeps the default; got %g)", f[k]);
    w->pair_overrides[override_index(a, b)] = *def;
    w->pair_params_dirty = 1;
    w->need_rebuild = 1;
    w->dt = w->def.dt > 0 ? w->def.dt : 0;
    return PL_OK;
}

static pl_status check_pair_index(pl_world *w, const char *fn, int a, int b) {
    if (a < 0 || a >= w->material_count || b < 0 || b >= w->material_count)
        return pl__error(w, PL_ERR_ARG, "%s: material index out of range 0..%d (got %d, %d)", fn,
                         w->material_count - 1, a, b);
    return PL_OK;
}

pl_status pl_world_pair_override(pl_world *w, int a, int b, pl_pair_def *out) {
    const pl_status st = check_pair_index(w, "pair_override", a, b);
    if (st != PL_OK) return st;
    *out = w->pair_overrides[override_index(a, b)];
    return PL_OK;
}

pl_status pl_world_pair_params(pl_world *w, int a, int b, pl_pair_def *out) {
    const pl_status st = check_pair_index(w, "pair_params", a, b);
    if (st != PL_OK) return st;
    if (w->pair_params_dirty) pl__update_pair_params(w);
    const pl_pair_params *p = pl__pair_params(w, a, b);
    *out = (pl_pair_def){p->kn, p->ks, p->friction, p->cohesion, p->cn, p->cs, p->restitution, p->rolling};
    return PL_OK;
}

void pl__update_pair_params(pl_world *w) {
    const int n = w->material_count;
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++) {
            const pl_material_def *a = &w->materials[i].def, *b = &w->materials[j].def;
            const pl_pair_def *o = &w->pair_overrides[override_index(i, j)];
            pl_pair_params p;
            p.kn = o->kn >= 0 ? o->kn : series(material_kn(a), material_kn(b));
            p.ks = o->ks >= 0 ? o->ks : series(material_ks(a), material_ks(b));
            p.friction = o->friction >= 0 ? o->friction : fmin(a->friction, b->friction);
            p.cohesion = o->cohesion >= 0 ? o->cohesion : fmin(a->cohesion, b->cohesion);
            p.rolling = o->rolling >= 0 ? o->rolling : fmin(a->rolling, b->rolling);
            p.cn = o->cn >= 0 ? o->cn : 0.5 * (a->cn + b->cn);
            double csa = a->cs >= 0 ? a->cs : (material_kn(a) > 0 ? a->cn * material_ks(a) / material_kn(a) : 0);
            double csb = b->cs >= 0 ? b->cs : (material_kn(b) > 0 ? b->cn * material_ks(b) / material_kn(b) : 0);
            p.cs = o->cs >= 0 ? o->cs : 0.5 * (csa + csb);
            if (o->restitution >= 0)
                p.restitution = o->restitution;
            else if (a->restitution >= 0 && b->restitution >= 0)
                p.restitution = fmin(a->restitution, b->restitution);
            else if (a->restitution >= 0)
                p.restitution = a->restitution;
            else
                p.restitution = b->restitution;
            p.zeta = p.restitution >= 0 ? zeta_from_restitution(p.restitution) : -1;
            p.inv_ks = p.ks > 0 ? 1.0 / p.ks : 0;
            w->pair_params[i * n + j] = p;
        }
    }
    w->pair_params_dirty = 0;
    w->need_rebuild = 1; /* pairs cache their parameter index and dashpots */
}
