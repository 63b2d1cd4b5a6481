/* The simulation behind the window: the scene, its world, the run plan (when on_frame is
 * called), scene parameters, in-memory snapshots, and an interaction log that makes
 * rewinding exact.
 *
 * Rewind to step S: from the latest snapshot at or before S (pl_world_snapshot: bodies,
 * contacts with their history, energy tallies, flags, the pore fluid's fields, boundary
 * conditions and update phase), replaying the logged interactions (parameter changes,
 * fix/release, spring loads) and the steps from there to S. Snapshots are taken at scene
 * frames while playing (memory budget PL_WSIM_SNAP_BYTES; when it is full every other
 * snapshot is dropped, so they thin out evenly) for scenes whose Lua state cannot diverge:
 * an on_frame hook may keep state in Lua variables, so such scenes are reloaded and
 * replayed from t = 0 instead. Either way the result is bit-identical to the first pass
 * (same state hash). */
#ifndef PL_APP_WINDOW_SIM_H
#define PL_APP_WINDOW_SIM_H

#include <limits.h>
#include <time.h>
#include "cli_common.h"
#include "scene.h"
#include "run_plan.h"
#include "render/drawlist.h"
#include "window_live.h"

#define PL_WSIM_MAX_PARAMS PL_SCENE_MAX_PARAMS

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

#define PL_WSIM_SNAP_BYTES ((size_t)256 << 20)

typedef struct pl_wsnap {
    long long step, next_k; /* steps since the scene start; next on_frame index */
    int replay;             /* log events already applied */
    double values[PL_WSIM_MAX_PARAMS];
    pl_snapshot *s;
} pl_wsnap;

typedef struct pl_wsim {
    const pl_opts *o;
    char path[PATH_MAX];            /* the open scene (the picker changes it) */
    pl_live live;                   /* the scene's live charts (render.live), sampled per frame */
    char out_dir[PATH_MAX];
    pl_scene *s;
    pl_world *w;
    pl_render_options ropt;
    int scene_auto_camera;          /* the scene's own camera, restored by 'z' */
    unsigned scene_layers;          /* the scene's own layers, colouring and field (a new scene) */
    int scene_coloring, scene_fluid_field;
    pl_vec2 scene_view_lo, scene_view_hi;
    pl_run_plan plan;
    pl_draw_list overlay;
    long long start_step, next_k; /* next on_frame is frame next_k */
    pl_wparam params[PL_WSIM_MAX_PARAMS];
    int nparams;
    pl_wevent *log;
    int nlog, caplog, replay; /* replay: log events already applied */
    pl_wsnap *snaps;            /* ascending steps */
    int nsnaps, capsnaps, snap_ok;
    long long snap_spacing;     /* steps between snapshots (doubles when thinned) */
    size_t snap_bytes;
    long long last_rewind_from; /* step of the snapshot the last rewind started from, -1 = t = 0 */
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
/* Goes back to step `step` (>= 0) from the latest snapshot before it (or from the start);
 * drops the interactions after it. */
int pl_wsim_rewind(pl_wsim *sim, long long step);
/* Interactions (applied now and logged for rewinds). */
int pl_wsim_set_param(pl_wsim *sim, int i, double value);
int pl_wsim_set_motion(pl_wsim *sim, int body, pl_motion_type motion);
int pl_wsim_set_load(pl_wsim *sim, int body, pl_vec2 force);
/* 1 when the scene file changed on disk since it was loaded. */
int pl_wsim_file_changed(pl_wsim *sim);

#endif
