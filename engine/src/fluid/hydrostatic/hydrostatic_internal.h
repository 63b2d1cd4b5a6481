/* Kernels of the hydrostatic water model (porelab/hydrostatic.h) on plain structs, so that the
 * unit tests drive them without a world: the water body, the submerged part of a disc (closed
 * form) or of a convex polygon (the project's clipper), the load on a body, and the moving
 * level's root solve. hydrostatic.c wraps them as the model class. */
#ifndef PL_HYDROSTATIC_INTERNAL_H
#define PL_HYDROSTATIC_INTERNAL_H

#include "porelab/core.h"
#include "porelab/hydrostatic.h"
#include "porelab/world.h" /* pl_shape_type */
#include "world/model.h"

/* The water as the kernels see it. */
typedef struct pl_hs_water {
    double x_min, x_max, bottom, level; /* m */
    pl_vec2 up;                         /* unit, -g/|g| (or +y when g = 0) */
    double g;                           /* |g|, m/s^2 */
    double rho, beta;                   /* kg/m^3, N s/m^3 */
} pl_hs_water;

pl_hs_water pl_hs_water_make(const pl_hydrostatic_def *d, pl_vec2 gravity);

/* Submerged part of a body: area (m^2), centroid, and J_c = ∫ |x - c|^2 dA about the body's
   centroid c (m^4). */
typedef struct pl_hs_part {
    double area;
    pl_vec2 centroid;
    double j_c;
} pl_hs_part;

/* Closed form: the part of the disc (c, r) with (x - c) . up <= s (s: height of the surface
   above the centre). Depth of submersion d = s + r in [0, 2r]. */
void pl_hs_disc_segment(pl_vec2 c, double r, pl_vec2 up, double s, pl_hs_part *out);

/* The water body T ∩ {h <= level} as a counter-clockwise polygon (<= 5 vertices) into out[8];
   returns the vertex count (0: no water, or gravity pointing out of the tank). */
int pl_hs_water_polygon(const pl_hs_water *wt, double level, pl_vec2 out[8]);
/* Area of the water body at a level (the tank's area below it), m^2. */
double pl_hs_tank_area(const pl_hs_water *wt, double level);

/* Submerged part of a disc / a convex counter-clockwise polygon (n <= PL_CLIP_MAX_IN) with the
   surface at `level`. Bodies inside the tank's side walls and above its bottom use one cut (the
   closed-form segment, or one half-plane pass); others are intersected with the water body. */
void pl_hs_disc_part(const pl_hs_water *wt, double level, pl_vec2 c, double r, pl_hs_part *out);
void pl_hs_polygon_part(const pl_hs_water *wt, double level, const pl_vec2 *v, int n, pl_vec2 c,
                        pl_hs_part *out);
/* Submerged part of body i of a grain view (segments and bodies without area: area 0). */
void pl_hs_body_part(const pl_hs_water *wt, double level, const pl_grain_view *g, int i, pl_hs_part *out);

/* Buoyancy plus linear drag on a body with centroid c, velocity v and spin omega whose
   submerged part is p (porelab/hydrostatic.h): force and moment about c. */
void pl_hs_load(const pl_hs_water *wt, const pl_hs_part *p, pl_vec2 c, pl_vec2 v, double omega, pl_vec2 *force,
                double *moment);

/* The pressure field for drawing (pl_field_sample): the water body fanned into nt <= 3 triangles
   from its first vertex, with the pressure at the nn <= 5 vertices. The pressure is linear in the
   water body, so linear triangles show it exactly. Returns nn (0: no water). */
int pl_hs_field(const pl_hs_water *wt, double level, pl_vec2 xy[8], int32_t tri[18], double value[8], int *nt);

/* Total solid area inside the water body at a level, over every body of the view with area. */
double pl_hs_solid_area(const pl_hs_water *wt, double level, const pl_grain_view *g);
/* The level with A_T(level) - A_solid(level) = a_water, starting from `level0` (bracketed
   Illinois secant, bisection fallback; |error| <= 1e-12 x the tank's size). *evals (may be
   NULL) receives the number of area evaluations. */
double pl_hs_solve_level(const pl_hs_water *wt, const pl_grain_view *g, double a_water, double level0, int *evals);

/* The model's pressure field for drawing (for a `field` function of pl_model_class once the
   interface has one): fills out with the water body's triangles and pressures, stored in the
   model instance `self` (valid until the next call or step). Returns the node count. */
int pl__hydrostatic_field(void *self, pl_vec2 gravity, pl_field_sample *out);

#endif
