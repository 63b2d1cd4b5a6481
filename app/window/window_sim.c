/* Scene, stepping, parameters and the replay log of the window (see window_sim.h). */
#include "window_sim.h"
#include "scene_chart.h"
#include "scene_render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static void get_mtime(const char *path, struct timespec *t)
{
    struct stat st;
    if (stat(path, &st) == 0) *t = st.st_mtim;
    else t->tv_sec = t->tv_nsec = 0;
}

int pl_wsim_file_changed(pl_wsim *sim)
{
    struct timespec t;
    get_mtime(sim->path, &t);
    return t.tv_sec != sim->mtime.tv_sec || t.tv_nsec != sim->mtime.tv_nsec;
}

long long pl_wsim_steps(const pl_wsim *sim)
{
    return sim->w ? (long long)pl_world_step_count(sim->w) - sim->start_step : 0;
}

static int call_set(pl_wsim *sim, int i, double value)
{
    if (pl_scene_set_param(sim->s, i, value) != 0) {
        snprintf(sim->error, sizeof sim->error, "%s", pl_scene_error(sim->s));
        return -1;
    }
    return 0;
}

static int apply_event(pl_wsim *sim, const pl_wevent *e)
{
    switch (e->kind) {
    case PL_WEV_PARAM:
        if (e->index < sim->nparams) sim->params[e->index].value = e->a;
        return e->index < sim->nparams ? call_set(sim, e->index, e->a) : 0;
    case PL_WEV_MOTION:
        return pl_world_set_body_motion(sim->w, e->index, (pl_motion_type)(int)e->a) == PL_OK ? 0 : -1;
    case PL_WEV_LOAD:
        return pl_world_set_body_load(sim->w, e->index, (pl_vec2){e->a, e->b}, 0.0) == PL_OK ? 0 : -1;
    default: return 0;
    }
}

/* ------------------------------------------------------------ snapshots */

static void drop_snaps_from(pl_wsim *sim, long long step)
{
    while (sim->nsnaps > 0 && sim->snaps[sim->nsnaps - 1].step >= step) {
        pl_wsnap *z = &sim->snaps[--sim->nsnaps];
        sim->snap_bytes -= pl_snapshot_bytes(z->s);
        pl_snapshot_destroy(&z->s);
    }
}

static void free_snaps(pl_wsim *sim)
{
    drop_snaps_from(sim, LLONG_MIN);
    free(sim->snaps);
    sim->snaps = NULL;
    sim->capsnaps = 0;
    sim->snap_bytes = 0;
}

/* Takes a snapshot at the current step when snapshots are possible and the last one is at
 * least snap_spacing steps back; thins them out when over the memory budget. */
static void maybe_snapshot(pl_wsim *sim)
{
    if (!sim->snap_ok) return;
    long long now = pl_wsim_steps(sim);
    if (sim->nsnaps > 0 && now < sim->snaps[sim->nsnaps - 1].step + sim->snap_spacing) return;
    if (sim->nsnaps == sim->capsnaps) {
        int c = sim->capsnaps ? 2 * sim->capsnaps : 64;
        pl_wsnap *p = realloc(sim->snaps, (size_t)c * sizeof *p);
        if (!p) { sim->snap_ok = 0; return; }
        sim->snaps = p;
        sim->capsnaps = c;
    }
    pl_snapshot *ss = pl_world_snapshot(sim->w);
    if (!ss) { sim->snap_ok = 0; return; } /* out of memory: rewinds replay from the start */
    pl_wsnap *z = &sim->snaps[sim->nsnaps++];
    z->step = now;
    z->next_k = sim->next_k;
    z->replay = sim->replay;
    for (int i = 0; i < sim->nparams; i++) z->values[i] = sim->params[i].value;
    z->s = ss;
    sim->snap_bytes += pl_snapshot_bytes(ss);
    if (sim->snap_bytes > PL_WSIM_SNAP_BYTES && sim->nsnaps > 2) {
        /* keep the first, every other one after it, and the newest */
        int m = 1;
        for (int i = 1; i < sim->nsnaps; i++) {
            if (i % 2 == 0 || i == sim->nsnaps - 1) {
                sim->snaps[m++] = sim->snaps[i];
            } else {
                sim->snap_bytes -= pl_snapshot_bytes(sim->snaps[i].s);
                pl_snapshot_destroy(&sim->snaps[i].s);
            }
        }
        sim->nsnaps = m;
        sim->snap_spacing *= 2;
    }
}

