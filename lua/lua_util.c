#include "lua_util.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

int pl_lua_where_from(lua_State *L, int level)
{
    lua_Debug ar;
    /* Prefer the innermost frame running scene code (a file chunk, source "@..."); the
     * embedded helpers are named "=porelab...", so errors point at the scene line that
     * called them. */
    for (; lua_getstack(L, level, &ar); level++) {
        lua_getinfo(L, "Sl", &ar);
        if (ar.currentline > 0 && ar.source[0] == '@') {
            lua_pushfstring(L, "%s:%d: ", ar.short_src, ar.currentline);
            return 1;
        }
    }
    return 0;
}

void pl_lua_where(lua_State *L)
{
    if (!pl_lua_where_from(L, 1)) luaL_where(L, 1);
}

int pl_lua_error(lua_State *L, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    pl_lua_where(L);
    lua_pushvfstring(L, fmt, ap);
    va_end(ap);
    lua_concat(L, 2);
    return lua_error(L);
}

int pl_lua_range_error(lua_State *L, const char *fn, const char *field, const char *range,
                       double got)
{
    char num[64];
    snprintf(num, sizeof num, "%.10g", got);
    return pl_lua_error(L, "%s: %s must be %s (got %s)", fn, field, range, num);
}

void pl_lua_check_range(lua_State *L, const char *fn, const char *field, double v, double lo,
                        double hi, int open_lo, const char *unit)
{
    if (isfinite(v) && (open_lo ? v > lo : v >= lo) && v <= hi) return;
    char range[160];
    snprintf(range, sizeof range, "a finite number in %s%.10g, %.10g]%s%s", open_lo ? "(" : "[", lo,
             hi, unit && unit[0] ? " " : "", unit ? unit : "");
    pl_lua_range_error(L, fn, field, range, v);
}

void pl_lua_check_vec2_range(lua_State *L, const char *fn, const char *field, pl_vec2 v,
                             double limit, const char *unit)
{
    if (isfinite(v.x) && isfinite(v.y) && fabs(v.x) <= limit && fabs(v.y) <= limit) return;
    char gx[40], gy[40], lim[40];
    snprintf(gx, sizeof gx, "%.10g", v.x);
    snprintf(gy, sizeof gy, "%.10g", v.y);
    snprintf(lim, sizeof lim, "%.10g", limit); /* lua_pushfstring knows no %g precision */
    pl_lua_error(L, "%s: %s must be a vector of finite numbers within +-%s%s%s (got {%s, %s})", fn,
                 field, lim, unit && unit[0] ? " " : "", unit ? unit : "", gx, gy);
}

void pl_lua_check_def(lua_State *L, int arg, const char *fn)
{
    if (!lua_istable(L, arg))
        pl_lua_error(L, "%s: expected a table of fields as argument %d (got %s)", fn, arg,
                     luaL_typename(L, arg));
}

void pl_lua_join(char *buf, size_t n, const char *const names[])
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; names[i] && used < n; i++) {
        int k = snprintf(buf + used, n - used, "%s%s", i ? ", " : "", names[i]);
        if (k < 0) break;
        used += (size_t)k;
    }
}

void pl_lua_check_fields(lua_State *L, int t, const char *fn, const char *const valid[])
{
    lua_pushnil(L);
    while (lua_next(L, t)) {
        lua_pop(L, 1);
        int ok = 0;
        if (lua_type(L, -1) == LUA_TSTRING) {
            const char *k = lua_tostring(L, -1);
            for (int i = 0; valid[i]; i++)
                if (strcmp(k, valid[i]) == 0) ok = 1;
        }
        if (!ok) {
            char list[1024];
            pl_lua_join(list, sizeof list, valid);
            const char *key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1)
                                                              : luaL_tolstring(L, -1, NULL);
            pl_lua_error(L, "%s: unknown field '%s' (valid: %s)", fn, key, list);
        }
    }
}

static int field_type_error(lua_State *L, const char *fn, const char *field, const char *want)
{
    return pl_lua_error(L, "%s: %s must be %s (got %s)", fn, field, want,
                        luaL_typename(L, -1));
}

int pl_lua_has_field(lua_State *L, int t, const char *field)
{
    int present = lua_getfield(L, t, field) != LUA_TNIL;
    lua_pop(L, 1);
    return present;
}

