/* Annotations: time stamp, title, scale bar, colour bar, material legend. All in pixels. */
#include "draw_world.h"
#include "isolines.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const pl_rgba ink = {0.13f, 0.13f, 0.15f, 1.0f};

float pl_render_font_size(int width, int height) {
    double m = width < height ? width : height, M = width < height ? height : width;
    /* a wide strip (1600 x 200) is shown scaled down to a page's width: its text follows the
     * long side too */
    double fs = fmax(m / 38.0, M / 80.0);
    if (fs < 11.0) fs = 11.0;
    if (fs > 30.0) fs = 30.0;
    return (float)fs;
}

void pl_draw_time_stamp(pl_draw_list *dl, pl_vec2 at, double t, float fs) {
    char buf[64];
    double a = fabs(t);
    if (a < 10.0) snprintf(buf, sizeof buf, "t = %.3f s", t);
    else if (a < 1000.0) snprintf(buf, sizeof buf, "t = %.2f s", t);
    else snprintf(buf, sizeof buf, "t = %.6g s", t);
    pl_dl_text(dl, PL_SPACE_PIXEL, at, buf, fs, PL_ANCHOR_LEFT | PL_ANCHOR_MIDDLE, 0.0f, ink, NULL);
}

void pl_draw_title(pl_draw_list *dl, pl_vec2 at, const char *title, float fs) {
    pl_dl_text(dl, PL_SPACE_PIXEL, at, title, 1.15f * fs, PL_ANCHOR_CENTER | PL_ANCHOR_MIDDLE,
               0.0f, ink, NULL);
}

void pl_draw_scale_bar(pl_draw_list *dl, pl_vec2 left, double max_px, float fs) {
    double scale = dl->camera.scale;
    if (!(scale > 0.0) || !(max_px > 0.0)) return;
    double target = 0.2 * max_px / scale; /* metres */
    double len = pl_nice_number(target, 1);
    double px = len * scale;
    if (px > 0.45 * max_px) { /* never wider than about half the plot */
        len = pl_nice_number(0.5 * len, 1);
        px = len * scale;
    }
    char buf[64];
    if (len < 0.01) snprintf(buf, sizeof buf, "%g mm", len * 1000.0);
    else if (len < 1.0) snprintf(buf, sizeof buf, "%g cm", len * 100.0);
    else if (len < 1000.0) snprintf(buf, sizeof buf, "%g m", len);
    else snprintf(buf, sizeof buf, "%g km", len / 1000.0);
    double x0 = left.x, x1 = left.x + px, y = left.y;
    double tick = 0.35 * fs;
    pl_vec2 bar[4] = {{x0, y - tick}, {x0, y}, {x1, y}, {x1, y - tick}};
    pl_dl_polyline(dl, PL_SPACE_PIXEL, bar, 4, ink, 2.0f);
    pl_vec2 at = {0.5 * (x0 + x1), y - 0.45 * fs};
    pl_dl_text(dl, PL_SPACE_PIXEL, at, buf, 0.9f * fs, PL_ANCHOR_CENTER | PL_ANCHOR_BOTTOM, 0.0f,
               ink, NULL);
}

/* Digits after the decimal point needed to print multiples of step exactly. */
static int decimals_for(double step) {
    int d = 0;
    while (d < 6) {
        double m = step * pow(10.0, d);
        if (fabs(m - floor(m + 0.5)) < 1e-6 * (m > 1.0 ? m : 1.0)) break;
        d++;
    }
    return d;
}

