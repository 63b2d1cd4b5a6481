/* porelab run SCENE.lua: steps a declarative scene, writes frames, calls its hooks between
 * steps, prints a summary; runs an imperative script and reports how it ended. */
#include "cli_common.h"
#include "commands.h"
#include "progress.h"
#include "restart.h"
#include "report.h"
#include "run_plan.h"
#include "vtk_series.h"
#include "manifest.h"
#include "render/drawlist.h"
#include "gl_cli.h"
#include "window.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>
#include "thread_pool.h"

static const pl_opt_spec run_specs[] = {
    {"--out", NULL, "DIR", "output folder (default out/<scene-name>/)"},
    {"--until", NULL, "T", "simulated end time, s"},
    {"--steps", NULL, "N", "number of steps to take"},
    {"--fps", NULL, "F", "frames per simulated second (default: the scene's, else 30)"},
    {"--every", NULL, "N", "one frame every N steps"},
    {"--size", NULL, "WxH", "frame size in pixels (default: the scene's, else 800x600)"},
    {"--layers", NULL, "LIST", "layers to draw, e.g. bodies,forces,time or +mesh,-time"},
    {"--video", NULL, "FILE", "also encode the frames into FILE (.mp4 or .gif) with ffmpeg"},
    {"--quiet", "-q", NULL, "no progress bar and no summary"},
    {"--trust", NULL, NULL, "lift the sandbox (only for scenes you trust)"},
    {"--hash", NULL, NULL, "print the final state hash as 'state-hash: <16 hex digits>'"},
    {"--vtk", NULL, NULL, "also write VTK files per frame (DIR/vtk/, indexed by DIR/run.pvd) for ParaView"},
    {"--traceback", NULL, NULL, "print the Lua traceback with errors"},
    {"--renderer", NULL, "NAME", "cairo (default) or gl (OpenGL through OSMesa) for the frames"},
    {"--window", NULL, NULL, "open the live lab window instead of writing frames (porelab view)"},
    {"--param", NULL, "NAME=VALUE", "set a parameter the scene declares (repeatable), checked against its range"},
    {"--seed", NULL, "N", "run seed feeding every random helper (default 0: the scene's own seeds)"},
    {"--no-frames", NULL, NULL, "write no frame images (hooks, CSV and the manifest as usual): for sweeps"},
    {"--threads", NULL, "N", "compute the contacts on N threads (same results as without; default: one, no pool)"},
    {"--skip-done", NULL, NULL, "do nothing when DIR/manifest.json holds a finished run with the same inputs"},
    PL_RESTART_OPTION_ROWS,
    {NULL, NULL, NULL, NULL}};

static const pl_command_help run_help = {
    "run", "SCENE.lua [options]",
    "Runs a scene. A declarative scene (one that returns its world) is stepped by porelab,\n"
    "which writes DIR/frame_000000.png ... and calls the scene's on_frame hook after each\n"
    "frame. An imperative script steps itself; porelab exits non-zero if it raises an error.\n"
    "The run length comes from --until/--steps, else the scene's run table, else the flag\n"
    "TIMESTEPS, else 1 s; the frame interval from --fps/--every, else the scene, else the\n"
    "flag PRINT_INT, else 30 frames per second. Every run writes DIR/manifest.json: scene and\n"
    "its hash, parameters, seed, build, final state hash, wall and CPU time, exit status and\n"
    "the scene's results (docs/scene-reference.md).",
    run_specs};

typedef struct run_ctx {
    const pl_opts *o;
    pl_scene *s;
    pl_world *w;
    const pl_run_plan *plan;
    pl_render_options *ropt;
    pl_draw_list *overlay;
    const char *out_dir;
    pl_frame_writer *fw;
    pl_vtk_series *vtk;
    long long start_step;
    double last_frame_time;
    pl_gl_frames *gfw; /* --renderer gl: frames drawn by OpenGL instead of fw (last member) */
    pl_restart *rs;    /* restart files (restart.c), NULL without --save-every/--save-at/--resume */
    int first_frame;   /* index of the first frame this process writes (a resumed run: > 0) */
    int no_frames;     /* --no-frames: frame times reached (hooks called), no images written */
    int skipped;       /* frame times passed without an image (--no-frames) */
} run_ctx;

