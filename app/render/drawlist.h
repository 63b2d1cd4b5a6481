/// Draw list: backend-independent drawing primitives (circles, polygons, polylines, Gouraud
/// triangles, arrows, text) in world or pixel coordinates, plus the camera that maps world
/// coordinates (m, y up) to pixels (y down). Builders append primitives in painter's order;
/// backends (cairo now, OpenGL later) only rasterize a list. Nothing here depends on cairo.
#ifndef PORELAB_DRAWLIST_H
#define PORELAB_DRAWLIST_H

#include <stddef.h>
#include <stdint.h>
#include "render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ camera */

/// Maps world coordinates (m, y up) to pixels (origin top-left, y down), aspect preserved.
/// x_px = (x - center.x) * scale + px_center.x;  y_px = px_center.y - (y - center.y) * scale.
typedef struct pl_camera {
    int width, height;   ///< image size, pixels
    double scale;        ///< pixels per metre
    pl_vec2 center;      ///< world point shown at px_center
    pl_vec2 px_center;   ///< pixel position of center (usually the middle of the plot area)
} pl_camera;

/// A rectangle in pixels (x0 < x1, y0 < y1) where the scene is drawn.
typedef struct pl_px_rect {
    double x0, y0, x1, y1;
} pl_px_rect;

/// Fits the world rectangle [lo, hi] into the pixel area, adding margin (fraction of the
/// larger side of the world rectangle, e.g. 0.05) on every side, aspect preserved, centred.
/// A degenerate rectangle (zero width and height) gets a 1 m view around it.
pl_camera pl_camera_fit(pl_vec2 lo, pl_vec2 hi, int width, int height, pl_px_rect area,
                        double margin);
pl_vec2 pl_camera_to_px(const pl_camera *cam, pl_vec2 world);
pl_vec2 pl_camera_to_world(const pl_camera *cam, pl_vec2 px);

/* --------------------------------------------------------------- primitives */

typedef enum pl_prim_kind {
    PL_PRIM_CIRCLE = 0,   ///< points[0] centre; radius; fill and/or stroke
    PL_PRIM_POLYGON = 1,  ///< closed polygon; fill and/or stroke
    PL_PRIM_POLYLINE = 2, ///< open line through the points; stroke only
    PL_PRIM_TRIANGLES = 3,///< Gouraud triangles: 3 points and 3 colours per triangle
    PL_PRIM_ARROW = 4,    ///< points[0] tail, points[1] tip; shaft width, head length in px
    PL_PRIM_TEXT = 5,     ///< points[0] anchor point; size in px; angle (rad, counter-clockwise)
    PL_PRIM_SEGMENTS = 6  ///< independent segments (2 points each), one style; stroke only
} pl_prim_kind;

typedef enum pl_space {
    PL_SPACE_WORLD = 0,   ///< coordinates and radii in metres, transformed by the camera
    PL_SPACE_PIXEL = 1    ///< coordinates and radii in pixels
} pl_space;

/// Text anchor: which point of the text's box sits on the anchor point.
typedef enum pl_text_anchor {
    PL_ANCHOR_LEFT = 0, PL_ANCHOR_CENTER = 1, PL_ANCHOR_RIGHT = 2,          ///< horizontal
    PL_ANCHOR_BASELINE = 0, PL_ANCHOR_MIDDLE = 4, PL_ANCHOR_TOP = 8, PL_ANCHOR_BOTTOM = 12 ///< vertical
} pl_text_anchor;
#define PL_ANCHOR_H(a) ((a) & 3)
#define PL_ANCHOR_V(a) ((a) & 12)

/// One primitive. Line widths, text sizes and arrow heads are always in pixels so that
/// lines stay crisp at any zoom; positions and radii follow `space`.
typedef struct pl_prim {
    uint8_t kind;        ///< pl_prim_kind
    uint8_t space;       ///< pl_space
    uint8_t anchor;      ///< text: pl_text_anchor bits
    uint8_t has_fill, has_stroke, has_halo; ///< halo: text drawn over a background outline
    float width;         ///< stroke width (px); arrow shaft width
    float size;          ///< text size (px); arrow head length (px)
    float angle;         ///< text rotation, rad (counter-clockwise on screen)
    double radius;       ///< circle radius (world m or px)
    pl_rgba fill, stroke;///< text: fill = text colour, stroke = halo colour
    int32_t first, count;///< range in the list's point array
    int32_t color_first; ///< triangles: first colour in the list's colour array (count colours)
    int32_t text;        ///< text: offset of a NUL-terminated string in the text buffer
    uint16_t layer;      ///< PL_LAYER_* bit index this primitive belongs to (for backends/debug)
} pl_prim;

