/* Field layers: filled P1 fields, mesh wireframe, labelled isolines, arrows. */
#include "draw_field.h"
#include "label_place.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------- filled field */

static void fill_tri(pl_draw_list *dl, const pl_vec2 p[3], const double v[3], pl_colormap map,
                     double vmin, double vmax, int depth) {
    double lo = v[0], hi = v[0];
    for (int k = 1; k < 3; k++) {
        if (v[k] < lo) lo = v[k];
        if (v[k] > hi) hi = v[k];
    }
    double range = vmax - vmin;
    if (depth < 3 && range > 0.0 && (hi - lo) > range / 16.0) {
        pl_vec2 m[3];
        double mv[3];
        for (int k = 0; k < 3; k++) {
            int j = (k + 1) % 3;
            m[k].x = 0.5 * (p[k].x + p[j].x);
            m[k].y = 0.5 * (p[k].y + p[j].y);
            mv[k] = 0.5 * (v[k] + v[j]);
        }
        pl_vec2 t0[3] = {p[0], m[0], m[2]}, t1[3] = {m[0], p[1], m[1]};
        pl_vec2 t2[3] = {m[2], m[1], p[2]}, t3[3] = {m[0], m[1], m[2]};
        double v0[3] = {v[0], mv[0], mv[2]}, v1[3] = {mv[0], v[1], mv[1]};
        double v2[3] = {mv[2], mv[1], v[2]}, v3[3] = {mv[0], mv[1], mv[2]};
        fill_tri(dl, t0, v0, map, vmin, vmax, depth + 1);
        fill_tri(dl, t1, v1, map, vmin, vmax, depth + 1);
        fill_tri(dl, t2, v2, map, vmin, vmax, depth + 1);
        fill_tri(dl, t3, v3, map, vmin, vmax, depth + 1);
        return;
    }
    pl_rgba c[3];
    for (int k = 0; k < 3; k++) c[k] = pl_colormap_value(map, v[k], vmin, vmax);
    pl_dl_triangle_add(dl, p, c);
}

void pl_draw_field_fill(pl_draw_list *dl, const pl_vec2 *nodes, const int *tris, int tri_count,
                        const double *values, pl_colormap map, double vmin, double vmax) {
    pl_dl_triangles_begin(dl, PL_SPACE_WORLD);
    for (int t = 0; t < tri_count; t++) {
        const int *n = tris + 3 * t;
        pl_vec2 p[3] = {nodes[n[0]], nodes[n[1]], nodes[n[2]]};
        double v[3] = {values[n[0]], values[n[1]], values[n[2]]};
        fill_tri(dl, p, v, map, vmin, vmax, 0);
    }
}

/* ------------------------------------------------------------------- mesh */

