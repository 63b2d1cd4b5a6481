#include "run_plan.h"

#include "render/render.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* Steps to cover `duration`; PL_STEPS_NEVER when that is beyond what a long long holds
 * (huge durations, tiny steps), so later comparisons stay exact and loops end. */
static long long steps_for(double duration, double dt)
{
    /* The small tolerance keeps t = n dt from needing one extra step by round-off. */
    double n = ceil(duration / dt - 1e-9);
    if (!(n < 9.0e18)) return PL_STEPS_NEVER; /* also NaN */
    return n > 0 ? (long long)n : 0;
}

/* The run's length in steps must be in 0..PL_MAX_STEPS (beyond it the step and frame
 * arithmetic loses exactness, and no run would end). Prints the error. */
static int check_length(const pl_scene *s, const pl_run_plan *p, double duration)
{
    if (p->total_steps >= 0 && p->total_steps <= PL_MAX_STEPS) return 0;
    const int usage = strncmp(p->length_from, "--", 2) == 0;
    if (duration >= 0)
        fprintf(stderr, "porelab: %s: the run would take %.3g steps (%s: %.6g s at dt = %.6g "
                        "s); the valid range is 0..%.0e steps: give a larger time step "
                        "(world{dt = ...}) or a shorter run\n",
                pl_scene_result_location(s), duration / p->dt, p->length_from, duration, p->dt,
                (double)PL_MAX_STEPS);
    else
        fprintf(stderr, "porelab: %s: %s = %lld steps is out of range (0..%.0e steps)\n",
                pl_scene_result_location(s), p->length_from, p->total_steps, (double)PL_MAX_STEPS);
    return usage ? PL_EXIT_USAGE : PL_EXIT_FAIL;
}

int pl_run_plan_make(const pl_opts *o, pl_scene *s, pl_world *w, pl_run_plan *p)
{
    pl_scene_run r;
    int rc;
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
        fprintf(stderr, "porelab: %s: no usable time step: %s\n", pl_scene_result_location(s),
                why[0] ? why
                       : "no dynamic body to take the automatic step from; give world{dt = ...}");
        return PL_EXIT_FAIL;
    }
    p->t_start = pl_world_time(w);
    double flag, duration = -1; /* s, when the length comes from a time */
    if (pl_opts_has(o, "--steps")) {
        p->total_steps = steps, p->length_from = "--steps";
    } else if (pl_opts_has(o, "--until")) {
        if (until < p->t_start) {
            fprintf(stderr, "porelab %s: --until %g is before the scene's current time %g s\n",
                    cmd, until, p->t_start);
            return PL_EXIT_USAGE;
        }
        duration = until - p->t_start;
        p->total_steps = steps_for(duration, p->dt), p->length_from = "--until";
    } else if (r.steps > 0) {
        p->total_steps = r.steps, p->length_from = "run.steps";
    } else if (r.t_end > 0) {
        duration = r.t_end > p->t_start ? r.t_end - p->t_start : 0;
        p->total_steps = steps_for(duration, p->dt), p->length_from = "run.t_end";
    } else if (pl_scene_flag_was_set(s, "TIMESTEPS", &flag) && flag >= 1) {
        p->total_steps = flag <= (double)PL_MAX_STEPS ? (long long)flag : PL_STEPS_NEVER;
        p->length_from = "flag TIMESTEPS";
    } else {
        duration = PL_DEFAULT_DURATION;
        p->total_steps = steps_for(duration, p->dt), p->length_from = "default";
    }
    if ((rc = check_length(s, p, duration)) != 0) return rc;

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
        p->every = flag < 9.0e18 ? (long long)flag : PL_STEPS_NEVER,
        p->frames_from = "flag PRINT_INT";
    else
        p->fps = PL_DEFAULT_FPS, p->frames_from = "default";
    if (p->fps > 0 && p->fps * p->dt >= 1) /* more frames than steps: one per step */
        p->fps = 0, p->every = 1;
    long long frames = pl_run_plan_frame_count(p);
    if (frames > INT_MAX) {
        fprintf(stderr, "porelab: %s: the run would draw %lld frames (frames from %s); the "
                        "valid range is 1..%d frames: draw fewer (--fps, --every)\n",
                pl_scene_result_location(s), frames, p->frames_from, INT_MAX);
        return strncmp(p->frames_from, "--", 2) == 0 ? PL_EXIT_USAGE : PL_EXIT_FAIL;
    }
    return 0;
}

long long pl_run_plan_steps_to(const pl_run_plan *p, double t)
{
    return t > p->t_start ? steps_for(t - p->t_start, p->dt) : 0;
}

long long pl_run_plan_frame_step(const pl_run_plan *p, long long k)
{
    if (p->every > 0) return k <= PL_STEPS_NEVER / p->every ? k * p->every : PL_STEPS_NEVER;
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

int pl_run_plan_check_view(const pl_scene *s, const pl_render_options *o)
{
    if (o->auto_camera) return 0;
    const double lo = PL_VIEW_MIN_SIDE, hi = PL_VIEW_MAX_SIDE, far = PL_VIEW_MAX_COORD;
    const double v[4] = {o->view_lo.x, o->view_lo.y, o->view_hi.x, o->view_hi.y};
    const double wx = v[2] - v[0], wy = v[3] - v[1];
    int ok = 1;
    for (int i = 0; i < 4; i++) ok = ok && isfinite(v[i]) && fabs(v[i]) <= far;
    ok = ok && wx >= lo && wx <= hi && wy >= lo && wy <= hi;
    if (ok) return 0;
    fprintf(stderr, "porelab: %s: render: camera {%g, %g, %g, %g} is %g x %g m; the valid "
                    "range is %g..%g m each side, corners within +-%g m\n",
            pl_scene_result_location(s), v[0], v[1], v[2], v[3], wx, wy, lo, hi, far);
    return PL_EXIT_FAIL;
}