static long long steps_done(const run_ctx *c)
{
    return (long long)pl_world_step_count(c->w) - c->start_step;
}

static int frame_count(const run_ctx *c)
{
    return c->gfw ? pl_gl_frames_count(c->gfw) : c->fw ? pl_frame_writer_count(c->fw) : 0;
}

/* the index the next frame gets (also with --no-frames) */
static long long frame_index(const run_ctx *c) { return (long long)frame_count(c) + c->skipped; }

static void print_stop_at(const run_ctx *c, const char *where, const char *why)
{
    fprintf(stderr, "porelab: %s%srun stopped at t = %.6g s (step %lld of %lld): %s\n",
            where ? where : "", where ? ": " : "", pl_world_time(c->w), steps_done(c),
            c->plan->total_steps, why);
    int n = frame_count(c);
    if (n > 0)
        fprintf(stderr, "porelab: %d frame%s kept in %s/ (the last at t = %.6g s)\n", n,
                n == 1 ? "" : "s", c->out_dir, c->last_frame_time);
    else
        fprintf(stderr, "porelab: no frames were written\n");
}

static void print_stop(const run_ctx *c, const char *why) { print_stop_at(c, NULL, why); }

/* The world stopped (an engine error while stepping or preparing a frame: the fluid's set-up at
 * the first update, a guard against instability): named with the line of the scene's return
 * that handed the world over, so that the message points at the scene the user wrote. */
static void print_world_stop(const run_ctx *c)
{
    print_stop_at(c, pl_scene_result_location(c->s), pl_world_last_error(c->w));
}

/* Writes the next frame and calls on_frame; 0 or -1 (after reporting). */
static int frame(run_ctx *c)
{
    char err[1024];
    long long index = frame_index(c);
    if (c->no_frames) {
        c->skipped++;
        c->last_frame_time = pl_world_time(c->w);
        goto hooks;
    }
    if (pl_cli_overlay(c->o, c->s, c->overlay, c->ropt) != 0) {
        print_stop(c, "the scene's render.overlay raised an error (above)");
        return -1;
    }
    if (pl_render_prepare(c->w, c->ropt, c->vtk != NULL) != PL_OK) {
        print_world_stop(c);
        return -1;
    }
    if ((c->gfw ? pl_gl_frames_add(c->gfw, c->w, c->ropt, err, sizeof err)
                : pl_frame_writer_add(c->fw, c->w, c->ropt, err, sizeof err)) != 0) {
        print_stop(c, err);
        return -1;
    }
    c->last_frame_time = pl_world_time(c->w);
    if (c->vtk && pl_vtk_series_add(c->vtk, c->w, err, sizeof err) != 0) {
        print_stop(c, err);
        return -1;
    }
hooks:
    if (pl_scene_call_hook(c->s, "on_frame", index) != 0) {
        pl_cli_print_scene_error(c->o, c->s);
        print_stop(c, "the scene's on_frame hook raised an error (above)");
        return -1;
    }
    /* the CSV rows so far reach the disk as whole lines once per frame */
    if (pl_report_flush_csv(stderr, c->s) != 0) {
        print_stop(c, "a CSV file could not be written (above)");
        return -1;
    }
    return 0;
}

