/* Overlap kernels for the area-based contact law (seed 004 §3): the intersection of two
 * convex polygons, of a convex polygon with a disc, and of a convex polygon with the region
 * beyond a wall segment, each with area, centroid and the points where the outlines cross. */
#ifndef PL_GEOM_CLIP_H
#define PL_GEOM_CLIP_H
#include "porelab/core.h"

/* Largest outline handled (matches PL_MAX_POLY_VERTICES) and the largest overlap polygon:
 * each clipping line adds at most one vertex, so n + m bounds the convex-convex result. */
#define PL_CLIP_MAX_IN 64
#define PL_CLIP_MAX_OUT (2 * PL_CLIP_MAX_IN + 4)
#define PL_CLIP_MAX_CROSS 16

/* Result of an overlap computation. */
typedef struct pl_overlap {
    double area;         /* m^2; 0 when the outlines do not overlap */
    pl_vec2 centroid;    /* centroid S of the overlap region (valid when area > 0) */
    int cross_n;         /* number of outline intersection points found */
    pl_vec2 cross[PL_CLIP_MAX_CROSS]; /* the first PL_CLIP_MAX_CROSS of them */
    pl_vec2 p1, p2;      /* the two intersection points farthest apart (cross_n >= 2) */
    double chord;        /* |p2 - p1|, m (0 when cross_n < 2) */
    pl_vec2 chord_vec;   /* sum of the overlap outline's edges that belong to the FIRST
                          * outline (the part of it inside the other body). With two
                          * crossings this is p2 - p1 in outline order; in general it is the
                          * area gradient rotated by 90 degrees: moving the second body by dx
                          * changes the area by -(chord_vec.y, -chord_vec.x) . dx. The contact
                          * normal from the first to the second body is
                          * (chord_vec.y, -chord_vec.x) / |chord_vec|. */
    int n;               /* overlap polygon vertex count (polygon kernels; 0 for the disc) */
    pl_vec2 v[PL_CLIP_MAX_OUT]; /* overlap polygon, counter-clockwise */
} pl_overlap;

/* Intersection of two convex counter-clockwise polygons p (np) and q (nq) by
 * Sutherland-Hodgman clipping of p against the edges of q. Every edge of the result is
 * labelled with the outline it comes from; a vertex between an edge of p and an edge of q is
 * a point where the outlines cross. Returns the area. */
double pl_clip_convex(const pl_vec2 *p, int np, const pl_vec2 *q, int nq, pl_overlap *out);

/* Exact intersection of the disc (c, r) with the convex counter-clockwise polygon p (np):
 * each edge contributes a triangle with the centre where it runs inside the circle and a
 * circular sector where it runs outside. The crossings are where the edges cut the circle.
 * out->n is 0 (the region is not a polygon). Returns the area. */
double pl_clip_disc(pl_vec2 c, double r, const pl_vec2 *p, int np, pl_overlap *out);

/* Part of the convex counter-clockwise polygon p lying beyond the wall segment a-b, seen
 * from `side` (a point on the polygon's side of the wall, normally its centroid): the
 * polygon clipped to the half-plane behind the segment's line and to the strip between the
 * perpendiculars through a and b. The crossings are the ends of the overlap's edge on the
 * wall line. *wall_normal receives the unit normal of the wall pointing to `side`.
 * Returns the area. */
double pl_clip_segment(const pl_vec2 *p, int np, pl_vec2 a, pl_vec2 b, pl_vec2 side,
                       pl_overlap *out, pl_vec2 *wall_normal);

/* Part of the convex polygon p on the side {x : (x - o) . nrm <= 0} of a line (one
 * Sutherland-Hodgman pass). out may hold up to np + 1 vertices. Returns the vertex count. */
int pl_clip_halfplane(const pl_vec2 *p, int np, pl_vec2 o, pl_vec2 nrm, pl_vec2 *out);

/* Area and centroid of a polygon given by its vertices (shoelace with the first vertex as
 * origin). Returns the signed area. */
double pl_clip_area_centroid(const pl_vec2 *v, int n, pl_vec2 *centroid);
#endif
