/* porelab.world{...}: the world userdata, its stepping, queries and flags. */
#include "fluid_auto.h"
#include "wrap.h"
#include "file_writer.h"
#include "lua_util.h"
#include "scene_internal.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

extern const luaL_Reg pl_lua_body_constructors[];
extern const luaL_Reg pl_lua_material_constructors[];
extern const luaL_Reg pl_lua_fluid_methods[]; /* wrap_fluid.c (fluid work) */
extern const luaL_Reg pl_lua_darcy_methods[]; /* wrap_darcy.c (the Darcy model's parameters) */
extern const luaL_Reg pl_lua_hydrostatic_methods[]; /* wrap_hydrostatic.c (hydrostatic water) */
extern const luaL_Reg pl_lua_bond_methods[]; /* wrap_bonds.c (bonds, heat, wear) */
extern const luaL_Reg pl_lua_navier_stokes_methods[]; /* wrap_navier_stokes.c (resolved Navier-Stokes) */
extern const luaL_Reg pl_lua_stokes_methods[]; /* wrap_stokes.c (boundary-element Stokes fluid) */
extern const luaL_Reg pl_lua_solid_methods[]; /* wrap_solid.c (finite-element solid) */
extern const luaL_Reg pl_lua_state_methods[]; /* wrap_state.c (w:save, w:load) */

pl_lua_world *pl_lua_check_world(lua_State *L, int idx)
{
    pl_lua_world *lw = luaL_testudata(L, idx, PL_LUA_WORLD_MT);
    if (!lw)
        luaL_argerror(L, idx, lua_pushfstring(L, "porelab.world expected, got %s%s",
                                              luaL_typename(L, idx),
                                              lua_istable(L, idx)
                                                  ? " (call methods with ':', as in w:disc{...})"
                                                  : ""));
    if (!lw->w) pl_lua_error(L, "attempt to use a destroyed world");
    return lw;
}

void pl_lua_check_status(lua_State *L, const pl_world *w, int s, const char *fn)
{
    if (s >= 0) return;
    const char *msg = pl_world_last_error(w);
    size_t k = strlen(fn);
    if (strncmp(msg, fn, k) == 0 && msg[k] == ':') /* the engine already named it */
        pl_lua_error(L, "%s", msg);
    pl_lua_error(L, "%s: %s", fn, msg[0] ? msg : pl_status_name((pl_status)s));
}

void pl_lua_mark_flag(pl_lua_world *lw, const char *name)
{
    for (int i = 0; i < lw->flag_count; i++)
        if (strcmp(pl_flag_at(i)->name, name) == 0) lw->flag_set[i] = 1;
}

/* ------------------------------------------------------------------ flags */

static const pl_flag_info *find_flag(const char *name)
{
    for (int i = 0; i < pl_flag_count(); i++)
        if (strcmp(pl_flag_at(i)->name, name) == 0) return pl_flag_at(i);
    return NULL;
}

/* Sets flag name = value at index vidx (number or boolean). The engine checks the name,
 * the range and whether the feature is built, and words the refusal. */
static void set_flag(lua_State *L, pl_lua_world *lw, const char *name, int vidx,
                     const char *fn)
{
    double v;
    if (lua_type(L, vidx) == LUA_TBOOLEAN)
        v = lua_toboolean(L, vidx);
    else if (lua_type(L, vidx) == LUA_TNUMBER)
        v = lua_tonumber(L, vidx);
    else
        return (void)pl_lua_error(L, "%s: value of flag %s must be a number or boolean (got %s)",
                                  fn, name, luaL_typename(L, vidx));
    pl_lua_check_status(L, lw->w, pl_world_set_flag(lw->w, name, v), fn);
    pl_lua_mark_flag(lw, name);
}

static int w_set_flag(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const char *name = luaL_checkstring(L, 2);
    luaL_checkany(L, 3);
    set_flag(L, lw, name, 3, "set_flag");
    return 0;
}