double pl_lua_field_number(lua_State *L, int t, const char *fn, const char *field, double def)
{
    double v = def;
    if (lua_getfield(L, t, field) != LUA_TNIL) {
        if (lua_type(L, -1) != LUA_TNUMBER) field_type_error(L, fn, field, "a number");
        v = lua_tonumber(L, -1);
    }
    lua_pop(L, 1);
    return v;
}

int pl_lua_field_int(lua_State *L, int t, const char *fn, const char *field, int def)
{
    int v = def;
    if (lua_getfield(L, t, field) != LUA_TNIL) {
        int isint = 0;
        lua_Integer i = lua_tointegerx(L, -1, &isint);
        if (lua_type(L, -1) != LUA_TNUMBER || !isint || i < -2147483647 || i > 2147483647)
            field_type_error(L, fn, field, "an integer");
        v = (int)i;
    }
    lua_pop(L, 1);
    return v;
}

int pl_lua_field_bool(lua_State *L, int t, const char *fn, const char *field, int def)
{
    int v = def;
    if (lua_getfield(L, t, field) != LUA_TNIL) {
        if (lua_type(L, -1) != LUA_TBOOLEAN) field_type_error(L, fn, field, "true or false");
        v = lua_toboolean(L, -1);
    }
    lua_pop(L, 1);
    return v;
}

const char *pl_lua_field_string(lua_State *L, int t, const char *fn, const char *field,
                                const char *def)
{
    const char *v = def;
    if (lua_getfield(L, t, field) != LUA_TNIL) {
        if (lua_type(L, -1) != LUA_TSTRING) field_type_error(L, fn, field, "a string");
        v = lua_tostring(L, -1); /* stays alive: the def table holds it */
    }
    lua_pop(L, 1);
    return v;
}

int pl_lua_to_vec2(lua_State *L, int idx, pl_vec2 *out)
{
    idx = lua_absindex(L, idx);
    if (!lua_istable(L, idx)) return 0;
    int ok = 1;
    double c[2];
    const char *named[2] = {"x", "y"};
    for (int k = 0; k < 2; k++) {
        if (lua_geti(L, idx, k + 1) == LUA_TNIL) {
            lua_pop(L, 1);
            lua_getfield(L, idx, named[k]);
        }
        ok = ok && lua_type(L, -1) == LUA_TNUMBER;
        c[k] = lua_tonumber(L, -1);
        lua_pop(L, 1);
    }
    if (ok) {
        out->x = c[0];
        out->y = c[1];
    }
    return ok;
}

pl_vec2 pl_lua_field_vec2(lua_State *L, int t, const char *fn, const char *field, pl_vec2 def)
{
    pl_vec2 v = def;
    if (lua_getfield(L, t, field) != LUA_TNIL) {
        if (!pl_lua_to_vec2(L, -1, &v))
            field_type_error(L, fn, field, "a vector {x, y} of two numbers");
    }
    lua_pop(L, 1);
    return v;
}

int pl_lua_field_option(lua_State *L, int t, const char *fn, const char *field, int def,
                        const char *const names[])
{
    int v = def;
    if (lua_getfield(L, t, field) != LUA_TNIL) {
        if (lua_type(L, -1) != LUA_TSTRING) field_type_error(L, fn, field, "a string");
        const char *s = lua_tostring(L, -1);
        v = -1;
        for (int i = 0; names[i]; i++)
            if (strcmp(s, names[i]) == 0) v = i;
        if (v < 0) {
            char list[512];
            pl_lua_join(list, sizeof list, names);
            pl_lua_error(L, "%s: %s must be one of %s (got '%s')", fn, field, list, s);
        }
    }
    lua_pop(L, 1);
    return v;
}

void pl_lua_push_vec2(lua_State *L, pl_vec2 v)
{
    lua_createtable(L, 2, 2);
    lua_pushnumber(L, v.x);
    lua_rawseti(L, -2, 1);
    lua_pushnumber(L, v.y);
    lua_rawseti(L, -2, 2);
    lua_pushnumber(L, v.x);
    lua_setfield(L, -2, "x");
    lua_pushnumber(L, v.y);
    lua_setfield(L, -2, "y");
}
