/* The simulation behind the window: the scene, its world, the run plan (when on_frame is
 * called), scene parameters, and an interaction log that makes rewinding exact.
 *
 * Rewind: the engine has no snapshot/restore of its full state yet, so rewinding to step S
 * reloads the scene and replays it deterministically to S, applying the logged interactions
 * (parameter changes, fix/release, spring loads) at the steps where they happened. The
 * result is bit-identical to the first pass (same state hash); its cost grows with S. */
#ifndef PL_APP_WINDOW_SIM_H
#define PL_APP_WINDOW_SIM_H

#include <limits.h>
#include <time.h>
#include "cli_common.h"
#include "run_plan.h"
#include "render/drawlist.h"

#define PL_WSIM_MAX_PARAMS 16

typedef struct pl_wparam {
    char name[48];
    char unit[24];
    double value, min, max, step, initial;
} pl_wparam;

enum { PL_WEV_PARAM = 0, PL_WEV_MOTION = 1, PL_WEV_LOAD = 2 };
typedef struct pl_wevent {
    long long step; /* steps since the scene start when it applies */
    int kind, index; /* parameter index or body */
    double a, b;     /* value / motion / load x, y */
} pl_wevent;

typedef struct pl_wsim {
    const pl_opts *o;
    char out_dir[PATH_MAX];
    pl_scene *s;
    pl_world *w;
    pl_render_options ropt;
    int scene_auto_camera;          /* the scene's own camera, restored by 'z' */
    pl_vec2 scene_view_lo, scene_view_hi;
    pl_run_plan plan;
    pl_draw_list overlay;
    long long start_step, next_k; /* next on_frame is frame next_k */
    pl_wparam params[PL_WSIM_MAX_PARAMS];
    int nparams;
    pl_wevent *log;
    int nlog, caplog, replay; /* replay: log events already applied */
    char error[1024];           /* shown in the window ("" = none) */
    int stopped;                /* a guard fired or a hook failed: stepping disabled */
    struct timespec mtime;      /* scene file modification time */
} pl_wsim;

/* Loads (or reloads) the scene. On failure keeps the previous scene (if any), writes the
 * message into sim->error and returns -1. keep_params re-applies the current parameter
 * values at step 0 (restart); 0 uses the scene's values. */
int pl_wsim_load(pl_wsim *sim, int keep_params);
void pl_wsim_free(pl_wsim *sim);
long long pl_wsim_steps(const pl_wsim *sim);
/* Advances n steps (calls on_frame at the plan's frame steps, applies logged events on
 * replay). Returns 0, or -1 (sim->error set, sim->stopped = 1). */
int pl_wsim_advance(pl_wsim *sim, long long n);
/* Goes back to step `step` (>= 0) by replay; drops the interactions after it. */
int pl_wsim_rewind(pl_wsim *sim, long long step);
/* Interactions (applied now and logged for rewinds). */
int pl_wsim_set_param(pl_wsim *sim, int i, double value);
int pl_wsim_set_motion(pl_wsim *sim, int body, pl_motion_type motion);
int pl_wsim_set_load(pl_wsim *sim, int body, pl_vec2 force);
/* 1 when the scene file changed on disk since it was loaded. */
int pl_wsim_file_changed(pl_wsim *sim);

#endif
