#include "scene_overlay.h"
#include "lua_util.h"
#include "scene_render.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Largest coordinate of an overlay point (m, or px in pixel space): the camera's reach
   (PL_VIEW_MAX_COORD in run_plan.h). */
#define PL_OVERLAY_MAX_COORD 1e12

typedef struct overlay_target {
    pl_scene *s;
    pl_draw_list *dl;
    int present;
} overlay_target;

static const char *const item_fields[] = {"line", "polygon", "circle", "arrow", "text", "at",
                                          "radius", "color", "fill", "width", "size",
                                          "anchor", "space", NULL};
static const char *const kinds[] = {"line", "polygon", "circle", "arrow", "text", NULL};

/* Reads the list of points in field (at least min of them) into pts (max cap). */
/* A point of an item: finite and within the reach of a camera (cairo cannot draw NaN). */
static void check_point(lua_State *L, const char *what, const char *field, pl_vec2 p)
{
    if (isfinite(p.x) && isfinite(p.y) && fabs(p.x) <= PL_OVERLAY_MAX_COORD && fabs(p.y) <= PL_OVERLAY_MAX_COORD)
        return;
    char msg[256]; /* lua_pushfstring knows no %g */
    snprintf(msg, sizeof msg, "%s: %s must be a point with finite coordinates within +-%g (got {%g, %g})", what,
             field, PL_OVERLAY_MAX_COORD, p.x, p.y);
    luaL_error(L, "%s", msg);
}

enum { MAX_POINTS = 4096 };

