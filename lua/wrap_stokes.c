/* The boundary-element Stokes fluid (porelab/stokes.h) as world methods:
 *     w:stokes{ viscosity = , density = , disc_elements = , wall_elements = , element_length = ,
 *               polygon_elements = , gap = , solve_every = , check_stability = , field_grid = ,
 *               load_wall = <wall body or index>, load_force = , load_contacts = ,
 *               container = {<wall bodies or indices>} }
 *                                   attaches the fluid (or changes its fields); returns the def
 *     w:stokes()                    -> the def as a table
 *     w:stokes_solve()              solves for the bodies as they are (no time step)
 *     w:stokes_body(b)              -> {drag = {x, y}, moment, buoyancy = {x, y}, k, k_rot, dt_safe}
 *     w:stokes_point(x, y)          -> vx, vy, p  (nil, message outside the fluid)
 *     w:stokes_wall_pressure(b)     -> mean pressure on a container wall, Pa
 * The fields come from the model's parameter table (pl_stokes_params). */
#include "lua_params.h"
#include "lua_util.h"
#include "porelab/stokes.h"
#include "wrap.h"

static int s_stokes(lua_State *L) {
    const char *fn = "stokes";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_stokes_def d;
    const int has = pl_world_stokes_def(lw->w, &d) == PL_OK;
    if (!has) d = pl_default_stokes_def();
    if (!lua_isnoneornil(L, 2)) {
        pl_lua_check_def(L, 2, fn);
        /* load_wall may be a body handle: read it as its index */
        lua_getfield(L, 2, "load_wall");
        int wall = -2;
        if (lua_isuserdata(L, -1)) {
            pl_world *bw = NULL;
            wall = pl_lua_check_body(L, -1, &bw);
            if (bw != lw->w) pl_lua_error(L, "%s: load_wall is a body of another world", fn);
        }
        const int wall_ref = luaL_ref(L, LUA_REGISTRYINDEX);
        if (wall >= -1) {
            lua_pushinteger(L, wall);
            lua_setfield(L, 2, "load_wall");
        }
        /* container: a list of wall bodies (or indices); {} for every wall of the world */
        const int has_box = lua_getfield(L, 2, "container") != LUA_TNIL;
        if (has_box) {
            if (!lua_istable(L, -1))
                pl_lua_error(L, "%s: container must be a list of 3 to %d wall bodies (got %s)", fn,
                             PL_STOKES_CONTAINER_MAX, luaL_typename(L, -1));
            const lua_Integer n = (lua_Integer)lua_rawlen(L, -1);
            if (n != 0 && (n < 3 || n > PL_STOKES_CONTAINER_MAX))
                pl_lua_error(L, "%s: container must list 3 to %d wall bodies (got %d); {} for every wall", fn,
                             PL_STOKES_CONTAINER_MAX, (int)n);
            d.container_count = (int)n;
            for (int k = 0; k < (int)n; k++) {
                lua_rawgeti(L, -1, k + 1);
                int b = -1;
                if (lua_isuserdata(L, -1)) {
                    pl_world *bw = NULL;
                    b = pl_lua_check_body(L, -1, &bw);
                    if (bw != lw->w) pl_lua_error(L, "%s: container[%d] is a body of another world", fn, k + 1);
                } else if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 0 && lua_tointeger(L, -1) < 1000000000) {
                    b = (int)lua_tointeger(L, -1);
                } else {
                    pl_lua_error(L, "%s: container[%d] must be a wall body or its index in [0, 1e9) (got %s)", fn,
                                 k + 1, luaL_tolstring(L, -1, NULL));
                }
                d.container[k] = b;
                lua_pop(L, 1);
            }
            for (int k = (int)n; k < PL_STOKES_CONTAINER_MAX; k++) d.container[k] = 0;
        }
        const int box_ref = luaL_ref(L, LUA_REGISTRYINDEX);
        if (has_box) {
            lua_pushnil(L);
            lua_setfield(L, 2, "container");
        }
        pl_lua_read_params(L, 2, fn, pl_stokes_params, PL_STOKES_PARAM_COUNT, &d);
        if (wall >= -1) { /* give the scene its table back as it wrote it */
            lua_rawgeti(L, LUA_REGISTRYINDEX, wall_ref);
            lua_setfield(L, 2, "load_wall");
        }
        if (has_box) {
            lua_rawgeti(L, LUA_REGISTRYINDEX, box_ref);
            lua_setfield(L, 2, "container");
        }
        luaL_unref(L, LUA_REGISTRYINDEX, wall_ref);
        luaL_unref(L, LUA_REGISTRYINDEX, box_ref);
        pl_lua_check_status(L, lw->w, has ? pl_world_stokes_redefine(lw->w, &d) : pl_world_attach_stokes(lw->w, &d),
                            fn);
    } else if (!has) {
        pl_lua_check_status(L, lw->w, pl_world_attach_stokes(lw->w, &d), fn);
    }
    pl_lua_push_params(L, pl_stokes_params, PL_STOKES_PARAM_COUNT, &d);
    lua_createtable(L, d.container_count, 0);
    for (int k = 0; k < d.container_count; k++) {
        lua_pushinteger(L, d.container[k]);
        lua_rawseti(L, -2, k + 1);
    }
    lua_setfield(L, -2, "container");
    return 1;
}

