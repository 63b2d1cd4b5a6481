/* cairo backend: draw list -> cairo context. */
#define _POSIX_C_SOURCE 200809L
#include "backend_cairo.h"
#include "raster_gouraud.h"
#include "raster_aa.h"

#include <cairo-ft.h>
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* ------------------------------------------------------------------- font */

static pthread_once_t font_once = PTHREAD_ONCE_INIT;
static cairo_font_face_t *font_face;
static char font_error[256];

static void load_font(void) {
    FT_Library lib;
    FT_Face face;
    if (FT_Init_FreeType(&lib)) {
        snprintf(font_error, sizeof font_error, "FreeType could not be initialised");
        return;
    }
    if (FT_New_Face(lib, PL_FONT_PATH, 0, &face)) {
        snprintf(font_error, sizeof font_error,
                 "cannot load the font %s (install the Debian package fonts-dejavu-core)",
                 PL_FONT_PATH);
        FT_Done_FreeType(lib);
        return;
    }
    /* No hinting: glyph outlines independent of the FreeType hinting engine. The face and
     * library live for the whole process (the font face is shared by all renders). */
    font_face = cairo_ft_font_face_create_for_ft_face(face, FT_LOAD_NO_HINTING);
    if (cairo_font_face_status(font_face) != CAIRO_STATUS_SUCCESS) {
        snprintf(font_error, sizeof font_error, "cairo could not use the font %s", PL_FONT_PATH);
        font_face = NULL;
    }
}

cairo_font_face_t *pl_cairo_font_face(char *err, size_t errlen) {
    pthread_once(&font_once, load_font);
    if (!font_face && err && errlen) snprintf(err, errlen, "%s", font_error);
    return font_face;
}

/* ------------------------------------------------------------------ drawing */

static void set_color(cairo_t *cr, pl_rgba c) {
    cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
}

static void path_points(cairo_t *cr, const pl_draw_list *dl, const pl_prim *p, int closed) {
    const pl_vec2 *pts = dl->points + p->first;
    for (int i = 0; i < p->count; i++) {
        pl_vec2 q = pl_dl_px(dl, p, pts[i]);
        if (i == 0) cairo_move_to(cr, q.x, q.y);
        else cairo_line_to(cr, q.x, q.y);
    }
    if (closed) cairo_close_path(cr);
}

static void fill_stroke(cairo_t *cr, const pl_prim *p) {
    if (p->has_fill) {
        set_color(cr, p->fill);
        if (p->has_stroke) cairo_fill_preserve(cr);
        else cairo_fill(cr);
    }
    if (p->has_stroke) {
        set_color(cr, p->stroke);
        cairo_set_line_width(cr, p->width);
        cairo_stroke(cr);
    }
    cairo_new_path(cr);
}

/* True when cr draws onto an image surface with pixel coordinates (our own rasterizers can
 * then write pixels; vector surfaces keep cairo's primitives). */
static int raster_target(cairo_t *cr) {
    cairo_surface_t *t = cairo_get_target(cr);
    if (cairo_surface_get_type(t) != CAIRO_SURFACE_TYPE_IMAGE) return 0;
    cairo_matrix_t m;
    cairo_get_matrix(cr, &m);
    if (!(m.xx == 1.0 && m.yy == 1.0 && m.xy == 0.0 && m.yx == 0.0 && m.x0 == 0.0 && m.y0 == 0.0))
        return 0;
    /* and no clip of the caller's (ours is applied by the rasterizers themselves) */
    double x0, y0, x1, y1;
    cairo_clip_extents(cr, &x0, &y0, &x1, &y1);
    return x0 <= 0.0 && y0 <= 0.0 && x1 >= cairo_image_surface_get_width(t) &&
           y1 >= cairo_image_surface_get_height(t);
}

/* Gouraud triangles on an image target: rasterized by hand into a transparent image the
 * size of their bounding box (within the clip), then composited with cairo (so clipping and
 * blending stay cairo's). 40,000 triangles: a few ms instead of ~90 ms of mesh patterns. */
