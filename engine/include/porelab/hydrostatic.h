/// Hydrostatic water: the cheapest fluid model (no mesh), for scenes that need only buoyancy
/// (docs/hydrostatic.md).
///
/// The water fills the tank region T = {x_min <= x <= x_max, y >= bottom} up to a free surface
/// perpendicular to gravity. With up = -g/|g| (or +y when g = 0) and the height h(p) = p . up,
/// the water body is W = T ∩ {h(p) <= level}; for the usual gravity (0, -g) the surface is the
/// line y = level. Still water has the pressure
///
///     p(x) = rho_f |g| (level - h(x))   inside W,   0 above the surface or outside T.
///
/// The load on a body is the exact integral of that pressure over its outline, partial
/// submersion included. For a body whose submerged part S = body ∩ W has area A and centroid
/// c_s (Archimedes, exact for any convex outline):
///
///     F_b = rho_f |g| A up,   acting at c_s:   M_b = (c_s - c) x F_b   (c: body centroid)
///
/// Discs use the closed-form circular segment (area, centroid, second moment); polygons are
/// clipped by the surface (and by the side walls and the bottom when they cross them) with the
/// project's clipper. An optional linear drag acts on every submerged area element, dF = -beta
/// v(x) dA with v(x) = v + omega k x (x - c) the element's velocity (still water):
///
///     F_d = -beta A (v + omega k x (c_s - c)),   M_d = -beta (A (c_s - c) x v + omega J_c)
///
/// with J_c = ∫_S |x - c|^2 dA (m^4) the polar second moment of the submerged part about c.
///
/// With moving_level = 1 the water's area A_w is fixed when the model is attached (the tank
/// area below the given level minus the solid area below it then) and the level follows the
/// displaced area: each step it solves
///
///     A_T(level) - A_solid(level) = A_w
///
/// (A_T the tank's area below the level: (level - bottom)(x_max - x_min) for g along -y;
/// A_solid the area of every disc and polygon of the world inside W) by a bracketed secant
/// (Illinois) iteration to 1e-12 relative. So a block lowered into the tank raises the level by
/// its submerged area divided by the free width.
#ifndef PORELAB_HYDROSTATIC_H
#define PORELAB_HYDROSTATIC_H

#include "porelab/core.h"
#include "porelab/params.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pl_world pl_world;

/// The water body. Fill with pl_default_hydrostatic_def() and override what you need.
typedef struct pl_hydrostatic_def {
    double x_min;        ///< left side of the tank region, m; default 0
    double x_max;        ///< right side, m (> x_min); default 1
    double bottom;       ///< bottom of the tank region (y), m; default 0
    double level;        ///< free-surface level, m: height along -g/|g| (the y of the surface
                         ///< for g along -y), >= bottom. Default 0.5
    double density;      ///< water density rho_f, kg/m^3; default 1000
    double drag;         ///< linear drag coefficient beta, N s/m per m^2 of submerged area
                         ///< (N s/m^3); default 0 (no drag)
    int moving_level;    ///< 1: the level rises and falls with the displaced area (the water's
                         ///< area fixed at attachment); 0: fixed level. Default 0
} pl_hydrostatic_def;

/// The parameter table of pl_hydrostatic_def (names as in Lua w:water{...}: x_min, x_max,
/// bottom, level, density, drag, moving_level; no MIMES flags).
#define PL_HYDROSTATIC_PARAM_COUNT 7
extern const pl_param pl_hydrostatic_params[PL_HYDROSTATIC_PARAM_COUNT];
extern const int pl_hydrostatic_param_count;

/// Defaults of the table: tank [0, 1] from y = 0, level 0.5, rho_f 1000, no drag, fixed level.
pl_hydrostatic_def pl_default_hydrostatic_def(void);

/// Attaches hydrostatic water to the world. Every field is checked against the table; also
/// refused: x_max <= x_min, a level below the bottom, gravity pointing out of the tank
/// (g.y > 0 with g != 0: the water body would be unbounded), a second attach. Returns PL_OK or
/// PL_ERR_ARG / PL_ERR_STATE with the message in pl_world_last_error.
pl_status pl_world_attach_hydrostatic(pl_world *w, const pl_hydrostatic_def *def);
/// 1 when the world has hydrostatic water.
int pl_world_has_hydrostatic(const pl_world *w);
/// The current def (level: the current level, which moves with moving_level = 1). PL_ERR_STATE
/// without water.
pl_status pl_world_hydrostatic_def(const pl_world *w, pl_hydrostatic_def *out);
/// Replaces the parameters between steps (same checks as attach). A change of the region or of
/// the level (or turning moving_level on) fixes the water's area anew from the bodies now.
pl_status pl_world_hydrostatic_redefine(pl_world *w, const pl_hydrostatic_def *def);
/// Current free-surface level, m (NaN without water).
double pl_world_hydrostatic_level(const pl_world *w);
/// Water pressure at point p: rho_f |g| (level - h(p)) inside the water body, 0 above the
/// surface or outside the tank (and without water), Pa.
double pl_world_hydrostatic_pressure(const pl_world *w, pl_vec2 p);

#ifdef __cplusplus
}
#endif
#endif
