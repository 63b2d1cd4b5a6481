/* XY charts with PLplot: PNG and PDF drawn onto our own cairo surface (extcairo device);
 * SVG by PLplot's own svg device, which writes the text as <text> elements (cairo 1.16's SVG
 * surface only writes glyph outlines). PLplot keeps global state, so charts are made one at
 * a time under a mutex, each in its own stream. */
#define _POSIX_C_SOURCE 200809L
#include "charts.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <math.h>
#include <plplot.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"
#include "backend_cairo.h"

static pthread_mutex_t chart_lock = PTHREAD_MUTEX_INITIALIZER;

pl_chart_def pl_default_chart_def(void) {
    pl_chart_def d;
    memset(&d, 0, sizeof d);
    d.width = 800;
    d.height = 560;
    d.legend = 1;
    d.grid = 1;
    return d;
}

/* Chart palette: distinguishable, colour-blind aware, dark enough on white. */
static const uint32_t palette[PL_CHART_MAX_SERIES] = {
    0x1F5FA8, 0xC8384B, 0x2E8B57, 0xE08E1B, 0x6B4C9A, 0x2A9D9D,
    0x8C564B, 0x555555, 0xB5489C, 0x7A8B1F, 0x3D3D9E, 0xA05A2C};

enum { COL_BG = 0, COL_INK = 1, COL_GRID = 2, COL_SERIES = 3 };

static int to_byte(double v) {
    int b = (int)floor(v * 255.0 + 0.5);
    return b < 0 ? 0 : (b > 255 ? 255 : b);
}

static int check_def(const pl_chart_def *d, char *err, size_t errlen) {
    if (d->width < 64 || d->height < 64 || d->width > 16384 || d->height > 16384) {
        snprintf(err, errlen, "chart size %dx%d is out of range (64..16384)", d->width, d->height);
        return -1;
    }
    if (d->series_count < 1 || d->series_count > PL_CHART_MAX_SERIES || !d->series) {
        snprintf(err, errlen, "a chart needs 1..%d series (got %d)", PL_CHART_MAX_SERIES,
                 d->series_count);
        return -1;
    }
    for (int s = 0; s < d->series_count; s++) {
        const pl_chart_series *se = &d->series[s];
        if (se->n < 0 || (se->n > 0 && (!se->x || !se->y))) {
            snprintf(err, errlen, "chart series %d (%s) has no data arrays", s + 1,
                     se->name ? se->name : "unnamed");
            return -1;
        }
    }
    return 0;
}

/* Axis range from the data (or the definition), transformed for log axes. */
static int axis_range(const pl_chart_def *d, int axis, double *lo, double *hi, char *err,
                      size_t errlen) {
    int logax = axis == 0 ? d->logx : d->logy;
    double dmin = axis == 0 ? d->xmin : d->ymin, dmax = axis == 0 ? d->xmax : d->ymax;
    if (dmax > dmin) {
        if (logax && !(dmin > 0.0)) {
            snprintf(err, errlen, "logarithmic %s axis needs a positive minimum", axis ? "y" : "x");
            return -1;
        }
        *lo = logax ? log10(dmin) : dmin;
        *hi = logax ? log10(dmax) : dmax;
        return 0;
    }
    double a = INFINITY, b = -INFINITY;
    for (int s = 0; s < d->series_count; s++) {
        const pl_chart_series *se = &d->series[s];
        for (int i = 0; i < se->n; i++) {
            double v = axis == 0 ? se->x[i] : se->y[i];
            if (!isfinite(se->x[i]) || !isfinite(se->y[i])) continue;
            if (logax) {
                if (!(v > 0.0)) continue;
                v = log10(v);
            }
            if (v < a) a = v;
            if (v > b) b = v;
        }
    }
    if (!isfinite(a)) {
        snprintf(err, errlen, "the chart has no finite%s data on the %s axis",
                 logax ? " positive" : "", axis ? "y" : "x");
        return -1;
    }
    if (b <= a) {
        double pad = a != 0.0 ? 0.1 * fabs(a) : 1.0;
        a -= pad;
        b += pad;
    } else if (!logax || axis == 1) {
        double pad = 0.05 * (b - a);
        if (axis == 0 && !logax) pad = 0.0; /* x: data to the edges, as usual for series */
        a -= pad;
        b += pad;
    }
    *lo = a;
    *hi = b;
    return 0;
}

