/// Darcy seepage model (seed 000 ch. 3, Klosek 1997 "MIMES"): its typed definition.
///
/// The fields below are the model's parameters. Each has a row in the table returned by
/// pl_darcy_param_table (Lua name, MIMES flag, unit, range, default, doc); that one table
/// validates pl_world_set_darcy, maps the historical flags (FLUIDS_ON, FLUID_PERM, ...) onto the
/// fields, reads `w:darcy{...}` in Lua and writes the flag documentation. The flags and the def
/// are one storage: setting a flag changes the def and the reverse.
#ifndef PORELAB_DARCY_H
#define PORELAB_DARCY_H

#include "porelab/core.h"
#include "porelab/params.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pl_world pl_world;

/// Parameters of the Darcy model (defaults from pl_default_darcy_def).
typedef struct pl_darcy_def {
    int on; ///< turns the pore-fluid model on (1) or off (0: no fluid work at all) (0/1; flag FLUIDS_ON; [0, 1], default 0)
    int first_step_static; ///< start the transient fluid solution from the static solution (Klosek 1997 §3.9.3) (0/1; flag FIRST_STEP_STATIC; [0, 1], default 0)
    int perm_mode; ///< 0: FLUID_PERM_HIGH everywhere; 1: per element from the local void ratio (Kozeny-Carman); 2: per-element values set by the scene (0/1/2; flag FLUID_PERM; [0, 2], default 0)
    double perm_low; ///< lowest element conductivity (void ratio 0.01; clamp) (m/s; flag FLUID_PERM_LOW; [0, 1e+30], default 0.001)
    double perm_high; ///< highest element conductivity (void ratio 99; clamp); the uniform value when FLUID_PERM = 0 (m/s; flag FLUID_PERM_HIGH; [0, 1e+30], default 5)
    int solve_every; ///< grain steps between fluid solutions (steps; flag FLUID_SOLVE_TIMESTEPS; [1, 2e+09], default 1)
    double density; ///< density of the pore fluid (kg/m^3; flag FLUID_DENSITY; [1e-30, 1e+30], default 1000)
    int geometry_flag; ///< write the fluid mesh geometry to FLUID_GEOMETRY_FILENAME (MATLAB text) (0/1; flag FLUID_GEOMETRY_FLAG; [0, 1], default 0)
    int pressures_flag; ///< append the nodal pressure heads to FLUID_PRESSURES_FILENAME at every fluid solution (0/1; flag FLUID_PRESSURES_FLAG; [0, 1], default 0)
    double storage; ///< specific storage S of S dh/dt = div(K grad h) (Klosek 1997 eq. 3.17: rho c); 0 = quasi-static (1/m; flag FLUID_STORAGE; [0, 1e+30], default 0.0001)
    double viscosity; ///< dynamic viscosity; used when FLUID_PERM_UNITS = 1 (K = k rho g / mu) (Pa s; flag FLUID_VISCOSITY; [1e-30, 1e+30], default 0.001)
    int perm_units; ///< 0: FLUID_PERM_LOW/HIGH are hydraulic conductivities (m/s); 1: intrinsic permeabilities (m^2) (0/1; flag FLUID_PERM_UNITS; [0, 1], default 0)
    int method; ///< transient method: 0 backward Euler, 1 Crank-Nicolson, 2 explicit (Klosek 1997 §3.9.2, sub-stepped), 3 static every solve (0-3; flag FLUID_METHOD; [0, 3], default 0)
    int mass_consistent; ///< storage matrix: 0 lumped, 1 consistent (implicit methods) (0/1; flag FLUID_MASS; [0, 1], default 0)
    double explicit_safety; ///< fraction of the explicit stability limit used per sub-step (1; flag FLUID_EXPLICIT_SAFETY; [0.001, 1], default 0.9)
    int porosity_method; ///< solid area per element: 0 exact clipping, 1 pixellation (Klosek 1997 §3.6) (0/1; flag FLUID_POROSITY_METHOD; [0, 1], default 0)
    int pixels; ///< pixellation resolution: pixels along the longer side of an element's bounding box (pixels; flag FLUID_PIXELS; [1, 4096], default 16)
    int porosity_map; ///< porosity for permeability: 0 areal (2D), 1 mapped to 3D (1 - 2/sqrt(pi sqrt 3) (1 - n2)^1.5) (0/1; flag FLUID_POROSITY_MAP; [0, 1], default 1)
    int kc_mode; ///< 0: interpolate e^3/(1+e) between LOW (e = 0.01) and HIGH (e = 99); 1: K = FLUID_KC_C1 e^3/(1+e) clamped (0/1; flag FLUID_KC_MODE; [0, 1], default 0)
    double kc_c1; ///< Kozeny-Carman constant C1 of Klosek 1997 eq. 3.8 (FLUID_KC_MODE = 1) (m/s; flag FLUID_KC_C1; [0, 1e+30], default 0.01)
    int drag; ///< add the interphase drag of the porous skeleton (DESIGN §3) to the outline pressure force (0/1; flag FLUID_DRAG; [0, 1], default 1)
    int force_reuse; ///< 1: the fluid force on each body is computed at fluid updates (every FLUID_SOLVE_TIMESTEPS steps) and reused in between; 0: every grain step (0/1; flag FLUID_FORCE_REUSE; [0, 1], default 0)
    int consolidation; ///< 1: grains moving into or out of the pores change the pore pressure: (S + n rho_f g / K_f) dh/dt - div(K grad h) = -div(v_s) (docs/soil.md) (0/1; flag FLUID_CONSOLIDATION; [0, 1], default 0)
    int porosity_every; ///< grain steps between porosity updates (solid areas, permeability, storage, and the pieces of each grain in each element); in between, every fluid solution takes its source and pushes the grains with the last pieces (docs/soil.md §2); 0 = at every fluid solution (steps; flag FLUID_POROSITY_TIMESTEPS; [0, 2e+09], default 0)
    double bulk_modulus; ///< bulk modulus K_f of the pore fluid (storage n rho_f g / K_f with FLUID_CONSOLIDATION); 0 = incompressible (Pa; flag FLUID_BULK_MODULUS; [0, 1e+30], default 2.2e+09)
    int stagger_check; ///< 1: refuse a grain step times FLUID_SOLVE_TIMESTEPS above the staggering limit of the undrained coupling, 2 sqrt(m_min / k) with k = K_f d^2 / (n A_e) relaxed by seepage (docs/stability.md); 0: no check (stability sweeps) (0/1; flag FLUID_STAGGER_CHECK; [0, 1], default 1)
} pl_darcy_def;

/// The defaults of every field (the MIMES defaults of seed 000 Appendix B.2 where it gives one).
pl_darcy_def pl_default_darcy_def(void);
/// The parameter table of pl_darcy_def (rows in field order); *count receives the row count.
const pl_param *pl_darcy_param_table(int *count);
/// Sets every parameter of the world's Darcy model (checked against the table: the first bad
/// field gives PL_ERR_ARG naming it and its range, and nothing changes).
pl_status pl_world_set_darcy(pl_world *w, const pl_darcy_def *def);
/// The world's current Darcy parameters (also before any fluid quad exists).
void pl_world_get_darcy(const pl_world *w, pl_darcy_def *out);

#ifdef __cplusplus
}
#endif
#endif
