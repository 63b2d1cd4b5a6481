/* porelab still SCENE.lua --at T -o FILE: one figure (PNG, SVG or PDF) at time T. */
#include "cli_common.h"
#include "commands.h"
#include "render/drawlist.h"
#include "gl_cli.h"
#include "report.h"
#include "restart.h"
#include "run_plan.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const pl_opt_spec still_specs[] = {
    {"--at", NULL, "T", "simulated time of the figure, s (default: the scene's current time)"},
    {"--output", "-o", "FILE", "figure to write: .png, .svg or .pdf (required)"},
    {"--size", NULL, "WxH", "figure size in pixels (points for SVG/PDF)"},
    {"--layers", NULL, "LIST", "layers to draw, e.g. bodies,forces,time"},
    {"--out", NULL, "DIR", "output folder for files the scene writes (default out/<scene>/)"},
    {"--trust", NULL, NULL, "lift the sandbox (only for scenes you trust)"},
    {"--traceback", NULL, NULL, "print the Lua traceback with errors"},
    {"--quiet", "-q", NULL, "do not print what was written"},
    {"--renderer", NULL, "NAME", "cairo (default) or gl (OpenGL through OSMesa; PNG only)"},
    {"--fps", NULL, "F", "frame rate of the run whose on_frame hooks are replayed (as for run)"},
    {"--every", NULL, "N", "or: steps between those frames (as for run)"},
    {"--from-state", NULL, "DIR", "start from the latest restart file in DIR at or before --at (run --save-every)"},
    {NULL, NULL, NULL, NULL}};

static const pl_command_help still_help = {
    "still", "SCENE.lua --at T -o FILE.png|.svg|.pdf [options]",
    "Builds the scene, steps it to time T and draws one figure with the scene's render\n"
    "options. The format follows the file extension; all three come from the same drawing.\n"
    "The scene's on_frame hook is called at the frame times of `porelab run` (scene's run\n"
    "table, or --fps/--every), so the figure equals the run's frame at T.",
    still_specs};

static int has_extension(const char *path)
{
    const char *dot = strrchr(path, '.');
    return dot && (strcmp(dot, ".png") == 0 || strcmp(dot, ".svg") == 0 ||
                   strcmp(dot, ".pdf") == 0);
}

/* Steps to time `at` exactly as `porelab run` would: the scene's on_frame hook is called at
   every frame time of the run (from the scene's run table or PRINT_INT) before `at`, so that
   a scene that acts from its hooks (opening a gate, switching the fluid on) is in the same
   state as the run's frame at that time. */
static long long target_step(const pl_run_plan *p, double at)
{
    return pl_run_plan_steps_to(p, at); /* saturates: never overflows */
}

/* start: the world's step count at the run's start (a restart file may have been loaded since:
   the hooks of frames before its step are not called, as in `porelab run --resume`) */
static pl_status step_like_run(const pl_opts *o, pl_scene *s, pl_world *w, const pl_run_plan *p,
                               double at, long long start)
{
    const long long target = target_step(p, at);
    if (target > PL_MAX_STEPS) {
        fprintf(stderr, "porelab still: --at %g s is %.3g steps of dt = %g s after the start; "
                        "the valid range is up to %.0e steps\n",
                at, (at - p->t_start) / p->dt, p->dt, (double)PL_MAX_STEPS);
        return PL_ERR_ARG;
    }
    long long k = 0, next = 0, index = 0;
    if ((long long)pl_world_step_count(w) > start) {
        pl_restart_frame_at(p, (long long)pl_world_step_count(w) - start, &index, &next);
        k = index;
    }
    for (;;) {
        long long done = (long long)pl_world_step_count(w) - start;
        /* the run draws frame k first and then calls on_frame(k); the figure at `target`
           is that drawing, so hooks of frames at or after `target` are not called */
        while (next < target && done >= next) {
            if (pl_scene_call_hook(s, "on_frame", index++) != 0) {
                pl_cli_print_scene_error(o, s);
                fprintf(stderr, "porelab: the scene's on_frame hook raised an error (above)\n");
                return PL_ERR_STATE;
            }
            while (pl_run_plan_frame_step(p, k) <= done) k++;
            next = pl_run_plan_frame_step(p, k);
        }
        if (done >= target) return PL_OK;
        long long n = (next > done && next < target ? next : target) - done;
        if (n > INT_MAX) n = INT_MAX;
        pl_status st = pl_world_step(w, (int)n);
        if (st != PL_OK) {
            fprintf(stderr, "porelab: %s: run stopped at t = %.6g s before reaching %g s: %s\n",
                    pl_scene_result_location(s), pl_world_time(w), at, pl_world_last_error(w));
            return st;
        }
    }
}

