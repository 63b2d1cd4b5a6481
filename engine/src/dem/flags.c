/* Flags with the MIMES names (seed 000 Appendix B.2 and the Appendix C scripts).
 * Each flag has a unit, a valid range and a default; flags of features that are not built
 * yet are recognised and refused (unless set to their default "off" value). */
#include "dem/world_internal.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct flag_row {
    pl_flag_info info;
    double def;
} flag_row;

/* The order is the index into w->flag_values. */
static const flag_row FLAGS[] = {
    /* run control */
    {{"TIMESTEPS", "steps", "number of time steps a declarative run takes (when the command line gives none)", 0, 1e12, 1}, 0},
    {{"PRINT_INT", "steps", "steps between output frames (when the command line gives neither --fps nor --every)", 1, 1e12, 1}, 0},
    {{"MAX_DT_CR", "s", "cap on the time step (the automatic step is min(safety x critical, MAX_DT_CR)); 0 = no cap", 0, 1e6, 1}, 0},
    {{"DT", "s", "fixed time step; 0 = automatic (DT_SAFETY x critical step)", 0, 1e6, 1}, 0},
    {{"DT_SAFETY", "1", "fraction of the critical time step used by the automatic step", 1e-6, 1, 1}, 0.1},
    /* body forces and damping */
    {{"GRAVITY_X", "m/s^2", "gravity, x component", -1e6, 1e6, 1}, 0},
    {{"GRAVITY_Y", "m/s^2", "gravity, y component", -1e6, 1e6, 1}, -9.81},
    {{"RAYLEIGH_FACTOR", "1/s", "mass-proportional damping alpha of the Rege scheme (seed 000 eq. 2.5)", 0, 1e9, 1}, 0},
    {{"GLOBAL_DAMPING", "N s/m", "translational global damping C (seed 003 eq. 2.21)", 0, 1e30, 1}, 0},
    {{"GLOBAL_DAMPING_ROT", "N m s", "rotational global damping C* (seed 003 eq. 2.22)", 0, 1e30, 1}, 0},
    {{"LOCAL_DAMPING", "1", "non-viscous damping ratio proportional to the resultant force (seed 002 eqs. 24-29)", 0, 1, 1}, 0},
    {{"ENERGY_TRACKING", "0/1", "1: exact tallies of the energy dissipated by dashpots and friction; 0: off, for speed", 0, 1, 1}, 1},
    /* fluid (seed 000 Appendix B.2; rows below FLUID_PRESSURES_FLAG are porelab additions).
       Owned by the fluid module; see docs/fluid.md. */
    {{"FLUIDS_ON", "0/1", "turns the pore-fluid model on (1) or off (0: no fluid work at all)", 0, 1, 1}, 0},
    {{"FIRST_STEP_STATIC", "0/1", "start the transient fluid solution from the static solution (seed 000 §3.9.3)", 0, 1, 1}, 0},
    {{"FLUID_PERM", "0/1/2", "0: FLUID_PERM_HIGH everywhere; 1: per element from the local void ratio (Kozeny-Carman); 2: per-element values set by the scene", 0, 2, 1}, 0},
    {{"FLUID_PERM_LOW", "m/s", "lowest element conductivity (void ratio 0.01; clamp)", 0, 1e30, 1}, 0.001},
    {{"FLUID_PERM_HIGH", "m/s", "highest element conductivity (void ratio 99; clamp); the uniform value when FLUID_PERM = 0", 0, 1e30, 1}, 5.0},
    {{"FLUID_SOLVE_TIMESTEPS", "steps", "grain steps between fluid solutions", 1, 1e12, 1}, 1},
    {{"FLUID_DENSITY", "kg/m^3", "density of the pore fluid", 1e-30, 1e30, 1}, 1000},
    {{"FLUID_GEOMETRY_FLAG", "0/1", "write the fluid mesh geometry to FLUID_GEOMETRY_FILENAME (MATLAB text)", 0, 1, 1}, 0},
    {{"FLUID_PRESSURES_FLAG", "0/1", "append the nodal pressure heads to FLUID_PRESSURES_FILENAME at every fluid solution", 0, 1, 1}, 0},
    {{"FLUID_STORAGE", "1/m", "specific storage S of S dh/dt = div(K grad h) (seed 000 eq. 3.17: rho c); 0 = quasi-static", 0, 1e30, 1}, 1e-4},
    {{"FLUID_VISCOSITY", "Pa s", "dynamic viscosity; used when FLUID_PERM_UNITS = 1 (K = k rho g / mu)", 1e-30, 1e30, 1}, 1e-3},
    {{"FLUID_PERM_UNITS", "0/1", "0: FLUID_PERM_LOW/HIGH are hydraulic conductivities (m/s); 1: intrinsic permeabilities (m^2)", 0, 1, 1}, 0},
    {{"FLUID_METHOD", "0-3", "transient method: 0 backward Euler, 1 Crank-Nicolson, 2 explicit (seed 000 §3.9.2, sub-stepped), 3 static every solve", 0, 3, 1}, 0},
    {{"FLUID_MASS", "0/1", "storage matrix: 0 lumped, 1 consistent (implicit methods)", 0, 1, 1}, 0},
    {{"FLUID_EXPLICIT_SAFETY", "1", "fraction of the explicit stability limit used per sub-step", 1e-3, 1, 1}, 0.9},
    {{"FLUID_POROSITY_METHOD", "0/1", "solid area per element: 0 exact clipping, 1 pixellation (seed 000 §3.6)", 0, 1, 1}, 0},
    {{"FLUID_PIXELS", "pixels", "pixellation resolution: pixels along the longer side of an element's bounding box", 1, 4096, 1}, 16},
    {{"FLUID_POROSITY_MAP", "0/1", "porosity for permeability: 0 areal (2D), 1 mapped to 3D (1 - 2/sqrt(pi sqrt 3) (1 - n2)^1.5)", 0, 1, 1}, 1},
    {{"FLUID_KC_MODE", "0/1", "0: interpolate e^3/(1+e) between LOW (e = 0.01) and HIGH (e = 99); 1: K = FLUID_KC_C1 e^3/(1+e) clamped", 0, 1, 1}, 0},
    {{"FLUID_KC_C1", "m/s", "Kozeny-Carman constant C1 of seed 000 eq. 3.8 (FLUID_KC_MODE = 1)", 0, 1e30, 1}, 1e-2},
    {{"FLUID_DRAG", "0/1", "add the interphase drag of the porous skeleton (DESIGN §3) to the outline pressure force", 0, 1, 1}, 1},
    /* pore pressure from skeleton volume change (docs/soil.md) */
    {{"FLUID_FORCE_REUSE", "0/1", "1: the fluid force on each body is computed at fluid updates (every FLUID_SOLVE_TIMESTEPS steps) and reused in between; 0: every grain step", 0, 1, 1}, 0},
    {{"FLUID_CONSOLIDATION", "0/1", "1: grains moving into or out of the pores change the pore pressure: (S + n rho_f g / K_f) dh/dt - div(K grad h) = -div(v_s) (docs/soil.md)", 0, 1, 1}, 0},
    {{"FLUID_POROSITY_TIMESTEPS", "steps", "grain steps between porosity updates (solid areas, permeability, storage, and the pieces of each grain in each element); in between, every fluid solution takes its source and pushes the grains with the last pieces (docs/soil.md §2); 0 = at every fluid solution", 0, 1e12, 1}, 0},
    {{"FLUID_BULK_MODULUS", "Pa", "bulk modulus K_f of the pore fluid (storage n rho_f g / K_f with FLUID_CONSOLIDATION); 0 = incompressible", 0, 1e30, 1}, 2.2e9},
    /* MIMES output flags that porelab replaces with VTK/PNG output */
    {{"EXODUSFLAG", "0/1", "EXODUS output of MIMES: not built (porelab writes VTK .vtu/.pvd and PNG instead)", 0, 1, 0}, 0},
    {{"EXODUSOUTPUTSTEP", "steps", "EXODUS output interval of MIMES: not built (use PRINT_INT)", 0, 1e12, 0}, 0},
};
#define NFLAGS ((int)(sizeof FLAGS / sizeof FLAGS[0]))