static int draw_triangles_raster(cairo_t *cr, const pl_draw_list *dl, const pl_prim *p, int nt) {
    const pl_vec2 *pts = dl->points + p->first;
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    pl_vec2 *px = malloc((size_t)nt * 3u * sizeof *px);
    if (!px) return -1;
    for (int i = 0; i < 3 * nt; i++) {
        px[i] = pl_dl_px(dl, p, pts[i]);
        if (px[i].x < x0) x0 = px[i].x;
        if (px[i].x > x1) x1 = px[i].x;
        if (px[i].y < y0) y0 = px[i].y;
        if (px[i].y > y1) y1 = px[i].y;
    }
    double cx0, cy0, cx1, cy1;
    cairo_clip_extents(cr, &cx0, &cy0, &cx1, &cy1);
    int ix0 = (int)floor(fmax(x0, cx0)), iy0 = (int)floor(fmax(y0, cy0));
    /* cairo paints the pixel a sample falls in, floor(x), also for samples on the right or
     * bottom edge: the image spans up to floor(max) inclusive */
    int ix1 = (int)floor(fmin(x1, cx1)) + 1, iy1 = (int)floor(fmin(y1, cy1)) + 1;
    if (ix1 > (int)ceil(cx1)) ix1 = (int)ceil(cx1);
    if (iy1 > (int)ceil(cy1)) iy1 = (int)ceil(cy1);
    if (ix1 <= ix0 || iy1 <= iy0) {
        free(px);
        return 0;
    }
    int w = ix1 - ix0, h = iy1 - iy0;
    /* opaque colours and a clip on whole pixels: compositing the image would replace the
     * painted pixels, so paint them straight into the target */
    int opaque = 1;
    for (int i = 0; i < 3 * nt && opaque; i++) opaque = dl->colors[p->color_first + i].a >= 1.0f;
    cairo_surface_t *target = cairo_get_target(cr);
    if (opaque && cx0 == floor(cx0) && cy0 == floor(cy0) && cx1 == floor(cx1) &&
        cy1 == floor(cy1) && cairo_image_surface_get_format(target) == CAIRO_FORMAT_ARGB32) {
        cairo_surface_flush(target);
        int stride = cairo_image_surface_get_stride(target);
        uint8_t *data = cairo_image_surface_get_data(target);
        pl_raster_gouraud(data + (size_t)iy0 * (size_t)stride + 4u * (size_t)ix0, w, h, stride,
                          ix0, iy0, px, dl->colors + p->color_first, nt);
        cairo_surface_mark_dirty(target);
        free(px);
        return 0;
    }
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(img);
        free(px);
        return -1;
    }
    cairo_surface_flush(img);
    pl_raster_gouraud(cairo_image_surface_get_data(img), w, h, cairo_image_surface_get_stride(img),
                      ix0, iy0, px, dl->colors + p->color_first, nt);
    cairo_surface_mark_dirty(img);
    free(px);
    cairo_set_source_surface(cr, img, ix0, iy0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_rectangle(cr, ix0, iy0, w, h);
    cairo_fill(cr);
    cairo_surface_destroy(img);
    return 0;
}

static void draw_triangles(cairo_t *cr, const pl_draw_list *dl, const pl_prim *p, int own) {
    int nt = p->count / 3;
    if (nt <= 0) return;
    if (own && draw_triangles_raster(cr, dl, p, nt) == 0) return;
    cairo_pattern_t *mesh = cairo_pattern_create_mesh();
    const pl_vec2 *pts = dl->points + p->first;
    const pl_rgba *col = dl->colors + p->color_first;
    for (int t = 0; t < nt; t++) {
        cairo_mesh_pattern_begin_patch(mesh);
        for (int k = 0; k < 3; k++) {
            pl_vec2 q = pl_dl_px(dl, p, pts[3 * t + k]);
            if (k == 0) cairo_mesh_pattern_move_to(mesh, q.x, q.y);
            else cairo_mesh_pattern_line_to(mesh, q.x, q.y);
        }
        for (int k = 0; k < 3; k++) {
            pl_rgba c = col[3 * t + k];
            cairo_mesh_pattern_set_corner_color_rgba(mesh, (unsigned)k, c.r, c.g, c.b, c.a);
        }
        cairo_mesh_pattern_end_patch(mesh);
    }
    cairo_set_source(cr, mesh);
    cairo_paint(cr);
    cairo_pattern_destroy(mesh);
}