static void need(lua_State *L, pl_lua_world *lw, const char *fn) {
    if (!pl_world_has_stokes(lw->w)) pl_lua_error(L, "%s: the world has no Stokes fluid (add it with w:stokes{...})", fn);
}

static int s_solve(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    need(L, lw, "stokes_solve");
    pl_lua_check_status(L, lw->w, pl_world_stokes_solve(lw->w), "stokes_solve");
    return 0;
}

static int s_body(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    need(L, lw, "stokes_body");
    pl_world *bw = NULL;
    const int b = pl_lua_check_body(L, 2, &bw);
    pl_stokes_body_result r;
    const pl_status st = pl_world_stokes_body(lw->w, b, &r);
    if (st == PL_ERR_STATE) pl_lua_error(L, "stokes_body: no solve yet (step the world or call w:stokes_solve())");
    if (st != PL_OK) pl_lua_error(L, "stokes_body: body %d is not seen by the fluid", b);
    lua_createtable(L, 0, 6);
    pl_lua_push_vec2(L, r.drag);
    lua_setfield(L, -2, "drag");
    lua_pushnumber(L, r.moment);
    lua_setfield(L, -2, "moment");
    pl_lua_push_vec2(L, r.buoyancy);
    lua_setfield(L, -2, "buoyancy");
    lua_pushnumber(L, r.k_trans);
    lua_setfield(L, -2, "k");
    lua_pushnumber(L, r.k_rot);
    lua_setfield(L, -2, "k_rot");
    lua_pushnumber(L, r.dt_safe);
    lua_setfield(L, -2, "dt_safe");
    return 1;
}

static int s_point(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    need(L, lw, "stokes_point");
    pl_vec2 p = {luaL_checknumber(L, 2), luaL_checknumber(L, 3)}, u;
    double pr;
    const pl_status st = pl_world_stokes_point(lw->w, p, &u, &pr);
    if (st != PL_OK) {
        lua_pushnil(L);
        lua_pushstring(L, st == PL_ERR_STATE ? "no solve yet" : "the point is not in the fluid");
        return 2;
    }
    lua_pushnumber(L, u.x);
    lua_pushnumber(L, u.y);
    lua_pushnumber(L, pr);
    return 3;
}

static int s_wall_pressure(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    need(L, lw, "stokes_wall_pressure");
    pl_world *bw = NULL;
    const int b = pl_lua_check_body(L, 2, &bw);
    lua_pushnumber(L, pl_world_stokes_wall_pressure(lw->w, b));
    return 1;
}

const luaL_Reg pl_lua_stokes_methods[] = {{"stokes", s_stokes},
                                          {"stokes_solve", s_solve},
                                          {"stokes_body", s_body},
                                          {"stokes_point", s_point},
                                          {"stokes_wall_pressure", s_wall_pressure},
                                          {NULL, NULL}};
