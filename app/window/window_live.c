/* Live charts of the window (see window_live.h). */
#include "window_live.h"

#include <lauxlib.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lua_util.h"
#include "render/isolines.h"
#include "scene_render.h"

static const char *const chart_fields[] = {"title", "range", "series", NULL};
static const char *const series_fields[] = {"name", "color", "value", NULL};
/* the chart palette (colour-blind safe, as the PLplot charts) */
static const unsigned palette[PL_LIVE_MAX_SERIES] = {0x1F77B4, 0xD62728, 0x2CA02C, 0x9467BD};

void pl_live_free(pl_live *lv)
{
    for (int k = 0; k < lv->ncharts; k++)
        for (int i = 0; i < lv->c[k].nseries; i++) {
            free(lv->c[k].s[i].t);
            free(lv->c[k].s[i].v);
        }
    memset(lv, 0, sizeof *lv);
}

typedef struct live_ctx {
    pl_live *lv;
    pl_scene *s;
    int declare;
    double t;
} live_ctx;

static int push_sample(pl_live_series *q, double t, double v)
{
    if (q->n == q->cap) {
        int c = q->cap ? 2 * q->cap : 256;
        double *a = realloc(q->t, (size_t)c * sizeof *a);
        if (!a) return -1;
        q->t = a;
        double *b = realloc(q->v, (size_t)c * sizeof *b);
        if (!b) return -1;
        q->v = b;
        q->cap = c;
    }
    q->t[q->n] = t;
    q->v[q->n] = v;
    q->n++;
    return 0;
}

static void read_chart(lua_State *L, live_ctx *c, int k, int t)
{
    char what[64];
    snprintf(what, sizeof what, "render: live[%d]", k + 1);
    if (!lua_istable(L, t)) luaL_error(L, "%s must be a table {title = ..., series = {...}}", what);
    pl_lua_check_fields(L, t, what, chart_fields);
    pl_live_chart *ch = &c->lv->c[k];
    if (c->declare) {
        snprintf(ch->title, sizeof ch->title, "%s", pl_lua_field_string(L, t, what, "title", ""));
        if (pl_lua_has_field(L, t, "range")) {
            pl_vec2 r = pl_lua_field_vec2(L, t, what, "range", (pl_vec2){0, 0});
            if (!(isfinite(r.x) && isfinite(r.y) && r.y > r.x))
                luaL_error(L, "%s: range must be {lo, hi} with finite lo < hi", what);
            ch->lo = r.x;
            ch->hi = r.y;
        }
    }
    if (lua_getfield(L, t, "series") != LUA_TTABLE)
        luaL_error(L, "%s: series must be a list of {name = ..., value = function(world)}", what);
    int list = lua_gettop(L);
    int n = (int)luaL_len(L, list);
    if (n < 1 || n > PL_LIVE_MAX_SERIES) luaL_error(L, "%s: series must hold 1..%d entries (got %d)", what,
                                                    PL_LIVE_MAX_SERIES, n);
    if (c->declare) ch->nseries = n;
    for (int i = 0; i < n && i < ch->nseries; i++) {
        char sw[96];
        snprintf(sw, sizeof sw, "%s.series[%d]", what, i + 1);
        lua_geti(L, list, i + 1);
        int e = lua_gettop(L);
        if (!lua_istable(L, e)) luaL_error(L, "%s must be a table", sw);
        pl_live_series *q = &ch->s[i];
        if (c->declare) {
            pl_lua_check_fields(L, e, sw, series_fields);
            snprintf(q->name, sizeof q->name, "%s", pl_lua_field_string(L, e, sw, "name", ""));
            q->color = pl_rgb_hex(palette[i]);
            if (lua_getfield(L, e, "color") != LUA_TNIL) {
                char cw[112];
                snprintf(cw, sizeof cw, "%s: color", sw);
                q->color = pl_scene_render_color(L, lua_gettop(L), cw);
            }
            lua_pop(L, 1);
            if (lua_getfield(L, e, "value") != LUA_TFUNCTION)
                luaL_error(L, "%s: value must be a function(world) returning a number or nil", sw);
            lua_pop(L, 1);
        } else {
            lua_getfield(L, e, "value");
            pl_scene_push_result_field(c->s, "world");
            lua_call(L, 1, 1);
            if (!lua_isnil(L, -1)) {
                if (!lua_isnumber(L, -1))
                    luaL_error(L, "%s: value returned %s (a number or nil expected)", sw, luaL_typename(L, -1));
                double v = lua_tonumber(L, -1);
                if (isfinite(v) && push_sample(q, c->t, v) != 0) luaL_error(L, "out of memory (live chart)");
            }
            lua_pop(L, 1);
        }
        lua_settop(L, list);
    }
    lua_pop(L, 1);
}

