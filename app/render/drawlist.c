/* Draw list storage, camera and primitive builders. */
#include "drawlist.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------ camera */

pl_camera pl_camera_fit(pl_vec2 lo, pl_vec2 hi, int width, int height, pl_px_rect area,
                        double margin) {
    pl_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.width = width;
    cam.height = height;
    double w = hi.x - lo.x, h = hi.y - lo.y;
    if (!(w >= 0.0) || !(h >= 0.0) || !isfinite(w) || !isfinite(h)) { /* empty or invalid */
        lo.x = lo.y = 0.0;
        w = h = 0.0;
    }
    if (w <= 0.0 && h <= 0.0) { /* a point: show 1 m around it */
        lo.x -= 0.5; lo.y -= 0.5; w = h = 1.0;
    }
    double big = w > h ? w : h;
    double m = margin > 0.0 ? margin * big : 0.0;
    double vw = w + 2.0 * m, vh = h + 2.0 * m;
    double aw = area.x1 - area.x0, ah = area.y1 - area.y0;
    if (aw < 1.0) aw = 1.0;
    if (ah < 1.0) ah = 1.0;
    double sx = vw > 0.0 ? aw / vw : INFINITY, sy = vh > 0.0 ? ah / vh : INFINITY;
    cam.scale = sx < sy ? sx : sy;
    cam.center.x = lo.x + 0.5 * w;
    cam.center.y = lo.y + 0.5 * h;
    cam.px_center.x = 0.5 * (area.x0 + area.x1);
    cam.px_center.y = 0.5 * (area.y0 + area.y1);
    return cam;
}

pl_vec2 pl_camera_to_px(const pl_camera *cam, pl_vec2 p) {
    pl_vec2 q = {(p.x - cam->center.x) * cam->scale + cam->px_center.x,
                 cam->px_center.y - (p.y - cam->center.y) * cam->scale};
    return q;
}

pl_vec2 pl_camera_to_world(const pl_camera *cam, pl_vec2 q) {
    pl_vec2 p = {(q.x - cam->px_center.x) / cam->scale + cam->center.x,
                 (cam->px_center.y - q.y) / cam->scale + cam->center.y};
    return p;
}

/* ----------------------------------------------------------------- storage */

void pl_draw_list_init(pl_draw_list *dl) {
    memset(dl, 0, sizeof *dl);
    dl->background = pl_rgb(1, 1, 1);
}

void pl_draw_list_clear(pl_draw_list *dl) {
    dl->prim_count = dl->point_count = dl->color_count = dl->text_size = 0;
    dl->failed = 0;
    dl->current_layer = 0;
    dl->has_clip = 0;
    dl->auto_field_set = dl->auto_color_set = 0;
    dl->auto_field_lo = dl->auto_field_hi = dl->auto_color_lo = dl->auto_color_hi = 0.0;
    dl->auto_vscale = 0.0;
}

void pl_draw_list_free(pl_draw_list *dl) {
    free(dl->prims);
    free(dl->points);
    free(dl->colors);
    free(dl->text);
    pl_draw_list_init(dl);
}

/* Grows an array to hold at least need elements; returns 0 or -1 (list marked failed). */
static int grow(pl_draw_list *dl, void **arr, int *cap, int need, size_t elem) {
    if (need <= *cap) return 0;
    int nc = *cap ? *cap : 256;
    while (nc < need) {
        if (nc > (1 << 29)) { dl->failed = 1; return -1; }
        nc *= 2;
    }
    void *p = realloc(*arr, (size_t)nc * elem);
    if (!p) { dl->failed = 1; return -1; }
    *arr = p;
    *cap = nc;
    return 0;
}

static pl_prim *new_prim(pl_draw_list *dl, pl_prim_kind kind, pl_space sp, int npoints) {
    if (grow(dl, (void **)&dl->prims, &dl->prim_cap, dl->prim_count + 1, sizeof(pl_prim)) ||
        grow(dl, (void **)&dl->points, &dl->point_cap, dl->point_count + npoints, sizeof(pl_vec2)))
        return NULL;
    pl_prim *p = &dl->prims[dl->prim_count++];
    memset(p, 0, sizeof *p);
    p->kind = (uint8_t)kind;
    p->space = (uint8_t)sp;
    p->first = dl->point_count;
    p->count = 0;
    p->color_first = -1;
    p->text = -1;
    p->layer = dl->current_layer;
    return p;
}

static void add_points(pl_draw_list *dl, pl_prim *p, const pl_vec2 *pts, int n) {
    memcpy(dl->points + dl->point_count, pts, (size_t)n * sizeof(pl_vec2));
    dl->point_count += n;
    p->count += n;
}

