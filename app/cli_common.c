#include "cli_common.h"
#include "scene_chart.h"
#include "context.h"
#include "scene_overlay.h"
#include "scene_render.h"

#include <inttypes.h>
#include <stdio.h>
#include <string.h>

int pl_cli_require_scene(const pl_opts *o)
{
    if (o->npositional == 1) return 0;
    fprintf(stderr, "porelab %s: a scene file is required (usage: porelab %s %s)\n",
            o->cmd->command, o->cmd->command, o->cmd->usage);
    return -1;
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

pl_scene *pl_cli_load_scene(const pl_opts *o, const char *out_dir)
{
    pl_scene_options so = {o->positional[0], out_dir, pl_opts_has(o, "--trust")};
    pl_scene *s = pl_scene_create(&so);
    if (!s) {
        fprintf(stderr, "porelab: out of memory while creating the Lua state\n");
        return NULL;
    }
    pl_scene_register_chart(s);
    if (pl_scene_load(s) != 0) {
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