static int log_event(pl_wsim *sim, pl_wevent e)
{
    /* a snapshot at or after the event's step does not contain it */
    drop_snaps_from(sim, e.step);
    if (sim->nlog == sim->caplog) {
        int nc = sim->caplog ? 2 * sim->caplog : 256;
        pl_wevent *p = realloc(sim->log, (size_t)nc * sizeof *p);
        if (!p) return -1;
        sim->log = p;
        sim->caplog = nc;
    }
    sim->log[sim->nlog++] = e;
    sim->replay = sim->nlog;
    return 0;
}

/* Loads the scene into fresh state; on success replaces the current one. */
static int load_fresh(pl_wsim *sim, const pl_render_options *keep_view)
{
    pl_scene_options so = {sim->path, sim->out_dir, pl_opts_has(sim->o, "--trust"), 0, 0, NULL, NULL};
    pl_scene *s = pl_scene_create(&so);
    if (!s) {
        snprintf(sim->error, sizeof sim->error, "out of memory while creating the Lua state");
        return -1;
    }
    /* --max-cpu / --max-memory as for `porelab run` (checked when the window started) */
    if (pl_cli_scene_limits(sim->o, s) != 0) {
        snprintf(sim->error, sizeof sim->error, "invalid --max-cpu or --max-memory (see the terminal)");
        pl_scene_destroy(&s);
        return -1;
    }
    struct timespec mt;
    get_mtime(sim->path, &mt);
    pl_scene_register_chart(s);
    if (pl_scene_load(s) != 0) {
        snprintf(sim->error, sizeof sim->error, "%s", pl_scene_error(s));
        pl_scene_destroy(&s);
        sim->mtime = mt; /* do not retry until the file changes again */
        return -1;
    }
    if (!pl_scene_declarative(s) || !pl_scene_world(s)) {
        snprintf(sim->error, sizeof sim->error, "%s returns no world (an imperative script); "
                 "the window needs a declarative scene", pl_scene_path(s));
        pl_scene_destroy(&s);
        sim->mtime = mt;
        return -1;
    }
    pl_world *w = pl_scene_world(s);
    pl_render_options ropt = pl_default_render_options();
    if (pl_scene_render_options(s, w, &ropt) != 0) {
        snprintf(sim->error, sizeof sim->error, "%s", pl_scene_error(s));
        pl_scene_destroy(&s);
        sim->mtime = mt;
        return -1;
    }
    pl_run_plan plan;
    /* the plan prints its own errors (bad --until etc.) */
    if (pl_run_plan_make(sim->o, s, w, &plan) != 0) {
        snprintf(sim->error, sizeof sim->error, "invalid run length or frame interval "
                 "(see the terminal)");
        pl_scene_destroy(&s);
        sim->mtime = mt;
        return -1;
    }
    /* the scene's parameters: result.params (checked by the loader) or the global PARAMS */
    pl_scene_param sp[PL_SCENE_MAX_PARAMS];
    int np = pl_scene_params(s, sp);
    if (np < 0) {
        snprintf(sim->error, sizeof sim->error, "%s", pl_scene_error(s));
        pl_scene_destroy(&s);
        sim->mtime = mt;
        return -1;
    }
    pl_wparam params[PL_WSIM_MAX_PARAMS];
    memset(params, 0, sizeof params);
    for (int i = 0; i < np && i < PL_WSIM_MAX_PARAMS; i++) {
        snprintf(params[i].name, sizeof params[i].name, "%.47s", sp[i].name);
        snprintf(params[i].unit, sizeof params[i].unit, "%.23s", sp[i].unit);
        params[i].value = params[i].initial = sp[i].value;
        params[i].min = sp[i].min;
        params[i].max = sp[i].max;
        params[i].step = sp[i].step;
    }
    pl_live lv;
    memset(&lv, 0, sizeof lv);
    if (pl_live_declare(&lv, s, (double)plan.total_steps * plan.dt) < 0) {
        snprintf(sim->error, sizeof sim->error, "%s", pl_scene_error(s));
        pl_scene_destroy(&s);
        sim->mtime = mt;
        return -1;
    }
    pl_live_free(&sim->live);
    sim->live = lv;
    if (sim->s) pl_scene_destroy(&sim->s);
    sim->s = s;
    sim->w = w;
    sim->scene_auto_camera = ropt.auto_camera;
    sim->scene_view_lo = ropt.view_lo;
    sim->scene_view_hi = ropt.view_hi;
    sim->scene_layers = ropt.layers;
    sim->scene_coloring = (int)ropt.coloring;
    sim->scene_fluid_field = (int)ropt.fluid_field;
    if (keep_view) { /* window size, layers, colouring, camera survive reloads */
        ropt.width = keep_view->width;
        ropt.height = keep_view->height;
        ropt.layers = keep_view->layers;
        ropt.coloring = keep_view->coloring;
        ropt.auto_camera = keep_view->auto_camera;
        ropt.view_lo = keep_view->view_lo;
        ropt.view_hi = keep_view->view_hi;
        ropt.fluid_field = keep_view->fluid_field;
        ropt.color_min = keep_view->color_min;
        ropt.color_max = keep_view->color_max;
    }
    sim->ropt = ropt;
    sim->plan = plan;
    sim->start_step = (long long)pl_world_step_count(w);
    sim->next_k = 0;
    memcpy(sim->params, params, sizeof params);
    sim->nparams = np < PL_WSIM_MAX_PARAMS ? np : PL_WSIM_MAX_PARAMS;
    sim->mtime = mt;
    sim->stopped = 0;
    sim->error[0] = 0;
    /* snapshots (the engine's cover the pore fluid too); an on_frame hook may keep state in
     * Lua that a snapshot would not restore: such scenes replay from t = 0 */
    free_snaps(sim);
    int hook = pl_scene_push_result_field(s, "on_frame") != LUA_TNIL;
    lua_pop(pl_scene_lua(s), 1);
    sim->snap_ok = !hook;
    long long fi = pl_run_plan_frame_step(&plan, 1) - pl_run_plan_frame_step(&plan, 0);
    sim->snap_spacing = fi > 0 ? fi : 1;
    return 0;
}