static int step_loop(run_ctx *c, pl_progress *prog)
{
    const pl_run_plan *p = c->plan;
    double t_end = p->t_start + (double)p->total_steps * p->dt;
    long long chunk = 16, k = 1;
    int draw_first = 1, first_index = 0;
    pl_restart_frames(c->rs, p, &k, &draw_first, &first_index); /* a resumed run goes on numbering */
    if (c->fw) pl_frame_writer_start_at(c->fw, first_index);
    c->first_frame = first_index;
    long long next = pl_run_plan_frame_step(p, k);
    if (draw_first && frame(c) != 0) return -1;
    if (pl_restart_after_steps(c->rs, c->w, steps_done(c)) != 0) return print_stop(c, pl_restart_error(c->rs)), -1;
    while (steps_done(c) < p->total_steps) {
        long long target = next < p->total_steps ? next : p->total_steps;
        target = pl_restart_clip(c->rs, target, steps_done(c)); /* stop at the next restart file */
        long long n = target - steps_done(c);
        if (prog->enabled && n > chunk) n = chunk;
        if (n > INT_MAX) n = INT_MAX;
        if (n > 0) {
            double t0 = pl_wall_seconds();
            pl_status st = pl_world_step(c->w, (int)n);
            if (st != PL_OK) {
                pl_progress_finish(prog);
                print_world_stop(c);
                return -1;
            }
            double spent = pl_wall_seconds() - t0;
            if (prog->enabled) { /* aim at ~10 redraws per second */
                chunk = spent > 0 ? (long long)(0.1 * (double)n / spent) : chunk * 2;
                if (chunk < 1) chunk = 1;
                if (chunk > 1000000) chunk = 1000000;
            }
            pl_progress_update(prog, steps_done(c), pl_world_time(c->w), t_end);
        }
        if (pl_restart_after_steps(c->rs, c->w, steps_done(c)) != 0) {
            pl_progress_finish(prog);
            print_stop(c, pl_restart_error(c->rs));
            return -1;
        }
        /* >= rather than ==: a hook may have stepped the world itself. */
        if (steps_done(c) >= next) {
            if (frame(c) != 0) {
                pl_progress_finish(prog);
                return -1;
            }
            while (pl_run_plan_frame_step(p, k) <= steps_done(c)) k++;
            next = pl_run_plan_frame_step(p, k);
        }
    }
    pl_progress_finish(prog);
    if (pl_scene_call_hook(c->s, "on_finish", 0) != 0) {
        pl_cli_print_scene_error(c->o, c->s);
        print_stop(c, "the scene's on_finish hook raised an error (above)");
        return -1;
    }
    return 0;
}

static void print_summary(const run_ctx *c, double wall)
{
    const pl_run_plan *p = c->plan;
    long long n = steps_done(c);
    printf("porelab: finished %s\n", pl_scene_path(c->s));
    printf("  %-15s%lld of dt = %.6g s, t = %.6g -> %.6g s (length from %s)\n", "steps", n,
           p->dt, p->t_start, pl_world_time(c->w), p->length_from);
    printf("  %-15s%.3g s (%.0f steps/s)\n", "wall time", wall, wall > 0 ? (double)n / wall : 0);
    pl_report_bodies(stdout, c->w);
    printf("  %-15s%d\n", "contacts", pl_world_contact_count(c->w));
    pl_report_energy(stdout, c->w);
    int frames = frame_count(c);
    char interval[64];
    if (p->every > 0)
        snprintf(interval, sizeof interval, "every %lld steps", p->every);
    else
        snprintf(interval, sizeof interval, "%g per simulated second", p->fps);
    if (c->no_frames) {
        printf("  %-15snone written (--no-frames; %d frame times, %s, from %s)\n", "frames", c->skipped, interval,
               p->frames_from);
        return;
    }
    printf("  %-15s%d in %s/ (frame_%06d.png .. frame_%06d.png; %s, from %s)\n", "frames",
           frames - c->first_frame, c->out_dir, c->first_frame, frames > 0 ? frames - 1 : 0, interval,
           p->frames_from);
}

static int run_declarative_with(const pl_opts *o, pl_scene *s, pl_world *w, const char *out_dir, pl_manifest *man);

static int run_declarative(const pl_opts *o, pl_scene *s, const char *out_dir, pl_manifest *man)
{
    pl_world *w = pl_scene_world(s);
    int nthreads;
    if (pl_cli_threads("run", pl_opts_get(o, "--threads"), &nthreads) != 0) return PL_EXIT_FAIL;
    pl_thread_pool *pool = nthreads ? pl_thread_pool_create(nthreads) : NULL;
    if (nthreads && !pool) {
        fprintf(stderr, "porelab run: --threads %d: cannot start the threads\n", nthreads);
        return PL_EXIT_FAIL;
    }
    if (pool) pl_world_set_parallel_for(w, pl_thread_pool_parallel_for, pool);
    int rc = run_declarative_with(o, s, w, out_dir, man);
    if (pool) pl_world_set_parallel_for(w, NULL, NULL);
    pl_thread_pool_destroy(&pool);
    return rc;
}

