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

/* Range checks for numbers read from scenes: v must be finite and in [lo, hi] (the lower end
 * excluded with PL_LUA_OPEN_LO, i.e. (lo, hi]); otherwise raises
 * "fn: field must be a finite number in [lo, hi] unit (got v)" at the scene line. */
/* The ranges of scene numbers (docs/scene-reference.md): wide enough for any scene in SI or
 * MIMES units, finite, and far from overflow in energies (m v^2, k delta^2). */
#define PL_LUA_MAX_COORD 1e6     /* positions, lengths, radii, m */
#define PL_LUA_MAX_SPEED 1e6     /* m/s */
#define PL_LUA_MAX_SPIN 1e6      /* rad/s */
#define PL_LUA_MAX_ANGLE 1e4     /* rad */
#define PL_LUA_MAX_ACCEL 1e6     /* gravity, m/s^2 (the GRAVITY_X/Y flags' range) */
#define PL_LUA_MAX_FORCE 1e15    /* loads, cohesion, N (moments N m) */
#define PL_LUA_MAX_DENSITY 1e9   /* kg/m^3 */
#define PL_LUA_MAX_STIFFNESS 1e15 /* kn, ks N/m, young Pa */
#define PL_LUA_MAX_DASHPOT 1e12  /* cn, cs N s/m, global damping */
#define PL_LUA_MAX_FRICTION 100  /* friction and rolling coefficients */
#define PL_LUA_CLOSED 0
#define PL_LUA_OPEN_LO 1
void pl_lua_check_range(lua_State *L, const char *fn, const char *field, double v, double lo,
                        double hi, int open_lo, const char *unit);
/* Both components finite and within -limit..limit: "fn: field must be a vector of finite
 * numbers within +-limit unit (got {x, y})". */
void pl_lua_check_vec2_range(lua_State *L, const char *fn, const char *field, pl_vec2 v,
                             double limit, const char *unit);

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
