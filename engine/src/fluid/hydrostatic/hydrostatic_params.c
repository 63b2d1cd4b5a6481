/* The hydrostatic water's parameter table and defaults (porelab/hydrostatic.h). Apart from the
 * class so that the kernels' tests need no world. */
#include "porelab/hydrostatic.h"
#include <stddef.h>
#include <string.h>

#define HS_OFF(f) offsetof(pl_hydrostatic_def, f)

const pl_param pl_hydrostatic_params[PL_HYDROSTATIC_PARAM_COUNT] = {
    {"x_min", NULL, HS_OFF(x_min), PL_PARAM_DOUBLE, "m", -1e9, 1e9, 0, "left side of the tank region"},
    {"x_max", NULL, HS_OFF(x_max), PL_PARAM_DOUBLE, "m", -1e9, 1e9, 1, "right side of the tank region (> x_min)"},
    {"bottom", NULL, HS_OFF(bottom), PL_PARAM_DOUBLE, "m", -1e9, 1e9, 0, "bottom of the tank region (y)"},
    {"level", NULL, HS_OFF(level), PL_PARAM_DOUBLE, "m", -1e9, 1e9, 0.5,
     "free-surface level: height along -g/|g| (y for g along -y), >= bottom"},
    {"density", NULL, HS_OFF(density), PL_PARAM_DOUBLE, "kg/m^3", 1e-30, 1e30, 1000, "water density rho_f"},
    {"drag", NULL, HS_OFF(drag), PL_PARAM_DOUBLE, "N s/m^3", 0, 1e30, 0,
     "linear drag beta: force -beta v per m^2 of submerged area"},
    {"moving_level", NULL, HS_OFF(moving_level), PL_PARAM_BOOL, "0/1", 0, 1, 0,
     "1: the level follows the displaced area (water area fixed at attachment)"},
};
const int pl_hydrostatic_param_count = (int)(sizeof pl_hydrostatic_params / sizeof pl_hydrostatic_params[0]);

pl_hydrostatic_def pl_default_hydrostatic_def(void) {
    pl_hydrostatic_def d;
    memset(&d, 0, sizeof d);
    pl_params_defaults(pl_hydrostatic_params, pl_hydrostatic_param_count, &d);
    return d;
}