/* The shaft end and the head triangle of an arrow in pixels; 0 when it has no length. */
typedef struct arrow_px {
    pl_vec2 a, shaft_end, tip, left, right;
} arrow_px;

static int arrow_geometry(const pl_draw_list *dl, const pl_prim *p, arrow_px *g) {
    pl_vec2 a = pl_dl_px(dl, p, dl->points[p->first]);
    pl_vec2 b = pl_dl_px(dl, p, dl->points[p->first + 1]);
    double dx = b.x - a.x, dy = b.y - a.y, len = sqrt(dx * dx + dy * dy);
    if (!(len > 0.0)) return 0;
    double ux = dx / len, uy = dy / len;
    double head = p->size;
    if (head > 0.6 * len) head = 0.6 * len;
    double half = 0.42 * head;
    if (half < 0.5 * p->width) half = 0.5 * p->width;
    double bx = b.x - ux * head, by = b.y - uy * head;
    g->a = a;
    g->shaft_end = (pl_vec2){bx + ux * 0.5, by + uy * 0.5};
    g->tip = b;
    g->left = (pl_vec2){bx - uy * half, by + ux * half};
    g->right = (pl_vec2){bx + uy * half, by - ux * half};
    return 1;
}

static void draw_arrow(cairo_t *cr, const pl_draw_list *dl, const pl_prim *p) {
    arrow_px g;
    if (!arrow_geometry(dl, p, &g)) return;
    set_color(cr, p->stroke);
    cairo_set_line_width(cr, p->width);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    cairo_move_to(cr, g.a.x, g.a.y);
    cairo_line_to(cr, g.shaft_end.x, g.shaft_end.y);
    cairo_stroke(cr);
    cairo_move_to(cr, g.tip.x, g.tip.y);
    cairo_line_to(cr, g.left.x, g.left.y);
    cairo_line_to(cr, g.right.x, g.right.y);
    cairo_close_path(cr);
    set_color(cr, p->fill);
    cairo_fill(cr);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
}

static void draw_text(cairo_t *cr, const pl_draw_list *dl, const pl_prim *p) {
    const char *s = dl->text + p->text;
    pl_vec2 at = pl_dl_px(dl, p, dl->points[p->first]);
    cairo_set_font_size(cr, p->size);
    cairo_text_extents_t te;
    cairo_font_extents_t fe;
    cairo_text_extents(cr, s, &te);
    cairo_font_extents(cr, &fe);
    double x = 0.0, y = 0.0;
    switch (PL_ANCHOR_H(p->anchor)) {
    case PL_ANCHOR_CENTER: x = -0.5 * te.x_advance; break;
    case PL_ANCHOR_RIGHT: x = -te.x_advance; break;
    default: x = 0.0; break;
    }
    /* Vertical anchors use the cap height of DejaVu Sans (0.73 em) rather than ink extents,
     * so labels of different strings line up. */
    double cap = 0.729 * p->size;
    switch (PL_ANCHOR_V(p->anchor)) {
    case PL_ANCHOR_TOP: y = cap; break;
    case PL_ANCHOR_MIDDLE: y = 0.5 * cap; break;
    case PL_ANCHOR_BOTTOM: y = -fe.descent; break;
    default: y = 0.0; break;
    }
    cairo_save(cr);
    cairo_translate(cr, at.x, at.y);
    if (p->angle != 0.0f) cairo_rotate(cr, -p->angle);
    if (p->has_halo) { /* a background box a little larger than the text */
        double pad = 0.18 * p->size;
        set_color(cr, p->stroke);
        cairo_rectangle(cr, x - pad, y - cap - pad, te.x_advance + 2.0 * pad, cap + 2.0 * pad);
        cairo_fill(cr);
    }
    cairo_surface_type_t type = cairo_surface_get_type(cairo_get_target(cr));
    if (type == CAIRO_SURFACE_TYPE_SVG) {
        /* cairo's SVG surface would write glyph outlines: the text goes in as <text>
         * elements after the drawing (pl_svg_append_text), the box stays here */
    } else if (type == CAIRO_SURFACE_TYPE_PDF) {
        /* real text: cairo embeds a subset of the font with a Unicode map (searchable,
         * selectable, editable) */
        cairo_move_to(cr, x, y);
        set_color(cr, p->fill);
        cairo_show_text(cr, s);
    } else {
        cairo_move_to(cr, x, y);
        cairo_text_path(cr, s);
        set_color(cr, p->fill);
        cairo_fill(cr);
    }
    cairo_restore(cr);
}

