/* porelab.chart{...}: a scene turns the series it recorded into an XY chart (PNG, SVG or PDF)
 * drawn by the renderer's PLplot charts (render/charts.h). The Lua binding knows nothing of
 * the renderer, so the program registers this function into each scene's Lua state before
 * the scene runs (pl_cli_load_scene, the window). Files go inside the output folder like
 * porelab.csv's (sandbox). */
#include "scene_chart.h"
#include "lua_util.h"
#include "render/charts.h"
#include "sandbox.h"
#include "scene_render.h"

#include <lauxlib.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FN "chart"

/* Raises "scene.lua:12: chart: <message>". The message is formatted by vsnprintf first:
   lua_pushfstring knows no %g or %lld ("invalid option '%g' to 'lua_pushfstring'"). */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3), noreturn))
#endif
static void chart_error(lua_State *L, const char *fmt, ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    pl_lua_error(L, "%s", msg);
    abort(); /* not reached: pl_lua_error raises */
}

static const char *const chart_fields[] = {"file", "title", "xlabel", "ylabel", "size", "series",
                                           "xrange", "yrange", "logx", "logy", "legend", "grid",
                                           NULL};
static const char *const series_fields[] = {"name", "x", "y", "style", "color", "width", NULL};
static const char *const styles[] = {"line", "points", "line_points", "dashed", NULL};
static const char *const legends[] = {"none", "top right", "top left", "bottom right",
                                      "bottom left", NULL};

/* Reads the number array field `field` of the table at t into a new buffer (freed by the
   caller through the chart's cleanup list). */
static double *number_array(lua_State *L, int t, const char *what, const char *field, int *n)
{
    lua_getfield(L, t, field);
    if (!lua_istable(L, -1))
        chart_error(L, FN ": %s.%s must be an array of numbers (got %s)", what, field,
                     luaL_typename(L, -1));
    lua_Integer len = luaL_len(L, -1);
    if (len < 1 || len > 10000000)
        chart_error(L, FN ": %s.%s must have 1 to 10000000 values (got %lld)", what, field,
                     (long long)len);
    /* a full userdata owns the buffer, so a Lua error below cannot leak it */
    double *v = lua_newuserdatauv(L, sizeof(double) * (size_t)len, 0);
    lua_insert(L, -2);
    for (lua_Integer i = 1; i <= len; i++) {
        lua_geti(L, -1, i);
        int ok;
        v[i - 1] = lua_tonumberx(L, -1, &ok);
        if (!ok)
            chart_error(L, FN ": %s.%s[%lld] must be a number (got %s)", what, field,
                         (long long)i, luaL_typename(L, -1));
        lua_pop(L, 1);
    }
    lua_pop(L, 1); /* the array; the userdata stays on the stack until the call returns */
    *n = (int)len;
    return v;
}

static void range(lua_State *L, int t, const char *field, double *lo, double *hi)
{
    if (!pl_lua_has_field(L, t, field)) return;
    pl_vec2 r = pl_lua_field_vec2(L, t, FN, field, (pl_vec2){0, 0});
    if (!(r.y > r.x) || !isfinite(r.x) || !isfinite(r.y))
        chart_error(L, FN ": %s must be {min, max} with min < max (got {%g, %g})", field, r.x, r.y);
    *lo = r.x;
    *hi = r.y;
}

