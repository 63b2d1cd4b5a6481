/* What the run, still and info commands share: loading a scene with one clear error
 * message, the default output folder, and the render options (scene, then command line). */
#ifndef PL_APP_CLI_COMMON_H
#define PL_APP_CLI_COMMON_H

#include <stddef.h>
#include "context.h" /* PATH_MAX */
#include "options.h"
#include "render/render.h"
#include "scene.h"

/* Checks that exactly one scene file was given; prints the usage error otherwise. */
int pl_cli_require_scene(const pl_opts *o);

/* Default output folder for a scene: out/<scene-name>. */
void pl_cli_default_out(const char *scene_path, char *out, size_t n);

/* Reads --max-cpu and --max-memory and sets them on s (when s is not NULL; absent options keep
 * the scene's defaults). Prints the error and returns -1 when one is out of range. */
int pl_cli_scene_limits(const pl_opts *o, pl_scene *s);

/* The run inputs of the command line: --param name=value (repeatable) and --seed N, for the
 * commands that offer them. */
#define PL_CLI_MAX_PARAMS 32
typedef struct pl_cli_inputs {
    long long seed; /* 0: the scene's own seeds */
    int n;
    const char *names[PL_CLI_MAX_PARAMS];
    char name_buf[PL_CLI_MAX_PARAMS][48];
    double values[PL_CLI_MAX_PARAMS];
} pl_cli_inputs;
/* Parses them; prints "porelab run: --param ...: ..." and returns -1 when malformed. */
int pl_cli_parse_inputs(const pl_opts *o, pl_cli_inputs *in);

/* Creates and runs the scene (with the --param/--seed inputs, checked against the scene's
 * declared parameters); on failure prints "porelab: <message>" (plus the Lua
 * traceback when --traceback was given) and returns NULL. */
pl_scene *pl_cli_load_scene(const pl_opts *o, const char *out_dir);

/* Prints the scene's last error like pl_cli_load_scene does. */
void pl_cli_print_scene_error(const pl_opts *o, pl_scene *s);

/* Render options: defaults, then the scene's render table, then --size and --layers.
 * Returns 0, or -1 after printing the error. */
int pl_cli_render_options(const pl_opts *o, pl_scene *s, pl_world *w, pl_render_options *opt);

/* Redraws the scene's overlay (render.overlay) into dl and points opt at it; call before
 * each frame. Returns 0, or -1 after printing the error. */
struct pl_draw_list;
int pl_cli_overlay(const pl_opts *o, pl_scene *s, struct pl_draw_list *dl,
                   pl_render_options *opt);

/* Prints "state-hash: 0123456789abcdef". */
void pl_cli_print_hash(const pl_world *w);

#endif