/* The offset of a text primitive's baseline start from its anchor point (px, before the
 * rotation), as draw_text places it. */
void pl_cairo_text_origin(cairo_t *cr, const pl_prim *p, const char *s, double *ox, double *oy) {
    cairo_set_font_size(cr, p->size);
    cairo_text_extents_t te;
    cairo_font_extents_t fe;
    cairo_text_extents(cr, s, &te);
    cairo_font_extents(cr, &fe);
    double x = 0.0, y = 0.0, cap = 0.729 * p->size;
    switch (PL_ANCHOR_H(p->anchor)) {
    case PL_ANCHOR_CENTER: x = -0.5 * te.x_advance; break;
    case PL_ANCHOR_RIGHT: x = -te.x_advance; break;
    default: break;
    }
    switch (PL_ANCHOR_V(p->anchor)) {
    case PL_ANCHOR_TOP: y = cap; break;
    case PL_ANCHOR_MIDDLE: y = 0.5 * cap; break;
    case PL_ANCHOR_BOTTOM: y = -fe.descent; break;
    default: break;
    }
    *ox = x;
    *oy = y;
}

/* ------------------------------------------------------ direct rasterization */

/* On image surfaces, bodies, segments, lines and arrows are rasterized by raster_aa.c
 * straight into the surface's pixels (cairo's per-path cost dominates pictures of thousands
 * of small primitives; Gouraud fields: draw_triangles_raster); text and everything on
 * SVG/PDF stay with cairo. The pictures differ from cairo's by the measured amounts of
 * docs/rendering.md (Performance). */
typedef struct direct_ctx {
    pl_aa *aa;
    cairo_surface_t *target;
    uint8_t *data;
    int stride;
    int writing;  /* pixels written since the last flush: mark dirty before cairo draws */
    int failed;   /* out of memory in raster_aa.c: the picture is incomplete */
    int open;     /* a batch of one colour is being collected (segments, arrows) */
    int open_clipped, open_sum;
    pl_rgba open_color;
} direct_ctx;

static void direct_fill(direct_ctx *d, pl_rgba color) {
    if (pl_aa_fill(d->aa, d->data, d->stride, color)) d->failed = 1;
}

/* composites the open batch, if any */
static void direct_flush(direct_ctx *d) {
    if (d->open) {
        d->open = 0;
        direct_fill(d, d->open_color);
    }
}

static void direct_begin(direct_ctx *d) {
    if (!d->writing) {
        cairo_surface_flush(d->target);
        d->writing = 1;
    }
}

static void direct_end(direct_ctx *d) {
    if (d->aa) direct_flush(d);
    if (d->aa && d->writing) {
        cairo_surface_mark_dirty(d->target);
        d->writing = 0;
    }
}

static void direct_batch(direct_ctx *d, const pl_draw_list *dl, int clipped) {
    direct_flush(d);
    if (clipped)
        pl_aa_begin(d->aa, dl->clip.x0, dl->clip.y0, dl->clip.x1, dl->clip.y1);
    else
        pl_aa_begin(d->aa, 0.0, 0.0, 1e9, 1e9);
}

/* a batch of one shape: composited as it is rasterized */
static void direct_single(direct_ctx *d, const pl_draw_list *dl, int clipped, pl_rgba color) {
    direct_batch(d, dl, clipped);
    pl_aa_immediate(d->aa, d->data, d->stride, color);
}

/* Continues the open batch when it has this colour and clip, else starts one. Consecutive
 * primitives of one colour (the segment batches of a force class or of a mesh, the arrows of
 * a layer) are collected into one batch: where they overlap, the union (per-pixel maximum) is
 * composited once. */
