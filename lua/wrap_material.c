/* Materials: world:material{...}, world:pair(a, b, {...}), world:find_material(name) and
 * the material handle (an index plus its world). */
#include "wrap.h"
#include "lua_util.h"

#include <math.h>
#include <string.h>

typedef struct material_ud {
    int index;
} material_ud;

void pl_lua_push_material(lua_State *L, int world_idx, int material)
{
    world_idx = lua_absindex(L, world_idx);
    material_ud *m = lua_newuserdatauv(L, sizeof *m, 1);
    m->index = material;
    lua_pushvalue(L, world_idx);
    lua_setiuservalue(L, -2, 1);
    luaL_setmetatable(L, PL_LUA_MATERIAL_MT);
}

/* The material at idx and its world (pushed world userdata is left on the stack top). */
static material_ud *check_material(lua_State *L, int idx, pl_world **w)
{
    material_ud *m = luaL_checkudata(L, idx, PL_LUA_MATERIAL_MT);
    lua_getiuservalue(L, idx, 1);
    *w = pl_lua_check_world(L, -1)->w;
    lua_pop(L, 1); /* the handle keeps the world alive */
    return m;
}

static int unknown_material(lua_State *L, pl_world *w, const char *fn, const char *name)
{
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    int n = pl_world_material_count(w);
    for (int i = 0; i < n; i++) {
        if (i) luaL_addstring(&b, ", ");
        luaL_addstring(&b, pl_world_material(w, i).name);
    }
    if (n == 0) luaL_addstring(&b, "none defined yet; add one with world:material{...}");
    luaL_pushresult(&b);
    return pl_lua_error(L, "%s: unknown material '%s' (known: %s)", fn, name,
                        lua_tostring(L, -1));
}

int pl_lua_material_index(lua_State *L, int world_idx, int value_idx, const char *fn)
{
    pl_world *w = pl_lua_check_world(L, world_idx)->w;
    value_idx = lua_absindex(L, value_idx);
    if (lua_type(L, value_idx) == LUA_TSTRING) {
        const char *name = lua_tostring(L, value_idx);
        int i = pl_world_find_material(w, name);
        if (i < 0) unknown_material(L, w, fn, name);
        return i;
    }
    material_ud *m = luaL_testudata(L, value_idx, PL_LUA_MATERIAL_MT);
    if (!m)
        return pl_lua_error(L, "%s: material must be a material or its name (got %s)", fn,
                            luaL_typename(L, value_idx));
    lua_getiuservalue(L, value_idx, 1);
    int same = lua_rawequal(L, -1, world_idx);
    lua_pop(L, 1);
    if (!same) pl_lua_error(L, "%s: material belongs to another world", fn);
    return m->index;
}

/* ------------------------------------------------------------ constructors */

static const char *const material_fields[] = {
    "name", "density", "kn", "ks", "young", "young_overlap", "friction", "rolling", "cohesion",
    "cn", "cs", "restitution", NULL};

