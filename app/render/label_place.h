/// Label placement: a set of pixel-space obstacles (convex outlines of walls and large
/// bodies, circles, boxes of labels already placed, points of lines to keep clear) and a
/// test whether a rotated label box touches any of them. Used by the isoline labels so that
/// they avoid bodies, walls, other labels and other isolines (a simple collision pass:
/// candidates along the line are tried in turn, a label that fits nowhere is left out).
#ifndef PORELAB_LABEL_PLACE_H
#define PORELAB_LABEL_PLACE_H

#include "drawlist.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pl_label_box {
    pl_vec2 c;          ///< centre, px
    double hw, hh;      ///< half width, half height, px
    double angle;       ///< rad, counter-clockwise on screen
} pl_label_box;

typedef struct pl_obstacles {
    pl_vec2 *verts; int vert_count, vert_cap;  ///< convex outlines, px
    int *first; int poly_count, poly_cap;      ///< outline k: verts[first[k] .. first[k+1])
    pl_vec2 *circ; double *circ_r; int circ_count, circ_cap; ///< circles, px
    pl_label_box *boxes; int box_count, box_cap;              ///< placed labels
    pl_vec2 *pts; int *pt_tag; int pt_count, pt_cap;          ///< points to keep clear
    pl_vec2 *grain; double *grain_r; int grain_count, grain_cap; ///< grains (circles, px):
                                         ///< counted by pl_obstacles_grains, not by _hit
    int failed;
} pl_obstacles;

void pl_obstacles_init(pl_obstacles *o);
void pl_obstacles_free(pl_obstacles *o);
void pl_obstacles_clear(pl_obstacles *o);
void pl_obstacles_add_polygon(pl_obstacles *o, const pl_vec2 *px, int n);
void pl_obstacles_add_circle(pl_obstacles *o, pl_vec2 c, double r);
void pl_obstacles_add_box(pl_obstacles *o, pl_label_box b);
/// A point (px) of a line with tag (a label ignores the points of its own line's tag).
void pl_obstacles_add_point(pl_obstacles *o, pl_vec2 p, int tag);
/// A grain (a disc of the size of the packing's grains), px: labels keep clear of grains
/// where they can (pl_obstacles_grains), but lines are drawn over them.
void pl_obstacles_add_grain(pl_obstacles *o, pl_vec2 c, double r);
/// How many grains the box (grown by pad px) touches (exact rectangle-circle test).
int pl_obstacles_grains(const pl_obstacles *o, pl_label_box b, double pad);
/// 1 when the point lies inside an outline or a circle (not boxes or points).
int pl_obstacles_contain(const pl_obstacles *o, pl_vec2 p);
/// 1 when the box (grown by pad px) touches an obstacle, a placed box or a point of another
/// tag than own_tag (-1: every point counts).
int pl_obstacles_hit(const pl_obstacles *o, pl_label_box b, double pad, int own_tag);

#ifdef __cplusplus
}
#endif
#endif