static void direct_open(direct_ctx *d, const pl_draw_list *dl, int clipped, pl_rgba color,
                        int sum) {
    direct_begin(d);
    if (d->open && d->open_clipped == clipped && d->open_sum == sum &&
        memcmp(&d->open_color, &color, sizeof color) == 0)
        return;
    direct_batch(d, dl, clipped);
    if (sum) {
        if (clipped) pl_aa_begin_sum(d->aa, dl->clip.x0, dl->clip.y0, dl->clip.x1, dl->clip.y1);
        else pl_aa_begin_sum(d->aa, 0.0, 0.0, 1e9, 1e9);
    } else {
        pl_aa_incremental(d->aa, d->data, d->stride, color);
    }
    d->open_sum = sum;
    d->open = 1;
    d->open_clipped = clipped;
    d->open_color = color;
}

/* Largest size (px) of a body or mark drawn directly, and longest segment of a batch:
 * thousands of small primitives are where cairo's per-path cost dominates; large ones (few,
 * by nature) stay with cairo. */
#define DIRECT_MAX_PX 24.0

/* Longest segment (px, in x and in y) of a batch drawn directly; longer ones (few: zoomed-in
 * meshes) go to cairo. */
#define SEGMENT_MAX_PX 256.0

static int seg_is_direct(pl_vec2 a, pl_vec2 b) {
    return fabs(b.x - a.x) <= SEGMENT_MAX_PX && fabs(b.y - a.y) <= SEGMENT_MAX_PX;
}

/* Extent of a primitive's points in pixels (largest of width and height). */
static double px_extent(const pl_draw_list *dl, const pl_prim *p) {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (int i = 0; i < p->count; i++) {
        pl_vec2 q = pl_dl_px(dl, p, dl->points[p->first + i]);
        x0 = fmin(x0, q.x);
        x1 = fmax(x1, q.x);
        y0 = fmin(y0, q.y);
        y1 = fmax(y1, q.y);
    }
    return fmax(x1 - x0, y1 - y0);
}

/* Draws p directly when it is of a kind and size handled here; returns 1 when drawn. */
static int direct_draw(direct_ctx *d, const pl_draw_list *dl, const pl_prim *p, int clipped) {
    switch (p->kind) {
    case PL_PRIM_CIRCLE: {
        pl_vec2 c = pl_dl_px(dl, p, dl->points[p->first]);
        double r = pl_dl_px_radius(dl, p);
        if (2.0 * r > DIRECT_MAX_PX) return 0;
        direct_begin(d);
        if (p->has_fill) {
            direct_single(d, dl, clipped, p->fill);
            pl_aa_circle(d->aa, c, r);
            direct_fill(d, p->fill);
        }
        if (p->has_stroke) {
            double hw = 0.5 * p->width;
            direct_single(d, dl, clipped, p->stroke);
            pl_aa_ring(d->aa, c, r - hw, r + hw);
            direct_fill(d, p->stroke);
        }
        return 1;
    }
    case PL_PRIM_POLYGON: {
        if (p->count > 64 || p->count < 3 || px_extent(dl, p) > DIRECT_MAX_PX) return 0;
        pl_vec2 q[64];
        for (int i = 0; i < p->count; i++) q[i] = pl_dl_px(dl, p, dl->points[p->first + i]);
        /* outlines of convex polygons only (bodies are convex); others go to cairo */
        if (p->has_stroke && pl_aa_convex_outline_check(q, p->count, p->width)) return 0;
        direct_begin(d);
        if (p->has_fill) {
            direct_single(d, dl, clipped, p->fill);
            pl_aa_polygon(d->aa, q, p->count);
            direct_fill(d, p->fill);
        }
        if (p->has_stroke) {
            direct_single(d, dl, clipped, p->stroke);
            pl_aa_convex_outline(d->aa, q, p->count, p->width);
            direct_fill(d, p->stroke);
        }
        return 1;
    }
    case PL_PRIM_POLYLINE: { /* short lines (rotation marks) */
        if (p->count != 2 || px_extent(dl, p) > DIRECT_MAX_PX) return 0;
        direct_begin(d);
        direct_single(d, dl, clipped, p->stroke);
        pl_aa_capsule(d->aa, pl_dl_px(dl, p, dl->points[p->first]),
                      pl_dl_px(dl, p, dl->points[p->first + 1]), p->width);
        direct_fill(d, p->stroke);
        return 1;
    }
    case PL_PRIM_SEGMENTS: { /* short segments here; long ones (if any) then by cairo */
        const pl_vec2 *pts = dl->points + p->first;
        /* Segment batches (force classes, mesh wireframes) by their distance coverage
         * (pl_aa_thin_segment): consecutive batches of one colour form one batch, whose
         * per-pixel maximum is the coverage by the distance to the union of its segments, so
         * lines meeting at a node join without gaps and without doubly blended pixels (cairo
         * forms the exact area of the union of each path: a little darker at nodes). */
        int long_ones = 0;
        direct_open(d, dl, clipped, p->stroke, 0);
        for (int k = 0; k + 1 < p->count; k += 2) {
            pl_vec2 a = pl_dl_px(dl, p, pts[k]), b = pl_dl_px(dl, p, pts[k + 1]);
            if (seg_is_direct(a, b)) pl_aa_thin_segment(d->aa, a, b, p->width);
            else long_ones = 1;
        }
        return !long_ones;
    }
    default:
        return 0;
    }
}