static int run_declarative_with(const pl_opts *o, pl_scene *s, pl_world *w, const char *out_dir, pl_manifest *man)
{
    pl_render_options ropt;
    if (pl_cli_render_options(o, s, w, &ropt) != 0) return PL_EXIT_FAIL;
    int rc = pl_run_plan_check_view(s, &ropt);
    if (rc) return rc;
    pl_run_plan plan;
    if ((rc = pl_run_plan_make(o, s, w, &plan)) != 0) return rc;
    pl_draw_list overlay;
    pl_draw_list_init(&overlay);
    run_ctx c = {o, s, w, &plan, &ropt, &overlay, out_dir, NULL, NULL,
                 (long long)pl_world_step_count(w), 0, NULL, NULL, 0, pl_opts_has(o, "--no-frames"), 0};
    if ((rc = pl_restart_open(&c.rs, o, &plan, w, out_dir, c.start_step)) != 0) {
        pl_draw_list_free(&overlay);
        return rc;
    }
    char err[1024];
    const char *video = pl_opts_get(o, "--video");
    if (pl_gl_cli_parse_renderer(pl_opts_get(o, "--renderer"), "run") == 1)
        c.gfw = pl_gl_frames_open(out_dir, video, pl_run_plan_video_fps(&plan), err, sizeof err);
    else
        c.fw = pl_frame_writer_open(out_dir, video, pl_run_plan_video_fps(&plan), err, sizeof err);
    if (!c.fw && !c.gfw) {
        fprintf(stderr, "porelab: cannot write frames to %s/: %s\n", out_dir, err);
        pl_draw_list_free(&overlay);
        return PL_EXIT_FAIL;
    }
    if (pl_opts_has(o, "--vtk") && !(c.vtk = pl_vtk_series_open(out_dir, err, sizeof err))) {
        fprintf(stderr, "porelab: --vtk: %s\n", err);
        pl_frame_writer_close(&c.fw, err, sizeof err);
        pl_gl_frames_close(&c.gfw, err, sizeof err);
        pl_draw_list_free(&overlay);
        return PL_EXIT_FAIL;
    }
    int quiet = pl_opts_has(o, "--quiet");
    pl_progress prog;
    pl_progress_start(&prog, plan.total_steps, quiet);
    rc = step_loop(&c, &prog) == 0 ? PL_EXIT_OK : PL_EXIT_FAIL;
    /* every CSV written and closed (whether the scene closed it or not) before "finished" */
    if (pl_report_close_csv(stderr, s) != 0) {
        if (rc == PL_EXIT_OK)
            fprintf(stderr, "porelab: the run reached t = %.6g s, but its output is incomplete "
                            "(above); %d frame%s in %s/\n", pl_world_time(w), frame_count(&c),
                    frame_count(&c) == 1 ? "" : "s", out_dir);
        rc = PL_EXIT_FAIL;
    }
    double wall = pl_wall_seconds() - prog.wall_start;
    int frames = frame_count(&c);
    if (rc == PL_EXIT_OK && !quiet) print_summary(&c, wall);
    if ((c.gfw ? pl_gl_frames_close(&c.gfw, err, sizeof err)
               : pl_frame_writer_close(&c.fw, err, sizeof err)) != 0) {
        fprintf(stderr, "porelab: video: %s (the %d frames remain in %s/)\n", err, frames,
                out_dir);
        rc = PL_EXIT_FAIL;
    } else if (video && rc == PL_EXIT_OK && !quiet) {
        printf("  %-15s%s\n", "video", video);
    }
    if (c.vtk && rc == PL_EXIT_OK && !quiet) printf("  %-15s%s/run.pvd (open in ParaView)\n", "vtk", out_dir);
    pl_vtk_series_close(&c.vtk);
    if (pl_opts_has(o, "--hash")) pl_cli_print_hash(w);
    man->has_state = 1;
    man->state_hash = pl_world_state_hash(w);
    man->step_count = (long long)pl_world_step_count(w);
    man->t_end = pl_world_time(w);
    pl_restart_close(&c.rs);
    pl_draw_list_free(&overlay);
    return rc;
}

