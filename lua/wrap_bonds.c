/* Bonds, heat and wear (porelab/bonds.h) as world methods:
 *     w:bond_law{ a = mat, b = mat, law = "brittle"|"plastic"|"damage", kn =, kt =, kr =, rn =, rt =,
 *                 combined =, soften =, tension_only =, beam = }
 *     w:bond_touching(gap)            -> number of bonds made (discs at most gap m apart)
 *     w:bond(body1, body2)            -> bond number (1-based)
 *     w:bond_count()                  -> intact, total
 *     w:bonds()                       -> { {a =, b = (body numbers), state =, n =, s =, m =, damage =, x =, y =,
 *                                           broken_time = }, ... }  (state "intact", "tension", "shear",
 *                                           "combined", "removed")
 *     w:broken_bonds(since_step)      -> the bonds broken after that step (same tables)
 *     w:thermal{ material = mat, heat_capacity =, conductivity =, wear =, hardness =, softening =, t_ref =, h_min = }
 *     w:heat{ fraction = 1, initial = 293.15 }
 *     w:set_temperature(body, T [, hold])   w:temperature(body)   w:body_heat(body)
 *     w:wear{ remove = true }         w:body_wear(body)   w:removed(body) -> bool, time   w:removed_count()
 *     w:remove(body)                  (carves a disc out: kept index, no contacts or bonds, not drawn)
 *     w:touching(body)                -> number of touching contacts of the body after the last step
 * Body numbers are the scene's (1-based) like the handles' indices. Numeric fields are read through the
 * parameter tables pl_bond_params / pl_thermal_params (names, ranges and units from there). */
#include "wrap.h"
#include "lua_util.h"
#include "lua_params.h"
#include "porelab/bonds.h"
#include <stdlib.h>
#include <string.h>

/* A copy of the table at t without the keys in skip (those are read separately). */
static void copy_without(lua_State *L, int t, const char *const skip[]) {
    t = lua_absindex(L, t);
    lua_newtable(L);
    lua_pushnil(L);
    while (lua_next(L, t)) {
        int drop = 0;
        if (lua_type(L, -2) == LUA_TSTRING)
            for (int k = 0; skip[k]; k++) drop |= strcmp(lua_tostring(L, -2), skip[k]) == 0;
        if (drop) {
            lua_pop(L, 1);
            continue;
        }
        lua_pushvalue(L, -2);
        lua_insert(L, -2);
        lua_settable(L, -4);
    }
}

static int b_bond_law(lua_State *L) {
    const char *fn = "bond_law";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    if (!pl_lua_has_field(L, 2, "a") || !pl_lua_has_field(L, 2, "b"))
        pl_lua_error(L, "%s: give the material pair as a = and b = (materials or their names)", fn);
    lua_getfield(L, 2, "a");
    const int ma = pl_lua_material_index(L, 1, -1, fn);
    lua_getfield(L, 2, "b");
    const int mb = pl_lua_material_index(L, 1, -1, fn);
    lua_pop(L, 2);
    static const char *const laws[] = {"brittle", "plastic", "damage", NULL};
    pl_bond_def d = pl_default_bond_def();
    d.law = (pl_bond_law_kind)pl_lua_field_option(L, 2, fn, "law", 0, laws);
    static const char *const skip[] = {"a", "b", "law", NULL};
    copy_without(L, 2, skip);
    pl_lua_read_params(L, -1, fn, pl_bond_params, PL_BOND_PARAM_COUNT, &d);
    lua_pop(L, 1);
    pl_lua_check_status(L, lw->w, pl_world_set_bond_law(lw->w, ma, mb, &d), fn);
    return 0;
}

static int b_bond_touching(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const double gap = luaL_optnumber(L, 2, 0);
    const int n = pl_world_bond_touching(lw->w, gap);
    pl_lua_check_status(L, lw->w, n, "bond_touching");
    lua_pushinteger(L, n);
    return 1;
}

