/* The Stokes model's parameter table and defaults (porelab/stokes.h). Apart from the class so
 * that the kernels' tests need no world. */
#include "porelab/stokes.h"
#include <stddef.h>
#include <string.h>

#define SB_OFF(f) offsetof(pl_stokes_def, f)

const pl_param pl_stokes_params[PL_STOKES_PARAM_COUNT] = {
    {"viscosity", NULL, SB_OFF(viscosity), PL_PARAM_DOUBLE, "Pa s", 1e-30, 1e30, 1e-3, "dynamic viscosity mu"},
    {"density", NULL, SB_OFF(density), PL_PARAM_DOUBLE, "kg/m^3", 0, 1e30, 1000,
     "fluid density rho_l (buoyancy -rho_l A g, seed eq. 4.39)"},
    {"disc_elements", NULL, SB_OFF(disc_elements), PL_PARAM_INT, "elements", 6, 4096, 24, "boundary elements per disc"},
    {"wall_elements", NULL, SB_OFF(wall_elements), PL_PARAM_INT, "elements", 1, 100000, 40,
     "boundary elements per container side (uniform)"},
    {"element_length", NULL, SB_OFF(element_length), PL_PARAM_DOUBLE, "m", 0, 1e30, 0,
     "if > 0: target element length on container sides (more elements where a side is long)"},
    {"polygon_elements", NULL, SB_OFF(polygon_elements), PL_PARAM_INT, "elements", 3, 4096, 24,
     "boundary elements per polygon, spread over its sides by length (at least one per side)"},
    {"gap", NULL, SB_OFF(gap), PL_PARAM_DOUBLE, "m", 0, 1e30, 0,
     "artificial gap (seed 3.4): each particle's outline shrunk by gap/2 for the fluid"},
    {"solve_every", NULL, SB_OFF(solve_every), PL_PARAM_INT, "steps", 1, 1000000, 1,
     "solve every N grain steps; the loads are held in between"},
    {"check_stability", NULL, SB_OFF(check_stability), PL_PARAM_BOOL, "0/1", 0, 1, 1,
     "1: stop when solve_every*dt >= 2m/K for a particle (K from the solve)"},
    {"field_grid", NULL, SB_OFF(field_grid), PL_PARAM_INT, "points", 2, 1000, 40,
     "sample points along the container's longer side for the drawing field"},
    {"load_wall", NULL, SB_OFF(load_wall), PL_PARAM_INT, "body", -1, 1e9, -1,
     "wall body held by a set force (seed 5.3.2): its normal traction given; -1: none"},
    {"load_force", NULL, SB_OFF(load_force), PL_PARAM_DOUBLE, "N/m", -1e30, 1e30, 0,
     "force of the held wall on the fluid along the wall's inward normal, per m thickness"},
    {"load_contacts", NULL, SB_OFF(load_contacts), PL_PARAM_BOOL, "0/1", 0, 1, 0,
     "1: the fluid gets load_force minus the contact force on the held wall (seed 5.3.2)"},
};
const int pl_stokes_param_count = (int)(sizeof pl_stokes_params / sizeof pl_stokes_params[0]);

pl_stokes_def pl_default_stokes_def(void) {
    pl_stokes_def d;
    memset(&d, 0, sizeof d);
    pl_params_defaults(pl_stokes_params, pl_stokes_param_count, &d);
    return d;
}