static int w_flag(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const char *name = luaL_checkstring(L, 2);
    double v = 0;
    pl_lua_check_status(L, lw->w, pl_world_get_flag(lw->w, name, &v), "flag");
    lua_pushnumber(L, v);
    return 1;
}

/* ---------------------------------------------------------------- creation */

static const char *const world_fields[] = {
    "gravity", "dt", "dt_safety", "max_dt", "global_damping", "global_damping_rot",
    "rayleigh_alpha", "local_damping", "skin", "max_overlap_ratio", "energy_surge_ratio",
    "guard_interval", "flags", "fluid", "needs", "water", NULL};

static pl_world_def read_world_def(lua_State *L, int t)
{
    const char *fn = "world";
    pl_world_def d = pl_default_world_def();
    if (lua_isnoneornil(L, t)) return d;
    pl_lua_check_def(L, t, fn);
    pl_lua_check_fields(L, t, fn, world_fields);
    d.gravity = pl_lua_field_vec2(L, t, fn, "gravity", d.gravity);
    pl_lua_check_vec2_range(L, fn, "gravity", d.gravity, PL_LUA_MAX_ACCEL, "m/s^2");
    d.dt = pl_lua_field_number(L, t, fn, "dt", d.dt);
    PL_LUA_CHECK(L, d.dt >= 0 && isfinite(d.dt), fn, "dt", ">= 0 s (0 = automatic)", d.dt);
    d.dt_safety = pl_lua_field_number(L, t, fn, "dt_safety", d.dt_safety);
    PL_LUA_CHECK(L, d.dt_safety > 0 && d.dt_safety <= 1, fn, "dt_safety", "in (0, 1]",
                 d.dt_safety);
    d.max_dt = pl_lua_field_number(L, t, fn, "max_dt", d.max_dt);
    PL_LUA_CHECK(L, d.max_dt >= 0 && isfinite(d.max_dt), fn, "max_dt", ">= 0 s (0 = no cap)", d.max_dt);
    d.global_c = pl_lua_field_number(L, t, fn, "global_damping", d.global_c);
    pl_lua_check_range(L, fn, "global_damping", d.global_c, 0, PL_LUA_MAX_DASHPOT, PL_LUA_CLOSED, "N s/m");
    d.global_c_rot = pl_lua_field_number(L, t, fn, "global_damping_rot", d.global_c_rot);
    pl_lua_check_range(L, fn, "global_damping_rot", d.global_c_rot, 0, PL_LUA_MAX_DASHPOT, PL_LUA_CLOSED,
                       "N m s");
    d.rayleigh_alpha = pl_lua_field_number(L, t, fn, "rayleigh_alpha", d.rayleigh_alpha);
    pl_lua_check_range(L, fn, "rayleigh_alpha", d.rayleigh_alpha, 0, 1e9, PL_LUA_CLOSED, "1/s");
    d.local_damping = pl_lua_field_number(L, t, fn, "local_damping", d.local_damping);
    PL_LUA_CHECK(L, d.local_damping >= 0 && d.local_damping < 1, fn, "local_damping",
                 "in [0, 1)", d.local_damping);
    d.skin = pl_lua_field_number(L, t, fn, "skin", d.skin);
    pl_lua_check_range(L, fn, "skin", d.skin, 0, PL_LUA_MAX_COORD, PL_LUA_CLOSED, "m (0 = automatic)");
    d.max_overlap_ratio = pl_lua_field_number(L, t, fn, "max_overlap_ratio",
                                              d.max_overlap_ratio);
    pl_lua_check_range(L, fn, "max_overlap_ratio", d.max_overlap_ratio, 0, 100, PL_LUA_OPEN_LO, "");
    d.energy_surge_ratio = pl_lua_field_number(L, t, fn, "energy_surge_ratio",
                                               d.energy_surge_ratio);
    pl_lua_check_range(L, fn, "energy_surge_ratio", d.energy_surge_ratio, 0, 1e12, PL_LUA_OPEN_LO, "");
    d.guard_interval = pl_lua_field_int(L, t, fn, "guard_interval", d.guard_interval);
    PL_LUA_CHECK(L, d.guard_interval >= 1, fn, "guard_interval", ">= 1 step",
                 d.guard_interval);
    return d;
}

