/* porelab.csv(path, columns): a CSV writer for time series, writing inside the output
 * folder. csv:row(v1, v2, ...) or csv:row{v1, v2, ...}; csv:close(). */
#include "wrap.h"
#include "lua_util.h"
#include "sandbox.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

typedef struct csv_ud {
    FILE *f;
    int columns;
    char path[PATH_MAX];
} csv_ud;

static void write_field(FILE *f, lua_State *L, int idx)
{
    if (lua_type(L, idx) == LUA_TNUMBER) {
        if (lua_isinteger(L, idx))
            fprintf(f, "%lld", (long long)lua_tointeger(L, idx));
        else
            fprintf(f, "%.12g", lua_tonumber(L, idx));
        return;
    }
    const char *s = lua_tostring(L, idx);
    if (!strpbrk(s, ",\"\n\r")) {
        fputs(s, f);
        return;
    }
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"') fputc('"', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

int pl_lua_csv_new(lua_State *L)
{
    const char *fn = "csv";
    const char *path = luaL_checkstring(L, 1);
    luaL_checktype(L, 2, LUA_TTABLE);
    int n = (int)luaL_len(L, 2);
    if (n < 1) pl_lua_error(L, "%s: columns must be a non-empty list of names", fn);
    for (int i = 1; i <= n; i++) {
        if (lua_geti(L, 2, i) != LUA_TSTRING)
            pl_lua_error(L, "%s: column %d must be a string (got %s)", fn, i,
                         luaL_typename(L, -1));
        lua_pop(L, 1);
    }
    csv_ud *c = lua_newuserdatauv(L, sizeof *c, 0);
    memset(c, 0, sizeof *c);
    luaL_setmetatable(L, PL_LUA_CSV_MT);
    pl_lua_output_path(L, path, c->path, sizeof c->path, fn);
    c->f = fopen(c->path, "w");
    if (!c->f) pl_lua_error(L, "%s: cannot write '%s': %s", fn, c->path, strerror(errno));
    c->columns = n;
    for (int i = 1; i <= n; i++) {
        lua_geti(L, 2, i);
        if (i > 1) fputc(',', c->f);
        write_field(c->f, L, -1);
        lua_pop(L, 1);
    }
    fputc('\n', c->f);
    return 1;
}

static csv_ud *check_open(lua_State *L, const char *fn)
{
    csv_ud *c = luaL_checkudata(L, 1, PL_LUA_CSV_MT);
    if (!c->f) pl_lua_error(L, "%s: the CSV file '%s' is closed", fn, c->path);
    return c;
}

static int c_row(lua_State *L)
{
    const char *fn = "csv:row";
    csv_ud *c = check_open(L, fn);
    int first = 2, n = lua_gettop(L) - 1;
    if (n == 1 && lua_istable(L, 2)) { /* csv:row{...} */
        n = (int)luaL_len(L, 2);
        for (int i = 1; i <= n; i++) lua_geti(L, 2, i);
        first = 3;
    }
    if (n != c->columns)
        pl_lua_error(L, "%s: expected %d values (one per column), got %d", fn, c->columns, n);
    for (int i = 0; i < n; i++) {
        int t = lua_type(L, first + i);
        if (t != LUA_TNUMBER && t != LUA_TSTRING)
            pl_lua_error(L, "%s: value %d must be a number or string (got %s)", fn, i + 1,
                         lua_typename(L, t));
    }
    for (int i = 0; i < n; i++) {
        if (i) fputc(',', c->f);
        write_field(c->f, L, first + i);
    }
    fputc('\n', c->f);
    return 0;
}

static int c_close(lua_State *L)
{
    csv_ud *c = luaL_checkudata(L, 1, PL_LUA_CSV_MT);
    if (c->f) {
        int bad = fclose(c->f) != 0;
        c->f = NULL;
        if (bad) pl_lua_error(L, "csv:close: writing '%s' failed", c->path);
    }
    return 0;
}

static int c_gc(lua_State *L)
{
    csv_ud *c = luaL_checkudata(L, 1, PL_LUA_CSV_MT);
    if (c->f) fclose(c->f);
    c->f = NULL;
    return 0;
}

static int c_path(lua_State *L)
{
    lua_pushstring(L, ((csv_ud *)luaL_checkudata(L, 1, PL_LUA_CSV_MT))->path);
    return 1;
}

static const luaL_Reg csv_methods[] = {
    {"row", c_row}, {"close", c_close}, {"path", c_path}, {NULL, NULL}};

void pl_lua_register_csv(lua_State *L)
{
    luaL_newmetatable(L, PL_LUA_CSV_MT);
    lua_pushcfunction(L, c_gc);
    lua_setfield(L, -2, "__gc");
    lua_pushcfunction(L, c_gc);
    lua_setfield(L, -2, "__close");
    luaL_newlib(L, csv_methods);
    lua_setfield(L, -2, "__index");
    lua_pop(L, 1);
}
