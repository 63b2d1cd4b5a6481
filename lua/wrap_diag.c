/* World diagnostics for scenes: average stress in a region, coordination number, VTK export. */
#include "wrap.h"
#include "lua_util.h"
#include "sandbox.h"

#include <limits.h>
#include <stdio.h>

/* w:stress{lo = {x, y}, hi = {x, y}} -> {xx =, xy =, yx =, yy =, mean =, count =}
   (Pa per unit thickness; compression positive). */
static int w_stress(lua_State *L)
{
    static const char *const fields[] = {"lo", "hi", NULL};
    const char *fn = "stress";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    if (!pl_lua_has_field(L, 2, "lo") || !pl_lua_has_field(L, 2, "hi"))
        pl_lua_error(L, "stress: lo = {x, y} and hi = {x, y} are required");
    const pl_vec2 lo = pl_lua_field_vec2(L, 2, fn, "lo", (pl_vec2){0, 0});
    const pl_vec2 hi = pl_lua_field_vec2(L, 2, fn, "hi", (pl_vec2){0, 0});
    if (!(hi.x > lo.x && hi.y > lo.y)) pl_lua_error(L, "stress: hi must lie above and right of lo");
    double s[4];
    const int n = pl_world_stress_in_region(lw->w, lo, hi, s);
    lua_createtable(L, 0, 6);
    const char *names[] = {"xx", "xy", "yx", "yy"};
    for (int k = 0; k < 4; k++) {
        lua_pushnumber(L, s[k]);
        lua_setfield(L, -2, names[k]);
    }
    lua_pushnumber(L, 0.5 * (s[0] + s[3]));
    lua_setfield(L, -2, "mean");
    lua_pushinteger(L, n);
    lua_setfield(L, -2, "count");
    return 1;
}

static int w_coordination(lua_State *L)
{
    lua_pushnumber(L, pl_world_coordination_number(pl_lua_check_world(L, 1)->w));
    return 1;
}

/* w:write_vtk(prefix): PREFIX_bodies.vtu and PREFIX_contacts.vtu inside the output folder. */
static int w_write_vtk(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const char *prefix = luaL_checkstring(L, 2);
    char path[PATH_MAX];
    pl_lua_output_path(L, prefix, path, sizeof path, "write_vtk");
    pl_lua_check_status(L, lw->w, pl_world_write_vtk(lw->w, path), "write_vtk");
    return 0;
}

const luaL_Reg pl_lua_diag_methods[] = {
    {"stress", w_stress}, {"coordination", w_coordination}, {"write_vtk", w_write_vtk}, {NULL, NULL}};
