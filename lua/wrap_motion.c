/* Boundary motions of bodies: body:shake{...} (shaking table), body:servo{...} (servo wall,
 * seed 003 eqs. 5.11-5.12), body:hinge{...} (side wall of a simple-shear box). */
#include "wrap.h"
#include "lua_util.h"

#include <math.h>

/* body:shake{amplitude = {ax, ay}, frequency = f, start = t0, stop = t1, ramp = r}
   x(t) = x0 + e(t) A sin(2 pi f (t - t0)) for t0 <= t <= t1; m, Hz, s; e tapers the amplitude
   in and out over r seconds (raised cosine; 0 = none, at most half of t1 - t0). */
static int b_shake(lua_State *L)
{
    static const char *const fields[] = {"amplitude", "frequency", "start", "stop", "ramp", NULL};
    const char *fn = "shake";
    pl_world *w;
    const int i = pl_lua_check_body(L, 1, &w);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    if (!pl_lua_has_field(L, 2, "amplitude") || !pl_lua_has_field(L, 2, "frequency"))
        pl_lua_error(L, "shake: amplitude = {ax, ay} (m) and frequency (Hz) are required");
    const pl_vec2 a = pl_lua_field_vec2(L, 2, fn, "amplitude", (pl_vec2){0, 0});
    const double f = pl_lua_field_number(L, 2, fn, "frequency", 0);
    PL_LUA_CHECK(L, f > 0 && isfinite(f), fn, "frequency", "> 0 Hz", f);
    const double t0 = pl_lua_field_number(L, 2, fn, "start", pl_world_time(w));
    const double t1 = pl_lua_field_number(L, 2, fn, "stop", INFINITY);
    PL_LUA_CHECK(L, t1 >= t0, fn, "stop", ">= start", t1);
    const double ramp = pl_lua_field_number(L, 2, fn, "ramp", 0);
    PL_LUA_CHECK(L, ramp >= 0 && isfinite(ramp) && (isinf(t1) || ramp <= 0.5 * (t1 - t0)), fn, "ramp",
                 "0 .. half of stop - start (s)", ramp);
    pl_lua_check_status(L, w, pl_world_set_sinusoid(w, i, a, f, t0, t1), fn);
    pl_lua_check_status(L, w, pl_world_set_sinusoid_ramp(w, i, ramp), fn);
    return 0;
}

/* body:servo{direction = {dx, dy}, force = F, gain = G, vmax = V [, drive = {vx, vy}, fluid = b]}:
   the body moves along the direction it pushes in so that the contact force it receives holds F
   (N per m of depth); drive adds a velocity across that direction, fluid = true counts the pore
   fluid's force too. */
static int b_servo(lua_State *L)
{
    static const char *const fields[] = {"direction", "force", "gain", "vmax", "drive", "fluid", NULL};
    const char *fn = "servo";
    pl_world *w;
    const int i = pl_lua_check_body(L, 1, &w);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    if (!pl_lua_has_field(L, 2, "direction") || !pl_lua_has_field(L, 2, "force"))
        pl_lua_error(L, "servo: direction = {dx, dy} and force (N) are required");
    const pl_vec2 d = pl_lua_field_vec2(L, 2, fn, "direction", (pl_vec2){0, -1});
    const double F = pl_lua_field_number(L, 2, fn, "force", 0);
    PL_LUA_CHECK(L, F > 0 && isfinite(F), fn, "force", "> 0 N", F);
    const double g = pl_lua_field_number(L, 2, fn, "gain", 0.1);
    PL_LUA_CHECK(L, g > 0 && isfinite(g), fn, "gain", "> 0 m/s", g);
    const double v = pl_lua_field_number(L, 2, fn, "vmax", 0.05);
    PL_LUA_CHECK(L, v > 0 && isfinite(v), fn, "vmax", "> 0 m/s", v);
    pl_lua_check_status(L, w, pl_world_set_servo(w, i, d, F, g, v), fn);
    /* extras (engine/src/dem/servo_drive.c): drive = {vx, vy} across the servo direction,
       fluid = true to hold the total (contact + pore fluid) force */
    const pl_vec2 drive = pl_lua_field_vec2(L, 2, fn, "drive", (pl_vec2){0, 0});
    int with_fluid = 0;
    if (pl_lua_has_field(L, 2, "fluid")) {
        lua_getfield(L, 2, "fluid");
        if (!lua_isboolean(L, -1)) pl_lua_error(L, "servo: fluid must be a boolean (got %s)", luaL_typename(L, -1));
        with_fluid = lua_toboolean(L, -1);
        lua_pop(L, 1);
    }
    if (drive.x != 0 || drive.y != 0 || with_fluid)
        pl_lua_check_status(L, w, pl_world_set_servo_drive(w, i, drive, with_fluid), fn);
    return 0;
}

/* body:hinge{pivot = {x, y}, follow = top_wall, height = H} */
static int b_hinge(lua_State *L)
{
    static const char *const fields[] = {"pivot", "follow", "height", NULL};
    const char *fn = "hinge";
    pl_world *w;
    const int i = pl_lua_check_body(L, 1, &w);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    if (!pl_lua_has_field(L, 2, "pivot") || !pl_lua_has_field(L, 2, "follow") || !pl_lua_has_field(L, 2, "height"))
        pl_lua_error(L, "hinge: pivot = {x, y}, follow = <body> and height (m) are required");
    const pl_vec2 p = pl_lua_field_vec2(L, 2, fn, "pivot", (pl_vec2){0, 0});
    lua_getfield(L, 2, "follow");
    pl_world *w2;
    const int f = pl_lua_check_body(L, lua_gettop(L), &w2);
    lua_pop(L, 1);
    if (w2 != w) pl_lua_error(L, "hinge: follow must be a body of the same world");
    const double h = pl_lua_field_number(L, 2, fn, "height", 0);
    PL_LUA_CHECK(L, h > 0 && isfinite(h), fn, "height", "> 0 m", h);
    pl_lua_check_status(L, w, pl_world_set_hinge(w, i, p, f, h), fn);
    return 0;
}

const luaL_Reg pl_lua_motion_methods[] = {{"shake", b_shake}, {"servo", b_servo}, {"hinge", b_hinge}, {NULL, NULL}};
