/* The live lab window (`porelab view SCENE.lua`, `porelab run --window`). */
#ifndef PL_APP_WINDOW_H
#define PL_APP_WINDOW_H

#include "options.h"

/* Opens the window on the scene o->positional[0] with the options of `view` (or `run`):
 * --size, --layers, --trust, --traceback, --out, and when present --paused, --speed N.
 * Returns the exit code. Without SDL2 in this build, explains how to get the window. */
int pl_window_main(const pl_opts *o);

#endif