void pl_draw_list_append(pl_draw_list *dst, const pl_draw_list *src) {
    if (grow(dst, (void **)&dst->prims, &dst->prim_cap, dst->prim_count + src->prim_count,
             sizeof(pl_prim)) ||
        grow(dst, (void **)&dst->points, &dst->point_cap, dst->point_count + src->point_count,
             sizeof(pl_vec2)) ||
        grow(dst, (void **)&dst->colors, &dst->color_cap, dst->color_count + src->color_count,
             sizeof(pl_rgba)) ||
        grow(dst, (void **)&dst->text, &dst->text_cap, dst->text_size + src->text_size, 1))
        return;
    for (int i = 0; i < src->prim_count; i++) {
        pl_prim p = src->prims[i];
        p.first += dst->point_count;
        if (p.color_first >= 0) p.color_first += dst->color_count;
        if (p.text >= 0) p.text += dst->text_size;
        dst->prims[dst->prim_count++] = p;
    }
    if (src->point_count)
        memcpy(dst->points + dst->point_count, src->points, (size_t)src->point_count * sizeof(pl_vec2));
    if (src->color_count)
        memcpy(dst->colors + dst->color_count, src->colors, (size_t)src->color_count * sizeof(pl_rgba));
    if (src->text_size) memcpy(dst->text + dst->text_size, src->text, (size_t)src->text_size);
    dst->point_count += src->point_count;
    dst->color_count += src->color_count;
    dst->text_size += src->text_size;
}

/* ------------------------------------------------------------------ styles */

pl_style pl_style_fill(pl_rgba fill) {
    pl_style s;
    memset(&s, 0, sizeof s);
    s.fill = fill;
    s.has_fill = 1;
    return s;
}

pl_style pl_style_stroke(pl_rgba stroke, float width) {
    pl_style s;
    memset(&s, 0, sizeof s);
    s.stroke = stroke;
    s.has_stroke = 1;
    s.width = width;
    return s;
}

pl_style pl_style_fill_stroke(pl_rgba fill, pl_rgba stroke, float width) {
    pl_style s = pl_style_fill(fill);
    s.stroke = stroke;
    s.has_stroke = 1;
    s.width = width;
    return s;
}

static void apply_style(pl_prim *p, const pl_style *st) {
    p->fill = st->fill;
    p->stroke = st->stroke;
    p->has_fill = (uint8_t)(st->has_fill != 0);
    p->has_stroke = (uint8_t)(st->has_stroke != 0 && st->width > 0.0f);
    p->width = st->width;
}

/* -------------------------------------------------------------- primitives */

void pl_dl_circle(pl_draw_list *dl, pl_space sp, pl_vec2 c, double r, const pl_style *st) {
    pl_prim *p = new_prim(dl, PL_PRIM_CIRCLE, sp, 1);
    if (!p) return;
    apply_style(p, st);
    p->radius = r;
    add_points(dl, p, &c, 1);
}

void pl_dl_polygon(pl_draw_list *dl, pl_space sp, const pl_vec2 *pts, int n, const pl_style *st) {
    if (n < 2) return;
    pl_prim *p = new_prim(dl, PL_PRIM_POLYGON, sp, n);
    if (!p) return;
    apply_style(p, st);
    add_points(dl, p, pts, n);
}

void pl_dl_polyline(pl_draw_list *dl, pl_space sp, const pl_vec2 *pts, int n, pl_rgba color,
                    float width) {
    if (n < 2 || width <= 0.0f) return;
    pl_prim *p = new_prim(dl, PL_PRIM_POLYLINE, sp, n);
    if (!p) return;
    p->stroke = color;
    p->has_stroke = 1;
    p->width = width;
    add_points(dl, p, pts, n);
}

void pl_dl_line(pl_draw_list *dl, pl_space sp, pl_vec2 a, pl_vec2 b, pl_rgba color, float width) {
    pl_vec2 pts[2] = {a, b};
    pl_dl_polyline(dl, sp, pts, 2, color, width);
}

void pl_dl_segments_begin(pl_draw_list *dl, pl_space sp, pl_rgba color, float width) {
    pl_prim *p = new_prim(dl, PL_PRIM_SEGMENTS, sp, 0);
    if (!p) return;
    p->stroke = color;
    p->has_stroke = 1;
    p->width = width;
}

void pl_dl_segment_add(pl_draw_list *dl, pl_vec2 a, pl_vec2 b) {
    if (dl->prim_count == 0 || dl->prims[dl->prim_count - 1].kind != PL_PRIM_SEGMENTS) return;
    /* long batches are split: cairo strokes a batch as one path, and a path of thousands of
     * crossing segments tessellates much slower than many short ones */
    if (dl->prims[dl->prim_count - 1].count >= 2 * PL_SEGMENT_BATCH) {
        pl_prim prev = dl->prims[dl->prim_count - 1];
        pl_dl_segments_begin(dl, (pl_space)prev.space, prev.stroke, prev.width);
        if (dl->prims[dl->prim_count - 1].kind != PL_PRIM_SEGMENTS) return;
        dl->prims[dl->prim_count - 1].layer = prev.layer;
    }
    if (grow(dl, (void **)&dl->points, &dl->point_cap, dl->point_count + 2, sizeof(pl_vec2))) return;
    pl_vec2 pts[2] = {a, b};
    add_points(dl, &dl->prims[dl->prim_count - 1], pts, 2);
}

void pl_dl_triangles_begin(pl_draw_list *dl, pl_space sp) {
    pl_prim *p = new_prim(dl, PL_PRIM_TRIANGLES, sp, 0);
    if (!p) return;
    p->color_first = dl->color_count;
    p->has_fill = 1;
}

