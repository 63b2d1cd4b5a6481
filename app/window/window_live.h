/* The window's live charts: the series a scene declares in render.live, sampled after each
 * of the scene's frames (after on_frame) and drawn in the control panel while it runs.
 *
 *   render = { live = {
 *     { title = "r_u, free field", range = { -0.5, 1.5 },     -- range optional (else fitted)
 *       series = { { name = "loose + water", color = "#1f77b4",
 *                    value = function(world) return ru or nil end }, ... } },
 *     ... } }
 *
 * At most PL_LIVE_MAX_CHARTS charts of PL_LIVE_MAX_SERIES series; a value function returning
 * nil skips that sample (e.g. before a reference is known). */
#ifndef PL_APP_WINDOW_LIVE_H
#define PL_APP_WINDOW_LIVE_H

#include "render/drawlist.h"
#include "scene.h"

#define PL_LIVE_MAX_CHARTS 2
#define PL_LIVE_MAX_SERIES 4

typedef struct pl_live_series {
    char name[48];
    pl_rgba color;
    double *t, *v;
    int n, cap;
} pl_live_series;

typedef struct pl_live_chart {
    char title[96];
    double lo, hi; /* fixed range when hi > lo */
    int nseries;
    pl_live_series s[PL_LIVE_MAX_SERIES];
} pl_live_chart;

typedef struct pl_live {
    int ncharts;
    pl_live_chart c[PL_LIVE_MAX_CHARTS];
    double t_end; /* the scene's run length (the time axis), s */
} pl_live;

/* Frees the samples and forgets the charts. */
void pl_live_free(pl_live *lv);
/* Reads the chart declarations of render.live (called after a scene is loaded; the samples
 * are dropped). Returns the chart count, or -1 with the message in pl_scene_error. */
int pl_live_declare(pl_live *lv, pl_scene *s, double t_end);
/* Samples every series at time t (drops samples at or after t first, so a rewind and its
 * replay leave one sample per time). Returns 0, or -1 with the message in pl_scene_error. */
int pl_live_sample(pl_live *lv, pl_scene *s, double t);
/* Drops the samples after time t (a rewind). */
void pl_live_truncate(pl_live *lv, double t);
/* Draws chart k into the pixel box {x0, y0, x1, y1}: frame, axes with ticks, the series
 * and their names. measure(ud, text, size) gives text widths in px. */
void pl_live_draw(const pl_live *lv, int k, pl_draw_list *dl, double x0, double y0, double x1,
                  double y1, double (*measure)(void *, const char *, float), void *ud);

#endif
