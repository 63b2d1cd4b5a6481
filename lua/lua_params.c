/* Lua readers driven by parameter tables (lua_params.h). */
#include "lua_params.h"
#include "lua_util.h"
#include <lauxlib.h>
#include <stdio.h>
#include <string.h>

void pl_lua_read_params(lua_State *L, int t, const char *fn, const pl_param *table, int n, void *def) {
    t = lua_absindex(L, t);
    lua_pushnil(L);
    while (lua_next(L, t)) {
        lua_pop(L, 1);
        const pl_param *p = lua_type(L, -1) == LUA_TSTRING ? pl_param_find(table, n, lua_tostring(L, -1)) : NULL;
        if (!p) {
            char list[2048];
            size_t off = 0;
            for (int k = 0; k < n && off < sizeof list; k++)
                off += (size_t)snprintf(list + off, sizeof list - off, "%s%s", k ? ", " : "", table[k].name);
            const char *key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : luaL_tolstring(L, -1, NULL);
            pl_lua_error(L, "%s: unknown field '%s' (valid: %s)", fn, key, list);
        }
    }
    for (int k = 0; k < n; k++) {
        const pl_param *p = &table[k];
        const int ty = lua_getfield(L, t, p->name);
        if (ty != LUA_TNIL) {
            double v = 0;
            if (ty == LUA_TBOOLEAN && p->type != PL_PARAM_DOUBLE) v = lua_toboolean(L, -1);
            else if (ty == LUA_TNUMBER) v = lua_tonumber(L, -1);
            else
                pl_lua_error(L, "%s: %s must be a number%s (got %s)", fn, p->name,
                             p->type == PL_PARAM_BOOL ? " or a boolean" : "", luaL_typename(L, -1));
            char msg[512];
            if (pl_param_check(p, v, msg, sizeof msg) != PL_OK) pl_lua_error(L, "%s: %s", fn, msg);
            pl_param_write(p, def, v);
        }
        lua_pop(L, 1);
    }
}

void pl_lua_push_params(lua_State *L, const pl_param *table, int n, const void *def) {
    lua_createtable(L, 0, n);
    for (int k = 0; k < n; k++) {
        const double v = pl_param_read(&table[k], def);
        if (table[k].type == PL_PARAM_DOUBLE) lua_pushnumber(L, v);
        else lua_pushinteger(L, (lua_Integer)v);
        lua_setfield(L, -2, table[k].name);
    }
}