/* Applies world{flags = {NAME = value, ...}} in name order (deterministic). */
static void apply_def_flags(lua_State *L, int t, int world_idx)
{
    if (lua_isnoneornil(L, t) || lua_getfield(L, t, "flags") == LUA_TNIL) {
        if (!lua_isnoneornil(L, t)) lua_pop(L, 1);
        return;
    }
    int ft = lua_gettop(L);
    if (!lua_istable(L, ft))
        pl_lua_error(L, "world: flags must be a table {NAME = value} (got %s)",
                     luaL_typename(L, ft));
    pl_lua_world *lw = pl_lua_check_world(L, world_idx);
    for (int i = 0; i < pl_flag_count(); i++) { /* table order is not deterministic */
        if (lua_getfield(L, ft, pl_flag_at(i)->name) != LUA_TNIL)
            set_flag(L, lw, pl_flag_at(i)->name, lua_gettop(L), "world");
        lua_pop(L, 1);
    }
    lua_pushnil(L); /* anything left over is unknown: let the engine word it */
    while (lua_next(L, ft)) {
        const char *k = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : "?";
        if (!find_flag(k)) set_flag(L, lw, k, lua_gettop(L), "world");
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
}

int pl_lua_world_new(lua_State *L)
{
    pl_world_def def = read_world_def(L, 1);
    pl_lua_world *lw = lua_newuserdatauv(L, sizeof *lw, 1); /* user value 1: fluid = "auto" (fluid_auto.c) */
    memset(lw, 0, sizeof *lw);
    luaL_setmetatable(L, PL_LUA_WORLD_MT);
    lw->flag_count = pl_flag_count();
    lw->flag_set = calloc((size_t)lw->flag_count + 1, 1);
    lw->w = pl_world_create(&def);
    if (!lw->w || !lw->flag_set) return pl_lua_error(L, "world: out of memory");
    pl_lua_context *ctx = pl_lua_get_context(L);
    if (ctx) { /* the engine's files (VTK, MIMES output) go inside the output folder */
        const pl_file_writer fw = pl_lua_file_writer(ctx);
        pl_world_set_file_writer(lw->w, &fw);
    }
    int idx = lua_gettop(L);
    pl_lua_fluid_auto_read(L, 1, idx);
    apply_def_flags(L, 1, idx);
    lua_settop(L, idx);
    pl_lua_scene_note_world(L, idx);
    return 1;
}

static int w_gc(lua_State *L)
{
    pl_lua_world *lw = luaL_checkudata(L, 1, PL_LUA_WORLD_MT);
    pl_world_destroy(&lw->w);
    free(lw->flag_set);
    lw->flag_set = NULL;
    return 0;
}

static int w_tostring(lua_State *L)
{
    pl_lua_world *lw = luaL_checkudata(L, 1, PL_LUA_WORLD_MT);
    if (!lw->w) {
        lua_pushliteral(L, "porelab.world (destroyed)");
        return 1;
    }
    lua_pushfstring(L, "porelab.world (%d bodies, %d materials, t = %f s)",
                    pl_world_body_count(lw->w), pl_world_material_count(lw->w),
                    pl_world_time(lw->w));
    return 1;
}

/* ---------------------------------------------------------------- stepping */

static void step_checked(lua_State *L, pl_world *w, lua_Integer n, const char *fn)
{
    while (n > 0) { /* pl_world_step takes an int */
        int chunk = n > 1000000 ? 1000000 : (int)n;
        pl_lua_check_status(L, w, pl_world_step(w, chunk), fn);
        n -= chunk;
    }
}

static int w_step(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    lua_Integer n = luaL_optinteger(L, 2, 1);
    if (n < 0) pl_lua_range_error(L, "step", "n", ">= 0 steps", (double)n);
    pl_lua_fluid_auto_apply(L, 1, 0); /* fluid = "auto": choose before the first step */
    step_checked(L, lw->w, n, "step");
    return 0;
}

static int w_run_until(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    double t_end = luaL_checknumber(L, 2);
    pl_lua_fluid_auto_apply(L, 1, t_end - pl_world_time(lw->w));
    double t = pl_world_time(lw->w);
    if (!(t_end >= t) || !isfinite(t_end)) {
        char range[64];
        snprintf(range, sizeof range, ">= the current time %g s", t);
        pl_lua_range_error(L, "run_until", "t", range, t_end);
    }
    double dt = pl_world_dt(lw->w);
    if (!(dt > 0)) pl_lua_check_status(L, lw->w, -1, "run_until");
    lua_Integer n = (lua_Integer)ceil((t_end - t) / dt - 1e-9);
    step_checked(L, lw->w, n, "run_until");
    lua_pushinteger(L, n);
    return 1;
}

static int w_time(lua_State *L)
{
    lua_pushnumber(L, pl_world_time(pl_lua_check_world(L, 1)->w));
    return 1;
}

static int w_steps(lua_State *L)
{
    lua_pushinteger(L, (lua_Integer)pl_world_step_count(pl_lua_check_world(L, 1)->w));
    return 1;
}

static int w_dt(lua_State *L)
{
    lua_pushnumber(L, pl_world_dt(pl_lua_check_world(L, 1)->w));
    return 1;
}

static int w_dt_report(lua_State *L)
{
    pl_dt_report r = pl_world_dt_report(pl_lua_check_world(L, 1)->w);
    lua_createtable(L, 0, 6);
    lua_pushnumber(L, r.dt);
    lua_setfield(L, -2, "dt");
    lua_pushnumber(L, r.dt_critical);
    lua_setfield(L, -2, "dt_critical");
    if (r.limiting_body >= 0) {
        lua_pushinteger(L, r.limiting_body + 1);
        lua_setfield(L, -2, "limiting_body");
    }
    lua_pushstring(L, r.limit_kind ? r.limit_kind : "");
    lua_setfield(L, -2, "limit_kind");
    lua_pushboolean(L, r.capped);
    lua_setfield(L, -2, "capped");
    lua_pushboolean(L, r.fixed);
    lua_setfield(L, -2, "fixed");
    return 1;
}

/* ----------------------------------------------------------------- queries */

static int w_body_count(lua_State *L)
{
    lua_pushinteger(L, pl_world_body_count(pl_lua_check_world(L, 1)->w));
    return 1;
}

static int w_body(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    lua_Integer i = luaL_checkinteger(L, 2);
    int n = pl_world_body_count(lw->w);
    if (i < 1 || i > n) {
        char range[64];
        snprintf(range, sizeof range, "in 1..%d", n);
        pl_lua_range_error(L, "body", "index", range, (double)i);
    }
    pl_lua_push_body(L, 1, (int)i - 1);
    return 1;
}

static int w_contact_count(lua_State *L)
{
    lua_pushinteger(L, pl_world_contact_count(pl_lua_check_world(L, 1)->w));
    return 1;
}

static int w_contacts(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    int n = pl_world_contact_count(lw->w);
    pl_contact_info *c = n > 0 ? malloc(sizeof *c * (size_t)n) : NULL;
    if (n > 0 && !c) return pl_lua_error(L, "contacts: out of memory");
    n = n > 0 ? pl_world_copy_contacts(lw->w, c, n) : 0;
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; i++) {
        lua_createtable(L, 0, 7);
        lua_pushinteger(L, c[i].a + 1);
        lua_setfield(L, -2, "a");
        lua_pushinteger(L, c[i].b + 1);
        lua_setfield(L, -2, "b");
        pl_lua_push_vec2(L, c[i].point);
        lua_setfield(L, -2, "point");
        pl_lua_push_vec2(L, c[i].normal);
        lua_setfield(L, -2, "normal");
        lua_pushnumber(L, c[i].fn);
        lua_setfield(L, -2, "fn");
        lua_pushnumber(L, c[i].ft);
        lua_setfield(L, -2, "ft");
        lua_pushnumber(L, c[i].overlap);
        lua_setfield(L, -2, "overlap");
        lua_rawseti(L, -2, i + 1);
    }
    free(c);
    return 1;
}