int pl_cmd_still(int argc, char **argv)
{
    pl_opts o;
    int rc = pl_opts_parse(&o, &still_help, argc, argv, 1);
    if (rc >= 0) return rc;
    if (pl_cli_require_scene(&o) != 0) return PL_EXIT_USAGE;
    pl_report_ignore_file_size_signal();
    const char *file = pl_opts_get(&o, "--output");
    if (!file || !has_extension(file)) {
        fprintf(stderr, "porelab still: -o FILE is required and must end in .png, .svg or .pdf "
                        "(got '%s')\n", file ? file : "");
        return PL_EXIT_USAGE;
    }
    int use_gl = pl_gl_cli_parse_renderer(pl_opts_get(&o, "--renderer"), "still");
    if (use_gl < 0) return PL_EXIT_USAGE;
    double at = -1;
    if (pl_opts_double(&o, "--at", 0, 1, &at) != 0) return PL_EXIT_USAGE;
    char out_dir[PATH_MAX];
    if (pl_opts_has(&o, "--out"))
        snprintf(out_dir, sizeof out_dir, "%s", pl_opts_get(&o, "--out"));
    else
        pl_cli_default_out(o.positional[0], out_dir, sizeof out_dir);

    pl_scene *s = pl_cli_load_scene(&o, out_dir);
    if (!s) return PL_EXIT_FAIL;
    pl_world *w = pl_scene_world(s);
    rc = PL_EXIT_FAIL;
    pl_render_options ropt;
    if (!w) {
        fprintf(stderr, "porelab: %s creates no world, so there is nothing to draw\n",
                pl_scene_path(s));
    } else if (pl_cli_render_options(&o, s, w, &ropt) == 0 &&
               pl_run_plan_check_view(s, &ropt) == 0) {
        double t = pl_world_time(w);
        if (at < 0) at = t;
        pl_status st = PL_OK;
        pl_run_plan plan;
        if (at < t - 1e-12) {
            fprintf(stderr, "porelab still: --at %g is before the scene's current time %g s\n",
                    at, t);
            rc = PL_EXIT_USAGE;
        } else if ((rc = pl_run_plan_make(&o, s, w, &plan)) != 0) {
            rc = rc == PL_EXIT_USAGE ? PL_EXIT_USAGE : PL_EXIT_FAIL;
            st = PL_ERR_STATE;
        } else {
            rc = PL_EXIT_FAIL;
            const long long start = (long long)pl_world_step_count(w);
            int loaded = 0;
            char used[4200];
            if (pl_opts_has(&o, "--from-state") &&
                pl_restart_load_nearest(pl_opts_get(&o, "--from-state"), w, start, target_step(&plan, at), &loaded,
                                        used, sizeof used) != 0)
                st = PL_ERR_STATE;
            else if (loaded && !pl_opts_has(&o, "--quiet"))
                printf("porelab: started from %s (t = %.6g s)\n", used, pl_world_time(w));
            if (st == PL_OK) st = step_like_run(&o, s, w, &plan, at, start);
        }
        char err[1024];
        pl_draw_list overlay;
        pl_draw_list_init(&overlay);
        if (rc != PL_EXIT_USAGE && st == PL_OK && pl_render_prepare(w, &ropt, 0) != PL_OK) {
            fprintf(stderr, "porelab: %s: %s\n", pl_scene_result_location(s), pl_world_last_error(w));
        } else if (rc != PL_EXIT_USAGE && st == PL_OK && pl_cli_overlay(&o, s, &overlay, &ropt) == 0) {
            if ((use_gl ? pl_gl_cli_still(w, &ropt, file, err, sizeof err)
                        : pl_render_to_file(w, &ropt, file, err, sizeof err)) != 0) {
                fprintf(stderr, "porelab: cannot write %s: %s\n", file, err);
            } else {
                rc = PL_EXIT_OK;
                if (!pl_opts_has(&o, "--quiet"))
                    printf("porelab: wrote %s (t = %.6g s)\n", file, pl_world_time(w));
            }
        }
        pl_draw_list_free(&overlay);
    }
    if (pl_report_close_csv(stderr, s) != 0) rc = PL_EXIT_FAIL;
    pl_scene_destroy(&s);
    return rc;
}
