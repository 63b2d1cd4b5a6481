/* The Navier–Stokes water's parameter table and defaults (porelab/navier_stokes.h). Apart from
 * the class so that the docs and Lua read the same rows. */
#include "porelab/navier_stokes.h"
#include <stddef.h>
#include <string.h>

#define NS_OFF(f) offsetof(pl_navier_stokes_def, f)

const pl_param pl_navier_stokes_params[PL_NAVIER_STOKES_PARAM_COUNT] = {
    {"x_min", NULL, NS_OFF(x_min), PL_PARAM_DOUBLE, "m", -1e9, 1e9, 0, "left side of the fluid box"},
    {"y_min", NULL, NS_OFF(y_min), PL_PARAM_DOUBLE, "m", -1e9, 1e9, 0, "bottom of the fluid box"},
    {"x_max", NULL, NS_OFF(x_max), PL_PARAM_DOUBLE, "m", -1e9, 1e9, 1, "right side of the fluid box (> x_min)"},
    {"y_max", NULL, NS_OFF(y_max), PL_PARAM_DOUBLE, "m", -1e9, 1e9, 1, "top of the fluid box (> y_min)"},
    {"density", NULL, NS_OFF(density), PL_PARAM_DOUBLE, "kg/m^3", 1e-6, 1e6, 1000, "fluid density rho_F"},
    {"viscosity", NULL, NS_OFF(viscosity), PL_PARAM_DOUBLE, "Pa s", 1e-9, 1e9, 1e-3, "dynamic viscosity eta"},
    {"core_fraction", NULL, NS_OFF(core_fraction), PL_PARAM_DOUBLE, "1", 0.05, 1.0, 0.75,
     "grain core seen by the fluid / contact outline, about the centroid (Mueller et al. 2020 §5)"},
    {"h_near", NULL, NS_OFF(h_near), PL_PARAM_DOUBLE, "m", 1e-9, 1e9, 0.01, "mesh size on the grain cores"},
    {"h_far", NULL, NS_OFF(h_far), PL_PARAM_DOUBLE, "m", 1e-9, 1e9, 0.05, "mesh size far from the cores (>= h_near)"},
    {"grade_distance", NULL, NS_OFF(grade_distance), PL_PARAM_DOUBLE, "m", 0, 1e9, 0.1,
     "distance from the cores over which the mesh size grows to h_far"},
    {"element", NULL, NS_OFF(element), PL_PARAM_INT, "0/1/2", 0, 2, 0,
     "0: P2 + bubble / P1 (Mueller et al. 2020), 1: Taylor-Hood P2/P1, 2: MINI (P1 + bubble / P1)"},
    {"solve_every", NULL, NS_OFF(solve_every), PL_PARAM_INT, "steps", 1, 1e6, 1,
     "grain steps per fluid step (fluid step tau = solve_every dt)"},
    {"lid_velocity", NULL, NS_OFF(lid_velocity), PL_PARAM_DOUBLE, "m/s", -1e6, 1e6, 0,
     "tangential velocity of the top side (cavity lid)"},
    {"inflow_velocity", NULL, NS_OFF(inflow_velocity), PL_PARAM_DOUBLE, "m/s", -1e6, 1e6, 0,
     "centreline velocity of a parabolic inflow on the left side (0: wall)"},
    {"open_right", NULL, NS_OFF(open_right), PL_PARAM_BOOL, "0/1", 0, 1, 0, "1: right side is a do-nothing outflow"},
    {"open_top", NULL, NS_OFF(open_top), PL_PARAM_BOOL, "0/1", 0, 1, 0, "1: top side is open (do-nothing)"},
    {"disc_sides", NULL, NS_OFF(disc_sides), PL_PARAM_INT, "1", 6, 256, 32, "sides of the polygon standing for a disc core"},
    {"newton_tol", NULL, NS_OFF(newton_tol), PL_PARAM_DOUBLE, "1", 1e-14, 1e-2, 1e-8,
     "Newton stops when max |correction| <= tol (1 + max |unknown|)"},
    {"force_relaxation", NULL, NS_OFF(force_relaxation), PL_PARAM_DOUBLE, "1", 0.01, 1.0, 0.5,
     "beta: applied load = (1 - beta) previous + beta new fluid load (against the added-mass instability)"},
    {"remesh_angle", NULL, NS_OFF(remesh_angle), PL_PARAM_DOUBLE, "deg", 0, 60, 20,
     "nodes follow the cores while the smallest mesh angle stays above this; else gmsh remeshes (0: always)"},
    {"newton_max", NULL, NS_OFF(newton_max), PL_PARAM_INT, "1", 1, 200, 20, "Newton iterations per fluid step"},
    {"project", NULL, NS_OFF(project), PL_PARAM_BOOL, "0/1", 0, 1, 1,
     "1: project the interpolated solution and history onto divergence-free fields after a mesh change"},
    {"stability_every", NULL, NS_OFF(stability_every), PL_PARAM_INT, "steps", -1, 1e6, 50,
     "fluid steps between checks of the coupling limit beta (1 + D tau / m) < 2 (0: first fluid step only; "
     "-1: never, to watch the instability)"},
};
const int pl_navier_stokes_param_count = (int)(sizeof pl_navier_stokes_params / sizeof pl_navier_stokes_params[0]);

pl_navier_stokes_def pl_default_navier_stokes_def(void) {
    pl_navier_stokes_def d;
    memset(&d, 0, sizeof d);
    pl_params_defaults(pl_navier_stokes_params, pl_navier_stokes_param_count, &d);
    return d;
}