/* cr: draw onto this cairo context (extcairo); else svg_path: PLplot's svg device writes it */
static void draw_chart(const pl_chart_def *d, cairo_t *cr, const char *svg_path, double xlo,
                       double xhi, double ylo, double yhi) {
    PLINT strm;
    plmkstrm(&strm);
    if (cr) {
        plsdev("extcairo");
    } else {
        plsdev("svg");
        plsfnam(svg_path);
    }
    plspage(72.0, 72.0, d->width, d->height, 0, 0);
    plscol0(COL_BG, 255, 255, 255);
    plscol0(COL_INK, 34, 34, 38);
    plscol0(COL_GRID, 222, 222, 226);
    for (int s = 0; s < d->series_count; s++) {
        const pl_chart_series *se = &d->series[s];
        int r, g, b;
        if (se->color.a > 0.0f) {
            r = to_byte(se->color.r);
            g = to_byte(se->color.g);
            b = to_byte(se->color.b);
        } else {
            uint32_t c = palette[s % PL_CHART_MAX_SERIES];
            r = (int)(c >> 16) & 255;
            g = (int)(c >> 8) & 255;
            b = (int)c & 255;
        }
        plscol0(COL_SERIES + s, r, g, b);
    }
    plinit();
    if (cr) pl_cmd(PLESC_DEVINIT, cr);
    pladv(0);
    /* character height scales with the chart: about 1/40 of its smaller side */
    double side_mm = (d->width < d->height ? d->width : d->height) * 25.4 / 72.0;
    double ch = side_mm / 54.0;
    plschr(ch, 1.0);
    plssym(ch * 0.9, 1.0);
    double has_title = d->title && *d->title;
    plvpor(0.12, 0.96, 0.12, has_title ? 0.90 : 0.95);
    plwind(xlo, xhi, ylo, yhi);
    const char *xo = d->logx ? "bcnstl" : "bcnst";
    const char *yo = d->logy ? "bcnstvl" : "bcnstv";
    if (d->grid) {
        plcol0(COL_GRID);
        plwidth(1.0);
        plbox(d->logx ? "gl" : "g", 0.0, 0, d->logy ? "gl" : "g", 0.0, 0);
    }
    plcol0(COL_INK);
    plwidth(1.2);
    plbox(xo, 0.0, 0, yo, 0.0, 0);
    pllab(d->xlabel ? d->xlabel : "", d->ylabel ? d->ylabel : "", "");
    if (has_title) {
        plschr(ch, 1.2);
        plmtex("t", 1.6, 0.5, 0.5, d->title);
        plschr(ch, 1.0);
    }
    int maxn = 0;
    for (int s = 0; s < d->series_count; s++)
        if (d->series[s].n > maxn) maxn = d->series[s].n;
    PLFLT *xs = malloc((size_t)(maxn > 0 ? maxn : 1) * sizeof *xs);
    PLFLT *ys = malloc((size_t)(maxn > 0 ? maxn : 1) * sizeof *ys);
    for (int s = 0; s < d->series_count && xs && ys; s++) {
        const pl_chart_series *se = &d->series[s];
        plcol0(COL_SERIES + s);
        plwidth(se->line_width > 0.0 ? se->line_width : 2.0);
        pllsty(se->style == PL_SERIES_DASHED ? 2 : 1);
        /* runs of finite points become separate line pieces */
        int i = 0;
        while (i < se->n) {
            int m = 0;
            while (i < se->n) {
                double x = se->x[i], y = se->y[i];
                int ok = isfinite(x) && isfinite(y) && (!d->logx || x > 0.0) && (!d->logy || y > 0.0);
                i++;
                if (!ok) break;
                xs[m] = d->logx ? log10(x) : x;
                ys[m] = d->logy ? log10(y) : y;
                m++;
            }
            if (m == 0) continue;
            if (se->style != PL_SERIES_POINTS && m > 1) plline(m, xs, ys);
            if (se->style == PL_SERIES_POINTS || se->style == PL_SERIES_LINE_POINTS) {
                pllsty(1);
                plwidth(1.5);
                plstring(m, xs, ys, "\xe2\x97\x8b"); /* U+25CB white circle */
                plwidth(se->line_width > 0.0 ? se->line_width : 2.0);
            }
        }
    }
    pllsty(1);
    free(xs);
    free(ys);
    if (d->legend > 0) {
        PLINT opts[PL_CHART_MAX_SERIES], tcol[PL_CHART_MAX_SERIES], lcol[PL_CHART_MAX_SERIES];
        PLINT lsty[PL_CHART_MAX_SERIES], scol[PL_CHART_MAX_SERIES], snum[PL_CHART_MAX_SERIES];
        PLFLT lw[PL_CHART_MAX_SERIES], ssc[PL_CHART_MAX_SERIES];
        const char *text[PL_CHART_MAX_SERIES], *sym[PL_CHART_MAX_SERIES];
        int n = 0;
        for (int s = 0; s < d->series_count; s++) {
            const pl_chart_series *se = &d->series[s];
            if (!se->name || !*se->name) continue;
            opts[n] = se->style == PL_SERIES_POINTS ? PL_LEGEND_SYMBOL
                      : se->style == PL_SERIES_LINE_POINTS ? (PL_LEGEND_LINE | PL_LEGEND_SYMBOL)
                                                           : PL_LEGEND_LINE;
            tcol[n] = COL_INK;
            lcol[n] = scol[n] = COL_SERIES + s;
            lsty[n] = se->style == PL_SERIES_DASHED ? 2 : 1;
            lw[n] = se->line_width > 0.0 ? se->line_width : 2.0;
            ssc[n] = 1.0;
            snum[n] = 1;
            text[n] = se->name;
            sym[n] = "\xe2\x97\x8b";
            n++;
        }
        if (n > 0) {
            PLINT pos = PL_POSITION_INSIDE;
            pos |= (d->legend == 2 || d->legend == 4) ? PL_POSITION_LEFT : PL_POSITION_RIGHT;
            pos |= (d->legend == 3 || d->legend == 4) ? PL_POSITION_BOTTOM : PL_POSITION_TOP;
            PLFLT lw_out, lh_out;
            pllegend(&lw_out, &lh_out, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, pos, 0.02,
                     0.03, 0.08, COL_BG, COL_GRID, 1, 0, 0, n, opts, 0.8, 0.9, 2.0, 0.0, tcol,
                     (const char *const *)text, NULL, NULL, NULL, NULL, lcol, lsty, lw, scol, ssc,
                     snum, (const char *const *)sym);
        }
    }
    plend1();
}

