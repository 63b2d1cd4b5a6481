/* porelab view SCENE.lua: the live lab window. */
#include "commands.h"
#include "options.h"
#include "window.h"
#include "cli_common.h"

static const pl_opt_spec view_specs[] = {
    {"--size", NULL, "WxH", "window size in pixels (default: the scene's, else 800x600)"},
    {"--layers", NULL, "LIST", "layers shown at start, e.g. bodies,forces,pressure"},
    {"--paused", NULL, NULL, "open paused (space starts)"},
    {"--speed", NULL, "N", "steps per drawn frame at start (default: one frame interval of the "
                           "scene per 1/30 s of wall time)"},
    {"--out", NULL, "DIR", "folder for screenshots and files the scene writes "
                           "(default out/<scene>/)"},
    {"--trust", NULL, NULL, "lift the sandbox (only for scenes you trust)"},
    {"--traceback", NULL, NULL, "print the Lua traceback with errors"},
    {"--until", NULL, "T", "simulated time at which the run pauses (default: the scene's)"},
    {"--steps", NULL, "N", "number of steps after which the run pauses"},
    {"--fps", NULL, "F", "scene frames per simulated second (on_frame hook interval)"},
    {"--every", NULL, "N", "call on_frame every N steps"},
    {NULL, NULL, NULL, NULL}};

static const pl_command_help view_help = {
    "view", "SCENE.lua [options]",
    "Opens the scene in a window: play/pause (space), single step (s), faster/slower (+/-),\n"
    "restart (r), rewind (left arrow, backspace), layer keys 1-9, pan (drag empty space or\n"
    "middle button), zoom (wheel), grab a grain (drag it), fix/release (right click),\n"
    "scene parameters (tab, up/down), screenshot (p), help (h). Saving the scene file\n"
    "reloads it. The keys are listed in docs/classroom.md.",
    view_specs};

int pl_cmd_view(int argc, char **argv)
{
    pl_opts o;
    int rc = pl_opts_parse(&o, &view_help, argc, argv, 1);
    if (rc >= 0) return rc;
    if (o.npositional != 1) {
        pl_opts_print_help(stderr, &view_help);
        return PL_EXIT_USAGE;
    }
    if (pl_cli_scene_limits(&o, NULL) != 0) return PL_EXIT_USAGE;
    return pl_window_main(&o);
}
