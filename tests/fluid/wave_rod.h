/* The pressure-wave problem of seed 000 §4.3 (Figs. 4-10 to 4-12), shared by its test
 * (tests/fluid/test_fluid_wave.c), the charts of docs/fluid.md (tests/bench/fluid_charts.c)
 * and the Klosek 1997 figures (tests/render/wave_figures.c): a 1 x 0.1 rod of n cells, no
 * gravity, head 1 at x = 0 and 0 at x = 1 from t = 0, D = 1, storage 1, so that the head is
 * erfc(x / 2 sqrt(t)) while the wave has not reached the far end.
 * method: FLUID_METHOD (0 backward Euler, 1 Crank-Nicolson, 2 explicit);
 * mass: FLUID_MASS (0 lumped, 1 consistent storage). */
#ifndef PL_TEST_WAVE_ROD_H
#define PL_TEST_WAVE_ROD_H
#include "porelab/fluid.h"
#include "porelab/world.h"

static inline pl_world *wave_rod(int n, int method, int mass) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, 0};
    pl_world *w = pl_world_create(&wd);
    pl_world_set_flag(w, "GRAVITY_Y", 0);
    pl_fluid_quad_def d = pl_default_fluid_quad_def();
    d.corners[0] = (pl_vec2){0, 0};
    d.corners[1] = (pl_vec2){1, 0};
    d.corners[2] = (pl_vec2){1, 0.1};
    d.corners[3] = (pl_vec2){0, 0.1};
    d.ndivx = n;
    d.ndivy = 1;
    pl_world_add_fluid_quad(w, &d);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){0, 0.1}, 1.0);
    pl_world_add_fluid_bc(w, (pl_vec2){1, 0}, (pl_vec2){1, 0.1}, 0.0);
    pl_world_set_flag(w, "FLUID_PERM", 0);
    pl_world_set_flag(w, "FLUID_PERM_HIGH", 1.0);
    pl_world_set_flag(w, "FLUID_STORAGE", 1.0);
    pl_world_set_flag(w, "FLUID_DRAG", 0);
    pl_world_set_flag(w, "FLUID_METHOD", method);
    pl_world_set_flag(w, "FLUID_MASS", mass);
    pl_world_fluid_set_pressure_head(w, 0.0);
    return w;
}
#endif