int pl_wsim_load(pl_wsim *sim, int keep_params)
{
    int had = sim->s != NULL;
    pl_render_options view = sim->ropt;
    double values[PL_WSIM_MAX_PARAMS];
    int nold = sim->nparams;
    for (int i = 0; i < nold; i++) values[i] = sim->params[i].value;
    if (load_fresh(sim, had ? &view : NULL) != 0) return -1;
    sim->nlog = sim->replay = 0;
    if (keep_params)
        for (int i = 0; i < sim->nparams && i < nold; i++)
            if (values[i] != sim->params[i].initial) pl_wsim_set_param(sim, i, values[i]);
    return 0;
}

void pl_wsim_free(pl_wsim *sim)
{
    free_snaps(sim);
    pl_scene_destroy(&sim->s);
    pl_live_free(&sim->live);
    pl_draw_list_free(&sim->overlay);
    free(sim->log);
    sim->log = NULL;
    sim->nlog = sim->caplog = 0;
}

static int hook_frame(pl_wsim *sim)
{
    if (pl_scene_call_hook(sim->s, "on_frame", sim->next_k) != 0) {
        snprintf(sim->error, sizeof sim->error, "%s", pl_scene_error(sim->s));
        sim->stopped = 1;
        /* the window shows it; the terminal keeps it */
        fprintf(stderr, "porelab: stopped: %s\n", sim->error);
        return -1;
    }
    sim->next_k++;
    /* the live charts read what the hook (or the step) left */
    if (pl_live_sample(&sim->live, sim->s, pl_world_time(sim->w)) != 0) {
        snprintf(sim->error, sizeof sim->error, "%s", pl_scene_error(sim->s));
        pl_live_free(&sim->live); /* the chart is dropped; the scene runs on */
    }
    return 0;
}

static int apply_pending(pl_wsim *sim)
{
    long long now = pl_wsim_steps(sim);
    while (sim->replay < sim->nlog && sim->log[sim->replay].step <= now) {
        if (apply_event(sim, &sim->log[sim->replay]) != 0) {
            if (!sim->error[0])
                snprintf(sim->error, sizeof sim->error, "%s", pl_world_last_error(sim->w));
            sim->stopped = 1;
            return -1;
        }
        sim->replay++;
    }
    return 0;
}