static int read_live(lua_State *L)
{
    live_ctx *c = lua_touserdata(L, 1);
    if (lua_isnil(L, 2) || lua_getfield(L, 2, "live") == LUA_TNIL) return 0;
    int list = lua_gettop(L);
    if (!lua_istable(L, list)) return luaL_error(L, "render: live must be a list of charts (got %s)", luaL_typename(L, list));
    int n = (int)luaL_len(L, list);
    if (n > PL_LIVE_MAX_CHARTS) return luaL_error(L, "render: live holds at most %d charts (got %d)", PL_LIVE_MAX_CHARTS, n);
    if (c->declare) c->lv->ncharts = n;
    for (int k = 0; k < n && k < c->lv->ncharts; k++) {
        lua_geti(L, list, k + 1);
        read_chart(L, c, k, lua_gettop(L));
        lua_settop(L, list);
    }
    return 0;
}

int pl_live_declare(pl_live *lv, pl_scene *s, double t_end)
{
    pl_live_free(lv);
    lv->t_end = t_end;
    live_ctx c = {lv, s, 1, 0.0};
    if (pl_scene_read_field(s, "render", read_live, &c) != 0) {
        pl_live_free(lv);
        return -1;
    }
    return lv->ncharts;
}

void pl_live_truncate(pl_live *lv, double t)
{
    for (int k = 0; k < lv->ncharts; k++)
        for (int i = 0; i < lv->c[k].nseries; i++) {
            pl_live_series *q = &lv->c[k].s[i];
            while (q->n > 0 && q->t[q->n - 1] > t) q->n--;
        }
}

int pl_live_sample(pl_live *lv, pl_scene *s, double t)
{
    if (lv->ncharts == 0) return 0;
    for (int k = 0; k < lv->ncharts; k++)
        for (int i = 0; i < lv->c[k].nseries; i++) {
            pl_live_series *q = &lv->c[k].s[i];
            while (q->n > 0 && q->t[q->n - 1] >= t) q->n--;
        }
    live_ctx c = {lv, s, 0, t};
    return pl_scene_read_field(s, "render", read_live, &c);
}

/* Tick label without "-0" and with the digits the step needs. */
static void tick_label(char *out, size_t n, double v, double step)
{
    if (fabs(v) < 1e-9 * step) v = 0;
    int dec = step >= 1 ? 0 : (int)ceil(-log10(step) - 1e-9);
    if (dec > 6) dec = 6;
    snprintf(out, n, "%.*f", dec, v);
    if (strcmp(out, "-0") == 0 || (out[0] == '-' && strspn(out + 1, "0.") == strlen(out + 1))) memmove(out, out + 1, strlen(out));
}