void pl_dl_triangle_add(pl_draw_list *dl, const pl_vec2 pts[3], const pl_rgba c[3]) {
    if (dl->prim_count == 0 || dl->prims[dl->prim_count - 1].kind != PL_PRIM_TRIANGLES) return;
    if (grow(dl, (void **)&dl->points, &dl->point_cap, dl->point_count + 3, sizeof(pl_vec2)) ||
        grow(dl, (void **)&dl->colors, &dl->color_cap, dl->color_count + 3, sizeof(pl_rgba)))
        return;
    add_points(dl, &dl->prims[dl->prim_count - 1], pts, 3);
    memcpy(dl->colors + dl->color_count, c, 3 * sizeof(pl_rgba));
    dl->color_count += 3;
}

void pl_dl_arrow(pl_draw_list *dl, pl_space sp, pl_vec2 tail, pl_vec2 tip, pl_rgba color,
                 float shaft_width, float head_length) {
    pl_prim *p = new_prim(dl, PL_PRIM_ARROW, sp, 2);
    if (!p) return;
    p->fill = p->stroke = color;
    p->has_fill = p->has_stroke = 1;
    p->width = shaft_width;
    p->size = head_length;
    pl_vec2 pts[2] = {tail, tip};
    add_points(dl, p, pts, 2);
}

void pl_dl_text(pl_draw_list *dl, pl_space sp, pl_vec2 at, const char *s, float size,
                int anchor, float angle, pl_rgba color, const pl_rgba *halo) {
    if (!s || !*s || size <= 0.0f) return;
    int len = (int)strlen(s) + 1;
    if (grow(dl, (void **)&dl->text, &dl->text_cap, dl->text_size + len, 1)) return;
    pl_prim *p = new_prim(dl, PL_PRIM_TEXT, sp, 1);
    if (!p) return;
    p->fill = color;
    p->has_fill = 1;
    if (halo) {
        p->stroke = *halo;
        p->has_halo = 1;
    }
    p->size = size;
    p->anchor = (uint8_t)anchor;
    p->angle = angle;
    p->text = dl->text_size;
    memcpy(dl->text + dl->text_size, s, (size_t)len);
    dl->text_size += len;
    add_points(dl, p, &at, 1);
}

/* ----------------------------------------------------------------- colours */

pl_rgba pl_rgb(double r, double g, double b) {
    pl_rgba c = {(float)r, (float)g, (float)b, 1.0f};
    return c;
}

pl_rgba pl_rgb_hex(uint32_t v) {
    return pl_rgb(((v >> 16) & 255) / 255.0, ((v >> 8) & 255) / 255.0, (v & 255) / 255.0);
}

pl_rgba pl_rgba_mix(pl_rgba a, pl_rgba b, double t) {
    if (t < 0.0) t = 0.0;
    if (t > 1.0) t = 1.0;
    float u = (float)t, s = 1.0f - u;
    pl_rgba c = {s * a.r + u * b.r, s * a.g + u * b.g, s * a.b + u * b.b, s * a.a + u * b.a};
    return c;
}

pl_rgba pl_rgba_scale(pl_rgba a, double f) {
    pl_rgba c = {(float)(a.r * f), (float)(a.g * f), (float)(a.b * f), a.a};
    return c;
}

/* ----------------------------------------------------------------- sorting */

int pl_radix_sort_u64(uint64_t *keys, int32_t *vals, int n) {
    if (n < 2) return 0;
    uint64_t *tk = malloc((size_t)n * sizeof *tk);
    int32_t *tv = vals ? malloc((size_t)n * sizeof *tv) : NULL;
    if (!tk || (vals && !tv)) {
        free(tk);
        free(tv);
        return -1;
    }
    uint64_t *k0 = keys, *k1 = tk;
    int32_t *v0 = vals, *v1 = tv;
    uint64_t all_or = 0, all_and = ~(uint64_t)0;
    for (int i = 0; i < n; i++) {
        all_or |= keys[i];
        all_and &= keys[i];
    }
    uint64_t varying = all_or ^ all_and; /* bits that differ between some keys */
    for (int shift = 0; shift < 64; shift += 8) {
        if (!((varying >> shift) & 0xFFu)) continue;
        int count[257] = {0};
        for (int i = 0; i < n; i++) count[((k0[i] >> shift) & 0xFFu) + 1]++;
        for (int b = 0; b < 256; b++) count[b + 1] += count[b];
        for (int i = 0; i < n; i++) {
            int d = count[(k0[i] >> shift) & 0xFFu]++;
            k1[d] = k0[i];
            if (v0) v1[d] = v0[i];
        }
        uint64_t *t = k0; k0 = k1; k1 = t;
        int32_t *u = v0; v0 = v1; v1 = u;
    }
    if (k0 != keys) {
        memcpy(keys, k0, (size_t)n * sizeof *keys);
        if (vals) memcpy(vals, v0, (size_t)n * sizeof *vals);
    }
    free(tk);
    free(tv);
    return 0;
}
