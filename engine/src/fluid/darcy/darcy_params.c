/* The Darcy model's parameter table (porelab/darcy.h): one row per field of pl_darcy_def, in
 * field order. The rows with a MIMES flag are the flag table's fluid rows (world/flags.c). */
#include "porelab/darcy.h"
#include "fluid/darcy/darcy_internal.h"
#include "fluid/darcy/darcy_model.h"
#include <stddef.h>

#define R(lua, flag, field, type, unit, lo, hi, def, doc) \
    {lua, flag, offsetof(pl_darcy_def, field), PL_PARAM_##type, unit, lo, hi, def, doc}
static const pl_param TABLE[] = {
    R("on", "FLUIDS_ON", on, BOOL, "0/1", 0, 1, 0,
      "turns the pore-fluid model on (1) or off (0: no fluid work at all)"),
    R("first_step_static", "FIRST_STEP_STATIC", first_step_static, BOOL, "0/1", 0, 1, 0,
      "start the transient fluid solution from the static solution (Klosek 1997 §3.9.3)"),
    R("perm_mode", "FLUID_PERM", perm_mode, INT, "0/1/2", 0, 2, 0,
      "0: FLUID_PERM_HIGH everywhere; 1: per element from the local void ratio (Kozeny-Carman); 2: per-element values set by the scene"),
    R("perm_low", "FLUID_PERM_LOW", perm_low, DOUBLE, "m/s", 0, 1e+30, 0.001,
      "lowest element conductivity (void ratio 0.01; clamp)"),
    R("perm_high", "FLUID_PERM_HIGH", perm_high, DOUBLE, "m/s", 0, 1e+30, 5.0,
      "highest element conductivity (void ratio 99; clamp); the uniform value when FLUID_PERM = 0"),
    R("solve_every", "FLUID_SOLVE_TIMESTEPS", solve_every, INT, "steps", 1, 2000000000.0, 1,
      "grain steps between fluid solutions"),
    R("density", "FLUID_DENSITY", density, DOUBLE, "kg/m^3", 1e-30, 1e+30, 1000,
      "density of the pore fluid"),
    R("write_geometry", "FLUID_GEOMETRY_FLAG", geometry_flag, BOOL, "0/1", 0, 1, 0,
      "write the fluid mesh geometry to FLUID_GEOMETRY_FILENAME (MATLAB text)"),
    R("write_pressures", "FLUID_PRESSURES_FLAG", pressures_flag, BOOL, "0/1", 0, 1, 0,
      "append the nodal pressure heads to FLUID_PRESSURES_FILENAME at every fluid solution"),
    R("storage", "FLUID_STORAGE", storage, DOUBLE, "1/m", 0, 1e+30, 0.0001,
      "specific storage S of S dh/dt = div(K grad h) (Klosek 1997 eq. 3.17: rho c); 0 = quasi-static"),
    R("viscosity", "FLUID_VISCOSITY", viscosity, DOUBLE, "Pa s", 1e-30, 1e+30, 0.001,
      "dynamic viscosity; used when FLUID_PERM_UNITS = 1 (K = k rho g / mu)"),
    R("perm_units", "FLUID_PERM_UNITS", perm_units, INT, "0/1", 0, 1, 0,
      "0: FLUID_PERM_LOW/HIGH are hydraulic conductivities (m/s); 1: intrinsic permeabilities (m^2)"),
    R("method", "FLUID_METHOD", method, INT, "0-3", 0, 3, 0,
      "transient method: 0 backward Euler, 1 Crank-Nicolson, 2 explicit (Klosek 1997 §3.9.2, sub-stepped), 3 static every solve"),
    R("mass", "FLUID_MASS", mass_consistent, INT, "0/1", 0, 1, 0,
      "storage matrix: 0 lumped, 1 consistent (implicit methods)"),
    R("explicit_safety", "FLUID_EXPLICIT_SAFETY", explicit_safety, DOUBLE, "1", 0.001, 1, 0.9,
      "fraction of the explicit stability limit used per sub-step"),
    R("porosity_method", "FLUID_POROSITY_METHOD", porosity_method, INT, "0/1", 0, 1, 0,
      "solid area per element: 0 exact clipping, 1 pixellation (Klosek 1997 §3.6)"),
    R("pixels", "FLUID_PIXELS", pixels, INT, "pixels", 1, 4096, 16,
      "pixellation resolution: pixels along the longer side of an element's bounding box"),
    R("porosity_map", "FLUID_POROSITY_MAP", porosity_map, INT, "0/1", 0, 1, 1,
      "porosity for permeability: 0 areal (2D), 1 mapped to 3D (1 - 2/sqrt(pi sqrt 3) (1 - n2)^1.5)"),
    R("kc_mode", "FLUID_KC_MODE", kc_mode, INT, "0/1", 0, 1, 0,
      "0: interpolate e^3/(1+e) between LOW (e = 0.01) and HIGH (e = 99); 1: K = FLUID_KC_C1 e^3/(1+e) clamped"),
    R("kc_c1", "FLUID_KC_C1", kc_c1, DOUBLE, "m/s", 0, 1e+30, 0.01,
      "Kozeny-Carman constant C1 of Klosek 1997 eq. 3.8 (FLUID_KC_MODE = 1)"),
    R("drag", "FLUID_DRAG", drag, BOOL, "0/1", 0, 1, 1,
      "add the interphase drag of the porous skeleton (DESIGN §3) to the outline pressure force"),
    R("force_reuse", "FLUID_FORCE_REUSE", force_reuse, BOOL, "0/1", 0, 1, 0,
      "1: the fluid force on each body is computed at fluid updates (every FLUID_SOLVE_TIMESTEPS steps) and reused in between; 0: every grain step"),
    R("consolidation", "FLUID_CONSOLIDATION", consolidation, BOOL, "0/1", 0, 1, 0,
      "1: grains moving into or out of the pores change the pore pressure: (S + n rho_f g / K_f) dh/dt - div(K grad h) = -div(v_s) (docs/soil.md)"),
    R("porosity_every", "FLUID_POROSITY_TIMESTEPS", porosity_every, INT, "steps", 0, 2000000000.0, 0,
      "grain steps between porosity updates (solid areas, permeability, storage, and the pieces of each grain in each element); in between, every fluid solution takes its source and pushes the grains with the last pieces (docs/soil.md §2); 0 = at every fluid solution"),
    R("bulk_modulus", "FLUID_BULK_MODULUS", bulk_modulus, DOUBLE, "Pa", 0, 1e+30, 2200000000.0,
      "bulk modulus K_f of the pore fluid (storage n rho_f g / K_f with FLUID_CONSOLIDATION); 0 = incompressible"),
    R("stagger_check", "FLUID_STAGGER_CHECK", stagger_check, BOOL, "0/1", 0, 1, 1,
      "1: refuse a grain step times FLUID_SOLVE_TIMESTEPS above the staggering limit of the undrained coupling, 2 sqrt(m_min / k) with k = K_f d^2 / (n A_e) relaxed by seepage (docs/stability.md); 0: no check (stability sweeps)"),
};
#undef R
#define NROWS ((int)(sizeof TABLE / sizeof TABLE[0]))

const pl_param *pl_darcy_param_table(int *count) {
    if (count) *count = NROWS;
    return TABLE;
}

pl_darcy_def pl_default_darcy_def(void) {
    pl_darcy_def d;
    pl_params_defaults(TABLE, NROWS, &d);
    return d;
}

/* The model class (world/model.h); its functions are in darcy_model.c. */
const pl_model_class pl_darcy_class = {
    .name = "darcy",
    .label = "Darcy seepage on finite elements (Klosek 1997 ch. 3)",
    .def_size = sizeof(pl_darcy_def),
    .params = TABLE,
    .nparams = NROWS,
    .create = pl__darcy_create,
    .prepare = pl__darcy_prepare,
    .advance = pl__darcy_advance,
    .loads = pl__darcy_loads,
    .hash = pl__darcy_hash,
    .snapshot = pl__darcy_snapshot,
    .restore = pl__darcy_restore,
    .snapshot_free = pl__darcy_snapshot_free,
    .save = pl__darcy_save, /* restart files (world/snapshot_file.c) */
    .load = pl__darcy_load,
    .cost = pl__darcy_cost,
    .destroy = pl__darcy_destroy,
};