static int cmp_u64(const void *a, const void *b) {
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

int pl_draw_mesh_wire(pl_draw_list *dl, const pl_vec2 *nodes, const int *tris, int tri_count,
                      pl_rgba color, float width) {
    if (tri_count <= 0) return 0;
    uint64_t *keys = malloc((size_t)tri_count * 3u * sizeof *keys);
    if (!keys) return -1;
    int n = 0;
    for (int t = 0; t < tri_count; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = (uint32_t)tris[3 * t + k], b = (uint32_t)tris[3 * t + (k + 1) % 3];
            if (a > b) { uint32_t s = a; a = b; b = s; }
            keys[n++] = ((uint64_t)a << 32) | b;
        }
    if (pl_radix_sort_u64(keys, NULL, n)) qsort(keys, (size_t)n, sizeof *keys, cmp_u64);
    pl_dl_segments_begin(dl, PL_SPACE_WORLD, color, width);
    for (int i = 0; i < n; i++) {
        if (i > 0 && keys[i] == keys[i - 1]) continue;
        pl_dl_segment_add(dl, nodes[keys[i] >> 32], nodes[keys[i] & 0xffffffffu]);
    }
    free(keys);
    return 0;
}

/* --------------------------------------------------------------- isolines */

pl_isoline_style pl_default_isoline_style(void) {
    pl_isoline_style s;
    memset(&s, 0, sizeof s);
    s.color = pl_rgb(0.18, 0.18, 0.20);
    s.width = 1.2f;
    s.label_size = 11.0f;
    s.label_format = "%g";
    s.label_spacing = 280.0;
    s.halo = pl_rgb(1, 1, 1);
    return s;
}

/* Label box half sizes for a string (DejaVu Sans: about 0.56 em per character). */
static void label_half_size(const char *txt, float size, double *hw, double *hh) {
    size_t n = strlen(txt);
    *hw = 0.5 * 0.58 * size * (double)n + 0.18 * size;
    *hh = 0.5 * 0.729 * size + 0.18 * size;
}

void pl_draw_isolines(pl_draw_list *dl, const pl_isolines *iso, const pl_isoline_style *st) {
    const pl_camera *cam = &dl->camera;
    pl_obstacles *avoid = st->avoid;
    for (int l = 0; l < iso->line_count; l++) {
        int a = iso->starts[l], b = iso->starts[l + 1], n = b - a;
        if (n < 2) continue;
        const pl_vec2 *pts = iso->points + a;
        if (!avoid) {
            if (iso->closed[l]) {
                pl_style s = pl_style_stroke(st->color, st->width);
                pl_dl_polygon(dl, PL_SPACE_WORLD, pts, n, &s);
            } else {
                pl_dl_polyline(dl, PL_SPACE_WORLD, pts, n, st->color, st->width);
            }
            continue;
        }
        /* split the line where it runs inside a body or wall: those pieces are not drawn */
        int segs = iso->closed[l] ? n : n - 1, run = -1;
        for (int i = 0; i <= segs; i++) {
            int inside = 1;
            if (i < segs) {
                pl_vec2 p = pl_camera_to_px(cam, pts[i]), q = pl_camera_to_px(cam, pts[(i + 1) % n]);
                inside = pl_obstacles_contain(avoid, (pl_vec2){0.5 * (p.x + q.x), 0.5 * (p.y + q.y)});
            }
            if (!inside && run < 0) run = i;
            if (inside && run >= 0) {
                int m = i - run + 1;
                if (run + m <= n) {
                    pl_dl_polyline(dl, PL_SPACE_WORLD, pts + run, m, st->color, st->width);
                } else { /* a closed loop's last piece wraps to the first point */
                    pl_dl_polyline(dl, PL_SPACE_WORLD, pts + run, n - run, st->color, st->width);
                    pl_vec2 w2[2] = {pts[n - 1], pts[0]};
                    pl_dl_polyline(dl, PL_SPACE_WORLD, w2, 2, st->color, st->width);
                }
                run = -1;
            }
        }
    }
    if (!(st->label_size > 0.0f)) return;
    if (avoid) { /* every line, sampled every 3 px, keeps other lines' labels off it */
        for (int l = 0; l < iso->line_count; l++) {
            int a = iso->starts[l], b = iso->starts[l + 1], n = b - a;
            int segs = iso->closed[l] ? n : n - 1;
            for (int i = 0; i < segs; i++) {
                pl_vec2 p = pl_camera_to_px(cam, iso->points[a + i]);
                pl_vec2 q = pl_camera_to_px(cam, iso->points[a + (i + 1) % n]);
                int k = (int)(hypot(q.x - p.x, q.y - p.y) / 3.0) + 1;
                for (int j = 0; j < k; j++) {
                    double t = (double)j / k;
                    pl_obstacles_add_point(avoid, (pl_vec2){p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)}, l);
                }
            }
        }
    }
    for (int l = 0; l < iso->line_count; l++) {
        int a = iso->starts[l], b = iso->starts[l + 1], n = b - a;
        if (n < 2) continue;
        const pl_vec2 *pts = iso->points + a;
        int segs = iso->closed[l] ? n : n - 1;
        double total = 0.0;
        for (int i = 0; i < segs; i++) {
            pl_vec2 p = pl_camera_to_px(cam, pts[i]), q = pl_camera_to_px(cam, pts[(i + 1) % n]);
            total += hypot(q.x - p.x, q.y - p.y);
        }
        if (total < 4.0 * st->label_size) continue;
        double spacing = st->label_spacing > 0.0 ? st->label_spacing : 280.0;
        int nlab = (int)(total / spacing);
        if (nlab < 1) nlab = 1;
        char txt[64];
        double level = iso->levels[l];
        if (fabs(level) < 1e-12) level = 0.0; /* never "-0" */
        snprintf(txt, sizeof txt, st->label_format ? st->label_format : "%g", level);
        double hw, hh;
        label_half_size(txt, st->label_size, &hw, &hh);
        /* stagger neighbouring lines (golden-ratio offsets) so labels do not form a column */
        double shift = fmod(0.618033988749895 * l, 1.0) - 0.5;
        for (int k = 0; k < nlab; k++) {
            double f0 = (k + 0.5 + 0.6 * shift) / nlab;
            if (f0 < 0.1) f0 = 0.1;
            if (f0 > 0.9) f0 = 0.9;
            /* candidates: the preferred place, then alternately either side of it; first
             * clear of grains too, then (a line through a packing, where no place is clear of
             * grains) over three or more grains, never over one or two isolated grains */
            int tries = avoid ? 25 : 1;
            int passes = avoid && avoid->grain_count > 0 ? 2 : 1, placed_any = 0;
            for (int pass = 0; pass < passes && !placed_any; pass++)
            for (int c = 0; c < tries && !placed_any; c++) {
                double f = f0 + (c % 2 ? 1 : -1) * ((c + 1) / 2) * (0.4 / nlab) / 12.0;
                if (f < 0.03 || f > 0.97) continue;
                double target = total * f, s = 0.0;
                int placed = 0, done = 0;
                for (int i = 0; i < segs && !done; i++) {
                    pl_vec2 p = pl_camera_to_px(cam, pts[i]), q = pl_camera_to_px(cam, pts[(i + 1) % n]);
                    double len = hypot(q.x - p.x, q.y - p.y);
                    if (s + len >= target && len > 0.0) {
                        double g = (target - s) / len;
                        pl_vec2 at = {p.x + g * (q.x - p.x), p.y + g * (q.y - p.y)};
                        /* screen angle, counter-clockwise, kept upright */
                        double ang = atan2(-(q.y - p.y), q.x - p.x);
                        if (ang > 1.5707963267948966) ang -= 3.141592653589793;
                        if (ang < -1.5707963267948966) ang += 3.141592653589793;
                        pl_label_box box = {at, hw, hh, ang};
                        done = 1;
                        if (avoid) {
                            int inside_clip = !dl->has_clip ||
                                (at.x - hw > dl->clip.x0 && at.x + hw < dl->clip.x1 &&
                                 at.y - hw > dl->clip.y0 && at.y + hw < dl->clip.y1);
                            if (!inside_clip || pl_obstacles_hit(avoid, box, 2.0, l)) break;
                            if (passes == 2) {
                                int g = pl_obstacles_grains(avoid, box, 2.0);
                                if (pass == 0 ? g > 0 : g < 3) break;
                            }
                            /* later labels keep a clear gap of 1.2 label sizes from this
                             * one, so labels of close lines do not pile up side by side */
                            pl_label_box keep = box;
                            keep.hw += 1.2 * st->label_size;
                            keep.hh += 1.2 * st->label_size;
                            pl_obstacles_add_box(avoid, keep);
                        }
                        pl_dl_text(dl, PL_SPACE_PIXEL, at, txt, st->label_size,
                                   PL_ANCHOR_CENTER | PL_ANCHOR_MIDDLE, (float)ang, st->color,
                                   &st->halo);
                        placed = 1;
                    }
                    s += len;
                }
                if (placed) placed_any = 1;
            }
        }
    }
}

/* ------------------------------------------------------------------ arrows */

int pl_draw_arrows(pl_draw_list *dl, const pl_vec2 *at, const pl_vec2 *vec, int n,
                   double scale, pl_rgba color, float width, double min_px) {
    int drawn = 0;
    double px_per_m = dl->camera.scale;
    for (int i = 0; i < n; i++) {
        double len = hypot(vec[i].x, vec[i].y) * scale;
        if (!(len * px_per_m >= min_px)) continue;
        pl_vec2 tip = {at[i].x + vec[i].x * scale, at[i].y + vec[i].y * scale};
        double head = 0.35 * len * px_per_m;
        if (head > 4.0 * width + 6.0) head = 4.0 * width + 6.0;
        pl_dl_arrow(dl, PL_SPACE_WORLD, at[i], tip, color, width, (float)head);
        drawn++;
    }
    return drawn;
}
