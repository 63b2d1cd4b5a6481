/* The hydrostatic water model class (porelab/hydrostatic.h, world/model.h): the public attach
 * and queries, and the class functions the world calls (advance: the moving level; loads:
 * buoyancy and drag on every body; hash, snapshot, image, cost). The geometry lives in
 * hydrostatic_kernels.c. */
#define _POSIX_C_SOURCE 200809L
#include "fluid/hydrostatic/hydrostatic_internal.h"
#include "core/clock.h"
#include "core/alloc.h"
#include "porelab/fluid.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The model's state: its def (level: the current level) and the water's area. */
typedef struct pl_hydrostatic {
    pl_hydrostatic_def def;
    double a_water;  /* m^2, the water's area (moving level) */
    int last_evals;  /* area evaluations of the last level solve */
    /* the drawing field (pl__hydrostatic_field): not state */
    pl_vec2 fxy[8];
    int32_t ftri[18];
    double fval[8];
    double seconds;  /* in advance + loads */
    long calls;
} pl_hydrostatic;

/* What the world snapshot keeps (the state; cost counters are not state). */
typedef struct hs_snap {
    pl_hydrostatic_def def;
    double a_water;
} hs_snap;


static pl_status check_def(pl_world *w, const pl_hydrostatic_def *d) {
    char msg[320];
    if (!d) return pl__world_error(w, PL_ERR_ARG, "water: no def given (use pl_default_hydrostatic_def())");
    if (pl_params_check_all(pl_hydrostatic_params, pl_hydrostatic_param_count, d, "water", msg, sizeof msg) != PL_OK)
        return pl__world_error(w, PL_ERR_ARG, "%s", msg);
    if (!(d->x_max > d->x_min))
        return pl__world_error(w, PL_ERR_ARG, "water: x_max (%g m) must be greater than x_min (%g m)", d->x_max,
                               d->x_min);
    const pl_vec2 g = pl__world_gravity(w);
    if ((g.x != 0 || g.y != 0) && !(g.y < 0))
        return pl__world_error(w, PL_ERR_ARG,
                               "water: gravity (%g, %g) m/s^2 must point down into the tank (g.y < 0): the "
                               "tank {x_min <= x <= x_max, y >= bottom} is open upwards",
                               g.x, g.y);
    /* the level is a height along up; the water starts where the surface meets the bottom */
    const pl_hs_water wt = pl_hs_water_make(d, g);
    const double h_low = fmin(d->x_min * wt.up.x, d->x_max * wt.up.x) + d->bottom * wt.up.y;
    if (d->level < h_low)
        return pl__world_error(w, PL_ERR_ARG,
                               "water: level %g m is below the bottom (%g m): raise the level or lower the "
                               "bottom",
                               d->level, h_low);
    return PL_OK;
}

/* Fixes the water's area from the bodies now (moving level). */
static void fix_water_area(pl_hydrostatic *m, const pl_world *w) {
    const pl_hs_water wt = pl_hs_water_make(&m->def, pl__world_gravity(w));
    const pl_grain_view g = pl__world_grains(w);
    m->a_water = pl_hs_tank_area(&wt, m->def.level) - pl_hs_solid_area(&wt, m->def.level, &g);
    if (m->a_water < 0) m->a_water = 0;
}

pl_status pl_world_attach_hydrostatic(pl_world *w, const pl_hydrostatic_def *def) {
    if (!w) return PL_ERR_ARG;
    if (pl__world_model(w, &pl_hydrostatic_class))
        return pl__world_error(w, PL_ERR_STATE,
                               "water: this world already has hydrostatic water (one water body per world; "
                               "change it with pl_world_hydrostatic_redefine / w:water_set{...})");
    pl_status st = check_def(w, def);
    if (st != PL_OK) return st;
    pl_hydrostatic *m = pl_calloc(1, sizeof *m);
    if (!m) return pl__world_error(w, PL_ERR_NOMEM, "water: out of memory");
    m->def = *def;
    fix_water_area(m, w);
    st = pl__world_attach(w, &pl_hydrostatic_class, m);
    if (st != PL_OK) pl_free(m);
    return st;
}

int pl_world_has_hydrostatic(const pl_world *w) { return w && pl__world_model(w, &pl_hydrostatic_class) != NULL; }

pl_status pl_world_hydrostatic_def(const pl_world *w, pl_hydrostatic_def *out) {
    const pl_hydrostatic *m = w ? pl__world_model(w, &pl_hydrostatic_class) : NULL;
    if (!m || !out) return PL_ERR_STATE;
    *out = m->def;
    return PL_OK;
}

