/* The boundary-element Stokes fluid (porelab/stokes.h) as world methods:
 *     w:stokes{ viscosity = , density = , disc_elements = , wall_elements = , element_length = ,
 *               polygon_elements = , gap = , solve_every = , check_stability = , field_grid = ,
 *               load_wall = <wall body or index>, load_force = }
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
        pl_lua_read_params(L, 2, fn, pl_stokes_params, PL_STOKES_PARAM_COUNT, &d);
        if (wall >= -1) { /* give the scene its table back as it wrote it */
            lua_rawgeti(L, LUA_REGISTRYINDEX, wall_ref);
            lua_setfield(L, 2, "load_wall");
        }
        luaL_unref(L, LUA_REGISTRYINDEX, wall_ref);
        pl_lua_check_status(L, lw->w, has ? pl_world_stokes_redefine(lw->w, &d) : pl_world_attach_stokes(lw->w, &d),
                            fn);
    } else if (!has) {
        pl_lua_check_status(L, lw->w, pl_world_attach_stokes(lw->w, &d), fn);
    }
    pl_lua_push_params(L, pl_stokes_params, PL_STOKES_PARAM_COUNT, &d);
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