void pl_draw_colorbar(pl_draw_list *dl, pl_px_rect r, pl_colormap map, double vmin, double vmax,
                      const char *label, float fs) {
    if (!(r.x1 > r.x0) || !(r.y1 > r.y0)) return;
    if (!(vmax > vmin)) vmax = vmin + (vmin != 0.0 ? fabs(vmin) * 1e-6 : 1.0);
    const int slices = 48;
    pl_dl_triangles_begin(dl, PL_SPACE_PIXEL);
    for (int i = 0; i < slices; i++) {
        double t0 = (double)i / slices, t1 = (double)(i + 1) / slices;
        double y0 = r.y1 - t0 * (r.y1 - r.y0), y1 = r.y1 - t1 * (r.y1 - r.y0);
        pl_rgba c0 = pl_colormap_eval(map, t0), c1 = pl_colormap_eval(map, t1);
        pl_vec2 a[3] = {{r.x0, y0}, {r.x1, y0}, {r.x1, y1}};
        pl_rgba ca[3] = {c0, c0, c1};
        pl_vec2 b[3] = {{r.x0, y0}, {r.x1, y1}, {r.x0, y1}};
        pl_rgba cb[3] = {c0, c1, c1};
        pl_dl_triangle_add(dl, a, ca);
        pl_dl_triangle_add(dl, b, cb);
    }
    pl_vec2 box[4] = {{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}};
    pl_style st = pl_style_stroke(ink, 1.0f);
    pl_dl_polygon(dl, PL_SPACE_PIXEL, box, 4, &st);
    double ticks[32], step = 0.0;
    int nt = pl_nice_levels(vmin, vmax, 5, ticks + 1, 30, &step);
    /* ends count as ticks too when they are round numbers */
    int n = 0;
    double all[34];
    if (step > 0.0 && fabs(vmin / step - floor(vmin / step + 0.5)) < 1e-9) all[n++] = vmin;
    for (int i = 0; i < nt; i++) all[n++] = ticks[i + 1];
    if (step > 0.0 && fabs(vmax / step - floor(vmax / step + 0.5)) < 1e-9) all[n++] = vmax;
    int dec = decimals_for(step > 0.0 ? step : 1.0);
    double tick_len = 0.3 * fs;
    for (int i = 0; i < n; i++) {
        double y = r.y1 - (all[i] - vmin) / (vmax - vmin) * (r.y1 - r.y0);
        pl_dl_line(dl, PL_SPACE_PIXEL, (pl_vec2){r.x1, y}, (pl_vec2){r.x1 + tick_len, y}, ink, 1.0f);
        char buf[48];
        double v = all[i];
        /* ticks are multiples of the step: a tick within a millionth of a step of zero is
         * zero, and a printed "-0", "-0.0" loses its sign */
        if (step > 0.0 && fabs(v) < 1e-6 * step) v = 0.0;
        snprintf(buf, sizeof buf, "%.*f", dec, v);
        if (buf[0] == '-' && strspn(buf + 1, "0.") == strlen(buf + 1)) memmove(buf, buf + 1, strlen(buf));
        pl_dl_text(dl, PL_SPACE_PIXEL, (pl_vec2){r.x1 + tick_len + 0.3 * fs, y}, buf, 0.85f * fs,
                   PL_ANCHOR_LEFT | PL_ANCHOR_MIDDLE, 0.0f, ink, NULL);
    }
    if (label && *label)
        pl_dl_text(dl, PL_SPACE_PIXEL, (pl_vec2){r.x0, r.y0 - 0.6 * fs}, label, 0.9f * fs,
                   PL_ANCHOR_LEFT | PL_ANCHOR_BASELINE, 0.0f, ink, NULL);
}

void pl_draw_material_legend(pl_draw_list *dl, pl_vec2 at, const char (*names)[48],
                             const pl_rgba *colors, int n, float fs) {
    double y = at.y + 0.5 * fs;
    pl_dl_text(dl, PL_SPACE_PIXEL, (pl_vec2){at.x, at.y}, "material", 0.9f * fs,
               PL_ANCHOR_LEFT | PL_ANCHOR_TOP, 0.0f, ink, NULL);
    y += 1.3 * fs;
    for (int i = 0; i < n; i++) {
        pl_style st = pl_style_fill_stroke(colors[i], pl_rgba_scale(colors[i], 0.5), 1.0f);
        pl_dl_circle(dl, PL_SPACE_PIXEL, (pl_vec2){at.x + 0.5 * fs, y}, 0.45 * fs, &st);
        pl_dl_text(dl, PL_SPACE_PIXEL, (pl_vec2){at.x + 1.4 * fs, y}, names[i], 0.85f * fs,
                   PL_ANCHOR_LEFT | PL_ANCHOR_MIDDLE, 0.0f, ink, NULL);
        y += 1.4 * fs;
    }
}
