/* pl_window_main for builds without SDL2: says what is missing and how to get it. */
#include "window.h"

#include <stdio.h>

int pl_window_main(const pl_opts *o)
{
    (void)o;
    fprintf(stderr,
            "porelab: this porelab was built without the live window (it needs SDL2 and "
            "OSMesa/OpenGL).\n"
            "  Debian/Ubuntu: apt-get install libsdl2-dev libosmesa6-dev, then rebuild "
            "(cmake -DPL_WITH_SDL=AUTO or ON).\n"
            "  Meanwhile: porelab run SCENE.lua writes the frames, porelab still draws one "
            "figure.\n");
    return PL_EXIT_FAIL;
}
