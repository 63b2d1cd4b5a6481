/// Field layers over a triangulated domain, generic over (node coordinates, triangle node
/// indices, node values): smooth filled field (Gouraud triangles), mesh wireframe, labelled
/// isolines, and vector arrows. The fluid layers feed these from the fluid module's queries.
/// All coordinates are world coordinates (m); dl->camera must already be set.
#ifndef PORELAB_DRAW_FIELD_H
#define PORELAB_DRAW_FIELD_H

#include "colormap.h"
#include "drawlist.h"
#include "isolines.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Filled field: each triangle Gouraud-shaded from its node colours. Triangles whose value
/// range spans more than 1/16 of [vmin, vmax] are subdivided (up to 3 levels) so the shading
/// follows the colour map rather than a straight RGB blend.
void pl_draw_field_fill(pl_draw_list *dl, const pl_vec2 *nodes, const int *tris, int tri_count,
                        const double *values, pl_colormap map, double vmin, double vmax);

/// Mesh wireframe: every edge once (shared edges deduplicated), as one batch of segments.
/// Returns 0, or -1 when out of memory.
int pl_draw_mesh_wire(pl_draw_list *dl, const pl_vec2 *nodes, const int *tris, int tri_count,
                      pl_rgba color, float width);

/// Isoline style.
typedef struct pl_isoline_style {
    pl_rgba color;        ///< default dark grey
    float width;          ///< px; default 1.2
    float label_size;     ///< px; 0 = no labels; default 11
    const char *label_format; ///< printf format for the level value; default "%g"
    double label_spacing; ///< px of line between labels; default 280
    pl_rgba halo;         ///< label background outline; default white
    struct pl_obstacles *avoid; ///< NULL, or obstacles (label_place.h): lines are not drawn
                          ///< inside its outlines and labels go only where they touch no
                          ///< obstacle, placed label or other line (placed labels are added)
} pl_isoline_style;

pl_isoline_style pl_default_isoline_style(void);

/// Draws the polylines of iso with labels placed along them (rotated with the line, upright,
/// centred on the arc length; one per label_spacing px; lines shorter than 4 label heights
/// get none).
void pl_draw_isolines(pl_draw_list *dl, const pl_isolines *iso, const pl_isoline_style *st);

/// Arrows for vectors vec[i] (e.g. Darcy velocity, m/s) at points at[i]: length in world
/// metres = |vec| * scale (m per unit of the vector); vectors shorter than min_px pixels are
/// skipped. Returns the number of arrows drawn.
int pl_draw_arrows(pl_draw_list *dl, const pl_vec2 *at, const pl_vec2 *vec, int n,
                   double scale, pl_rgba color, float width, double min_px);

#ifdef __cplusplus
}
#endif
#endif
