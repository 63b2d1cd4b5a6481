/// XY charts (time series, profiles, analytic curves beside measured points, benchmark
/// speed-versus-accuracy) drawn with PLplot through its cairo "extcairo" device onto a cairo
/// surface of ours, so charts go to PNG (our libpng writer), SVG and PDF by the same code as
/// frames. Needs libplplot-dev and plplot-driver-cairo.
#ifndef PORELAB_CHARTS_H
#define PORELAB_CHARTS_H

#include <stddef.h>
#include "render.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum pl_series_style {
    PL_SERIES_LINE = 0,        ///< solid line
    PL_SERIES_POINTS = 1,      ///< markers only (open circles)
    PL_SERIES_LINE_POINTS = 2, ///< line with markers
    PL_SERIES_DASHED = 3       ///< dashed line (e.g. an analytic reference)
} pl_series_style;

typedef struct pl_chart_series {
    const char *name;      ///< legend text; NULL or "" = not in the legend
    const double *x, *y;   ///< n values each (non-finite points are skipped)
    int n;
    pl_series_style style;
    pl_rgba color;         ///< alpha 0 = automatic colour from the chart palette
    double line_width;     ///< px; 0 = 2
} pl_chart_series;

#define PL_CHART_MAX_SERIES 12

typedef struct pl_chart_def {
    int width, height;     ///< px (1 px = 1 pt for SVG/PDF); default 800 x 560
    const char *title;     ///< may be NULL
    const char *xlabel;    ///< with unit, e.g. "time (s)"
    const char *ylabel;    ///< with unit, e.g. "settlement (mm)"
    const pl_chart_series *series;
    int series_count;      ///< 1..PL_CHART_MAX_SERIES
    double xmin, xmax, ymin, ymax; ///< axis ranges; max <= min = automatic (data + 5 %)
    int logx, logy;        ///< logarithmic axes (data must be > 0)
    int legend;            ///< 0 none, 1 top right (default), 2 top left, 3 bottom right, 4 bottom left
    int grid;              ///< 1 draws light grid lines at major ticks (default 1)
} pl_chart_def;

pl_chart_def pl_default_chart_def(void);

/// Plain maths in chart text to PLplot's escape sequences, for labels written once for both
/// markdown and charts: a subscript after a symbol of one or two letters (`T_v`, `Re_p`,
/// `v_{out}`; at most 3 characters without braces) becomes `T#dv#u`, an exponent (`m^2`,
/// `s^-1`) `m#u2#d`, `<=` and `>=` become ≤ and ≥, and a literal `#` becomes `##`. Anything
/// else is copied. Writes at most n bytes (NUL-terminated) and returns the length the whole
/// result needs, as snprintf.
size_t pl_chart_text(const char *in, char *out, size_t n);

/// Draws the chart to path (.png, .svg or .pdf). Returns 0, or -1 with a message (bad
/// definition, unknown extension, PLplot or its cairo driver missing, write error).
int pl_chart_write(const char *path, const pl_chart_def *def, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
