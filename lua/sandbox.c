#define _XOPEN_SOURCE 700
#include "sandbox.h"
#include "context.h"
#include "lua_util.h"
#include "scene_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <unistd.h>
#include <lauxlib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TRUST_HINT "run with --trust to lift the sandbox"

/* ------------------------------------------------------------------ paths */

/* Refuses file names that cannot be what the scene meant: an embedded NUL byte (C would
 * silently cut the name there) or a control character (a newline in a file name breaks
 * every listing and message that shows it). The Lua string is looked up on the stack to
 * see its real length. */
static void check_name(lua_State *L, const char *path, const char *fn)
{
    for (int i = 1, top = lua_gettop(L); i <= top; i++) {
        size_t len;
        if (lua_type(L, i) != LUA_TSTRING || lua_tolstring(L, i, &len) != path) continue;
        if (len != strlen(path))
            pl_lua_error(L, "%s: the file name contains a NUL byte (at byte %d of %d); file "
                         "names must be plain text", fn, (int)strlen(path) + 1, (int)len);
        break;
    }
    for (const unsigned char *p = (const unsigned char *)path; *p; p++)
        if (*p < 0x20 || *p == 0x7f) {
            char byte[8]; /* lua_pushfstring has no %x */
            snprintf(byte, sizeof byte, "0x%02x", *p);
            pl_lua_error(L, "%s: the file name contains a control character (byte %s at "
                         "position %d); file names must be plain text", fn, byte,
                         (int)((const char *)p - path) + 1);
        }
}

/* 1 when the last component of path is empty, "." or "..": such a path names a folder. */
static int names_folder(const char *path)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    return base[0] == '\0' || strcmp(base, ".") == 0 || strcmp(base, "..") == 0;
}

/* Resolves path against base; in the sandbox it must lie inside base (or inside also,
 * when not NULL). */