static int w_energy(lua_State *L)
{
    pl_energy e = pl_world_energy(pl_lua_check_world(L, 1)->w);
    const struct {
        const char *name;
        double v;
    } f[] = {{"kinetic", e.kinetic},   {"gravitational", e.gravitational},
             {"elastic", e.elastic},   {"damped", e.damped},
             {"friction", e.friction}, {"external", e.external},
             {"balance", e.balance},   {"fracture", e.fracture}};
    lua_createtable(L, 0, 8);
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++) {
        lua_pushnumber(L, f[i].v);
        lua_setfield(L, -2, f[i].name);
    }
    return 1;
}

static int w_momentum(lua_State *L)
{
    pl_vec2 p = pl_world_momentum(pl_lua_check_world(L, 1)->w);
    lua_pushnumber(L, p.x);
    lua_pushnumber(L, p.y);
    return 2;
}

static int w_hash(lua_State *L)
{
    char buf[32];
    snprintf(buf, sizeof buf, "%016" PRIx64, pl_world_state_hash(pl_lua_check_world(L, 1)->w));
    lua_pushstring(L, buf);
    return 1;
}

static int w_bounds(lua_State *L)
{
    pl_vec2 lo, hi;
    pl_world_bounds(pl_lua_check_world(L, 1)->w, &lo, &hi);
    lua_pushnumber(L, lo.x);
    lua_pushnumber(L, lo.y);
    lua_pushnumber(L, hi.x);
    lua_pushnumber(L, hi.y);
    return 4;
}

