/* Helpers shared by the Lua wrappers: errors that name the scene file and line, reading
 * def tables field by field with type and range checks, vectors, and option names. */
#ifndef PL_LUA_UTIL_H
#define PL_LUA_UTIL_H

#include <lua.h>
#include <lauxlib.h>
#include "porelab/core.h"

/* Pushes "file:line: " of the innermost scene-file frame (skipping embedded porelab
 * libraries, whose chunk names start with '='), or "" when there is none. */
void pl_lua_where(lua_State *L);
/* The same, starting the search at stack level `level` (0 inside a hook: the function that
 * was running). Returns 1 when a scene-file frame was found (its location pushed), 0 when
 * not (nothing pushed). */
int pl_lua_where_from(lua_State *L, int level);

/* Raises a Lua error "file:line: <message>" located at the scene line (see pl_lua_where). */
int pl_lua_error(lua_State *L, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Raises "fn: field must be <range> (got v)". */
int pl_lua_range_error(lua_State *L, const char *fn, const char *field, const char *range,
                       double got);
#define PL_LUA_CHECK(L, cond, fn, field, range, v)                                        \
    do {                                                                                   \
        if (!(cond)) pl_lua_range_error((L), (fn), (field), (range), (v));                 \
    } while (0)

/* Checks that argument arg is a table (a "def" table); raises "fn: expected a table ...". */
void pl_lua_check_def(lua_State *L, int arg, const char *fn);

/* Raises an error naming the first key of table t that is not in valid (NULL-terminated),
 * listing the valid ones. Catches typos such as "radious". */
void pl_lua_check_fields(lua_State *L, int t, const char *fn, const char *const valid[]);

/* Field readers for the def table at absolute index t. A missing (nil) field gives def;
 * a field of the wrong type raises "fn: field must be a <type> (got <type>)". */
double pl_lua_field_number(lua_State *L, int t, const char *fn, const char *field, double def);
int pl_lua_field_int(lua_State *L, int t, const char *fn, const char *field, int def);
int pl_lua_field_bool(lua_State *L, int t, const char *fn, const char *field, int def);
const char *pl_lua_field_string(lua_State *L, int t, const char *fn, const char *field,
                                const char *def);
pl_vec2 pl_lua_field_vec2(lua_State *L, int t, const char *fn, const char *field, pl_vec2 def);
/* Option string among names (NULL-terminated); returns its index or def when missing. */
int pl_lua_field_option(lua_State *L, int t, const char *fn, const char *field, int def,
                        const char *const names[]);
/* 1 when the field is present (not nil). */
int pl_lua_has_field(lua_State *L, int t, const char *field);

/* Reads a vector from the value at index idx: {x, y} or {x = .., y = ..}. Returns 0 when
 * the value is not a vector. */
int pl_lua_to_vec2(lua_State *L, int idx, pl_vec2 *out);
/* Pushes a {x, y} table with both array and named fields. */
void pl_lua_push_vec2(lua_State *L, pl_vec2 v);

/* Joins names (NULL-terminated) with ", " into the buffer (truncating). */
void pl_lua_join(char *buf, size_t n, const char *const names[]);

#endif
