/* Materials and the combined parameters of material pairs. */
#include "core/alloc.h"
#include "dem/world_internal.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

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
    if (!(def->cohesion >= 0))
        return pl__error(w, PL_ERR_ARG, "material '%s': cohesion must be >= 0 (got %g)", def->name, def->cohesion);
    if (!(def->cn >= 0))
        return pl__error(w, PL_ERR_ARG, "material '%s': cn must be >= 0 N s/m (got %g)", def->name, def->cn);
    if (def->restitution >= 0 && !(def->restitution > 0 && def->restitution <= 1))
        return pl__error(w, PL_ERR_ARG, "material '%s': restitution must be in (0, 1] (got %g)", def->name, def->restitution);
    if (w->material_count == w->material_cap) {
        int cap = w->material_cap ? 2 * w->material_cap : 8;
        pl_material *m = pl_realloc(w->materials, (size_t)cap * sizeof *m);
        if (!m) return pl__error(w, PL_ERR_NOMEM, "material: out of memory");
        w->materials = m;
        w->material_cap = cap;
    }
    const int id = w->material_count;
    pl_material *m = &w->materials[id];
    memset(m, 0, sizeof *m);
    m->def = *def;
    strcpy(m->name, def->name);
    m->def.name = m->name;
    /* grow the override table keeping previous overrides */
    const int n = id + 1;
    pl_pair_def *ov = pl_malloc((size_t)n * n * sizeof *ov);
    pl_pair_params *pp = pl_malloc((size_t)n * n * sizeof *pp);
    if (!ov || !pp) {
        pl_free(ov);
        pl_free(pp);
        return pl__error(w, PL_ERR_NOMEM, "material: out of memory");
    }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            ov[i * n + j] = (i < id && j < id) ? w->pair_overrides[i * id + j] : pl_default_pair_def();
    pl_free(w->pair_overrides);
    pl_free(w->pair_params);
    w->pair_overrides = ov;
    w->pair_params = pp;
    w->material_count = n;
    pl__update_pair_params(w);
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
    const int n = w->material_count;
    w->pair_overrides[a * n + b] = *def;
    w->pair_overrides[b * n + a] = *def;
    pl__update_pair_params(w);
    w->dt = w->def.dt > 0 ? w->def.dt : 0;
    return PL_OK;
}

void pl__update_pair_params(pl_world *w) {
    const int n = w->material_count;
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++) {
            const pl_material_def *a = &w->materials[i].def, *b = &w->materials[j].def;
            const pl_pair_def *o = &w->pair_overrides[i * n + j];
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
