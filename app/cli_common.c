#include "cli_common.h"
#include "scene_chart.h"
#include "context.h"
#include "scene_overlay.h"
#include "scene_render.h"

#include <inttypes.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

/* Reads a limit option in (0, hi]; 0 when absent. */
static int limit_option(const pl_opts *o, const char *name, double lo, double hi,
                        const char *what, double *out)
{
    *out = 0;
    const char *v = pl_opts_get(o, name);
    if (!v) return 0;
    char *end;
    double x = strtod(v, &end);
    if (end == v || *end || !isfinite(x) || x < lo || x > hi || !(x > 0)) {
        fprintf(stderr, "porelab %s: %s must be %s in [%g, %g] (got '%s')\n", o->cmd->command,
                name, what, lo, hi, v);
        return -1;
    }
    *out = x;
    return 0;
}

/* Checks the sandbox limits and --out; prints the error and returns -1 when invalid. */
static int check_common(const pl_opts *o)
{
    double v;
    if (limit_option(o, "--max-cpu", 0.001, PL_SCENE_MAX_CPU_LIMIT, "a number of seconds", &v) ||
        limit_option(o, "--max-memory", PL_SCENE_MIN_MEMORY, PL_SCENE_MAX_MEMORY_LIMIT,
                     "a number of megabytes", &v))
        return -1;
    const char *out = pl_opts_get(o, "--out");
    if (out && out[0] == '\0') {
        fprintf(stderr, "porelab %s: --out must name a folder (got ''; use --out . for the "
                        "current folder)\n", o->cmd->command);
        return -1;
    }
    for (const unsigned char *p = (const unsigned char *)(out ? out : ""); *p; p++)
        if (*p < 0x20 || *p == 0x7f) {
            fprintf(stderr, "porelab %s: --out must be a plain folder name (byte 0x%02x at "
                            "position %d is a control character)\n", o->cmd->command, *p,
                    (int)((const char *)p - out) + 1);
            return -1;
        }
    return 0;
}

int pl_cli_require_scene(const pl_opts *o)
{
    if (o->npositional != 1) {
        fprintf(stderr, "porelab %s: a scene file is required (usage: porelab %s %s)\n",
                o->cmd->command, o->cmd->command, o->cmd->usage);
        return -1;
    }
    return check_common(o);
}

void pl_cli_default_out(const char *scene_path, char *out, size_t n)
{
    char stem[256];
    pl_path_stem(scene_path, stem, sizeof stem);
    snprintf(out, n, "out/%s", stem);
}

void pl_cli_print_scene_error(const pl_opts *o, pl_scene *s)
{
    fprintf(stderr, "porelab: %s\n", pl_scene_error(s));
    if (pl_opts_has(o, "--traceback") && pl_scene_traceback(s)[0])
        fprintf(stderr, "%s\n", pl_scene_traceback(s));
}

int pl_cli_scene_limits(const pl_opts *o, pl_scene *s)
{
    double cpu = 0, mem = 0;
    if (limit_option(o, "--max-cpu", 0.001, PL_SCENE_MAX_CPU_LIMIT, "a number of seconds", &cpu) ||
        limit_option(o, "--max-memory", PL_SCENE_MIN_MEMORY, PL_SCENE_MAX_MEMORY_LIMIT,
                     "a number of megabytes", &mem))
        return -1;
    if (s) pl_scene_set_limits(s, cpu, mem); /* 0 keeps the default (none with --trust) */
    return 0;
}

int pl_cli_parse_inputs(const pl_opts *o, pl_cli_inputs *in)
{
    memset(in, 0, sizeof *in);
    const char *cmd = o->cmd->command;
    const char *v = pl_opts_get(o, "--seed");
    if (v) {
        char *end;
        long long x = strtoll(v, &end, 10);
        if (end == v || *end || x < 0 || x > 9007199254740991LL) {
            fprintf(stderr, "porelab %s: --seed must be an integer in [0, 9007199254740991] (0: the scene's own "
                            "seeds; got '%s')\n", cmd, v);
            return -1;
        }
        in->seed = x;
    }
    const char *all[PL_CLI_MAX_PARAMS];
    int n = pl_opts_all(o, "--param", all, PL_CLI_MAX_PARAMS);
    if (n > PL_CLI_MAX_PARAMS) {
        fprintf(stderr, "porelab %s: at most %d --param options (got %d)\n", cmd, PL_CLI_MAX_PARAMS, n);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        const char *eq = strchr(all[i], '=');
        size_t len = eq ? (size_t)(eq - all[i]) : 0;
        char *end = NULL;
        double x = eq ? strtod(eq + 1, &end) : 0;
        if (!eq || len == 0 || len >= sizeof in->name_buf[i] || end == eq + 1 || *end || !isfinite(x)) {
            fprintf(stderr, "porelab %s: --param must be NAME=NUMBER with a parameter the scene declares (got '%s')\n",
                    cmd, all[i]);
            return -1;
        }
        memcpy(in->name_buf[i], all[i], len);
        in->name_buf[i][len] = '\0';
        for (int j = 0; j < i; j++)
            if (strcmp(in->name_buf[j], in->name_buf[i]) == 0) {
                fprintf(stderr, "porelab %s: --param %s given twice\n", cmd, in->name_buf[i]);
                return -1;
            }
        in->names[i] = in->name_buf[i];
        in->values[i] = x;
        in->n = i + 1;
    }
    return 0;
}

pl_scene *pl_cli_load_scene(const pl_opts *o, const char *out_dir)
{
    pl_cli_inputs in;
    if (pl_cli_parse_inputs(o, &in) != 0) return NULL;
    pl_scene_options so = {o->positional[0], out_dir, pl_opts_has(o, "--trust"), in.seed, in.n, in.names, in.values};
    pl_scene *s = pl_scene_create(&so);
    if (!s) {
        fprintf(stderr, "porelab: out of memory while creating the Lua state\n");
        return NULL;
    }
    if (pl_cli_scene_limits(o, s) != 0) {
        pl_scene_destroy(&s);
        return NULL;
    }
    pl_scene_register_chart(s);
    if (pl_scene_load(s) != 0 || pl_scene_apply_params(s) != 0) {
        pl_cli_print_scene_error(o, s);
        pl_scene_destroy(&s);
        return NULL;
    }
    return s;
}

int pl_cli_render_options(const pl_opts *o, pl_scene *s, pl_world *w, pl_render_options *opt)
{
    *opt = pl_default_render_options();
    if (pl_scene_render_options(s, w, opt) != 0) {
        pl_cli_print_scene_error(o, s);
        return -1;
    }
    if (pl_opts_size(o, "--size", &opt->width, &opt->height) != 0) return -1;
    const char *layers = pl_opts_get(o, "--layers");
    if (layers) {
        char err[512];
        if (pl_render_parse_layers(layers, &opt->layers, err, sizeof err) != 0) {
            fprintf(stderr, "porelab %s: --layers: %s\n", o->cmd->command, err);
            return -1;
        }
    }
    return 0;
}

int pl_cli_overlay(const pl_opts *o, pl_scene *s, pl_draw_list *dl, pl_render_options *opt)
{
    int present = pl_scene_overlay(s, dl);
    if (present < 0) {
        pl_cli_print_scene_error(o, s);
        return -1;
    }
    opt->overlay = present ? dl : NULL;
    return 0;
}

void pl_cli_print_hash(const pl_world *w)
{
    printf("state-hash: %016" PRIx64 "\n", pl_world_state_hash(w));
}