static int l_chart(lua_State *L)
{
    pl_lua_check_def(L, 1, FN);
    pl_lua_check_fields(L, 1, FN, chart_fields);
    const char *file = pl_lua_field_string(L, 1, FN, "file", NULL);
    if (!file) chart_error(L, FN ": file is required (a .png, .svg or .pdf name in the output folder)");
    const char *dot = strrchr(file, '.');
    if (!dot || (strcmp(dot, ".png") && strcmp(dot, ".svg") && strcmp(dot, ".pdf")))
        chart_error(L, FN ": file must end in .png, .svg or .pdf (got '%s')", file);
    char path[4096];
    pl_lua_output_path(L, file, path, sizeof path, FN);

    pl_chart_def def = pl_default_chart_def();
    def.title = pl_lua_field_string(L, 1, FN, "title", NULL);
    def.xlabel = pl_lua_field_string(L, 1, FN, "xlabel", NULL);
    def.ylabel = pl_lua_field_string(L, 1, FN, "ylabel", NULL);
    if (pl_lua_has_field(L, 1, "size")) {
        pl_vec2 sz = pl_lua_field_vec2(L, 1, FN, "size", (pl_vec2){0, 0});
        if (!(sz.x >= 100 && sz.x <= 8192 && sz.y >= 100 && sz.y <= 8192))
            chart_error(L, FN ": size must be {width, height} with each in 100..8192 (got {%g, %g})",
                         sz.x, sz.y);
        def.width = (int)sz.x;
        def.height = (int)sz.y;
    }
    range(L, 1, "xrange", &def.xmin, &def.xmax);
    range(L, 1, "yrange", &def.ymin, &def.ymax);
    def.logx = pl_lua_field_bool(L, 1, FN, "logx", 0);
    def.logy = pl_lua_field_bool(L, 1, FN, "logy", 0);
    def.legend = pl_lua_field_option(L, 1, FN, "legend", 1, legends);
    def.grid = pl_lua_field_bool(L, 1, FN, "grid", 1);

    lua_getfield(L, 1, "series");
    if (!lua_istable(L, -1))
        chart_error(L, FN ": series must be a list of {name, x, y, style, color, width} (got %s)",
                     luaL_typename(L, -1));
    const int st = lua_gettop(L);
    lua_Integer ns = luaL_len(L, st);
    if (ns < 1 || ns > PL_CHART_MAX_SERIES)
        chart_error(L, FN ": series must hold 1 to %d entries (got %lld)", PL_CHART_MAX_SERIES,
                     (long long)ns);
    pl_chart_series ser[PL_CHART_MAX_SERIES];
    memset(ser, 0, sizeof ser);
    for (int k = 0; k < (int)ns; k++) {
        char what[32];
        snprintf(what, sizeof what, "series[%d]", k + 1);
        luaL_checkstack(L, 8, FN ": too many series");
        lua_geti(L, st, k + 1);
        const int t = lua_gettop(L);
        if (!lua_istable(L, t))
            chart_error(L, FN ": %s must be a table {name, x, y, ...} (got %s)", what, luaL_typename(L, t));
        pl_lua_check_fields(L, t, FN, series_fields);
        ser[k].name = pl_lua_field_string(L, t, FN, "name", NULL);
        int nx, ny;
        ser[k].x = number_array(L, t, what, "x", &nx);
        ser[k].y = number_array(L, t, what, "y", &ny);
        if (nx != ny)
            chart_error(L, FN ": %s: x and y must have the same length (got %d and %d)", what, nx, ny);
        ser[k].n = nx;
        ser[k].style = (pl_series_style)pl_lua_field_option(L, t, FN, "style", 0, styles);
        if (pl_lua_has_field(L, t, "color")) {
            lua_getfield(L, t, "color");
            ser[k].color = pl_scene_render_color(L, -1, FN ": series color");
            lua_pop(L, 1);
        }
        ser[k].line_width = pl_lua_field_number(L, t, FN, "width", 0);
        if (!(ser[k].line_width >= 0 && ser[k].line_width <= 50))
            pl_lua_range_error(L, FN, "width", "in 0..50 px", ser[k].line_width);
        /* the table and the two userdata buffers stay on the stack (the strings and numbers
           they own live until this function returns) */
        (void)t;
    }
    def.series = ser;
    def.series_count = (int)ns;
    char err[512];
    if (pl_chart_write(path, &def, err, sizeof err) != 0)
        chart_error(L, FN ": cannot write %s: %s", file, err);
    lua_pushstring(L, path);
    return 1;
}

void pl_scene_register_chart(pl_scene *s)
{
    lua_State *L = pl_scene_lua(s);
    lua_getglobal(L, "porelab");
    if (lua_istable(L, -1)) {
        lua_pushcfunction(L, l_chart);
        lua_setfield(L, -2, "chart");
    }
    lua_pop(L, 1);
}