int pl_wsim_advance(pl_wsim *sim, long long n)
{
    if (sim->stopped || !sim->w) return -1;
    long long target = pl_wsim_steps(sim) + n;
    /* `porelab run` draws frame k and then calls on_frame(k) before stepping on; so here
     * the hooks of the frames at or before the current step run just before stepping
     * further, and the picture at a frame step is the state run draws there. */
    while (1) {
        if (apply_pending(sim) != 0) return -1;
        maybe_snapshot(sim);
        long long now = pl_wsim_steps(sim);
        if (now >= target) break;
        while (pl_run_plan_frame_step(&sim->plan, sim->next_k) <= now)
            if (hook_frame(sim) != 0) return -1;
        long long stop = target;
        long long f = pl_run_plan_frame_step(&sim->plan, sim->next_k);
        if (f < stop) stop = f;
        if (sim->replay < sim->nlog && sim->log[sim->replay].step < stop)
            stop = sim->log[sim->replay].step;
        long long k = stop - now;
        if (k > INT_MAX) k = INT_MAX;
        if (k <= 0) k = 1;
        if (pl_world_step(sim->w, (int)k) != PL_OK) {
            snprintf(sim->error, sizeof sim->error, "run stopped at t = %.6g s: %s",
                     pl_world_time(sim->w), pl_world_last_error(sim->w));
            sim->stopped = 1;
            return -1;
        }
    }
    return 0;
}

int pl_wsim_rewind(pl_wsim *sim, long long step)
{
    if (step < 0) step = 0;
    /* keep the interactions up to the target step, and the snapshots before it */
    int keep = 0;
    while (keep < sim->nlog && sim->log[keep].step <= step) keep++;
    drop_snaps_from(sim, step + 1);
    while (sim->nsnaps > 0) { /* from the latest snapshot at or before the target */
        pl_wsnap *z = &sim->snaps[sim->nsnaps - 1];
        if (z->replay > keep || pl_world_restore(sim->w, z->s) != PL_OK) {
            drop_snaps_from(sim, z->step);
            continue;
        }
        sim->nlog = keep;
        sim->replay = z->replay;
        sim->next_k = z->next_k;
        for (int i = 0; i < sim->nparams; i++) sim->params[i].value = z->values[i];
        sim->stopped = 0;
        sim->error[0] = 0;
        sim->last_rewind_from = z->step;
        pl_live_truncate(&sim->live, pl_world_time(sim->w));
        int rc = pl_wsim_advance(sim, step - z->step);
        if (rc == 0) rc = apply_pending(sim);
        return rc;
    }
    sim->last_rewind_from = -1;
    pl_wevent *log = sim->log;
    int caplog = sim->caplog;
    sim->log = NULL;
    sim->nlog = sim->caplog = 0;
    if (load_fresh(sim, &sim->ropt) != 0) {
        sim->log = log;
        sim->caplog = caplog;
        sim->nlog = keep;
        return -1;
    }
    sim->log = log;
    sim->caplog = caplog;
    sim->nlog = keep;
    sim->replay = 0;
    int rc = pl_wsim_advance(sim, step);
    if (rc == 0) rc = apply_pending(sim);
    return rc;
}

int pl_wsim_set_param(pl_wsim *sim, int i, double value)
{
    if (i < 0 || i >= sim->nparams || !sim->w) return -1;
    pl_wparam *p = &sim->params[i];
    value = fmin(p->max, fmax(p->min, value));
    pl_wevent e = {pl_wsim_steps(sim), PL_WEV_PARAM, i, value, 0.0};
    if (apply_event(sim, &e) != 0) return -1;
    return log_event(sim, e);
}

int pl_wsim_set_motion(pl_wsim *sim, int body, pl_motion_type motion)
{
    pl_wevent e = {pl_wsim_steps(sim), PL_WEV_MOTION, body, (double)motion, 0.0};
    if (apply_event(sim, &e) != 0) {
        snprintf(sim->error, sizeof sim->error, "%s", pl_world_last_error(sim->w));
        return -1;
    }
    return log_event(sim, e);
}

int pl_wsim_set_load(pl_wsim *sim, int body, pl_vec2 force)
{
    pl_wevent e = {pl_wsim_steps(sim), PL_WEV_LOAD, body, force.x, force.y};
    if (apply_event(sim, &e) != 0) return -1;
    return log_event(sim, e);
}
