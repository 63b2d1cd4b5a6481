#include "scene_render.h"
#include "lua_util.h"
#include "porelab/fluid.h"
#include "porelab/solid.h"
#include "render/colormap.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct render_target {
    pl_render_options *opt;
    pl_world *w;
} render_target;

static const char *const render_fields[] = {
    "size", "camera", "margin", "layers", "background", "colors", "wall_color",
    "force_color", "force_scale", "force_threshold", "force_max_width", "color_by", "title",
    "color_range", "fluid_field", "fluid_range", "isolines", "velocity_scale", "time_offset",
    "overlay", "excess_reference", "record_from", "hide", "live", NULL};

static int hex_digit(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

pl_rgba pl_scene_render_color(lua_State *L, int idx, const char *what)
{
    pl_rgba c = {0, 0, 0, 1};
    if (lua_type(L, idx) == LUA_TSTRING) {
        const char *s = lua_tostring(L, idx);
        size_t n = strlen(s);
        float v[4] = {0, 0, 0, 1};
        int ok = s[0] == '#' && (n == 7 || n == 9);
        for (size_t k = 0; ok && 2 * k + 2 < n; k++) {
            int hi = hex_digit(s[1 + 2 * k]), lo = hex_digit(s[2 + 2 * k]);
            ok = hi >= 0 && lo >= 0;
            v[k] = (float)(hi * 16 + lo) / 255.0f;
        }
        if (ok) return (pl_rgba){v[0], v[1], v[2], v[3]};
    } else if (lua_istable(L, idx)) {
        float v[4] = {0, 0, 0, 1};
        int n = (int)luaL_len(L, idx), ok = n == 3 || n == 4;
        for (int k = 0; ok && k < n; k++) {
            lua_geti(L, idx, k + 1);
            ok = lua_type(L, -1) == LUA_TNUMBER && lua_tonumber(L, -1) >= 0 &&
                 lua_tonumber(L, -1) <= 1;
            v[k] = (float)lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
        if (ok) return (pl_rgba){v[0], v[1], v[2], v[3]};
    }
    luaL_error(L, "%s must be a colour \"#rrggbb\", \"#rrggbbaa\" or {r, g, b [, a]} "
                  "with components in 0..1", what);
    return c;
}

static void field_color(lua_State *L, const char *field, pl_rgba *out)
{
    char what[64];
    snprintf(what, sizeof what, "render: %s", field);
    if (lua_getfield(L, 2, field) != LUA_TNIL) *out = pl_scene_render_color(L, -1, what);
    lua_pop(L, 1);
}

/* colors = {sand = "#c2b280", ...} by material name, or a list by material index. */
static void read_colors(lua_State *L, render_target *t)
{
    if (lua_getfield(L, 2, "colors") == LUA_TNIL) {
        lua_pop(L, 1);
        return;
    }
    int ct = lua_gettop(L);
    if (!lua_istable(L, ct)) luaL_error(L, "render: colors must be a table");
    int nmat = pl_world_material_count(t->w);
    if (nmat > PL_RENDER_MAX_MATERIAL_COLORS) nmat = PL_RENDER_MAX_MATERIAL_COLORS;
    pl_render_options *o = t->opt;
    /* Start from the palette so that materials without a colour keep theirs. */
    for (int i = o->material_color_count; i < PL_RENDER_MAX_MATERIAL_COLORS; i++)
        o->material_colors[i] = pl_material_palette(i);
    if (o->material_color_count < nmat) o->material_color_count = nmat;
    lua_pushnil(L);
    while (lua_next(L, ct)) {
        int index = -1;
        char what[96];
        if (lua_type(L, -2) == LUA_TSTRING) {
            index = pl_world_find_material(t->w, lua_tostring(L, -2));
            if (index < 0)
                luaL_error(L, "render: colors: unknown material '%s'", lua_tostring(L, -2));
            snprintf(what, sizeof what, "render: colors.%s", lua_tostring(L, -2));
        } else if (lua_isinteger(L, -2)) {
            index = (int)lua_tointeger(L, -2) - 1;
            if (index < 0 || index >= PL_RENDER_MAX_MATERIAL_COLORS)
                luaL_error(L, "render: colors[%d]: index must be in 1..%d", index + 1,
                           PL_RENDER_MAX_MATERIAL_COLORS);
            snprintf(what, sizeof what, "render: colors[%d]", index + 1);
        } else {
            luaL_error(L, "render: colors keys must be material names or indices");
        }
        if (index >= PL_RENDER_MAX_MATERIAL_COLORS) {
            lua_pop(L, 1);
            continue;
        }
        o->material_colors[index] = pl_scene_render_color(L, -1, what);
        if (o->material_color_count <= index) o->material_color_count = index + 1;
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
}

static void read_layers(lua_State *L, pl_render_options *o)
{
    int type = lua_getfield(L, 2, "layers");
    if (type == LUA_TNIL) {
        lua_pop(L, 1);
        return;
    }
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    if (type == LUA_TSTRING) {
        lua_pushvalue(L, -2);
        luaL_addvalue(&b);
    } else if (type == LUA_TTABLE) {
        int n = (int)luaL_len(L, -2);
        for (int i = 1; i <= n; i++) {
            if (lua_geti(L, -2, i) != LUA_TSTRING)
                luaL_error(L, "render: layers[%d] must be a layer name", i);
            if (i > 1) luaL_addchar(&b, ',');
            luaL_addvalue(&b);
        }
        if (n == 0) luaL_addstring(&b, "none");
    } else {
        luaL_error(L, "render: layers must be a list of names or a string like \"bodies,forces\"");
    }
    luaL_pushresult(&b);
    char err[512];
    if (pl_render_parse_layers(lua_tostring(L, -1), &o->layers, err, sizeof err) != 0)
        luaL_error(L, "render: layers: %s", err);
    lua_pop(L, 2);
}

static void read_camera(lua_State *L, pl_render_options *o)
{
    int type = lua_getfield(L, 2, "camera");
    if (type == LUA_TSTRING && strcmp(lua_tostring(L, -1), "auto") == 0) {
        o->auto_camera = 1;
    } else if (type == LUA_TTABLE) {
        double v[4] = {0, 0, 0, 0};
        int ok = luaL_len(L, -1) == 4;
        for (int k = 0; ok && k < 4; k++) {
            lua_geti(L, -1, k + 1);
            ok = lua_type(L, -1) == LUA_TNUMBER;
            v[k] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
        if (!ok || !(v[2] > v[0]) || !(v[3] > v[1]))
            luaL_error(L, "render: camera must be \"auto\" or {x0, y0, x1, y1} in m with "
                          "x1 > x0 and y1 > y0");
        o->auto_camera = 0;
        o->view_lo = (pl_vec2){v[0], v[1]};
        o->view_hi = (pl_vec2){v[2], v[3]};
    } else if (type != LUA_TNIL) {
        luaL_error(L, "render: camera must be \"auto\" or {x0, y0, x1, y1} (got %s)",
                   luaL_typename(L, -1));
    }
    lua_pop(L, 1);
}

/* A {min, max} range; both 0 (or absent) = automatic. */
static void read_range(lua_State *L, const char *field, double *lo, double *hi)
{
    if (lua_getfield(L, 2, field) != LUA_TNIL) {
        pl_vec2 r;
        if (!pl_lua_to_vec2(L, -1, &r) || !(r.y > r.x))
            luaL_error(L, "render: %s must be {min, max} with max > min", field);
        *lo = r.x;
        *hi = r.y;
    }
    lua_pop(L, 1);
}

/* Colour ranges, fluid field choice, isolines, arrows and the clock. */
static void read_field_options(lua_State *L, pl_render_options *o)
{
    const char *fn = "render";
    read_range(L, "color_range", &o->color_min, &o->color_max);
    read_range(L, "fluid_range", &o->fluid_min, &o->fluid_max);
    /* Names in the order of pl_fluid_node_field, so the option index is the enum value. */
    static const char *const fields[] = {"head", "pressure_head", "pressure",
                                         "excess_pressure", "velocity_x", "velocity_y",
                                         "speed", "mises", "plastic_strain",
                                         "solid_pressure", "displacement", NULL};
    _Static_assert(PL_FLUID_HEAD == 0 && PL_FLUID_PRESSURE_HEAD == 1 &&
                       PL_FLUID_PRESSURE == 2 && PL_FLUID_EXCESS_PRESSURE == 3 &&
                       PL_FLUID_VELOCITY_NODE_X == 4 && PL_RENDER_FLUID_SPEED == 6,
                   "fluid field names follow pl_fluid_node_field");
    o->fluid_field = pl_lua_field_option(L, 2, fn, "fluid_field", o->fluid_field, fields);
    if (o->fluid_field >= 7 && o->fluid_field < 11) /* the solid's fields (porelab/solid.h) */
        o->fluid_field += PL_SOLID_FIELD_MISES - 7;
    o->isoline_count = pl_lua_field_int(L, 2, fn, "isolines", o->isoline_count);
    PL_LUA_CHECK(L, o->isoline_count >= 1 && o->isoline_count <= 100, fn, "isolines",
                 "in 1..100", o->isoline_count);
    o->velocity_scale = pl_lua_field_number(L, 2, fn, "velocity_scale", o->velocity_scale);
    PL_LUA_CHECK(L, o->velocity_scale >= 0, fn, "velocity_scale",
                 ">= 0 m per m/s (0 = automatic)", o->velocity_scale);
    o->time_offset = pl_lua_field_number(L, 2, fn, "time_offset", o->time_offset);
    if (pl_lua_has_field(L, 2, "excess_reference")) {
        o->excess_reference = pl_lua_field_number(L, 2, fn, "excess_reference", 0.0);
        PL_LUA_CHECK(L, isfinite(o->excess_reference), fn, "excess_reference",
                     "a finite head in m", o->excess_reference);
        o->has_excess_reference = 1;
    }
    o->record_from = pl_lua_field_number(L, 2, fn, "record_from", o->record_from);
    PL_LUA_CHECK(L, o->record_from >= 0, fn, "record_from", ">= 0 s", o->record_from);
}

/* hide = {"ghost", ...}: materials whose bodies are not drawn. */
static void read_hide(lua_State *L, render_target *t)
{
    if (lua_getfield(L, 2, "hide") == LUA_TNIL) {
        lua_pop(L, 1);
        return;
    }
    if (!lua_istable(L, -1)) luaL_error(L, "render: hide must be a list of material names");
    int n = (int)luaL_len(L, -1);
    for (int i = 1; i <= n; i++) {
        if (lua_geti(L, -1, i) != LUA_TSTRING)
            luaL_error(L, "render: hide[%d] must be a material name", i);
        int m = pl_world_find_material(t->w, lua_tostring(L, -1));
        if (m < 0) luaL_error(L, "render: hide: unknown material '%s'", lua_tostring(L, -1));
        if (m >= 32) luaL_error(L, "render: hide: only the first 32 materials can be hidden "
                                   "('%s' is material %d)", lua_tostring(L, -1), m + 1);
        t->opt->hidden_materials |= 1u << m;
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
}

static int read_render(lua_State *L)
{
    const char *fn = "render";
    render_target *t = lua_touserdata(L, 1);
    pl_render_options *o = t->opt;
    if (lua_isnil(L, 2)) return 0;
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, render_fields);
    if (pl_lua_has_field(L, 2, "size")) {
        pl_vec2 sz = pl_lua_field_vec2(L, 2, fn, "size", (pl_vec2){0, 0});
        if (!(sz.x >= 16 && sz.x <= 16384 && sz.y >= 16 && sz.y <= 16384) ||
            sz.x != floor(sz.x) || sz.y != floor(sz.y))
            luaL_error(L, "render: size must be {width, height} in whole pixels, each in "
                          "16..16384 (got {%f, %f})", sz.x, sz.y);
        o->width = (int)sz.x;
        o->height = (int)sz.y;
    }
    read_camera(L, o);
    o->margin = pl_lua_field_number(L, 2, fn, "margin", o->margin);
    PL_LUA_CHECK(L, o->margin >= 0 && o->margin < 1, fn, "margin", "in [0, 1)", o->margin);
    read_layers(L, o);
    field_color(L, "background", &o->background);
    field_color(L, "wall_color", &o->wall_color);
    field_color(L, "force_color", &o->force_color);
    read_colors(L, t);
    read_hide(L, t);
    o->force_scale = pl_lua_field_number(L, 2, fn, "force_scale", o->force_scale);
    PL_LUA_CHECK(L, o->force_scale >= 0, fn, "force_scale", ">= 0 N (0 = largest force)",
                 o->force_scale);
    o->force_threshold = pl_lua_field_number(L, 2, fn, "force_threshold", o->force_threshold);
    PL_LUA_CHECK(L, o->force_threshold >= 0 && o->force_threshold <= 1, fn, "force_threshold",
                 "in [0, 1]", o->force_threshold);
    o->force_max_width = pl_lua_field_number(L, 2, fn, "force_max_width", o->force_max_width);
    PL_LUA_CHECK(L, o->force_max_width > 0 && o->force_max_width <= 100, fn, "force_max_width",
                 "in (0, 100] pixels", o->force_max_width);
    static const char *const coloring[] = {"material", "speed", "stress", "temperature", NULL};
    o->coloring = (pl_body_coloring)pl_lua_field_option(L, 2, fn, "color_by", (int)o->coloring,
                                                        coloring);
    read_field_options(L, o);
    if (pl_lua_has_field(L, 2, "overlay")) o->layers |= PL_LAYER_OVERLAY; /* drawn per frame */
    const char *title = pl_lua_field_string(L, 2, fn, "title", NULL);
    if (title) {
        snprintf(o->title, sizeof o->title, "%s", title);
        o->layers |= PL_LAYER_TITLE;
    }
    return 0;
}

int pl_scene_render_options(pl_scene *s, pl_world *w, pl_render_options *opt)
{
    render_target t = {opt, w};
    return pl_scene_read_field(s, "render", read_render, &t);
}