static int w_material(lua_State *L)
{
    const char *fn = "material";
    pl_world *w = pl_lua_check_world(L, 1)->w;
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, material_fields);
    pl_material_def d = pl_default_material_def();
    d.name = pl_lua_field_string(L, 2, fn, "name", NULL);
    if (!d.name || !d.name[0]) pl_lua_error(L, "%s: name is required (a non-empty string)", fn);
    if (pl_world_find_material(w, d.name) >= 0)
        pl_lua_error(L, "%s: a material named '%s' already exists", fn, d.name);
    if (!pl_lua_has_field(L, 2, "density"))
        pl_lua_error(L, "%s: density is required (kg/m^3, > 0)", fn);
    d.density = pl_lua_field_number(L, 2, fn, "density", d.density);
    pl_lua_check_range(L, fn, "density", d.density, 0, PL_LUA_MAX_DENSITY, PL_LUA_OPEN_LO, "kg/m^3");
    d.kn = pl_lua_field_number(L, 2, fn, "kn", 0);
    pl_lua_check_range(L, fn, "kn", d.kn, 0, PL_LUA_MAX_STIFFNESS, PL_LUA_CLOSED, "N/m");
    d.young = pl_lua_field_number(L, 2, fn, "young", d.young);
    pl_lua_check_range(L, fn, "young", d.young, 0, PL_LUA_MAX_STIFFNESS, PL_LUA_CLOSED, "Pa");
    if (d.kn == 0 && !(d.young > 0))
        pl_lua_error(L, "%s: give a normal stiffness kn (N/m, > 0) or a Young's modulus young "
                     "(Pa, > 0)", fn);
    d.young_overlap = pl_lua_field_number(L, 2, fn, "young_overlap", d.young_overlap);
    PL_LUA_CHECK(L, d.young_overlap > 0 && d.young_overlap < 1, fn, "young_overlap",
                 "in (0, 1)", d.young_overlap);
    if (pl_lua_has_field(L, 2, "ks")) {
        d.ks = pl_lua_field_number(L, 2, fn, "ks", d.ks);
        pl_lua_check_range(L, fn, "ks", d.ks, 0, PL_LUA_MAX_STIFFNESS, PL_LUA_CLOSED, "N/m");
    }
    d.friction = pl_lua_field_number(L, 2, fn, "friction", d.friction);
    pl_lua_check_range(L, fn, "friction", d.friction, 0, PL_LUA_MAX_FRICTION, PL_LUA_CLOSED, "");
    d.rolling = pl_lua_field_number(L, 2, fn, "rolling", d.rolling);
    pl_lua_check_range(L, fn, "rolling", d.rolling, 0, PL_LUA_MAX_FRICTION, PL_LUA_CLOSED, "");
    d.cohesion = pl_lua_field_number(L, 2, fn, "cohesion", d.cohesion);
    pl_lua_check_range(L, fn, "cohesion", d.cohesion, 0, PL_LUA_MAX_FORCE, PL_LUA_CLOSED, "N");
    d.cn = pl_lua_field_number(L, 2, fn, "cn", d.cn);
    pl_lua_check_range(L, fn, "cn", d.cn, 0, PL_LUA_MAX_DASHPOT, PL_LUA_CLOSED, "N s/m");
    if (pl_lua_has_field(L, 2, "cs")) {
        d.cs = pl_lua_field_number(L, 2, fn, "cs", d.cs);
        pl_lua_check_range(L, fn, "cs", d.cs, 0, PL_LUA_MAX_DASHPOT, PL_LUA_CLOSED, "N s/m");
    }
    if (pl_lua_has_field(L, 2, "restitution")) {
        if (pl_lua_has_field(L, 2, "cn") || pl_lua_has_field(L, 2, "cs"))
            pl_lua_error(L, "%s: give either restitution or the dashpots cn/cs, not both", fn);
        d.restitution = pl_lua_field_number(L, 2, fn, "restitution", d.restitution);
        PL_LUA_CHECK(L, d.restitution > 0 && d.restitution <= 1, fn, "restitution",
                     "in (0, 1]", d.restitution);
    }
    int index = pl_world_add_material(w, &d);
    pl_lua_check_status(L, w, index, fn);
    pl_lua_push_material(L, 1, index);
    return 1;
}

static const char *const pair_fields[] = {"kn",  "ks", "friction", "cohesion",
                                          "cn",  "cs", "restitution", "rolling", NULL};

static int w_pair(lua_State *L)
{
    const char *fn = "pair";
    pl_world *w = pl_lua_check_world(L, 1)->w;
    int a = pl_lua_material_index(L, 1, 2, fn);
    int b = pl_lua_material_index(L, 1, 3, fn);
    pl_lua_check_def(L, 4, fn);
    pl_lua_check_fields(L, 4, fn, pair_fields);
    /* merge: the fields given replace those of the pair's existing override, the others are
       kept (porelab.mimes sets friction, kn and ks of a pair in three separate calls) */
    pl_pair_def d;
    pl_lua_check_status(L, w, pl_world_pair_override(w, a, b, &d), fn);
    double *v[] = {&d.kn, &d.ks, &d.friction, &d.cohesion, &d.cn, &d.cs, &d.restitution, &d.rolling};
    static const double pair_max[] = {PL_LUA_MAX_STIFFNESS, PL_LUA_MAX_STIFFNESS, PL_LUA_MAX_FRICTION,
                                      PL_LUA_MAX_FORCE,     PL_LUA_MAX_DASHPOT,   PL_LUA_MAX_DASHPOT,
                                      1,                    PL_LUA_MAX_FRICTION};
    static const char *const pair_units[] = {"N/m", "N/m", "", "N", "N s/m", "N s/m", "", ""};
    for (int i = 0; pair_fields[i]; i++) {
        if (!pl_lua_has_field(L, 4, pair_fields[i])) continue;
        *v[i] = pl_lua_field_number(L, 4, fn, pair_fields[i], -1);
        pl_lua_check_range(L, fn, pair_fields[i], *v[i], 0, pair_max[i], PL_LUA_CLOSED, pair_units[i]);
    }
    if (d.restitution >= 0)
        PL_LUA_CHECK(L, d.restitution > 0 && d.restitution <= 1, fn, "restitution",
                     "in (0, 1]", d.restitution);
    pl_lua_check_status(L, w, pl_world_set_pair(w, a, b, &d), fn);
    return 0;
}