static void resolve_in(lua_State *L, const char *path, const char *base, const char *also,
                       int write, char *out, size_t n, const char *fn)
{
    pl_lua_context *ctx = pl_lua_get_context(L);
    check_name(L, path, fn);
    char joined[PATH_MAX];
    pl_path_join(joined, sizeof joined, base, path);
    if (write && names_folder(joined))
        pl_lua_error(L, "%s: '%s' names a folder, not a file: give a file name inside the "
                     "output folder (e.g. 'result')", fn, path);
    if (pl_path_resolve(joined, out, n) != 0) {
        /* The file's folder does not exist: the open itself will fail with its own
         * message, and nothing can be read or written there. */
        snprintf(out, n, "%s", joined);
        return;
    }
    if (write && strcmp(out, base) == 0)
        pl_lua_error(L, "%s: '%s' is the output folder itself, not a file: give a file name "
                     "inside it", fn, path);
    if (ctx->trust) return;
    if (pl_path_inside(out, base) || (also && pl_path_inside(out, also))) {
        /* realpath follows a link that exists; a dangling one (its target missing) is
         * left as the last component and would be followed by the open: refuse links. */
        if (pl_path_is_link(out))
            pl_lua_error(L, "%s: '%s' is a symbolic link; a sandboxed scene may not %s "
                         "through links (%s)", fn, path, write ? "write" : "read", TRUST_HINT);
        return;
    }
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

/* Parses an fopen mode ("w", "a+", "r+b", ...) into open(2) flags; -1 when invalid. */
static int open_flags(const char *mode)
{
    int flags;
    switch (mode[0]) {
    case 'r': flags = 0; break;
    case 'w': flags = O_CREAT | O_TRUNC; break;
    case 'a': flags = O_CREAT | O_APPEND; break;
    default: return -1;
    }
    const char *p = mode + 1;
    int plus = *p == '+';
    if (plus) p++;
    while (*p == 'b') p++;
    if (*p) return -1;
    return flags | (plus ? O_RDWR : mode[0] == 'r' ? O_RDONLY : O_WRONLY);
}

FILE *pl_lua_output_fopen(lua_State *L, const char *path, const char *mode, char *resolved,
                          size_t n, const char *fn)
{
    pl_lua_output_path(L, path, resolved, n, fn);
    int flags = open_flags(mode);
    if (flags < 0) pl_lua_error(L, "%s: invalid mode '%s' (use w, a, r+, w+ or a+)", fn, mode);
    /* The check above refused links; O_NOFOLLOW keeps a link created since then (by
     * another program) from redirecting the write. */
    int fd = open(resolved, flags | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0) return NULL;
    FILE *f = fdopen(fd, mode);
    if (!f) {
        int e = errno;
        close(fd);
        errno = e;
    }
    return f;
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

/* Closes a file opened by io_open_checked (the io library's own close is static). */
static int stream_close(lua_State *L)
{
    luaL_Stream *p = (luaL_Stream *)luaL_checkudata(L, 1, LUA_FILEHANDLE);
    int res = fclose(p->f);
    return luaL_fileresult(L, res == 0, NULL);
}

static int io_open_checked(lua_State *L)
{
    const char *path = luaL_checkstring(L, 1);
    const char *mode = luaL_optstring(L, 2, "r");
    char resolved[PATH_MAX];
    if (!is_write_mode(mode)) {
        pl_lua_input_path(L, path, resolved, sizeof resolved, "io.open");
        lua_pushstring(L, resolved);
        lua_replace(L, 1);
        return call_original(L, 1);
    }
    if (pl_lua_get_context(L)->trust) {
        pl_lua_output_path(L, path, resolved, sizeof resolved, "io.open");
        lua_pushstring(L, resolved);
        lua_replace(L, 1);
        return call_original(L, 1);
    }
    /* Writing in the sandbox: opened here with O_NOFOLLOW (pl_lua_output_fopen), handed to
     * Lua as an ordinary file handle. */
    luaL_Stream *p = (luaL_Stream *)lua_newuserdatauv(L, sizeof(luaL_Stream), 0);
    p->closef = NULL; /* not yet a valid handle */
    luaL_setmetatable(L, LUA_FILEHANDLE);
    p->f = pl_lua_output_fopen(L, path, mode, resolved, sizeof resolved, "io.open");
    if (!p->f) return luaL_fileresult(L, 0, path);
    p->closef = stream_close;
    return 1;
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

/* setmetatable(t, mt) without a __gc field: Lua runs finalizers with hooks off, so an
 * endless loop in one could not be stopped by the CPU limit. */
static int setmetatable_checked(lua_State *L)
{
    if (lua_type(L, 2) == LUA_TTABLE) {
        lua_pushliteral(L, "__gc");
        int has_gc = lua_rawget(L, 2) != LUA_TNIL;
        lua_pop(L, 1);
        if (has_gc)
            return pl_lua_error(L, "setmetatable: a __gc metamethod (finalizer) is not allowed "
                                "in a sandboxed scene: finalizers run where the CPU limit "
                                "cannot stop them (%s)", TRUST_HINT);
    }
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

/* ---------------------------------------------------------------- require */

/* In the sandbox `require` is this function: package.loaded, then package.preload (the
 * porelab module and its embedded helpers, lua/embed.cmake), then Lua source files in the
 * scene's folder: NAME.lua or NAME/init.lua with the dots of NAME as folders. It reads no
 * package.path, package.cpath or package.searchers (whatever the scene sets), loads text
 * chunks only and never C code. */

/* Checks a module name: dot-separated parts of letters, digits, '_' and '-'. */
static int valid_module_name(const char *name)
{
    int part = 0;
    for (const char *p = name;; p++) {
        if (*p == '.' || *p == '\0') {
            if (part == 0) return 0;
            if (*p == '\0') return 1;
            part = 0;
            continue;
        }
        if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') ||
              *p == '_' || *p == '-'))
            return 0;
        part++;
    }
}

/* Loads the file rel (relative to the scene's folder) as a text chunk and pushes it;
 * returns 0 when the file does not exist. Raises errors for anything else. */
static int load_module_file(lua_State *L, const char *name, const char *rel)
{
    pl_lua_context *ctx = pl_lua_get_context(L);
    char joined[PATH_MAX], resolved[PATH_MAX];
    pl_path_join(joined, sizeof joined, ctx->scene_dir, rel);
    if (!realpath(joined, resolved)) return 0;
    char shown[PATH_MAX + 64], dir[PATH_MAX]; /* named like the scene in messages */
    pl_path_dirname(ctx->scene_path, dir, sizeof dir);
    if (strcmp(dir, ".") == 0) snprintf(shown, sizeof shown, "%s", rel);
    else snprintf(shown, sizeof shown, "%s/%s", dir, rel);
    if (!pl_path_inside(resolved, ctx->scene_dir))
        pl_lua_error(L, "require '%s': %s leads outside the scene's folder (a link to %s); "
                     "a sandboxed scene may require only files in its folder (%s)", name,
                     shown, resolved, TRUST_HINT);
    FILE *f = fopen(resolved, "rb");
    if (!f) pl_lua_error(L, "require '%s': cannot read %s: %s", name, shown, strerror(errno));
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    char chunk[8192];
    size_t k;
    while ((k = fread(chunk, 1, sizeof chunk, f)) > 0) luaL_addlstring(&b, chunk, k);
    int failed = ferror(f);
    fclose(f);
    if (failed) pl_lua_error(L, "require '%s': cannot read %s", name, shown);
    luaL_pushresult(&b);
    size_t len;
    const char *text = lua_tolstring(L, -1, &len);
    if (len > 0 && text[0] == LUA_SIGNATURE[0])
        pl_lua_error(L, "require '%s': %s is a precompiled (binary) chunk; a sandboxed scene "
                     "may load only Lua source text (%s)", name, shown, TRUST_HINT);
    size_t skip = 0; /* a first line "#!..." is skipped, as lua does, keeping its newline */
    if (len > 0 && text[0] == '#')
        while (skip < len && text[skip] != '\n') skip++;
    lua_pushfstring(L, "@%s", shown);
    if (luaL_loadbufferx(L, text + skip, len - skip, lua_tostring(L, -1), "t") != LUA_OK)
        return lua_error(L); /* a syntax error: "shown:line: ..." */
    lua_replace(L, -3);
    lua_pop(L, 1);
    return 1;
}

/* "porelab.packing, porelab.mimes, ..." (pushed; stays on the stack). */
static const char *helper_names(lua_State *L)
{
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    for (int i = 0; i < pl_lua_lib_count; i++) {
        if (i) luaL_addstring(&b, ", ");
        luaL_addstring(&b, pl_lua_libs[i].name);
    }
    luaL_pushresult(&b);
    return lua_tostring(L, -1);
}

static int sandbox_require(lua_State *L)
{
    const char *name = luaL_checkstring(L, 1);
    lua_settop(L, 1);
    luaL_getsubtable(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE); /* 2 */
    if (lua_getfield(L, 2, name) != LUA_TNIL && lua_toboolean(L, -1)) return 1;
    lua_pop(L, 1);
    luaL_getsubtable(L, LUA_REGISTRYINDEX, LUA_PRELOAD_TABLE); /* 3 */
    if (lua_getfield(L, 3, name) == LUA_TFUNCTION) { /* 4: loader */
        lua_pushliteral(L, ":preload:");         /* 5 */
    } else {
        lua_pop(L, 1);
        if (!valid_module_name(name))
            return pl_lua_error(L, "require: '%s' is not a module name (dot-separated names of "
                                "letters, digits, '_' and '-', e.g. \"helpers\" or "
                                "\"lib.walls\")", name);
        char rel[PATH_MAX], rel2[PATH_MAX + 16];
        snprintf(rel, sizeof rel, "%s", name);
        for (char *p = rel; *p; p++)
            if (*p == '.') *p = '/';
        snprintf(rel2, sizeof rel2, "%s/init.lua", rel);
        strncat(rel, ".lua", sizeof rel - strlen(rel) - 1);
        const char *found = load_module_file(L, name, rel) ? rel
                          : load_module_file(L, name, rel2) ? rel2 : NULL;
        if (!found)
            return pl_lua_error(L, "require: module '%s' not found: a sandboxed scene may "
                                "require porelab's helpers (%s) and Lua files in its own "
                                "folder (%s or %s there; package.path is not used)", name,
                                helper_names(L), rel, rel2);
        lua_pushstring(L, found); /* 5 */
    }
    lua_pushvalue(L, 4);
    lua_pushvalue(L, 1);
    lua_pushvalue(L, 5);
    lua_call(L, 2, 1);
    if (!lua_isnil(L, -1)) lua_setfield(L, 2, name);
    else lua_pop(L, 1);
    if (lua_getfield(L, 2, name) == LUA_TNIL) {
        lua_pushboolean(L, 1);
        lua_copy(L, -1, -2);
        lua_setfield(L, 2, name);
    }
    lua_pushvalue(L, 5);
    return 2;
}

/* package fields a sandboxed scene may not change: the search paths and searchers (which
 * sandbox_require ignores anyway) and the C loader. */
static const char *const package_fixed[] = {"path", "cpath", "searchers", "searchpath",
                                            "loadlib", NULL};

static int package_index(lua_State *L)
{
    const char *k = lua_tostring(L, 2);
    if (k && strcmp(k, "path") == 0) {
        lua_pushvalue(L, lua_upvalueindex(1));
        return 1;
    }
    if (k && strcmp(k, "cpath") == 0) {
        lua_pushliteral(L, "");
        return 1;
    }
    if (k && (strcmp(k, "searchpath") == 0 || strcmp(k, "loadlib") == 0)) {
        lua_pushfstring(L, "package.%s", k);
        lua_pushcclosure(L, refused, 1);
        return 1;
    }
    return 0;
}

static int package_newindex(lua_State *L)
{
    const char *k = lua_tostring(L, 2);
    for (int i = 0; k && package_fixed[i]; i++)
        if (strcmp(k, package_fixed[i]) == 0)
            return pl_lua_error(L, "package.%s cannot be changed in a sandboxed scene: require "
                                "looks only in the scene's folder and porelab's library (%s)",
                                k, TRUST_HINT);
    lua_rawset(L, 1);
    return 0;
}

/* Module search: the scene's folder first; in the sandbox the require above. */
static void restrict_require(lua_State *L, int trust, const char *scene_dir)
{
    lua_getglobal(L, "package");
    int pkg = lua_gettop(L);
    if (trust) {
        lua_getfield(L, pkg, "path");
        const char *old = lua_tostring(L, -1);
        lua_pushfstring(L, "%s/?.lua;%s/?/init.lua;%s", scene_dir, scene_dir, old ? old : "");
        lua_setfield(L, pkg, "path");
        lua_pop(L, 2);
        return;
    }
    for (int i = 0; package_fixed[i]; i++) {
        lua_pushnil(L);
        lua_setfield(L, pkg, package_fixed[i]);
    }
    lua_createtable(L, 0, 2);
    lua_pushfstring(L, "%s/?.lua;%s/?/init.lua", scene_dir, scene_dir);
    lua_pushcclosure(L, package_index, 1);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, package_newindex);
    lua_setfield(L, -2, "__newindex");
    lua_pushliteral(L, "package");
    lua_setfield(L, -2, "__metatable");
    lua_setmetatable(L, pkg);
    lua_pop(L, 1);
    lua_pushcfunction(L, sandbox_require);
    lua_setglobal(L, "require");
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
    wrap_global(L, NULL, "setmetatable", setmetatable_checked, -1, NULL);
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
