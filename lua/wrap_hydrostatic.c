/* Hydrostatic water (porelab/hydrostatic.h) as world methods:
 *     w:water{ level = , x_min = , x_max = , bottom = , density = , drag = , moving_level = }
 *     w:water_set{ density = ... }     (change fields between steps; the others keep their values)
 *     w:water_level()                  -> current free-surface level, m
 *     w:water_pressure(x, y)           -> water pressure at a point, Pa
 *     w:water_def()                    -> the fields as a table (level: the current level)
 * The fields are read through the model's parameter table (pl_hydrostatic_params): the valid
 * names, the ranges and the units come from it, so Lua and C cannot disagree. Registered into
 * the world metatable with luaL_setfuncs(L, pl_lua_hydrostatic_methods, 0). */
#include "wrap.h"
#include "lua_util.h"
#include "lua_params.h"
#include "porelab/hydrostatic.h"
#include "porelab/params.h"


/* Reads the fields of the table at index 2 into d (missing fields keep d's values) through the
   shared parameter-table reader (lua_params.c). */
static void read_def(lua_State *L, const char *fn, pl_hydrostatic_def *d)
{
    pl_lua_check_def(L, 2, fn);
    pl_lua_read_params(L, 2, fn, pl_hydrostatic_params, PL_HYDROSTATIC_PARAM_COUNT, d);
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

/* w:water_def() -> {x_min = , ..., level = current level, ...} */
static int h_water_def(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_hydrostatic_def d;
    if (pl_world_hydrostatic_def(lw->w, &d) != PL_OK)
        pl_lua_error(L, "water_def: the world has no water (add it with w:water{...})");
    pl_lua_push_params(L, pl_hydrostatic_params, PL_HYDROSTATIC_PARAM_COUNT, &d);
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
                                               {"water_def", h_water_def},
                                               {NULL, NULL}};