static int body_arg(lua_State *L, int idx, const char *fn) {
    pl_world *w = NULL;
    if (lua_isinteger(L, idx)) {
        const pl_world *ww = pl_lua_check_world(L, 1)->w;
        const lua_Integer i = lua_tointeger(L, idx);
        if (i < 1 || i > pl_world_body_count(ww))
            pl_lua_error(L, "%s: body number must be in 1..%d (got %lld)", fn, pl_world_body_count(ww), (long long)i);
        return (int)i - 1;
    }
    if (!luaL_testudata(L, idx, PL_LUA_BODY_MT)) pl_lua_error(L, "%s: argument %d must be a body or a body number", fn, idx - 1);
    return pl_lua_check_body(L, idx, &w);
}

static int b_bond(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const int a = body_arg(L, 2, "bond"), b = body_arg(L, 3, "bond");
    const int k = pl_world_add_bond(lw->w, a, b);
    pl_lua_check_status(L, lw->w, k, "bond");
    lua_pushinteger(L, k + 1);
    return 1;
}

static int b_bond_count(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    lua_pushinteger(L, pl_world_bond_count(lw->w));
    lua_pushinteger(L, pl_world_bond_total(lw->w));
    return 2;
}

static const char *const STATES[] = {"intact", "tension", "shear", "combined", "removed"};

static void push_infos(lua_State *L, const pl_bond_info *o, int n) {
    lua_createtable(L, n, 0);
    for (int k = 0; k < n; k++) {
        lua_createtable(L, 0, 12);
        lua_pushinteger(L, o[k].a + 1);
        lua_setfield(L, -2, "a");
        lua_pushinteger(L, o[k].b + 1);
        lua_setfield(L, -2, "b");
        lua_pushstring(L, STATES[o[k].state >= 0 && o[k].state <= 4 ? o[k].state : 0]);
        lua_setfield(L, -2, "state");
        const struct {
            const char *name;
            double v;
        } f[] = {{"n", o[k].n},           {"s", o[k].s},           {"m", o[k].m},
                 {"un", o[k].un},         {"ut", o[k].ut},         {"damage", o[k].damage},
                 {"elastic", o[k].elastic}, {"dissipated", o[k].dissipated}, {"x", o[k].point.x},
                 {"y", o[k].point.y},     {"broken_time", o[k].broken_time}};
        for (size_t i = 0; i < sizeof f / sizeof f[0]; i++) {
            lua_pushnumber(L, f[i].v);
            lua_setfield(L, -2, f[i].name);
        }
        lua_rawseti(L, -2, k + 1);
    }
}

static int b_bonds(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const int n = pl_world_bond_total(lw->w);
    pl_bond_info *o = malloc((size_t)(n > 0 ? n : 1) * sizeof *o);
    if (!o) return pl_lua_error(L, "bonds: out of memory");
    const int c = pl_world_copy_bonds(lw->w, 0, o, n);
    push_infos(L, o, c);
    free(o);
    return 1;
}

static int b_broken_bonds(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const lua_Integer since = luaL_checkinteger(L, 2);
    const int n = pl_world_broken_bonds(lw->w, since, NULL, 0);
    pl_bond_info *o = malloc((size_t)(n > 0 ? n : 1) * sizeof *o);
    if (!o) return pl_lua_error(L, "broken_bonds: out of memory");
    const int c = pl_world_broken_bonds(lw->w, since, o, n);
    push_infos(L, o, c);
    free(o);
    return 1;
}

static int b_thermal(lua_State *L) {
    const char *fn = "thermal";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    if (!pl_lua_has_field(L, 2, "material")) pl_lua_error(L, "%s: give the material (material = ...)", fn);
    lua_getfield(L, 2, "material");
    const int m = pl_lua_material_index(L, 1, -1, fn);
    lua_pop(L, 1);
    pl_thermal_def d = pl_default_thermal_def();
    static const char *const skip[] = {"material", NULL};
    copy_without(L, 2, skip);
    pl_lua_read_params(L, -1, fn, pl_thermal_params, PL_THERMAL_PARAM_COUNT, &d);
    lua_pop(L, 1);
    pl_lua_check_status(L, lw->w, pl_world_set_thermal(lw->w, m, &d), fn);
    return 0;
}

