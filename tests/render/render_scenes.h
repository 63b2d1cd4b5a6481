/* Small deterministic worlds and fields for the render tests, built with the engine API.
 * Every golden image in tests/golden/ is produced from one of these cases by
 * render_case() (tools/update-goldens.sh runs test_render_golden --update). */
#ifndef PL_TEST_RENDER_SCENES_H
#define PL_TEST_RENDER_SCENES_H

#include "draw_world.h"
#include "porelab/world.h"

/* A box (floor and two walls) holding a pyramid of discs of two materials, a square and a
 * hexagon on top, and one fixed disc; stepped twice so contacts carry forces. */
pl_world *make_pile_world(void);

/* Discs thrown with different velocities (for speed colouring). */
pl_world *make_moving_world(void);

/* A synthetic pore-pressure field on a structured triangle mesh over the pile's box
 * (hydrostatic plus a bump and a dip of excess pressure, with the matching Darcy velocity),
 * set into the scene as the fluid field; field is PL_FLUID_PRESSURE (2) or
 * PL_FLUID_EXCESS_PRESSURE (3). */
int set_synthetic_fluid(pl_render_scene *s, int field);

/* A structured pressure field for benchmarks and rasterizer checks: gx x gy cells (two
 * triangles each) over [0, s->hi], value 9810 (hi.y - y) + 3000 sin(kx i) cos(ky j) as
 * PL_FLUID_PRESSURE, Darcy velocity vscale (cos(kx i), sin(ky j)) per cell (exactly zero when
 * vscale is 0). Returns 0, or -1 when out of memory. */
int set_grid_field(pl_render_scene *s, int gx, int gy, double kx, double ky, double vscale);

/* Golden cases. */
typedef struct render_case {
    const char *name;    /* golden file tests/golden/<name>.png */
    const char *what;    /* what it shows */
} render_case_info;

int render_case_count(void);
const render_case_info *render_case_at(int i);
/* Builds the draw list of case i (with optional tweaks used by the negative tests:
 * colour_shift changes the first material colour, drop_layers removes layers from the mask,
 * shift_body moves body 6 (a disc) by a third of its radius). Returns 0 or -1 with err. */
typedef struct render_tweak {
    int colour_shift;
    unsigned drop_layers;
    int shift_body;
} render_tweak;
int render_case(int i, const render_tweak *tw, pl_draw_list *dl, char *err, size_t errlen);

#endif
