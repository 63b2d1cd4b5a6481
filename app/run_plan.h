/* How long a declarative run lasts and when frames are drawn, decided from (in order) the
 * command line, the scene's run table, the MIMES flags TIMESTEPS / PRINT_INT, defaults. */
#ifndef PL_APP_RUN_PLAN_H
#define PL_APP_RUN_PLAN_H

#include "options.h"
#include "scene.h"

#define PL_DEFAULT_DURATION 1.0 /* s of simulated time when nothing says otherwise */
#define PL_DEFAULT_FPS 30.0
#define PL_MAX_STEPS 1000000000000000LL /* 1e15: longest run, in steps */
#define PL_STEPS_NEVER 0x7fffffffffffffffLL /* "beyond any run" (LLONG_MAX) */
/* A camera (render.camera) the renderer can draw: each side in [MIN_SIDE, MAX_SIDE] m,
 * corners within +-MAX_COORD m (a 1e-300 m camera makes cairo's arcs never end). */
#define PL_VIEW_MIN_SIDE 1e-9
#define PL_VIEW_MAX_SIDE 1e9
#define PL_VIEW_MAX_COORD 1e12

typedef struct pl_run_plan {
    double dt;               /* time step, s */
    double t_start;          /* world time when the run starts, s */
    long long total_steps;   /* steps the run takes */
    double fps;              /* frames per simulated second, or 0 when `every` is used */
    long long every;         /* steps between frames, or 0 when fps is used */
    const char *length_from; /* "--steps", "run.t_end", "flag TIMESTEPS", "default", ... */
    const char *frames_from;
} pl_run_plan;

/* Returns 0, or an exit code after printing the error: also when the run would take more
 * than PL_MAX_STEPS steps or draw more than INT_MAX frames. */
int pl_run_plan_make(const pl_opts *o, pl_scene *s, pl_world *w, pl_run_plan *p);

/* Steps from the run's start to time t (0 when t is not after it; PL_STEPS_NEVER when too
 * many to count). */
long long pl_run_plan_steps_to(const pl_run_plan *p, double t);

/* Checks the camera of the render options (render.camera) against the PL_VIEW_ limits.
 * Returns 0, or PL_EXIT_FAIL after printing "porelab: scene.lua: render: camera ...". */
struct pl_render_options;
int pl_run_plan_check_view(const pl_scene *s, const struct pl_render_options *o);

/* Steps after the start at which frame k is drawn (frame 0 at step 0); PL_STEPS_NEVER for
 * a frame beyond any run. */
long long pl_run_plan_frame_step(const pl_run_plan *p, long long k);

/* Number of frames the run draws (frames at steps 0..total_steps). */
long long pl_run_plan_frame_count(const pl_run_plan *p);

/* Frame rate to give a video encoder. */
int pl_run_plan_video_fps(const pl_run_plan *p);

#endif