void pl_live_draw(const pl_live *lv, int k, pl_draw_list *dl, double x0, double y0, double x1,
                  double y1, double (*measure)(void *, const char *, float), void *ud)
{
    if (k < 0 || k >= lv->ncharts) return;
    const pl_live_chart *ch = &lv->c[k];
    const pl_rgba ink = pl_rgb(0.95, 0.95, 0.92), grid = pl_rgb(0.32, 0.32, 0.36);
    const float fs = 11.0f;
    /* the range: fixed, else fitted to all samples (never shrinking within a sample set) */
    double lo = ch->lo, hi = ch->hi;
    if (!(hi > lo)) {
        lo = INFINITY;
        hi = -INFINITY;
        for (int i = 0; i < ch->nseries; i++)
            for (int j = 0; j < ch->s[i].n; j++) {
                lo = fmin(lo, ch->s[i].v[j]);
                hi = fmax(hi, ch->s[i].v[j]);
            }
        if (!(hi >= lo)) { lo = 0; hi = 1; }
        if (lo > 0) lo = 0; /* one-signed values from zero */
        if (hi - lo < 1e-12) hi = lo + 1;
        double pad = 0.05 * (hi - lo);
        hi += pad;
        if (lo < 0) lo -= pad;
    }
    double ta = 0, tb = lv->t_end > 0 ? lv->t_end : 1;
    for (int i = 0; i < ch->nseries; i++)
        if (ch->s[i].n > 0 && ch->s[i].t[ch->s[i].n - 1] > tb) tb = ch->s[i].t[ch->s[i].n - 1];
    /* title, legend rows, then the plot box with the tick labels left and below */
    double y = y0;
    pl_dl_text(dl, PL_SPACE_PIXEL, (pl_vec2){x0, y + 0.65 * fs}, ch->title, fs + 1.0f,
               PL_ANCHOR_LEFT | PL_ANCHOR_MIDDLE, 0.0f, pl_rgb(0.65, 0.78, 1.0), NULL);
    y += 1.4 * fs;
    for (int i = 0; i < ch->nseries; i++) {
        const pl_live_series *q = &ch->s[i];
        pl_dl_line(dl, PL_SPACE_PIXEL, (pl_vec2){x0, y + 0.6 * fs}, (pl_vec2){x0 + 14, y + 0.6 * fs}, q->color, 2.5f);
        char l[96];
        if (q->n > 0) snprintf(l, sizeof l, "%s: %.3g", q->name, q->v[q->n - 1]);
        else snprintf(l, sizeof l, "%s", q->name);
        pl_dl_text(dl, PL_SPACE_PIXEL, (pl_vec2){x0 + 19, y + 0.6 * fs}, l, fs, PL_ANCHOR_LEFT | PL_ANCHOR_MIDDLE,
                   0.0f, ink, NULL);
        y += 1.25 * fs;
    }
    double step = 0, ticks[16];
    int nt = pl_nice_levels(lo, hi, 4, ticks, 16, &step);
    double lw = 0;
    char l[48];
    for (int i = 0; i < nt; i++) {
        tick_label(l, sizeof l, ticks[i], step);
        double w = measure ? measure(ud, l, fs) : 0.6 * fs * strlen(l);
        if (w > lw) lw = w;
    }
    double bx0 = x0 + lw + 5, bx1 = x1, by0 = y + 4, by1 = y1 - 1.4 * fs;
    if (by1 - by0 < 20 || bx1 - bx0 < 40) return;
    pl_vec2 box[4] = {{bx0, by0}, {bx1, by0}, {bx1, by1}, {bx0, by1}};
    pl_style bg = pl_style_fill_stroke(pl_rgb(0.08, 0.08, 0.10), pl_rgb(0.55, 0.55, 0.6), 1.0f);
    pl_dl_polygon(dl, PL_SPACE_PIXEL, box, 4, &bg);
#define PX(t) (bx0 + ((t) - ta) / (tb - ta) * (bx1 - bx0))
#define PY(v) (by1 - ((v) - lo) / (hi - lo) * (by1 - by0))
    for (int i = 0; i < nt; i++) {
        double py = PY(ticks[i]);
        pl_dl_line(dl, PL_SPACE_PIXEL, (pl_vec2){bx0, py}, (pl_vec2){bx1, py},
                   fabs(ticks[i]) < 1e-9 * step ? pl_rgb(0.6, 0.6, 0.65) : grid, 1.0f);
        tick_label(l, sizeof l, ticks[i], step);
        pl_dl_text(dl, PL_SPACE_PIXEL, (pl_vec2){bx0 - 3, py}, l, fs, PL_ANCHOR_RIGHT | PL_ANCHOR_MIDDLE, 0.0f, ink,
                   NULL);
    }
    double tstep = 0, tt[16];
    int ntt = pl_nice_levels(ta, tb, 4, tt, 16, &tstep);
    for (int i = 0; i < ntt; i++) {
        double px = PX(tt[i]);
        pl_dl_line(dl, PL_SPACE_PIXEL, (pl_vec2){px, by1}, (pl_vec2){px, by1 + 3}, ink, 1.0f);
        tick_label(l, sizeof l, tt[i], tstep);
        if (i == ntt - 1) strncat(l, " s", sizeof l - strlen(l) - 1); /* the time axis' unit */
        double w = measure ? measure(ud, l, fs) : 0.6 * fs * strlen(l);
        int right = px + 0.5 * w > x1;
        pl_dl_text(dl, PL_SPACE_PIXEL, (pl_vec2){right ? x1 : px, by1 + 0.75 * fs}, l, fs,
                   (right ? PL_ANCHOR_RIGHT : PL_ANCHOR_CENTER) | PL_ANCHOR_MIDDLE, 0.0f, ink, NULL);
    }
    /* the series, clipped to the box (at most ~2 points per pixel column) */
    enum { MAXP = 2048 };
    static pl_vec2 pts[MAXP];
    for (int i = 0; i < ch->nseries; i++) {
        const pl_live_series *q = &ch->s[i];
        int stride = q->n / MAXP + 1, m = 0;
        for (int j = 0; j < q->n && m < MAXP; j += stride) {
            double v = fmin(hi, fmax(lo, q->v[j]));
            pts[m++] = (pl_vec2){PX(q->t[j]), PY(v)};
        }
        if (m >= 2) pl_dl_polyline(dl, PL_SPACE_PIXEL, pts, m, q->color, 1.8f);
        else if (m == 1) {
            pl_style dot = pl_style_fill(q->color);
            pl_dl_circle(dl, PL_SPACE_PIXEL, pts[0], 2.0, &dot);
        }
    }
#undef PX
#undef PY
}
