/* Hydrostatic water (porelab/hydrostatic.h) as world methods:
 *     w:water{ level = , x_min = , x_max = , bottom = , density = , drag = , moving_level = }
 *     w:water_set{ density = ... }     (change fields between steps; the others keep their values)
 *     w:water_level()                  -> current free-surface level, m
 *     w:water_pressure(x, y)           -> water pressure at a point, Pa
 * The fields are read through the model's parameter table (pl_hydrostatic_params): the valid
 * names, the ranges and the units come from it, so Lua and C cannot disagree. Registered into
 * the world metatable with luaL_setfuncs(L, pl_lua_hydrostatic_methods, 0). */
#include "wrap.h"
#include "lua_util.h"
#include "porelab/hydrostatic.h"
#include "porelab/params.h"

#include <math.h>
#include <string.h>

/* Reads the fields of the table at index 2 into d (missing fields keep d's values). */
static void read_def(lua_State *L, const char *fn, pl_hydrostatic_def *d)
{
    const char *names[PL_HYDROSTATIC_PARAM_COUNT + 1];
    for (int k = 0; k < PL_HYDROSTATIC_PARAM_COUNT; k++) names[k] = pl_hydrostatic_params[k].name;
    names[PL_HYDROSTATIC_PARAM_COUNT] = NULL;
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, names);
    for (int k = 0; k < PL_HYDROSTATIC_PARAM_COUNT; k++) {
        const pl_param *p = &pl_hydrostatic_params[k];
        if (!pl_lua_has_field(L, 2, p->name)) continue;
        double v = 0;
        if (p->type == PL_PARAM_BOOL) {
            /* true/false or 0/1 */
            lua_getfield(L, 2, p->name);
            if (lua_isboolean(L, -1)) v = lua_toboolean(L, -1);
            else if (lua_type(L, -1) == LUA_TNUMBER) v = lua_tonumber(L, -1);
            else pl_lua_error(L, "%s: %s must be true, false, 0 or 1 (got %s)", fn, p->name, luaL_typename(L, -1));
            lua_pop(L, 1);
        } else {
            v = pl_lua_field_number(L, 2, fn, p->name, 0);
        }
        char msg[256];
        if (pl_param_check(p, v, msg, sizeof msg) != PL_OK) pl_lua_error(L, "%s: %s (%s)", fn, msg, p->doc);
        pl_param_write(p, d, v);
    }
}

static int h_water(lua_State *L)
{
    const char *fn = "water";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_hydrostatic_def d = pl_default_hydrostatic_def();
    read_def(L, fn, &d);
    pl_lua_check_status(L, lw->w, pl_world_attach_hydrostatic(lw->w, &d), fn);
    return 0;
}

static int h_water_set(lua_State *L)
{
    const char *fn = "water_set";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_hydrostatic_def d;
    if (pl_world_hydrostatic_def(lw->w, &d) != PL_OK)
        pl_lua_error(L, "%s: the world has no water yet (add it with w:water{...})", fn);
    read_def(L, fn, &d);
    pl_lua_check_status(L, lw->w, pl_world_hydrostatic_redefine(lw->w, &d), fn);
    return 0;
}

static int h_water_level(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    if (!pl_world_has_hydrostatic(lw->w)) pl_lua_error(L, "water_level: the world has no water (add it with w:water{...})");
    lua_pushnumber(L, pl_world_hydrostatic_level(lw->w));
    return 1;
}

static int h_water_pressure(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_vec2 p;
    if (lua_istable(L, 2)) {
        if (!pl_lua_to_vec2(L, 2, &p)) pl_lua_error(L, "water_pressure: expected a point {x, y} or x, y");
    } else {
        p.x = luaL_checknumber(L, 2);
        p.y = luaL_checknumber(L, 3);
    }
    lua_pushnumber(L, pl_world_hydrostatic_pressure(lw->w, p));
    return 1;
}

const luaL_Reg pl_lua_hydrostatic_methods[] = {{"water", h_water},
                                               {"water_set", h_water_set},
                                               {"water_level", h_water_level},
                                               {"water_pressure", h_water_pressure},
                                               {NULL, NULL}};