pl_status pl_world_hydrostatic_redefine(pl_world *w, const pl_hydrostatic_def *def) {
    pl_hydrostatic *m = w ? pl__world_model(w, &pl_hydrostatic_class) : NULL;
    if (!m) return w ? pl__world_error(w, PL_ERR_STATE, "water_set: the world has no hydrostatic water (add it with w:water{...})") : PL_ERR_ARG;
    pl_status st = check_def(w, def);
    if (st != PL_OK) return st;
    const pl_hydrostatic_def old = m->def;
    m->def = *def;
    if (def->x_min != old.x_min || def->x_max != old.x_max || def->bottom != old.bottom || def->level != old.level ||
        (def->moving_level && !old.moving_level))
        fix_water_area(m, w);
    return PL_OK;
}

double pl_world_hydrostatic_level(const pl_world *w) {
    const pl_hydrostatic *m = w ? pl__world_model(w, &pl_hydrostatic_class) : NULL;
    return m ? m->def.level : NAN;
}

double pl_world_hydrostatic_pressure(const pl_world *w, pl_vec2 p) {
    const pl_hydrostatic *m = w ? pl__world_model(w, &pl_hydrostatic_class) : NULL;
    if (!m) return 0;
    const pl_hs_water wt = pl_hs_water_make(&m->def, pl__world_gravity(w));
    if (p.x < wt.x_min || p.x > wt.x_max || p.y < wt.bottom) return 0;
    const double depth = m->def.level - (p.x * wt.up.x + p.y * wt.up.y);
    return depth > 0 ? wt.rho * wt.g * depth : 0;
}

int pl__hydrostatic_field(void *self, pl_vec2 gravity, pl_field_sample *out) {
    pl_hydrostatic *m = self;
    const pl_hs_water wt = pl_hs_water_make(&m->def, gravity);
    int nt = 0;
    const int nn = pl_hs_field(&wt, m->def.level, m->fxy, m->ftri, m->fval, &nt);
    *out = (pl_field_sample){nn, nt, m->fxy, m->ftri, m->fval};
    return nn;
}

/* The water body's field for drawing (pl_model_class.field): pressure, pressure head, total
   head (uniform in still water) or excess pressure (zero in still water). */
static int hs_field(const void *self, const pl_world *w, int quantity, pl_vec2 *xy, int32_t *tri, double *value,
                    int cap_nodes, int cap_tris, int *nt) {
    const pl_hydrostatic *m = self;
    const pl_hs_water wt = pl_hs_water_make(&m->def, pl__world_gravity(w));
    pl_vec2 fxy[8];
    int32_t ftri[18];
    double fval[8];
    int n_t = 0;
    const int nn = pl_hs_field(&wt, m->def.level, fxy, ftri, fval, &n_t);
    *nt = n_t;
    if (nn <= 0 || quantity < PL_FLUID_HEAD || quantity > PL_FLUID_EXCESS_PRESSURE) return 0;
    if (nn > cap_nodes || n_t > cap_tris || !xy || !tri || !value) return nn;
    const double rg = wt.rho * wt.g;
    for (int i = 0; i < nn; i++) {
        xy[i] = fxy[i];
        const double p = fval[i];
        const double z = fxy[i].x * wt.up.x + fxy[i].y * wt.up.y;
        switch (quantity) {
        case PL_FLUID_PRESSURE: value[i] = p; break;
        case PL_FLUID_PRESSURE_HEAD: value[i] = rg > 0 ? p / rg : 0; break;
        case PL_FLUID_HEAD: value[i] = (rg > 0 ? p / rg : 0) + z; break;
        default: value[i] = 0; break; /* excess pressure: still water */
        }
    }
    for (int k = 0; k < 3 * n_t; k++) tri[k] = ftri[k];
    return nn;
}

/* ------------------------------------------------------------------ class functions */

/* An empty instance (a snapshot restored into a world without water fills it). */
static void *hs_create(void) {
    pl_hydrostatic *m = pl_calloc(1, sizeof *m);
    if (m) m->def = pl_default_hydrostatic_def();
    return m;
}

static pl_status hs_advance(void *self, pl_world *w, const pl_grain_view *g, double dt) {
    (void)dt;
    pl_hydrostatic *m = self;
    if (!m->def.moving_level) return PL_OK;
    const double t0 = pl_clock_seconds();
    const pl_hs_water wt = pl_hs_water_make(&m->def, g->gravity);
    if (g->gravity.x != 0 || g->gravity.y != 0) {
        if (!(g->gravity.y < 0))
            return pl__world_error(w, PL_ERR_STATE,
                                   "water: gravity (%g, %g) m/s^2 at t = %g s points out of the tank; the "
                                   "hydrostatic water needs g.y < 0",
                                   g->gravity.x, g->gravity.y, g->time);
        const double L = pl_hs_solve_level(&wt, g, m->a_water, m->def.level, &m->last_evals);
        if (!isfinite(L))
            return pl__world_error(w, PL_ERR_NUMERIC, "water: the moving level did not converge at t = %g s",
                                   g->time);
        m->def.level = L;
    }
    m->seconds += pl_clock_seconds() - t0;
    return PL_OK;
}

