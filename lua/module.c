/* The `porelab` Lua module: constructors, flag table, paths; and the embedded helpers. */
#include "wrap.h"
#include "lua_util.h"
#include "scene_internal.h"
#include "run_inputs.h"

#include <lualib.h>
#include <string.h>

static const char last_world_key = 'w';

void pl_lua_scene_note_world(lua_State *L, int idx)
{
    lua_pushvalue(L, idx);
    lua_rawsetp(L, LUA_REGISTRYINDEX, &last_world_key);
}

void pl_lua_scene_push_last_world(lua_State *L)
{
    lua_rawgetp(L, LUA_REGISTRYINDEX, &last_world_key);
}

/* porelab.flags(): list of {name, unit, description, min, max, built}. */
static int p_flags(lua_State *L)
{
    int n = pl_flag_count();
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; i++) {
        const pl_flag_info *f = pl_flag_at(i);
        lua_createtable(L, 0, 6);
        lua_pushstring(L, f->name);
        lua_setfield(L, -2, "name");
        lua_pushstring(L, f->unit);
        lua_setfield(L, -2, "unit");
        lua_pushstring(L, f->description);
        lua_setfield(L, -2, "description");
        lua_pushnumber(L, f->min);
        lua_setfield(L, -2, "min");
        lua_pushnumber(L, f->max);
        lua_setfield(L, -2, "max");
        lua_pushboolean(L, f->built);
        lua_setfield(L, -2, "built");
        lua_rawseti(L, -2, i + 1);
    }
    return 1;
}

/* porelab.error(message): raises message located at the scene line (not inside an
 * embedded helper), like the built-in constructors do. */
static int p_error(lua_State *L)
{
    return pl_lua_error(L, "%s", luaL_checkstring(L, 1));
}

int pl_lua_state_load(lua_State *L); /* wrap_state.c: porelab.load(w, path) */

static const luaL_Reg porelab_functions[] = {{"world", pl_lua_world_new},
                                             {"load", pl_lua_state_load},
                                             {"csv", pl_lua_csv_new},
                                             {"flags", p_flags},
                                             {"error", p_error},
                                             {"params", pl_lua_p_params},
                                             {"seed", pl_lua_p_seed},
                                             {"mix_seed", pl_lua_p_mix_seed},
                                             {NULL, NULL}};

static int luaopen_porelab(lua_State *L)
{
    pl_lua_context *ctx = pl_lua_get_context(L);
    luaL_newlib(L, porelab_functions);
    lua_pushliteral(L, PL_VERSION_STRING);
    lua_setfield(L, -2, "version");
    lua_pushstring(L, ctx->scene_dir);
    lua_setfield(L, -2, "scene_dir");
    lua_pushstring(L, ctx->out_dir);
    lua_setfield(L, -2, "out_dir");
    lua_pushboolean(L, ctx->trust);
    lua_setfield(L, -2, "trusted");
    return 1;
}

/* package.preload loader for one embedded helper; upvalue: index into pl_lua_libs. */
static int load_embedded(lua_State *L)
{
    const pl_lua_lib *lib = &pl_lua_libs[lua_tointeger(L, lua_upvalueindex(1))];
    lua_pushfstring(L, "=%s", lib->name);
    if (luaL_loadbufferx(L, (const char *)lib->code, lib->size, lua_tostring(L, -1), "t") !=
        LUA_OK)
        return lua_error(L);
    lua_pushstring(L, lib->name);
    lua_call(L, 1, 1);
    return 1;
}

void pl_lua_open_porelab(lua_State *L)
{
    luaL_openlibs(L);
    pl_lua_register_world(L);
    pl_lua_register_body(L);
    pl_lua_register_material(L);
    pl_lua_register_csv(L);
    luaL_requiref(L, "porelab", luaopen_porelab, 1);
    lua_pop(L, 1);
    luaL_getsubtable(L, LUA_REGISTRYINDEX, LUA_PRELOAD_TABLE);
    for (int i = 0; i < pl_lua_lib_count; i++) {
        lua_pushinteger(L, i);
        lua_pushcclosure(L, load_embedded, 1);
        lua_setfield(L, -2, pl_lua_libs[i].name);
    }
    lua_pop(L, 1);
}