/* Features built at run time by modules that register themselves (the fluid module marks
   its flags built). */
static int g_built_override[NFLAGS];

int pl_flag_count(void) { return NFLAGS; }

const pl_flag_info *pl_flag_at(int i) {
    static pl_flag_info copy[NFLAGS];
    if (i < 0 || i >= NFLAGS) return NULL;
    copy[i] = FLAGS[i].info;
    copy[i].built = FLAGS[i].info.built || g_built_override[i];
    return &copy[i];
}

static int find_flag(const char *name) {
    for (int i = 0; i < NFLAGS; i++)
        if (strcmp(FLAGS[i].info.name, name) == 0) return i;
    return -1;
}

void pl__flags_mark_built(const char *name) {
    const int i = find_flag(name);
    if (i >= 0) g_built_override[i] = 1;
}

void pl__flags_init(pl_world *w) {
    w->flag_values = malloc(NFLAGS * sizeof *w->flag_values);
    if (!w->flag_values) return;
    for (int i = 0; i < NFLAGS; i++) w->flag_values[i] = FLAGS[i].def;
    /* flags mirrored by the world definition */
    w->flag_values[find_flag("GRAVITY_X")] = w->def.gravity.x;
    w->flag_values[find_flag("GRAVITY_Y")] = w->def.gravity.y;
    w->flag_values[find_flag("MAX_DT_CR")] = w->def.max_dt;
    w->flag_values[find_flag("DT")] = w->def.dt;
    w->flag_values[find_flag("DT_SAFETY")] = w->def.dt_safety;
    w->flag_values[find_flag("RAYLEIGH_FACTOR")] = w->def.rayleigh_alpha;
    w->flag_values[find_flag("GLOBAL_DAMPING")] = w->def.global_c;
    w->flag_values[find_flag("GLOBAL_DAMPING_ROT")] = w->def.global_c_rot;
    w->flag_values[find_flag("LOCAL_DAMPING")] = w->def.local_damping;
    w->flag_values[find_flag("ENERGY_TRACKING")] = w->def.track_energy;
}