static int b_heat(lua_State *L) {
    const char *fn = "heat";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    double fraction = 1, t0 = 293.15;
    if (!lua_isnoneornil(L, 2)) {
        pl_lua_check_def(L, 2, fn);
        static const char *const valid[] = {"fraction", "initial", NULL};
        pl_lua_check_fields(L, 2, fn, valid);
        fraction = pl_lua_field_number(L, 2, fn, "fraction", 1);
        t0 = pl_lua_field_number(L, 2, fn, "initial", 293.15);
    }
    pl_lua_check_status(L, lw->w, pl_world_enable_heat(lw->w, fraction, t0), fn);
    return 0;
}

static int b_set_temperature(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const int i = body_arg(L, 2, "set_temperature");
    const double t = luaL_checknumber(L, 3);
    const int hold = lua_toboolean(L, 4);
    pl_lua_check_status(L, lw->w, pl_world_set_body_temperature(lw->w, i, t, hold), "set_temperature");
    return 0;
}

static int b_temperature(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    lua_pushnumber(L, pl_world_body_temperature(lw->w, body_arg(L, 2, "temperature")));
    return 1;
}

static int b_body_heat(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    lua_pushnumber(L, pl_world_body_heat(lw->w, body_arg(L, 2, "body_heat")));
    return 1;
}

static int b_wear(lua_State *L) {
    const char *fn = "wear";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    int remove = 1;
    if (!lua_isnoneornil(L, 2)) {
        pl_lua_check_def(L, 2, fn);
        static const char *const valid[] = {"remove", NULL};
        pl_lua_check_fields(L, 2, fn, valid);
        remove = pl_lua_field_bool(L, 2, fn, "remove", 1);
    }
    pl_lua_check_status(L, lw->w, pl_world_enable_wear(lw->w, remove), fn);
    return 0;
}

static int b_body_wear(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    lua_pushnumber(L, pl_world_body_wear(lw->w, body_arg(L, 2, "body_wear")));
    return 1;
}

static int b_removed(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    double t = -1;
    const int r = pl_world_body_removed(lw->w, body_arg(L, 2, "removed"), &t);
    lua_pushboolean(L, r);
    if (r) lua_pushnumber(L, t);
    else lua_pushnil(L);
    return 2;
}

static int b_remove(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_status(L, lw->w, pl_world_remove_body(lw->w, body_arg(L, 2, "remove")), "remove");
    return 0;
}

static int b_touching(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    lua_pushinteger(L, pl_world_body_touching(lw->w, body_arg(L, 2, "touching")));
    return 1;
}

static int b_removed_count(lua_State *L) {
    lua_pushinteger(L, pl_world_removed_count(pl_lua_check_world(L, 1)->w));
    return 1;
}

const luaL_Reg pl_lua_bond_methods[] = {{"bond_law", b_bond_law},
                                        {"bond_touching", b_bond_touching},
                                        {"bond", b_bond},
                                        {"bond_count", b_bond_count},
                                        {"bonds", b_bonds},
                                        {"broken_bonds", b_broken_bonds},
                                        {"thermal", b_thermal},
                                        {"heat", b_heat},
                                        {"set_temperature", b_set_temperature},
                                        {"temperature", b_temperature},
                                        {"body_heat", b_body_heat},
                                        {"wear", b_wear},
                                        {"body_wear", b_body_wear},
                                        {"removed", b_removed},
                                        {"removed_count", b_removed_count},
                                        {"remove", b_remove},
                                        {"touching", b_touching},
                                        {NULL, NULL}};