static int run_imperative(const pl_opts *o, pl_scene *s, pl_manifest *man)
{
    static const char *const ignored[] = {"--until", "--steps", "--fps", "--every", "--video",
                                          "--size", "--layers", "--vtk", "--threads", NULL};
    for (int i = 0; ignored[i]; i++)
        if (pl_opts_has(o, ignored[i]))
            fprintf(stderr, "porelab run: note: %s is an imperative script (it returns no "
                            "world), so %s does not apply\n", pl_scene_path(s), ignored[i]);
    pl_world *w = pl_scene_world(s);
    if (pl_report_close_csv(stderr, s) != 0) {
        fprintf(stderr, "porelab: %s ran, but its output is incomplete (above)\n",
                pl_scene_path(s));
        return PL_EXIT_FAIL;
    }
    if (!pl_opts_has(o, "--quiet")) {
        printf("porelab: %s ran to completion (imperative script)\n", pl_scene_path(s));
        if (w) {
            printf("  %-15s%lld, t = %.6g s\n", "steps", (long long)pl_world_step_count(w),
                   pl_world_time(w));
            pl_report_bodies(stdout, w);
            printf("  %-15s%d\n", "contacts", pl_world_contact_count(w));
            pl_report_energy(stdout, w);
        }
    }
    if (pl_opts_has(o, "--hash") && w) pl_cli_print_hash(w);
    if (w) {
        man->has_state = 1;
        man->state_hash = pl_world_state_hash(w);
        man->step_count = (long long)pl_world_step_count(w);
        man->t_end = pl_world_time(w);
    }
    return PL_EXIT_OK;
}

static double cpu_seconds(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru) != 0) return 0;
    return (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec + (double)ru.ru_stime.tv_sec +
           1e-6 * (double)ru.ru_stime.tv_usec;
}

/* The manifest's inputs (before the run). Returns 0, or an exit code after printing. */
static int manifest_start(const pl_opts *o, const char *out_dir, pl_manifest *m)
{
    pl_cli_inputs in;
    if (pl_cli_parse_inputs(o, &in) != 0) return PL_EXIT_USAGE;
    m->seed = in.seed;
    m->nover = in.n;
    for (int i = 0; i < in.n; i++) {
        snprintf(m->over_name[i], sizeof m->over_name[i], "%s", in.names[i]);
        m->over_value[i] = in.values[i];
    }
    m->until = pl_opts_get(o, "--until");
    m->steps = pl_opts_get(o, "--steps");
    char abs[PATH_MAX];
    if (out_dir[0] == '/' || !getcwd(abs, sizeof abs)) snprintf(m->out_dir, sizeof m->out_dir, "%s", out_dir);
    else pl_path_join(m->out_dir, sizeof m->out_dir, abs, out_dir);
    time_t now = time(NULL);
    struct tm tm;
    gmtime_r(&now, &tm);
    strftime(m->started_utc, sizeof m->started_utc, "%Y-%m-%dT%H:%M:%SZ", &tm);
    char err[512];
    pl_manifest_prepare(m, o->positional[0], err, sizeof err); /* unreadable: the loader says so */
    return 0;
}