static const luaL_Reg world_methods[] = {
    {"step", w_step},
    {"run_until", w_run_until},
    {"time", w_time},
    {"steps", w_steps},
    {"dt", w_dt},
    {"dt_report", w_dt_report},
    {"body_count", w_body_count},
    {"body", w_body},
    {"contact_count", w_contact_count},
    {"contacts", w_contacts},
    {"energy", w_energy},
    {"momentum", w_momentum},
    {"hash", w_hash},
    {"bounds", w_bounds},
    {"set_flag", w_set_flag},
    {"flag", w_flag},
    {NULL, NULL}};

void pl_lua_register_world(lua_State *L)
{
    luaL_newmetatable(L, PL_LUA_WORLD_MT);
    lua_pushcfunction(L, w_gc);
    lua_setfield(L, -2, "__gc");
    lua_pushcfunction(L, w_tostring);
    lua_setfield(L, -2, "__tostring");
    lua_newtable(L);
    luaL_setfuncs(L, world_methods, 0);
    luaL_setfuncs(L, pl_lua_body_constructors, 0);
    luaL_setfuncs(L, pl_lua_material_constructors, 0);
    luaL_setfuncs(L, pl_lua_fluid_methods, 0);
    luaL_setfuncs(L, pl_lua_darcy_methods, 0);
    luaL_setfuncs(L, pl_lua_hydrostatic_methods, 0);
    luaL_setfuncs(L, pl_lua_bond_methods, 0);
    luaL_setfuncs(L, pl_lua_navier_stokes_methods, 0);
    luaL_setfuncs(L, pl_lua_stokes_methods, 0);
    luaL_setfuncs(L, pl_lua_solid_methods, 0);
    luaL_setfuncs(L, pl_lua_diag_methods, 0);
    luaL_setfuncs(L, pl_lua_state_methods, 0);
    lua_setfield(L, -2, "__index");
    lua_pop(L, 1);
}