int pl_chart_write(const char *path, const pl_chart_def *def, char *err, size_t errlen) {
    int fmt = pl_file_format(path);
    if (fmt < 0) {
        snprintf(err, errlen, "%s: unknown chart format (valid extensions: .png, .svg, .pdf)", path);
        return -1;
    }
    if (check_def(def, err, errlen)) return -1;
    double xlo, xhi, ylo, yhi;
    if (axis_range(def, 0, &xlo, &xhi, err, errlen) || axis_range(def, 1, &ylo, &yhi, err, errlen))
        return -1;
    /* PLplot's cairo driver picks fonts through fontconfig; ask for DejaVu Sans. */
    setenv("PLPLOT_FREETYPE_SANS_FAMILY", "DejaVu Sans", 0);
    cairo_surface_t *surf;
    int W = def->width, H = def->height;
    /* SVG/PDF: cairo writes a temporary that is renamed into place when complete; PNG:
       pl_png_write does the same */
    pl_atomic_file af;
    af.tmp_path[0] = '\0';
    if (fmt != 0 && pl_atomic_file_begin(&af, path, err, errlen)) return -1;
    if (fmt == 1) { /* PLplot's svg device: real text */
        pthread_mutex_lock(&chart_lock);
        draw_chart(def, NULL, af.tmp_path, xlo, xhi, ylo, yhi);
        pthread_mutex_unlock(&chart_lock);
        FILE *f = fopen(af.tmp_path, "rb");
        long n = -1;
        if (f) {
            fseek(f, 0, SEEK_END);
            n = ftell(f);
            fclose(f);
        }
        if (n <= 0) snprintf(err, errlen, "cannot write %s: PLplot's svg device wrote nothing", path);
        return pl_atomic_file_end(&af, n > 0, err, errlen) != 0 || n <= 0 ? -1 : 0;
    }
    if (fmt == 0) surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, W, H);
    else if (fmt == 1) surf = cairo_svg_surface_create(af.tmp_path, W, H);
    else surf = cairo_pdf_surface_create(af.tmp_path, W, H);
    if (cairo_surface_status(surf) != CAIRO_STATUS_SUCCESS) {
        snprintf(err, errlen, "cannot write %s: %s", path,
                 cairo_status_to_string(cairo_surface_status(surf)));
        cairo_surface_destroy(surf);
        if (fmt != 0) pl_atomic_file_end(&af, 0, err, errlen);
        return -1;
    }
    if (fmt == 2) {
        cairo_pdf_surface_set_metadata(surf, CAIRO_PDF_METADATA_CREATOR, "porelab");
        cairo_pdf_surface_set_metadata(surf, CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00Z");
    }
    cairo_t *cr = cairo_create(surf);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    pthread_mutex_lock(&chart_lock);
    draw_chart(def, cr, NULL, xlo, xhi, ylo, yhi);
    pthread_mutex_unlock(&chart_lock);
    int rc = 0;
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
        snprintf(err, errlen, "drawing the chart failed: %s", cairo_status_to_string(cairo_status(cr)));
        rc = -1;
    }
    cairo_destroy(cr);
    if (rc == 0 && fmt == 0) {
        cairo_surface_flush(surf);
        pl_image img = {W, H, malloc((size_t)W * (size_t)H * 4u)};
        if (!img.rgba) {
            snprintf(err, errlen, "out of memory");
            rc = -1;
        } else {
            const unsigned char *data = cairo_image_surface_get_data(surf);
            int stride = cairo_image_surface_get_stride(surf);
            for (int y = 0; y < H; y++) {
                const uint32_t *row = (const uint32_t *)(const void *)(data + (size_t)y * (size_t)stride);
                for (int x = 0; x < W; x++) {
                    uint32_t v = row[x]; /* opaque: background painted white */
                    uint8_t *o = img.rgba + ((size_t)y * (size_t)W + (size_t)x) * 4u;
                    o[0] = (uint8_t)(v >> 16);
                    o[1] = (uint8_t)(v >> 8);
                    o[2] = (uint8_t)v;
                    o[3] = 255;
                }
            }
            rc = pl_png_write(path, &img, 6, 1, err, errlen);
            pl_image_free(&img);
        }
    }
    cairo_surface_finish(surf);
    if (rc == 0 && cairo_surface_status(surf) != CAIRO_STATUS_SUCCESS) {
        snprintf(err, errlen, "cannot write %s: %s", path,
                 cairo_status_to_string(cairo_surface_status(surf)));
        rc = -1;
    }
    cairo_surface_destroy(surf);
    if (fmt != 0) rc = pl_atomic_file_end(&af, rc == 0, err, errlen);
    return rc;
}
