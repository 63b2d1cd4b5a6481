#include "run_plan.h"

#include <math.h>
#include <stdio.h>

static long long steps_for(double duration, double dt)
{
    /* The small tolerance keeps t = n dt from needing one extra step by round-off. */
    return (long long)ceil(duration / dt - 1e-9);
}

int pl_run_plan_make(const pl_opts *o, pl_scene *s, pl_world *w, pl_run_plan *p)
{
    pl_scene_run r;
    if (pl_scene_run_settings(s, &r) != 0) {
        fprintf(stderr, "porelab: %s\n", pl_scene_error(s));
        return PL_EXIT_FAIL;
    }
    const char *cmd = o->cmd->command;
    if (pl_opts_has(o, "--until") && pl_opts_has(o, "--steps")) {
        fprintf(stderr, "porelab %s: give --until or --steps, not both\n", cmd);
        return PL_EXIT_USAGE;
    }
    if (pl_opts_has(o, "--fps") && pl_opts_has(o, "--every")) {
        fprintf(stderr, "porelab %s: give --fps or --every, not both\n", cmd);
        return PL_EXIT_USAGE;
    }
    double until = 0, fps = 0;
    long long steps = 0, every = 0;
    if (pl_opts_double(o, "--until", 0, 0, &until) || pl_opts_count(o, "--steps", 0, &steps) ||
        pl_opts_double(o, "--fps", 0, 0, &fps) || pl_opts_count(o, "--every", 1, &every))
        return PL_EXIT_USAGE;

    p->dt = pl_world_dt(w);
    if (!(p->dt > 0) || !isfinite(p->dt)) {
        const char *why = pl_world_last_error(w);
        fprintf(stderr, "porelab: %s: no usable time step: %s\n", pl_scene_path(s),
                why[0] ? why
                       : "no dynamic body to take the automatic step from; give world{dt = ...}");
        return PL_EXIT_FAIL;
    }
    p->t_start = pl_world_time(w);
    double flag;
    if (pl_opts_has(o, "--steps")) {
        p->total_steps = steps, p->length_from = "--steps";
    } else if (pl_opts_has(o, "--until")) {
        if (until < p->t_start) {
            fprintf(stderr, "porelab %s: --until %g is before the scene's current time %g s\n",
                    cmd, until, p->t_start);
            return PL_EXIT_USAGE;
        }
        p->total_steps = steps_for(until - p->t_start, p->dt), p->length_from = "--until";
    } else if (r.steps > 0) {
        p->total_steps = r.steps, p->length_from = "run.steps";
    } else if (r.t_end > 0) {
        double left = r.t_end > p->t_start ? r.t_end - p->t_start : 0;
        p->total_steps = steps_for(left, p->dt), p->length_from = "run.t_end";
    } else if (pl_scene_flag_was_set(s, "TIMESTEPS", &flag) && flag >= 1) {
        p->total_steps = (long long)flag, p->length_from = "flag TIMESTEPS";
    } else {
        p->total_steps = steps_for(PL_DEFAULT_DURATION, p->dt), p->length_from = "default";
    }

    p->fps = 0, p->every = 0;
    if (pl_opts_has(o, "--fps"))
        p->fps = fps, p->frames_from = "--fps";
    else if (pl_opts_has(o, "--every"))
        p->every = every, p->frames_from = "--every";
    else if (r.fps > 0)
        p->fps = r.fps, p->frames_from = "run.fps";
    else if (r.every > 0)
        p->every = r.every, p->frames_from = "run.every";
    else if (pl_scene_flag_was_set(s, "PRINT_INT", &flag) && flag >= 1)
        p->every = (long long)flag, p->frames_from = "flag PRINT_INT";
    else
        p->fps = PL_DEFAULT_FPS, p->frames_from = "default";
    if (p->fps > 0 && p->fps * p->dt >= 1) /* more frames than steps: one per step */
        p->fps = 0, p->every = 1;
    return 0;
}

long long pl_run_plan_frame_step(const pl_run_plan *p, long long k)
{
    if (p->every > 0) return k * p->every;
    return k == 0 ? 0 : steps_for((double)k / p->fps, p->dt);
}

long long pl_run_plan_frame_count(const pl_run_plan *p)
{
    if (p->every > 0) return p->total_steps / p->every + 1;
    /* frames k with ceil(k / (fps dt)) <= total_steps */
    long long k = (long long)floor(p->total_steps * p->dt * p->fps + 1e-9);
    while (k > 0 && pl_run_plan_frame_step(p, k) > p->total_steps) k--;
    while (pl_run_plan_frame_step(p, k + 1) <= p->total_steps) k++;
    return k + 1;
}

int pl_run_plan_video_fps(const pl_run_plan *p)
{
    double f = p->every > 0 ? PL_DEFAULT_FPS : p->fps;
    int v = (int)lround(f);
    return v < 1 ? 1 : v > 240 ? 240 : v;
}