static int read_points(lua_State *L, int t, const char *what, const char *field, pl_vec2 *pts,
                       int cap, int min)
{
    lua_getfield(L, t, field);
    int n = lua_istable(L, -1) ? (int)luaL_len(L, -1) : 0;
    if (n < min || n > cap)
        luaL_error(L, "%s: %s must be a list of %d..%d points {x, y}", what, field, min, cap);
    for (int i = 0; i < n; i++) {
        lua_geti(L, -1, i + 1);
        if (!pl_lua_to_vec2(L, -1, &pts[i]))
            luaL_error(L, "%s: %s[%d] must be a point {x, y}", what, field, i + 1);
        char f[64];
        snprintf(f, sizeof f, "%s[%d]", field, i + 1);
        check_point(L, what, f, pts[i]);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return n;
}

static pl_rgba item_color(lua_State *L, int t, const char *what, const char *field,
                          pl_rgba def)
{
    char w[96];
    snprintf(w, sizeof w, "%s: %s", what, field);
    if (lua_getfield(L, t, field) != LUA_TNIL) def = pl_scene_render_color(L, -1, w);
    lua_pop(L, 1);
    return def;
}



/* One overlay item at index t, e.g. {line = {{0, 1}, {2, 1}}, color = "#1f77b4"}. */
static void add_item(lua_State *L, int t, int index, pl_draw_list *dl)
{
    static pl_vec2 pts[MAX_POINTS]; /* between steps only; single-threaded */
    char what[48];
    snprintf(what, sizeof what, "render: overlay[%d]", index);
    if (!lua_istable(L, t)) luaL_error(L, "%s must be a table", what);
    pl_lua_check_fields(L, t, what, item_fields);
    int kind = -1;
    for (int k = 0; kinds[k]; k++)
        if (pl_lua_has_field(L, t, kinds[k])) {
            if (kind >= 0) luaL_error(L, "%s: give one of line, polygon, circle, arrow, text", what);
            kind = k;
        }
    if (kind < 0) luaL_error(L, "%s: give one of line, polygon, circle, arrow, text", what);
    static const char *const spaces[] = {"world", "pixel", NULL};
    pl_space sp = (pl_space)pl_lua_field_option(L, t, what, "space", 0, spaces);
    pl_rgba black = {0, 0, 0, 1};
    pl_rgba color = item_color(L, t, what, "color", black);
    float width = (float)pl_lua_field_number(L, t, what, "width", 2);
    PL_LUA_CHECK(L, width > 0 && width <= 100, what, "width", "in (0, 100] px", width);
    if (kind == 0 || kind == 1) { /* line, polygon */
        int n = read_points(L, t, what, kinds[kind], pts, MAX_POINTS, kind == 0 ? 2 : 3);
        if (kind == 0) {
            pl_dl_polyline(dl, sp, pts, n, color, width);
        } else {
            pl_style st = pl_lua_has_field(L, t, "fill")
                              ? pl_style_fill_stroke(item_color(L, t, what, "fill", color),
                                                     color, width)
                              : pl_style_stroke(color, width);
            pl_dl_polygon(dl, sp, pts, n, &st);
        }
    } else if (kind == 2) { /* circle */
        pl_vec2 c = pl_lua_field_vec2(L, t, what, "circle", (pl_vec2){0, 0});
        check_point(L, what, "circle", c);
        double r = pl_lua_field_number(L, t, what, "radius", 0);
        PL_LUA_CHECK(L, r > 0 && r <= PL_OVERLAY_MAX_COORD, what, "radius", "> 0 and at most 1e12 (m, or px in pixel space)", r);
        pl_style st = pl_lua_has_field(L, t, "fill")
                          ? pl_style_fill_stroke(item_color(L, t, what, "fill", color), color,
                                                 width)
                          : pl_style_stroke(color, width);
        pl_dl_circle(dl, sp, c, r, &st);
    } else if (kind == 3) { /* arrow: {tail, tip} */
        read_points(L, t, what, "arrow", pts, 2, 2);
        float head = (float)pl_lua_field_number(L, t, what, "size", 4 * width + 4);
        pl_dl_arrow(dl, sp, pts[0], pts[1], color, width, head);
    } else { /* text at a point */
        const char *text = pl_lua_field_string(L, t, what, "text", "");
        if (!pl_lua_has_field(L, t, "at")) luaL_error(L, "%s: at is required (a point {x, y})", what);
        pl_vec2 at = pl_lua_field_vec2(L, t, what, "at", (pl_vec2){0, 0});
        check_point(L, what, "at", at);
        float size = (float)pl_lua_field_number(L, t, what, "size", 14);
        PL_LUA_CHECK(L, size > 0 && size <= 500, what, "size", "in (0, 500] px", size);
        static const char *const anchors[] = {"left", "center", "right", NULL};
        int anchor = pl_lua_field_option(L, t, what, "anchor", 0, anchors);
        pl_rgba white = {1, 1, 1, 0.85f};
        pl_dl_text(dl, sp, at, text, size, anchor | PL_ANCHOR_MIDDLE, 0, color, &white);
    }
}

static int read_overlay(lua_State *L)
{
    overlay_target *o = lua_touserdata(L, 1);
    if (lua_isnil(L, 2) || lua_getfield(L, 2, "overlay") == LUA_TNIL) return 0;
    if (lua_isfunction(L, -1)) { /* overlay(world) -> list */
        pl_scene_push_result_field(o->s, "world");
        lua_call(L, 1, 1);
    }
    int list = lua_gettop(L);
    if (!lua_istable(L, list))
        return luaL_error(L, "render: overlay must be a list of items or a function returning "
                             "one (got %s)", luaL_typename(L, list));
    o->present = 1;
    int n = (int)luaL_len(L, list);
    for (int i = 1; i <= n; i++) {
        lua_geti(L, list, i);
        add_item(L, lua_gettop(L), i, o->dl);
        lua_pop(L, 1);
    }
    return 0;
}

int pl_scene_overlay(pl_scene *s, pl_draw_list *dl)
{
    pl_draw_list_clear(dl);
    overlay_target o = {s, dl, 0};
    if (pl_scene_read_field(s, "render", read_overlay, &o) != 0) return -1;
    return o.present;
}