/* An arrow drawn directly: shaft (butt caps), then head, as cairo draws them. */
static int direct_arrow(direct_ctx *d, const pl_draw_list *dl, const pl_prim *p, int clipped) {
    arrow_px g;
    if (!arrow_geometry(dl, p, &g)) return 1;
    /* many short arrows in pixel space (tangential forces) here; long ones, and arrows in
     * the clipped plot area (velocity fields: a few hundred), where cairo's clipped
     * rendering differs from ours by more than the tolerance, with cairo */
    if (clipped || fabs(g.tip.x - g.a.x) > 2.0 * DIRECT_MAX_PX ||
        fabs(g.tip.y - g.a.y) > 2.0 * DIRECT_MAX_PX)
        return 0;
    direct_begin(d);
    pl_vec2 t[3] = {g.tip, g.left, g.right};
    if (memcmp(&p->stroke, &p->fill, sizeof p->fill) == 0) {
        /* one colour: shaft and head as one shape, the arrows of a layer in one batch */
        direct_open(d, dl, clipped, p->fill, 1);
        pl_aa_arrow(d->aa, g.a, g.shaft_end, p->width, t);
        return 1;
    }
    direct_single(d, dl, clipped, p->stroke);
    pl_aa_bar(d->aa, g.a, g.shaft_end, p->width);
    direct_fill(d, p->stroke);
    direct_single(d, dl, clipped, p->fill);
    pl_aa_polygon(d->aa, t, 3);
    direct_fill(d, p->fill);
    return 1;
}