static pl_status hs_loads(void *self, pl_world *w, const pl_grain_view *g, double dt, pl_vec2 *force,
                          double *moment) {
    (void)dt;
    pl_hydrostatic *m = self;
    const double t0 = pl_clock_seconds();
    if ((g->gravity.x != 0 || g->gravity.y != 0) && !(g->gravity.y < 0))
        return pl__world_error(w, PL_ERR_STATE,
                               "water: gravity (%g, %g) m/s^2 at t = %g s points out of the tank; the hydrostatic "
                               "water needs g.y < 0",
                               g->gravity.x, g->gravity.y, g->time);
    const pl_hs_water wt = pl_hs_water_make(&m->def, g->gravity);
    for (int i = 0; i < g->n; i++) {
        if (!g->wants_load[i] || g->shape[i] == PL_SHAPE_SEGMENT) continue;
        pl_hs_part p;
        pl_hs_body_part(&wt, m->def.level, g, i, &p);
        if (!(p.area > 0)) continue;
        pl_vec2 F;
        double M;
        pl_hs_load(&wt, &p, g->pos[i], g->vel[i], g->omega[i], &F, &M);
        force[i].x += F.x;
        force[i].y += F.y;
        moment[i] += M;
    }
    m->seconds += pl_clock_seconds() - t0;
    m->calls++;
    return PL_OK;
}

static uint64_t hs_hash(const void *self, uint64_t h) {
    const pl_hydrostatic *m = self;
    const double v[7] = {m->def.x_min, m->def.x_max, m->def.bottom, m->def.level,
                         m->def.density, m->def.drag, m->a_water};
    const int32_t ml = m->def.moving_level;
    h = pl_hash_bytes(h, v, sizeof v);
    return pl_hash_bytes(h, &ml, sizeof ml);
}

static void *hs_snapshot(const void *self, size_t *bytes) {
    const pl_hydrostatic *m = self;
    hs_snap *s = pl_malloc(sizeof *s);
    if (!s) return NULL;
    s->def = m->def;
    s->a_water = m->a_water;
    if (bytes) *bytes = sizeof *s;
    return s;
}

static pl_status hs_restore(void *self, pl_world *w, const void *snap) {
    (void)w;
    pl_hydrostatic *m = self;
    const hs_snap *s = snap;
    m->def = s->def;
    m->a_water = s->a_water;
    return PL_OK;
}

static void hs_snapshot_free(void *snap) { pl_free(snap); }

/* Image layout (one section of the state image): 7 doubles (x_min, x_max, bottom, level,
   density, drag, a_water) and one int32 (moving_level). */
static pl_status hs_save(const void *self, pl_image *img) {
    const pl_hydrostatic *m = self;
    const double v[7] = {m->def.x_min, m->def.x_max, m->def.bottom, m->def.level,
                         m->def.density, m->def.drag, m->a_water};
    const int32_t ml = m->def.moving_level;
    pl_status st = pl__image_put(img, v, sizeof v);
    return st != PL_OK ? st : pl__image_put(img, &ml, sizeof ml);
}

static pl_status hs_load(void *self, pl_world *w, pl_image *img) {
    pl_hydrostatic *m = self;
    double v[7];
    int32_t ml;
    pl_status st = pl__image_get(img, v, sizeof v);
    if (st == PL_OK) st = pl__image_get(img, &ml, sizeof ml);
    if (st != PL_OK) return st;
    pl_hydrostatic_def d = m->def;
    d.x_min = v[0];
    d.x_max = v[1];
    d.bottom = v[2];
    d.level = v[3];
    d.density = v[4];
    d.drag = v[5];
    d.moving_level = ml;
    if (!(v[6] >= 0) || check_def(w, &d) != PL_OK)
        return pl__world_error(w, PL_ERR_IO, "load: the image's hydrostatic section is damaged (a field is out of its "
                                             "range)");
    m->def = d;
    m->a_water = v[6];
    return PL_OK;
}

static double hs_cost(const void *self, long *calls) {
    const pl_hydrostatic *m = self;
    if (calls) *calls = m->calls;
    return m->seconds;
}

static void hs_destroy(void *self) { pl_free(self); }

const pl_model_class pl_hydrostatic_class = {
    .name = "hydrostatic",
    .label = "hydrostatic water (exact outline pressure, no mesh)",
    .def_size = sizeof(pl_hydrostatic_def),
    .params = pl_hydrostatic_params,
    .nparams = PL_HYDROSTATIC_PARAM_COUNT,
    .create = hs_create,
    .advance = hs_advance,
    .loads = hs_loads,
    .hash = hs_hash,
    .snapshot = hs_snapshot,
    .restore = hs_restore,
    .snapshot_free = hs_snapshot_free,
    .save = hs_save,
    .load = hs_load,
    .field = hs_field,
    .cost = hs_cost,
    .destroy = hs_destroy,
};
