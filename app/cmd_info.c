/* porelab info SCENE.lua: what the scene contains and how it will be computed. */
#include "cli_common.h"
#include "commands.h"
#include "report.h"
#include "run_plan.h"
#include "render/drawlist.h"

#include <limits.h>
#include <stdio.h>

static const pl_opt_spec info_specs[] = {
    {"--trust", NULL, NULL, "lift the sandbox (only for scenes you trust)"},
    {"--traceback", NULL, NULL, "print the Lua traceback with errors"},
    {NULL, NULL, NULL, NULL}};

static const pl_command_help info_help = {
    "info", "SCENE.lua [options]",
    "Builds the scene (without running it) and prints its bodies, materials, contact law,\n"
    "damping, the time step chosen and the critical step it came from (with the body that\n"
    "limits it), the fluid model, the flags the scene set, and the planned run.",
    info_specs};

/* Checks what `porelab run` checks before its first step - the render table (and the
 * overlay at the start), the camera, the run plan - and prints the plan. Returns 0 or an
 * exit code after printing the error. */
static int check_and_print_plan(const pl_opts *o, pl_scene *s, pl_world *w)
{
    pl_render_options ropt;
    if (pl_cli_render_options(o, s, w, &ropt) != 0) return PL_EXIT_FAIL;
    int rc = pl_run_plan_check_view(s, &ropt);
    if (rc) return rc;
    pl_draw_list overlay;
    pl_draw_list_init(&overlay);
    rc = pl_cli_overlay(o, s, &overlay, &ropt) != 0 ? PL_EXIT_FAIL : 0;
    pl_draw_list_free(&overlay);
    if (rc) return rc;
    pl_run_plan p;
    if ((rc = pl_run_plan_make(o, s, w, &p)) != 0) return rc;
    printf("  %-15s%lld steps to t = %.6g s (from %s)\n", "run", p.total_steps,
           p.t_start + (double)p.total_steps * p.dt, p.length_from);
    if (p.every > 0)
        printf("  %-15s%lld, one every %lld steps (from %s)\n", "frames",
               pl_run_plan_frame_count(&p), p.every, p.frames_from);
    else
        printf("  %-15s%lld, %g per simulated second (from %s)\n", "frames",
               pl_run_plan_frame_count(&p), p.fps, p.frames_from);
    return 0;
}

int pl_cmd_info(int argc, char **argv)
{
    pl_opts o;
    int rc = pl_opts_parse(&o, &info_help, argc, argv, 1);
    if (rc >= 0) return rc;
    if (pl_cli_require_scene(&o) != 0) return PL_EXIT_USAGE;
    pl_report_ignore_file_size_signal();
    char out_dir[PATH_MAX];
    pl_cli_default_out(o.positional[0], out_dir, sizeof out_dir);
    pl_scene *s = pl_cli_load_scene(&o, out_dir);
    if (!s) return PL_EXIT_FAIL;
    pl_world *w = pl_scene_world(s);
    int declarative = pl_scene_declarative(s);
    rc = PL_EXIT_OK;
    printf("porelab info %s (%s)\n", pl_scene_path(s),
           declarative ? "declarative: porelab runs it"
                       : "imperative script: it ran itself; its last world is shown");
    if (!w) {
        printf("  the scene creates no world\n");
    } else {
        pl_report_bodies(stdout, w);
        pl_report_materials(stdout, w);
        pl_report_contact_law(stdout, w);
        pl_report_damping(stdout, w);
        pl_report_time_step(stdout, w);
        pl_report_models(stdout, w, declarative ? 20 : 0);
        fputs(pl_scene_fluid_notes(s), stdout); /* fluid = "auto": the choice and why */
        pl_report_flags(stdout, s);
        if (declarative) rc = check_and_print_plan(&o, s, w);
    }
    if (pl_report_close_csv(stderr, s) != 0 && rc == PL_EXIT_OK) rc = PL_EXIT_FAIL;
    pl_scene_destroy(&s);
    return rc;
}