static void manifest_finish(pl_manifest *m, pl_scene *s, const char *out_dir, int rc, double wall0, int quiet)
{
    char err[1024];
    m->exit_status = rc;
    m->wall_s = pl_wall_seconds() - wall0;
    m->cpu_s = cpu_seconds();
    if (s) {
        m->nparams = pl_scene_declared_params(s, m->params, m->overridden, 2 * PL_SCENE_MAX_PARAMS);
        if (rc == PL_EXIT_OK) {
            int n = pl_scene_results(s, m->results);
            if (n < 0) {
                fprintf(stderr, "porelab: %s\n", pl_scene_error(s));
                m->exit_status = PL_EXIT_FAIL;
                snprintf(m->error, sizeof m->error, "%s", pl_scene_error(s));
            } else {
                m->nresults = n;
            }
        } else if (pl_scene_error(s)[0]) {
            snprintf(m->error, sizeof m->error, "%s", pl_scene_error(s));
        }
    }
    if (m->exit_status != 0 && !m->error[0]) snprintf(m->error, sizeof m->error, "the run failed (its messages above)");
    if (pl_path_mkdirs(out_dir) != 0 || pl_manifest_write(m, out_dir, err, sizeof err) != 0) {
        fprintf(stderr, "porelab: manifest: %s\n", err[0] ? err : out_dir);
        if (m->exit_status == 0) m->exit_status = PL_EXIT_FAIL;
        return;
    }
    if (!quiet && m->exit_status == 0) {
        for (int i = 0; i < m->nresults; i++) {
            const pl_scene_result *r = &m->results[i];
            if (r->kind == 2 || r->kind == 1)
                printf("  %-15s%s = %s\n", i ? "" : "results", r->name, r->kind == 2 ? r->text : r->value != 0 ? "true" : "false");
            else printf("  %-15s%s = %.6g%s%s\n", i ? "" : "results", r->name, r->value, r->unit[0] ? " " : "", r->unit);
        }
        printf("  %-15s%s/manifest.json\n", "manifest", out_dir);
    }
}

int pl_cmd_run(int argc, char **argv)
{
    double wall0 = pl_wall_seconds();
    pl_opts o;
    int rc = pl_opts_parse(&o, &run_help, argc, argv, 1);
    if (rc >= 0) return rc;
    if (pl_cli_require_scene(&o) != 0) return PL_EXIT_USAGE;
    pl_report_ignore_file_size_signal();
    if (pl_gl_cli_parse_renderer(pl_opts_get(&o, "--renderer"), "run") < 0) return PL_EXIT_USAGE;
    if (pl_opts_has(&o, "--window")) return pl_window_main(&o);
    if (pl_opts_has(&o, "--no-frames") && (pl_opts_has(&o, "--video") || pl_opts_has(&o, "--vtk"))) {
        fprintf(stderr, "porelab run: --no-frames writes no frames: it cannot be combined with --video or --vtk\n");
        return PL_EXIT_USAGE;
    }
    char out_dir[PATH_MAX];
    if (pl_opts_has(&o, "--out"))
        snprintf(out_dir, sizeof out_dir, "%s", pl_opts_get(&o, "--out"));
    else
        pl_cli_default_out(o.positional[0], out_dir, sizeof out_dir);
    size_t len = strlen(out_dir);
    while (len > 1 && out_dir[len - 1] == '/') out_dir[--len] = '\0';
    static pl_manifest man; /* large (results, parameters): not on the stack */
    memset(&man, 0, sizeof man);
    if ((rc = manifest_start(&o, out_dir, &man)) != 0) return rc;
    if (pl_opts_has(&o, "--skip-done") && pl_manifest_done(out_dir, man.inputs)) {
        if (!pl_opts_has(&o, "--quiet"))
            printf("porelab: %s/manifest.json already holds this run (same scene, parameters, seed, length and "
                   "build): skipped\n", out_dir);
        return PL_EXIT_OK;
    }
    pl_scene *s = pl_cli_load_scene(&o, out_dir);
    if (!s) {
        snprintf(man.error, sizeof man.error, "the scene could not be loaded (its message above)");
        manifest_finish(&man, NULL, out_dir, PL_EXIT_FAIL, wall0, 1);
        return PL_EXIT_FAIL;
    }
    fputs(pl_scene_fluid_notes(s), stderr); /* fluid = "auto": the choice; model warnings */
    rc = pl_scene_declarative(s) ? run_declarative(&o, s, out_dir, &man) : run_imperative(&o, s, &man);
    if (pl_report_close_csv(stderr, s) != 0 && rc == PL_EXIT_OK) rc = PL_EXIT_FAIL;
    manifest_finish(&man, s, out_dir, rc, wall0, pl_opts_has(&o, "--quiet"));
    rc = man.exit_status;
    pl_scene_destroy(&s);
    return rc;
}
