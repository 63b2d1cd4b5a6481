/* Convex polygon basics: area, centroid and second moment from the outline (seed 000 §3.12). */
#ifndef PL_GEOM_POLYGON_H
#define PL_GEOM_POLYGON_H
#include "porelab/core.h"

/* Signed area (positive for counter-clockwise vertex order), m^2. */
double pl_poly_signed_area(const pl_vec2 *v, int n);
/* Centroid of the polygon's area. */
pl_vec2 pl_poly_centroid(const pl_vec2 *v, int n);
/* Polar second moment of area about the centroid, m^4 (multiply by density for inertia). */
double pl_poly_polar_moment(const pl_vec2 *v, int n);
/* 1 when the polygon is strictly convex and counter-clockwise, else 0. */
int pl_poly_is_convex_ccw(const pl_vec2 *v, int n);
#endif