int pl_cairo_draw(cairo_t *cr, const pl_draw_list *dl, char *err, size_t errlen) {
    if (dl->failed) {
        snprintf(err, errlen, "the draw list is incomplete (out of memory while building it)");
        return -1;
    }
    int has_text = 0;
    for (int i = 0; i < dl->prim_count && !has_text; i++)
        has_text = dl->prims[i].kind == PL_PRIM_TEXT;
    if (has_text) {
        cairo_font_face_t *ff = pl_cairo_font_face(err, errlen);
        if (!ff) return -1;
        cairo_set_font_face(cr, ff);
        cairo_font_options_t *fo = cairo_font_options_create();
        cairo_font_options_set_antialias(fo, CAIRO_ANTIALIAS_GRAY);
        cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
        cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
        cairo_font_options_set_subpixel_order(fo, CAIRO_SUBPIXEL_ORDER_DEFAULT);
        cairo_set_font_options(cr, fo);
        cairo_font_options_destroy(fo);
    }
    cairo_save(cr);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    set_color(cr, dl->background);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    const double two_pi = 6.283185307179586;
    int clipped = 0;
    direct_ctx d;
    memset(&d, 0, sizeof d);
    /* our own rasterizers on image surfaces; PORELAB_CAIRO_ONLY=1 leaves everything to cairo
     * (for comparisons: tests/bench/bench_render.c) */
    int own = raster_target(cr) && !getenv("PORELAB_CAIRO_ONLY");
    if (own) {
        d.target = cairo_get_target(cr);
        cairo_surface_flush(d.target);
        d.data = cairo_image_surface_get_data(d.target);
        d.stride = cairo_image_surface_get_stride(d.target);
        if (d.data && cairo_image_surface_get_format(d.target) == CAIRO_FORMAT_ARGB32)
            d.aa = pl_aa_create(cairo_image_surface_get_width(d.target),
                                cairo_image_surface_get_height(d.target));
    }
    for (int i = 0; i < dl->prim_count; i++) {
        const pl_prim *p = &dl->prims[i];
        if (d.aa) {
            int is_clipped = dl->has_clip && p->space == PL_SPACE_WORLD;
            if (p->kind == PL_PRIM_ARROW && direct_arrow(&d, dl, p, is_clipped)) continue;
            if (direct_draw(&d, dl, p, is_clipped)) continue;
            direct_end(&d);
        }
        if (dl->has_clip && p->space == PL_SPACE_WORLD && !clipped) {
            cairo_save(cr);
            cairo_rectangle(cr, dl->clip.x0, dl->clip.y0, dl->clip.x1 - dl->clip.x0,
                            dl->clip.y1 - dl->clip.y0);
            cairo_clip(cr);
            clipped = 1;
        } else if (clipped && p->space != PL_SPACE_WORLD) {
            cairo_restore(cr);
            clipped = 0;
        }
        switch (p->kind) {
        case PL_PRIM_CIRCLE: {
            pl_vec2 c = pl_dl_px(dl, p, dl->points[p->first]);
            double r = pl_dl_px_radius(dl, p);
            cairo_new_sub_path(cr);
            cairo_arc(cr, c.x, c.y, r, 0.0, two_pi);
            fill_stroke(cr, p);
            break;
        }
        case PL_PRIM_POLYGON:
            path_points(cr, dl, p, 1);
            fill_stroke(cr, p);
            break;
        case PL_PRIM_POLYLINE:
            path_points(cr, dl, p, 0);
            set_color(cr, p->stroke);
            cairo_set_line_width(cr, p->width);
            cairo_stroke(cr);
            break;
        case PL_PRIM_SEGMENTS: {
            const pl_vec2 *pts = dl->points + p->first;
            for (int k = 0; k + 1 < p->count; k += 2) {
                pl_vec2 a = pl_dl_px(dl, p, pts[k]), b = pl_dl_px(dl, p, pts[k + 1]);
                if (d.aa && seg_is_direct(a, b))
                    continue; /* drawn directly above */
                cairo_move_to(cr, a.x, a.y);
                cairo_line_to(cr, b.x, b.y);
            }
            set_color(cr, p->stroke);
            cairo_set_line_width(cr, p->width);
            cairo_stroke(cr);
            break;
        }
        case PL_PRIM_TRIANGLES: draw_triangles(cr, dl, p, own); break;
        case PL_PRIM_ARROW: draw_arrow(cr, dl, p); break;
        case PL_PRIM_TEXT: draw_text(cr, dl, p); break;
        default: break;
        }
    }
    direct_end(&d);
    pl_aa_destroy(d.aa);
    if (clipped) cairo_restore(cr);
    if (d.failed) {
        snprintf(err, errlen, "out of memory while rasterizing");
        return -1;
    }
    cairo_status_t st = cairo_status(cr);
    if (st != CAIRO_STATUS_SUCCESS) {
        snprintf(err, errlen, "cairo: %s", cairo_status_to_string(st));
        return -1;
    }
    return 0;
}

/* ------------------------------------------------------------------- images */

void pl_image_free(pl_image *img) {
    free(img->rgba);
    img->rgba = NULL;
    img->width = img->height = 0;
}

