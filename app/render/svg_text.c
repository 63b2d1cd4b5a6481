/* SVG text: the text primitives of a draw list as <text> elements, appended to an SVG file
 * written by cairo (whose SVG surface only knows glyph outlines). */
#include "backend_cairo.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void put_escaped(FILE *f, const char *s) {
    for (; *s; s++) {
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f); break;
        }
    }
}

static int channel(float c) {
    int v = (int)lround(c * 255.0f);
    return v < 0 ? 0 : v > 255 ? 255 : v;
}

int pl_svg_append_text(const pl_draw_list *dl, const char *path, char *err, size_t errlen) {
    int n = 0;
    for (int i = 0; i < dl->prim_count; i++) n += dl->prims[i].kind == PL_PRIM_TEXT;
    if (n == 0) return 0;
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "cannot read back %s to add its text", path);
        return -1;
    }
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = len > 0 ? malloc((size_t)len + 1) : NULL;
    size_t got = buf ? fread(buf, 1, (size_t)len, f) : 0;
    fclose(f);
    if (!buf || got != (size_t)len) {
        free(buf);
        snprintf(err, errlen, "cannot read back %s to add its text", path);
        return -1;
    }
    buf[len] = 0;
    char *end = strstr(buf, "</svg>");
    if (!end) {
        free(buf);
        snprintf(err, errlen, "%s: no </svg> in cairo's output", path);
        return -1;
    }
    /* a scratch context with the drawing's font measures the strings as draw_text does */
    cairo_surface_t *scratch = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
    cairo_t *cr = cairo_create(scratch);
    cairo_font_face_t *ff = pl_cairo_font_face(err, errlen);
    if (!ff) {
        cairo_destroy(cr);
        cairo_surface_destroy(scratch);
        free(buf);
        return -1;
    }
    cairo_set_font_face(cr, ff);
    cairo_font_options_t *fo = cairo_font_options_create();
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_set_font_options(cr, fo);
    cairo_font_options_destroy(fo);
    f = fopen(path, "wb");
    int rc = 0;
    if (!f) {
        snprintf(err, errlen, "cannot write %s", path);
        rc = -1;
    } else {
        fwrite(buf, 1, (size_t)(end - buf), f);
        fputs("<g font-family=\"DejaVu Sans\" font-style=\"normal\" font-weight=\"normal\">\n", f);
        for (int i = 0; i < dl->prim_count; i++) {
            const pl_prim *p = &dl->prims[i];
            if (p->kind != PL_PRIM_TEXT) continue;
            const char *s = dl->text + p->text;
            pl_vec2 at = pl_dl_px(dl, p, dl->points[p->first]);
            double ox, oy;
            pl_cairo_text_origin(cr, p, s, &ox, &oy);
            fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"%.2f\" fill=\"rgb(%d,%d,%d)\"",
                    ox, oy, p->size, channel(p->fill.r), channel(p->fill.g), channel(p->fill.b));
            if (p->fill.a < 1.0f) fprintf(f, " fill-opacity=\"%.3f\"", p->fill.a);
            fprintf(f, " transform=\"translate(%.2f %.2f)", at.x, at.y);
            if (p->angle != 0.0f) fprintf(f, " rotate(%.3f)", -p->angle * 180.0 / M_PI);
            fputs("\" xml:space=\"preserve\">", f);
            put_escaped(f, s);
            fputs("</text>\n", f);
        }
        fputs("</g>\n", f);
        fputs(end, f);
        if (fclose(f) != 0) {
            snprintf(err, errlen, "cannot write %s", path);
            rc = -1;
        }
    }
    cairo_destroy(cr);
    cairo_surface_destroy(scratch);
    free(buf);
    return rc;
}