static void list_flags(char *buf, size_t len) {
    size_t off = 0;
    for (int i = 0; i < NFLAGS && off < len; i++)
        off += (size_t)snprintf(buf + off, len - off, "%s%s", i ? ", " : "", FLAGS[i].info.name);
}

pl_status pl_world_set_flag(pl_world *w, const char *name, double v) {
    const int i = name ? find_flag(name) : -1;
    if (i < 0) {
        char list[1024];
        list_flags(list, sizeof list);
        return pl__error(w, PL_ERR_UNKNOWN, "unknown flag '%s'; valid flags: %s", name ? name : "(null)", list);
    }
    const pl_flag_info *f = pl_flag_at(i);
    if (!isfinite(v) || v < f->min || v > f->max)
        return pl__error(w, PL_ERR_ARG, "flag %s must be in [%g, %g] %s (got %g)", f->name, f->min, f->max, f->unit, v);
    if (!f->built && v != FLAGS[i].def)
        return pl__error(w, PL_ERR_NOT_BUILT,
                         "flag %s is recognised but its feature is not built in this version of porelab (%s); "
                         "remove the line or leave it at %g",
                         f->name, f->description, FLAGS[i].def);
    w->flag_values[i] = v;
    if (!strcmp(name, "GRAVITY_X")) w->def.gravity.x = v;
    else if (!strcmp(name, "GRAVITY_Y")) w->def.gravity.y = v;
    else if (!strcmp(name, "MAX_DT_CR")) w->def.max_dt = v;
    else if (!strcmp(name, "DT")) w->def.dt = v;
    else if (!strcmp(name, "DT_SAFETY")) w->def.dt_safety = v;
    else if (!strcmp(name, "RAYLEIGH_FACTOR")) w->def.rayleigh_alpha = v;
    else if (!strcmp(name, "GLOBAL_DAMPING")) w->def.global_c = v;
    else if (!strcmp(name, "GLOBAL_DAMPING_ROT")) w->def.global_c_rot = v;
    else if (!strcmp(name, "LOCAL_DAMPING")) w->def.local_damping = v;
    else if (!strcmp(name, "ENERGY_TRACKING")) w->def.track_energy = v != 0;
    w->dt = 0; /* recompute the step with the new settings */
    w->energy_initialised = 0;
    return PL_OK;
}

pl_status pl_world_get_flag(const pl_world *w, const char *name, double *v) {
    const int i = name ? find_flag(name) : -1;
    if (i < 0) {
        char list[1024];
        list_flags(list, sizeof list);
        return pl__error((pl_world *)w, PL_ERR_UNKNOWN, "unknown flag '%s'; valid flags: %s", name ? name : "(null)",
                         list);
    }
    *v = w->flag_values[i];
    return PL_OK;
}
