/* Shape generators as body constructors (engine/include/porelab/shapes.h):
 *   w:ngon{center =, radius =, sides =, ...}              regular polygon (circumradius)
 *   w:superquad{center =, a =, b =, n1 =, n2 =, sides =, ...}   |x/a|^n1 + |y/b|^n2 = 1
 *   w:random_polygon{center =, seed =, corners = {min, max}, axis = {a_min, a_max},
 *                    aspect = {min, max}, jitter =, ...}   seed 004 §2.1 grains
 * Each also takes the common body fields (material, motion, fixed, velocity, omega, angle, id);
 * `angle` turns the generated outline about its centroid. */
#include "wrap.h"
#include "run_inputs.h"
#include "lua_util.h"
#include "porelab/shapes.h"

#include <math.h>
#include <stdio.h>

static int add_polygon(lua_State *L, pl_body_def *d, pl_vec2 *v, int n, const char *fn, const char *err)
{
    if (n < 3) pl_lua_error(L, "%s: %s", fn, err[0] ? err : "could not build the outline");
    d->shape = PL_SHAPE_POLYGON;
    d->vertices = v;
    d->vertex_count = n;
    pl_lua_add_body(L, 1, d, fn);
    return 1;
}

static int range_pair(lua_State *L, const char *fn, const char *field, double *lo, double *hi)
{
    if (!pl_lua_has_field(L, 2, field)) return 0;
    const pl_vec2 r = pl_lua_field_vec2(L, 2, fn, field, (pl_vec2){*lo, *hi});
    *lo = r.x;
    *hi = r.y;
    return 1;
}

int pl_lua_w_ngon(lua_State *L)
{
    static const char *const fields[] = {PL_LUA_COMMON_BODY_FIELDS, "center", "radius", "sides", NULL};
    const char *fn = "ngon";
    pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    pl_body_def d = pl_lua_read_common(L, fn, PL_MOTION_DYNAMIC);
    const pl_vec2 c = pl_lua_required_vec2(L, fn, "center");
    const double r = pl_lua_required_positive(L, fn, "radius");
    const int sides = pl_lua_field_int(L, 2, fn, "sides", 6);
    char range[32];
    snprintf(range, sizeof range, "in 3..%d", PL_MAX_POLY_VERTICES);
    PL_LUA_CHECK(L, sides >= 3 && sides <= PL_MAX_POLY_VERTICES, fn, "sides", range, sides);
    pl_vec2 v[PL_MAX_POLY_VERTICES];
    char err[256] = "";
    const int n = pl_shape_regular_polygon(c, r, sides, 0, v, PL_MAX_POLY_VERTICES, err, sizeof err);
    return add_polygon(L, &d, v, n, fn, err);
}

int pl_lua_w_superquad(lua_State *L)
{
    static const char *const fields[] = {PL_LUA_COMMON_BODY_FIELDS, "center", "a", "b", "n1", "n2", "n", "sides",
                                         NULL};
    const char *fn = "superquad";
    pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    pl_body_def d = pl_lua_read_common(L, fn, PL_MOTION_DYNAMIC);
    pl_superquad_def q = pl_default_superquad_def();
    q.center = pl_lua_required_vec2(L, fn, "center");
    q.a = pl_lua_required_positive(L, fn, "a");
    q.b = pl_lua_field_number(L, 2, fn, "b", q.a);
    PL_LUA_CHECK(L, q.b > 0 && isfinite(q.b), fn, "b", "> 0 m", q.b);
    const double n = pl_lua_field_number(L, 2, fn, "n", 2);
    q.n1 = pl_lua_field_number(L, 2, fn, "n1", n);
    q.n2 = pl_lua_field_number(L, 2, fn, "n2", n);
    PL_LUA_CHECK(L, q.n1 >= 1 && isfinite(q.n1), fn, "n1", ">= 1 (convex)", q.n1);
    PL_LUA_CHECK(L, q.n2 >= 1 && isfinite(q.n2), fn, "n2", ">= 1 (convex)", q.n2);
    q.sides = pl_lua_field_int(L, 2, fn, "sides", q.sides);
    char range[32];
    snprintf(range, sizeof range, "in 4..%d", PL_MAX_POLY_VERTICES);
    PL_LUA_CHECK(L, q.sides >= 4 && q.sides <= PL_MAX_POLY_VERTICES, fn, "sides", range, q.sides);
    pl_vec2 v[PL_MAX_POLY_VERTICES];
    char err[256] = "";
    const int k = pl_shape_superquad(&q, v, PL_MAX_POLY_VERTICES, err, sizeof err);
    return add_polygon(L, &d, v, k, fn, err);
}

int pl_lua_w_random_polygon(lua_State *L)
{
    static const char *const fields[] = {PL_LUA_COMMON_BODY_FIELDS, "center", "seed", "corners", "axis", "aspect",
                                         "jitter", NULL};
    const char *fn = "random_polygon";
    pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    pl_body_def d = pl_lua_read_common(L, fn, PL_MOTION_DYNAMIC);
    const pl_vec2 c = pl_lua_required_vec2(L, fn, "center");
    pl_random_polygon_def r = pl_default_random_polygon_def();
    double cmin = r.min_corners, cmax = r.max_corners;
    range_pair(L, fn, "corners", &cmin, &cmax);
    char range[48];
    snprintf(range, sizeof range, "{min, max} in 3..%d, min <= max", PL_MAX_POLY_VERTICES);
    PL_LUA_CHECK(L, cmin >= 3 && cmax <= PL_MAX_POLY_VERTICES && cmin <= cmax && cmin == floor(cmin) &&
                        cmax == floor(cmax), fn, "corners", range, cmin);
    r.min_corners = (int)cmin;
    r.max_corners = (int)cmax;
    range_pair(L, fn, "axis", &r.a_min, &r.a_max);
    PL_LUA_CHECK(L, r.a_min > 0 && r.a_max >= r.a_min && isfinite(r.a_max), fn, "axis",
                 "{a_min, a_max} with 0 < a_min <= a_max (m)", r.a_min);
    range_pair(L, fn, "aspect", &r.aspect_min, &r.aspect_max);
    PL_LUA_CHECK(L, r.aspect_min > 0 && r.aspect_max >= r.aspect_min && r.aspect_max <= 1, fn, "aspect",
                 "{min, max} in (0, 1], min <= max", r.aspect_min);
    r.jitter = pl_lua_field_number(L, 2, fn, "jitter", r.jitter);
    PL_LUA_CHECK(L, r.jitter >= 0 && r.jitter <= 0.9, fn, "jitter", "in 0..0.9", r.jitter);
    if (!pl_lua_has_field(L, 2, "seed")) pl_lua_error(L, "%s: seed is required (an integer: the same seed gives the same polygon)", fn);
    lua_getfield(L, 2, "seed");
    if (!lua_isinteger(L, -1)) pl_lua_error(L, "%s: seed must be an integer (got %s)", fn, luaL_typename(L, -1));
    const lua_Integer seed = lua_tointeger(L, -1);
    lua_pop(L, 1);
    pl_rng rng;
    pl_rng_seed(&rng, pl_lua_mix_seed(L, (uint64_t)seed)); /* the run seed feeds it too */
    pl_vec2 v[PL_MAX_POLY_VERTICES];
    char err[256] = "";
    const int n = pl_shape_random_polygon(&r, &rng, c, v, PL_MAX_POLY_VERTICES, err, sizeof err);
    return add_polygon(L, &d, v, n, fn, err);
}
