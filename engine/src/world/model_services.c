/* Two world services for models (world/model.h): the models' share of the automatic time step
 * (the world takes the smallest critical step of the grains and of every model that reports
 * one) and the bodies near a box, read from the grains' own neighbour grid. */
#include "world/world_layer.h"
#include "dem/box_query.h"
#include <math.h>

int pl__world_bodies_near(const pl_world *w, pl_vec2 lo, pl_vec2 hi, int32_t *out, int cap) {
    return pl__bodies_in_box(w, lo, hi, out, cap);
}

void pl__world_invalidate_dt(pl_world *w) { w->dt = 0; }

void pl__models_limit_dt(pl_world *w) {
    pl_dt_report *r = &w->dt_report;
    for (int k = 0; k < w->model_n; k++) {
        const pl_model_slot *m = &w->models[k];
        if (!m->cls->critical_dt) continue;
        const double d = m->cls->critical_dt(m->self, w);
        if (!(d > 0) || !isfinite(d) || !(d < r->dt_critical)) continue;
        r->dt_critical = d;
        r->limiting_body = -1;
        r->limit_kind = m->cls->name;
    }
    if (r->fixed) return;
    /* as pl__compute_dt: a cap applies also when nothing limits the step */
    double dt = isfinite(r->dt_critical) ? w->def.dt_safety * r->dt_critical : INFINITY;
    r->capped = 0;
    if (w->def.max_dt > 0 && dt > w->def.max_dt) {
        dt = w->def.max_dt;
        r->capped = 1;
    }
    if (!isfinite(dt)) dt = 0;
    r->dt = dt;
    w->dt = dt;
}
