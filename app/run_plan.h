/* How long a declarative run lasts and when frames are drawn, decided from (in order) the
 * command line, the scene's run table, the MIMES flags TIMESTEPS / PRINT_INT, defaults. */
#ifndef PL_APP_RUN_PLAN_H
#define PL_APP_RUN_PLAN_H

#include "options.h"
#include "scene.h"

#define PL_DEFAULT_DURATION 1.0 /* s of simulated time when nothing says otherwise */
#define PL_DEFAULT_FPS 30.0

typedef struct pl_run_plan {
    double dt;               /* time step, s */
    double t_start;          /* world time when the run starts, s */
    long long total_steps;   /* steps the run takes */
    double fps;              /* frames per simulated second, or 0 when `every` is used */
    long long every;         /* steps between frames, or 0 when fps is used */
    const char *length_from; /* "--steps", "run.t_end", "flag TIMESTEPS", "default", ... */
    const char *frames_from;
} pl_run_plan;

/* Returns 0, or an exit code after printing the error. */
int pl_run_plan_make(const pl_opts *o, pl_scene *s, pl_world *w, pl_run_plan *p);

/* Steps after the start at which frame k is drawn (frame 0 at step 0). */
long long pl_run_plan_frame_step(const pl_run_plan *p, long long k);

/* Number of frames the run draws (frames at steps 0..total_steps). */
long long pl_run_plan_frame_count(const pl_run_plan *p);

/* Frame rate to give a video encoder. */
int pl_run_plan_video_fps(const pl_run_plan *p);

#endif
