/// Shape helpers: outlines for PL_SHAPE_POLYGON bodies (rectangles, regular n-gons,
/// superquadrics, random convex polygons inscribed in ellipses), outline validation with
/// messages, exact mass properties, and a small deterministic random number generator.
///
/// Every generator writes counter-clockwise convex vertices in world coordinates into
/// out[0..cap) and returns the vertex count (>= 3), or a negative pl_status on bad input
/// with a message in err (err may be NULL; messages are cut to err_cap bytes). The vertex
/// arrays are meant for pl_body_def.vertices with shape PL_SHAPE_POLYGON.
#ifndef PORELAB_SHAPES_H
#define PORELAB_SHAPES_H

#include "porelab/core.h"
#include "porelab/world.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------ random numbers */

/// Deterministic pseudo-random generator: xoshiro256** (Blackman & Vigna 2018) seeded
/// through splitmix64. Same seed, same sequence, on every platform. 32 bytes of state.
typedef struct pl_rng {
    uint64_t s[4];
} pl_rng;

/// Seeds the generator (any 64-bit value, 0 included).
void pl_rng_seed(pl_rng *rng, uint64_t seed);
/// Next 64 random bits.
uint64_t pl_rng_next(pl_rng *rng);
/// Uniform double in [0, 1) with 53 random bits.
double pl_rng_uniform(pl_rng *rng);
/// Uniform double in [lo, hi).
double pl_rng_range(pl_rng *rng, double lo, double hi);
/// Uniform integer in [lo, hi] (inclusive; lo <= hi), without modulo bias.
int pl_rng_int(pl_rng *rng, int lo, int hi);

/* ---------------------------------------------------------------- validation */

/// Checks a polygon outline for use as a body: 3..PL_SHAPE_MAX_VERTICES vertices, finite
/// coordinates, no repeated vertices, counter-clockwise, strictly convex (no collinear or
/// reflex corner) and a non-degenerate area. Returns PL_OK or PL_ERR_ARG with a message
/// naming the offending vertex and what to change.
#define PL_SHAPE_MAX_VERTICES PL_MAX_POLY_VERTICES
pl_status pl_polygon_check(const pl_vec2 *v, int n, char *err, size_t err_cap);

/* ----------------------------------------------------------- mass properties */

/// Exact mass properties of a polygon from its outline (seed 000 §3.12, triangle fan).
typedef struct pl_mass_props {
    double area;            ///< m^2 (positive for counter-clockwise outlines)
    pl_vec2 centroid;       ///< m
    double polar_moment;    ///< second polar moment of area about the centroid, m^4
    double mass;            ///< density x area x 1 m, kg
    double inertia;         ///< density x polar_moment x 1 m, kg m^2
    double bounding_radius; ///< largest vertex distance from the centroid, m
} pl_mass_props;

/// Fills out for density (kg/m^3, > 0). Returns PL_ERR_ARG for an invalid outline.
pl_status pl_polygon_mass_properties(const pl_vec2 *v, int n, double density,
                                     pl_mass_props *out, char *err, size_t err_cap);

/* ---------------------------------------------------------------- generators */

/// Rectangle of width x height (m) centred at center, rotated by angle (rad). 4 vertices.
int pl_shape_rectangle(pl_vec2 center, double width, double height, double angle,
                       pl_vec2 *out, int cap, char *err, size_t err_cap);

/// Regular polygon with `sides` corners (3..64) on a circle of radius circumradius (m),
/// the first corner at angle `angle` (rad) from the +x axis.
int pl_shape_regular_polygon(pl_vec2 center, double circumradius, int sides, double angle,
                             pl_vec2 *out, int cap, char *err, size_t err_cap);

/// Superquadric |x/a|^n1 + |y/b|^n2 = 1 (seed 000 §2.1.1 footnote; MIMES add_superquad,
/// Appendix C.2), tessellated into `sides` straight edges. Corners are placed at
/// x = a sgn(cos t)|cos t|^(2/n1), y = b sgn(sin t)|sin t|^(2/n2), t = 2 pi k / sides, so
/// n1 = n2 = 2 gives an ellipse (a = b: a circle), n = 1 a rhombus, n -> infinity the
/// 2a x 2b rectangle. Exponents must be >= 1 (convex outline). Corners that coincide or are
/// collinear to round-off (very large exponents) are merged, so the result may have fewer
/// than `sides` corners; the return value says how many.
typedef struct pl_superquad_def {
    pl_vec2 center;  ///< m
    double a, b;     ///< half axes along local x and y, m; > 0
    double n1, n2;   ///< exponents, >= 1; default 2 (ellipse)
    int sides;       ///< 4..64; default 16 (as the MIMES example of seed 000 Appendix C.2)
    double angle;    ///< rotation of the local axes, rad; default 0
} pl_superquad_def;
pl_superquad_def pl_default_superquad_def(void);
int pl_shape_superquad(const pl_superquad_def *def, pl_vec2 *out, int cap,
                       char *err, size_t err_cap);

/// Random convex polygon inscribed in an ellipse (seed 004 §2.1: polygons "with varying
/// number of corners which are inscribed into ellipses with a statistical variation of the
/// length of the half axes"). The corner count is uniform in [min_corners, max_corners];
/// the major half axis a is uniform in [a_min, a_max]; the minor half axis is b = a x r with
/// r uniform in [aspect_min, aspect_max]; the corners lie on the ellipse at parametric
/// angles 2 pi (k + jitter u_k) / corners with u_k uniform in [-1/2, 1/2) (jitter < 1 keeps
/// them ordered, hence convex); the polygon is turned by a uniform angle in [0, 2 pi) when
/// random_orientation is set. All draws come from rng, so the same seed gives the same
/// polygons.
typedef struct pl_random_polygon_def {
    int min_corners, max_corners; ///< 3..64; default 5 and 9
    double a_min, a_max;          ///< major half axis range, m; default 0.005 and 0.0075
    double aspect_min, aspect_max;///< b / a range, (0, 1]; default 0.6 and 1.0
    double jitter;                ///< 0..0.9 of the corner spacing; default 0.5
    int random_orientation;       ///< 1 (default): random rotation; 0: major axis along x
} pl_random_polygon_def;
pl_random_polygon_def pl_default_random_polygon_def(void);
int pl_shape_random_polygon(const pl_random_polygon_def *def, pl_rng *rng, pl_vec2 center,
                            pl_vec2 *out, int cap, char *err, size_t err_cap);

/* ------------------------------------------------------------ overlap queries */

/// Area (m^2) and centroid of the intersection of two convex counter-clockwise polygons.
/// Returns the area (0 when disjoint); centroid may be NULL.
double pl_overlap_polygons(const pl_vec2 *p, int np, const pl_vec2 *q, int nq, pl_vec2 *centroid);
/// Area (m^2) and centroid of the intersection of a disc (centre c, radius r) with a convex
/// counter-clockwise polygon, exact (straight pieces + circular sectors).
double pl_overlap_disc_polygon(pl_vec2 c, double r, const pl_vec2 *p, int np, pl_vec2 *centroid);

#ifdef __cplusplus
}
#endif
#endif