/// A growable list of primitives. Zero-initialise, or use pl_draw_list_init; reuse across
/// frames with pl_draw_list_clear (keeps the memory, so no allocation in steady state).
typedef struct pl_draw_list {
    pl_prim *prims;   int prim_count, prim_cap;
    pl_vec2 *points;  int point_count, point_cap;
    pl_rgba *colors;  int color_count, color_cap;
    char *text;       int text_size, text_cap;
    pl_camera camera; ///< camera used for PL_SPACE_WORLD primitives
    pl_px_rect clip;  ///< world-space primitives are clipped to this pixel rectangle when
                      ///< has_clip (the plot area, so a scene never runs over the labels)
    int has_clip;
    pl_rgba background;
    int failed;       ///< set when an allocation failed; the list is then incomplete
    uint16_t current_layer; ///< tag given to appended primitives
    /* the frame's automatic ranges (what the frame would have used without fixed ranges;
     * pl_render_ranges keeps them fixed across a run) */
    int auto_field_set, auto_color_set; ///< 1 when the frame had that quantity
    double auto_field_lo, auto_field_hi, auto_color_lo, auto_color_hi; ///< SI units
    double auto_vscale;     ///< automatic velocity arrow scale, m per (m/s); 0 = no arrows
} pl_draw_list;

void pl_draw_list_init(pl_draw_list *dl);
void pl_draw_list_clear(pl_draw_list *dl);
void pl_draw_list_free(pl_draw_list *dl);
/// Appends every primitive of src (with its points, colours and text) to dst.
void pl_draw_list_append(pl_draw_list *dst, const pl_draw_list *src);

/// Line/fill style for the builders below. A NULL style pointer never occurs in valid use.
typedef struct pl_style {
    pl_rgba fill;   int has_fill;
    pl_rgba stroke; int has_stroke;
    float width;    ///< stroke width, px
} pl_style;

pl_style pl_style_fill(pl_rgba fill);
pl_style pl_style_stroke(pl_rgba stroke, float width);
pl_style pl_style_fill_stroke(pl_rgba fill, pl_rgba stroke, float width);

void pl_dl_circle(pl_draw_list *dl, pl_space sp, pl_vec2 c, double r, const pl_style *st);
void pl_dl_polygon(pl_draw_list *dl, pl_space sp, const pl_vec2 *p, int n, const pl_style *st);
void pl_dl_polyline(pl_draw_list *dl, pl_space sp, const pl_vec2 *p, int n, pl_rgba color,
                    float width);
void pl_dl_line(pl_draw_list *dl, pl_space sp, pl_vec2 a, pl_vec2 b, pl_rgba color, float width);
/// Segments per batch primitive; longer batches are split automatically.
#define PL_SEGMENT_BATCH 64
/// Starts a batch of independent segments sharing colour and width; add with pl_dl_segment_add.
void pl_dl_segments_begin(pl_draw_list *dl, pl_space sp, pl_rgba color, float width);
void pl_dl_segment_add(pl_draw_list *dl, pl_vec2 a, pl_vec2 b);
/// Starts a batch of Gouraud triangles; add triangles with pl_dl_triangle_add.
void pl_dl_triangles_begin(pl_draw_list *dl, pl_space sp);
void pl_dl_triangle_add(pl_draw_list *dl, const pl_vec2 p[3], const pl_rgba c[3]);
void pl_dl_arrow(pl_draw_list *dl, pl_space sp, pl_vec2 tail, pl_vec2 tip, pl_rgba color,
                 float shaft_width, float head_length);
/// Text in DejaVu Sans. size in px; anchor from pl_text_anchor; when halo != NULL the text
/// sits on a box of the halo colour (labels on lines and fields).
void pl_dl_text(pl_draw_list *dl, pl_space sp, pl_vec2 at, const char *s, float size,
                int anchor, float angle, pl_rgba color, const pl_rgba *halo);

/// Position of a primitive point in pixels (applies the camera to world-space points).
static inline pl_vec2 pl_dl_px(const pl_draw_list *dl, const pl_prim *p, pl_vec2 q) {
    if (p->space != PL_SPACE_WORLD) return q;
    const pl_camera *cam = &dl->camera; /* pl_camera_to_px, inline */
    pl_vec2 r = {(q.x - cam->center.x) * cam->scale + cam->px_center.x,
                 cam->px_center.y - (q.y - cam->center.y) * cam->scale};
    return r;
}
/// Radius of a circle primitive in pixels.
static inline double pl_dl_px_radius(const pl_draw_list *dl, const pl_prim *p) {
    return p->space == PL_SPACE_WORLD ? p->radius * dl->camera.scale : p->radius;
}

/* ----------------------------------------------------------------- sorting */

/// Sorts keys ascending, stably (LSD radix, 8 bits a pass; passes where every key has the same
/// byte are skipped), carrying vals along when not NULL. Returns -1 when out of memory
/// (arrays unchanged). Used by the builders for their large sorts (forces, mesh edges).
int pl_radix_sort_u64(uint64_t *keys, int32_t *vals, int n);

/* ----------------------------------------------------------------- colours */

pl_rgba pl_rgb(double r, double g, double b);           ///< opaque colour, components 0..1
pl_rgba pl_rgb_hex(uint32_t rrggbb);                    ///< opaque colour from 0xRRGGBB
pl_rgba pl_rgba_mix(pl_rgba a, pl_rgba b, double t);    ///< (1-t) a + t b, t in [0, 1]
pl_rgba pl_rgba_scale(pl_rgba a, double f);             ///< darker (f < 1), alpha kept

#ifdef __cplusplus
}
#endif
#endif
