#include "sandbox.h"
#include "context.h"
#include "lua_util.h"

#include <errno.h>
#include <lauxlib.h>
#include <stdio.h>
#include <string.h>

#define TRUST_HINT "run with --trust to lift the sandbox"

/* ------------------------------------------------------------------ paths */

/* Resolves path against base; in the sandbox it must lie inside base (or inside also,
 * when not NULL). */
static void resolve_in(lua_State *L, const char *path, const char *base, const char *also,
                       int write, char *out, size_t n, const char *fn)
{
    pl_lua_context *ctx = pl_lua_get_context(L);
    char joined[PATH_MAX];
    pl_path_join(joined, sizeof joined, base, path);
    if (pl_path_resolve(joined, out, n) != 0) {
        /* The file's folder does not exist: the open itself will fail with its own
         * message, and nothing can be read or written there. */
        snprintf(out, n, "%s", joined);
        return;
    }
    if (ctx->trust || pl_path_inside(out, base) || (also && pl_path_inside(out, also))) return;
    pl_lua_error(L, "%s: %s '%s' is not allowed in a sandboxed scene: scenes may %s only "
                 "inside %s%s (%s)", fn, write ? "writing" : "reading", path,
                 write ? "write" : "read", base, also ? " and the output folder" : "",
                 TRUST_HINT);
}

void pl_lua_output_path(lua_State *L, const char *path, char *out, size_t n, const char *fn)
{
    pl_lua_context *ctx = pl_lua_get_context(L);
    if (pl_path_mkdirs(ctx->out_dir) != 0)
        pl_lua_error(L, "%s: cannot create the output folder '%s': %s", fn, ctx->out_dir,
                     strerror(errno));
    char base[PATH_MAX];
    if (pl_path_resolve(ctx->out_dir, base, sizeof base) != 0)
        snprintf(base, sizeof base, "%s", ctx->out_dir);
    resolve_in(L, path, base, NULL, 1, out, n, fn);
}

void pl_lua_input_path(lua_State *L, const char *path, char *out, size_t n, const char *fn)
{
    pl_lua_context *ctx = pl_lua_get_context(L);
    char outdir[PATH_MAX]; /* a scene may read back what it wrote */
    int have_out = pl_path_resolve(ctx->out_dir, outdir, sizeof outdir) == 0;
    resolve_in(L, path, ctx->scene_dir, have_out ? outdir : NULL, 0, out, n, fn);
}

/* ------------------------------------------------------- refused functions */

static int refused(lua_State *L)
{
    return pl_lua_error(L, "%s is not allowed in a sandboxed scene (scenes may be shared; %s)",
                        lua_tostring(L, lua_upvalueindex(1)), TRUST_HINT);
}

static void refuse(lua_State *L, const char *lib, const char *name)
{
    if (lua_getglobal(L, lib) != LUA_TTABLE) {
        lua_pop(L, 1);
        return;
    }
    lua_pushfstring(L, "%s.%s", lib, name);
    lua_pushcclosure(L, refused, 1);
    lua_setfield(L, -2, name);
    lua_pop(L, 1);
}

/* ---------------------------------------------- path-checking file access */

/* Each wrapper keeps the original function as upvalue 1. */

static int call_original(lua_State *L, int first_arg)
{
    int nargs = lua_gettop(L) - first_arg + 1;
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, first_arg);
    lua_call(L, nargs, LUA_MULTRET);
    return lua_gettop(L) - first_arg + 1;
}

static int is_write_mode(const char *mode)
{
    return mode[0] != 'r' || strchr(mode, '+') != NULL;
}

static int io_open_checked(lua_State *L)
{
    const char *path = luaL_checkstring(L, 1);
    const char *mode = luaL_optstring(L, 2, "r");
    char resolved[PATH_MAX];
    if (is_write_mode(mode))
        pl_lua_output_path(L, path, resolved, sizeof resolved, "io.open");
    else
        pl_lua_input_path(L, path, resolved, sizeof resolved, "io.open");
    lua_pushstring(L, resolved);
    lua_replace(L, 1);
    return call_original(L, 1);
}

/* io.lines, io.input (read) and io.output (write) with a file name; a file handle or no
 * argument is passed through. */
static int io_named_checked(lua_State *L)
{
    int write = (int)lua_tointeger(L, lua_upvalueindex(2));
    const char *fn = lua_tostring(L, lua_upvalueindex(3));
    if (lua_type(L, 1) == LUA_TSTRING) {
        char resolved[PATH_MAX];
        if (write)
            pl_lua_output_path(L, lua_tostring(L, 1), resolved, sizeof resolved, fn);
        else
            pl_lua_input_path(L, lua_tostring(L, 1), resolved, sizeof resolved, fn);
        lua_pushstring(L, resolved);
        lua_replace(L, 1);
    }
    return call_original(L, 1);
}

/* dofile(path) and loadfile(path [, mode [, env]]): reading inside the scene folder, text
 * chunks only in the sandbox. */