/* world:pair_params(a, b): the parameters contacts between the two materials use (combination
   rules and overrides); restitution is absent when the pair uses the dashpots cn, cs. */
static int w_pair_params(lua_State *L)
{
    const char *fn = "pair_params";
    pl_world *w = pl_lua_check_world(L, 1)->w;
    int a = pl_lua_material_index(L, 1, 2, fn);
    int b = pl_lua_material_index(L, 1, 3, fn);
    pl_pair_def d;
    pl_lua_check_status(L, w, pl_world_pair_params(w, a, b, &d), fn);
    const double v[] = {d.kn, d.ks, d.friction, d.cohesion, d.cn, d.cs, d.restitution, d.rolling};
    lua_createtable(L, 0, 8);
    for (int i = 0; pair_fields[i]; i++) {
        if (v[i] < 0) continue;
        lua_pushnumber(L, v[i]);
        lua_setfield(L, -2, pair_fields[i]);
    }
    return 1;
}

static int w_find_material(lua_State *L)
{
    pl_world *w = pl_lua_check_world(L, 1)->w;
    int i = pl_world_find_material(w, luaL_checkstring(L, 2));
    if (i < 0)
        lua_pushnil(L);
    else
        pl_lua_push_material(L, 1, i);
    return 1;
}

static int w_material_count(lua_State *L)
{
    lua_pushinteger(L, pl_world_material_count(pl_lua_check_world(L, 1)->w));
    return 1;
}

const luaL_Reg pl_lua_material_constructors[] = {
    {"material", w_material},
    {"pair", w_pair},
    {"pair_params", w_pair_params},
    {"find_material", w_find_material},
    {"material_count", w_material_count},
    {NULL, NULL}};

/* ----------------------------------------------------------------- methods */

static int m_name(lua_State *L)
{
    pl_world *w;
    material_ud *m = check_material(L, 1, &w);
    lua_pushstring(L, pl_world_material(w, m->index).name);
    return 1;
}

static int m_index(lua_State *L)
{
    pl_world *w;
    lua_pushinteger(L, check_material(L, 1, &w)->index + 1);
    return 1;
}

static int m_params(lua_State *L)
{
    pl_world *w;
    material_ud *m = check_material(L, 1, &w);
    pl_material_def d = pl_world_material(w, m->index);
    const struct {
        const char *name;
        double v;
    } f[] = {{"density", d.density}, {"kn", d.kn},           {"ks", d.ks},
             {"young", d.young},     {"friction", d.friction}, {"cohesion", d.cohesion},
             {"cn", d.cn},           {"cs", d.cs},           {"restitution", d.restitution},
             {"rolling", d.rolling}};
    lua_createtable(L, 0, 11);
    lua_pushstring(L, d.name);
    lua_setfield(L, -2, "name");
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++) {
        lua_pushnumber(L, f[i].v);
        lua_setfield(L, -2, f[i].name);
    }
    return 1;
}

static int m_tostring(lua_State *L)
{
    pl_world *w;
    material_ud *m = check_material(L, 1, &w);
    lua_pushfstring(L, "porelab.material '%s'", pl_world_material(w, m->index).name);
    return 1;
}

static const luaL_Reg material_methods[] = {
    {"name", m_name}, {"index", m_index}, {"params", m_params}, {NULL, NULL}};

void pl_lua_register_material(lua_State *L)
{
    luaL_newmetatable(L, PL_LUA_MATERIAL_MT);
    lua_pushcfunction(L, m_tostring);
    lua_setfield(L, -2, "__tostring");
    luaL_newlib(L, material_methods);
    lua_setfield(L, -2, "__index");
    lua_pop(L, 1);
}