int pl_cairo_rasterize(const pl_draw_list *dl, pl_image *img, char *err, size_t errlen) {
    int w = dl->camera.width, h = dl->camera.height;
    if (w <= 0 || h <= 0 || w > 32768 || h > 32768) {
        snprintf(err, errlen, "image size %dx%d is out of range (1..32768)", w, h);
        return -1;
    }
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        snprintf(err, errlen, "cannot create a %dx%d image: %s", w, h,
                 cairo_status_to_string(cairo_surface_status(s)));
        cairo_surface_destroy(s);
        return -1;
    }
    cairo_t *cr = cairo_create(s);
    int rc = pl_cairo_draw(cr, dl, err, errlen);
    cairo_destroy(cr);
    if (rc == 0) {
        cairo_surface_flush(s);
        if (!img->rgba || img->width != w || img->height != h) {
            uint8_t *buf = realloc(img->rgba, (size_t)w * (size_t)h * 4u);
            if (!buf) {
                snprintf(err, errlen, "out of memory for a %dx%d image", w, h);
                cairo_surface_destroy(s);
                return -1;
            }
            img->rgba = buf;
            img->width = w;
            img->height = h;
        }
        const unsigned char *data = cairo_image_surface_get_data(s);
        int stride = cairo_image_surface_get_stride(s);
        for (int y = 0; y < h; y++) {
            const uint32_t *row = (const uint32_t *)(const void *)(data + (size_t)y * (size_t)stride);
            uint8_t *out = img->rgba + (size_t)y * (size_t)w * 4u;
            for (int x = 0; x < w; x++) {
                uint32_t v = row[x];
                if (v >> 24 == 255u) { /* opaque: only the byte order changes */
                    uint32_t o = (v & 0xFF00FF00u) | (v >> 16 & 0xFFu) | (v & 0xFFu) << 16;
                    memcpy(out + 4 * x, &o, 4);
                    continue;
                }
                unsigned a = v >> 24, r = (v >> 16) & 255u, g = (v >> 8) & 255u, b = v & 255u;
                if (a != 255u && a != 0u) { /* un-premultiply with rounding */
                    r = (r * 255u + a / 2u) / a;
                    g = (g * 255u + a / 2u) / a;
                    b = (b * 255u + a / 2u) / a;
                }
                out[4 * x + 0] = (uint8_t)r;
                out[4 * x + 1] = (uint8_t)g;
                out[4 * x + 2] = (uint8_t)b;
                out[4 * x + 3] = (uint8_t)a;
            }
        }
    }
    cairo_surface_destroy(s);
    return rc;
}

int pl_file_format(const char *path) {
    const char *dot = strrchr(path, '.');
    if (!dot) return -1;
    if (strcasecmp(dot, ".png") == 0) return 0;
    if (strcasecmp(dot, ".svg") == 0) return 1;
    if (strcasecmp(dot, ".pdf") == 0) return 2;
    return -1;
}

int pl_cairo_write_file(const pl_draw_list *dl, const char *path, int png_level, char *err,
                        size_t errlen) {
    int fmt = pl_file_format(path);
    if (fmt < 0) {
        snprintf(err, errlen, "%s: unknown image format (valid extensions: .png, .svg, .pdf)", path);
        return -1;
    }
    if (fmt == 0) {
        pl_image img = {0, 0, NULL};
        int rc = pl_cairo_rasterize(dl, &img, err, errlen);
        if (rc == 0) rc = pl_png_write(path, &img, png_level, png_level > 1, err, errlen);
        pl_image_free(&img);
        return rc;
    }
    double w = dl->camera.width, h = dl->camera.height;
    /* Vector surfaces: 1 pixel = 1 pt, so a 800x600 still is an 800x600 pt page. */
    cairo_surface_t *s = fmt == 1 ? cairo_svg_surface_create(path, w, h)
                                  : cairo_pdf_surface_create(path, w, h);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        snprintf(err, errlen, "cannot write %s: %s", path,
                 cairo_status_to_string(cairo_surface_status(s)));
        cairo_surface_destroy(s);
        return -1;
    }
    if (fmt == 2) {
        /* Fixed metadata so the same picture gives the same bytes. */
        cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATOR, "porelab");
        cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00Z");
    }
    cairo_t *cr = cairo_create(s);
    int rc = pl_cairo_draw(cr, dl, err, errlen);
    cairo_destroy(cr);
    cairo_surface_finish(s);
    if (rc == 0 && cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        snprintf(err, errlen, "cannot write %s: %s", path,
                 cairo_status_to_string(cairo_surface_status(s)));
        rc = -1;
    }
    cairo_surface_destroy(s);
    if (rc == 0 && fmt == 1) rc = pl_svg_append_text(dl, path, err, errlen);
    return rc;
}