static int loadfile_checked(lua_State *L)
{
    int is_dofile = (int)lua_tointeger(L, lua_upvalueindex(2));
    const char *fn = is_dofile ? "dofile" : "loadfile";
    const char *path = lua_type(L, 1) == LUA_TSTRING ? lua_tostring(L, 1) : NULL;
    if (!path) return pl_lua_error(L, "%s: a file name is required", fn);
    char resolved[PATH_MAX];
    pl_lua_input_path(L, path, resolved, sizeof resolved, fn);
    pl_lua_context *ctx = pl_lua_get_context(L);
    const char *mode = ctx->trust ? (is_dofile ? NULL : luaL_optstring(L, 2, NULL)) : "t";
    int env = !is_dofile && !lua_isnone(L, 3) ? 3 : 0;
    if (luaL_loadfilex(L, resolved, mode) != LUA_OK) return lua_error(L);
    if (env) {
        lua_pushvalue(L, env);
        if (!lua_setupvalue(L, -2, 1)) lua_pop(L, 1);
    }
    if (!is_dofile) return 1;
    int base = lua_gettop(L);
    lua_call(L, 0, LUA_MULTRET);
    return lua_gettop(L) - base + 1;
}

/* load(chunk [, name [, mode [, env]]]) with text chunks only. */
static int load_text_only(lua_State *L)
{
    const char *mode = luaL_optstring(L, 3, "t");
    if (strchr(mode, 'b') ||
        (lua_type(L, 1) == LUA_TSTRING && lua_tostring(L, 1)[0] == LUA_SIGNATURE[0]))
        return pl_lua_error(L, "load: binary chunks are not allowed in a sandboxed scene (%s)",
                            TRUST_HINT);
    lua_settop(L, lua_gettop(L) < 3 ? 3 : lua_gettop(L));
    lua_pushliteral(L, "t");
    lua_replace(L, 3);
    return call_original(L, 1);
}

static void wrap_global(lua_State *L, const char *lib, const char *name, lua_CFunction f,
                        int extra_int, const char *extra_name)
{
    if (lib) lua_getglobal(L, lib);
    else lua_pushglobaltable(L);
    int t = lua_gettop(L);
    lua_getfield(L, t, name);
    int nup = 1;
    if (extra_name) {
        lua_pushinteger(L, extra_int);
        lua_pushstring(L, extra_name);
        nup = 3;
    } else if (extra_int >= 0) {
        lua_pushinteger(L, extra_int);
        nup = 2;
    }
    lua_pushcclosure(L, f, nup);
    lua_setfield(L, t, name);
    lua_pop(L, 1);
}

/* Module search path: the scene's folder; in the sandbox no C modules at all. */
static void restrict_require(lua_State *L, int trust, const char *scene_dir)
{
    lua_getglobal(L, "package");
    lua_getfield(L, -1, "path");
    const char *old = lua_tostring(L, -1);
    if (trust)
        lua_pushfstring(L, "%s/?.lua;%s/?/init.lua;%s", scene_dir, scene_dir, old ? old : "");
    else
        lua_pushfstring(L, "%s/?.lua;%s/?/init.lua", scene_dir, scene_dir);
    lua_setfield(L, -3, "path");
    lua_pop(L, 1);
    if (!trust) {
        lua_pushliteral(L, "");
        lua_setfield(L, -2, "cpath");
        /* package.searchers = {preload, Lua files}; the C and all-in-one searchers go. */
        lua_getfield(L, -1, "searchers");
        lua_pushnil(L);
        lua_rawseti(L, -2, 4);
        lua_pushnil(L);
        lua_rawseti(L, -2, 3);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (!trust) refuse(L, "package", "loadlib");
}

void pl_lua_install_sandbox(lua_State *L)
{
    pl_lua_context *ctx = pl_lua_get_context(L);
    restrict_require(L, ctx->trust, ctx->scene_dir);
    wrap_global(L, "io", "open", io_open_checked, -1, NULL);
    wrap_global(L, "io", "lines", io_named_checked, 0, "io.lines");
    wrap_global(L, "io", "input", io_named_checked, 0, "io.input");
    wrap_global(L, "io", "output", io_named_checked, 1, "io.output");
    wrap_global(L, NULL, "dofile", loadfile_checked, 1, NULL);
    wrap_global(L, NULL, "loadfile", loadfile_checked, 0, NULL);
    if (ctx->trust) return;
    wrap_global(L, NULL, "load", load_text_only, -1, NULL);
    static const char *const os_refused[] = {"execute", "remove", "rename", "exit",
                                             "getenv", "tmpname", "setlocale", NULL};
    for (int i = 0; os_refused[i]; i++) refuse(L, "os", os_refused[i]);
    refuse(L, "io", "popen");
    refuse(L, "io", "tmpfile");
    /* The debug library can reach the registry and upvalues, which would undo all of the
     * above; scenes keep only debug.traceback. */
    lua_getglobal(L, "debug");
    lua_createtable(L, 0, 1);
    lua_getfield(L, -2, "traceback");
    lua_setfield(L, -2, "traceback");
    lua_pushvalue(L, -1);
    lua_setglobal(L, "debug");
    luaL_getsubtable(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
    lua_insert(L, -2);
    lua_setfield(L, -2, "debug"); /* require "debug" gives the same reduced table */
    lua_pop(L, 2);
}
