/* The finite-element solid (porelab/solid.h) as world methods (docs/solids.md):
 *     w:solid{ young = , poisson = , density = , formulation = "fic_semi_implicit", ... }
 *     w:solid_rectangle{ x0 =, y0 =, x1 =, y1 =, nx =, ny = }          -> part number
 *     w:solid_quad{ corners = {{x,y} x 4, CCW}, nx =, ny = }            -> part number
 *     w:solid_annulus{ cx =, cy =, ri =, ro =, a0 = 0, a1 = 2 pi, nr =, nt = } -> part number
 *     w:solid_polygon{ points = {{x,y}, ...}, h = }                     -> part number
 *     w:solid_fix{ box = {x0, y0, x1, y1}, x = true, y = true }         -> set number
 *     w:solid_velocity{ box = {...}, vx = , vy = }  (components given are driven) -> set number
 *     w:solid_traction{ box = {...}, tx = 0, ty = 0, pressure = 0 }    -> edge count
 *     w:solid_initial_velocity{ box = {...}, vx = 0, vy = 0 }           -> node count
 *     w:solid_reaction(set) -> fx, fy        w:solid_displacement(x, y) -> ux, uy
 *     w:solid_energy() -> {kinetic, elastic, internal, external, damping, plastic, contact}
 *     w:solid_mesh{file = "part.msh"}       (gmsh mesh file in the scene's or the output folder)
 *     w:solid_info() -> {nodes, elements, critical_dt, solid_seconds, contact_seconds}
 *     w:solid_extremes() -> mises_max, plastic_strain_max
 *     w:solid_contact_force() -> fx, fy (of the grains on the solid)
 *     w:solid_bond{ law = "brittle", kn =, kt =, rn =, rt =, ..., gap = 0 } -> bonds made
 *     w:solid_bonds() -> total, intact
 *     w:solid_thermal{ heat_capacity =, wear =, hardness =, ..., fraction = 1, initial = 293.15 }
 *     w:solid_heat() -> heat (J/m), worn area (m^2/m), hottest node (K)
 * The def fields come from the parameter table (pl_solid_params); formulation may also be
 * given by name. Registered into the world metatable with luaL_setfuncs. */
#include "wrap.h"
#include "lua_util.h"
#include "lua_params.h"
#include "sandbox.h"
#include "porelab/solid.h"
#include "porelab/bonds.h"
#include <math.h>

static const char *const FORMS[] = {"plain", "fic_explicit", "fic_semi_implicit", "q1p0", NULL};

static int s_solid(lua_State *L) {
    const char *fn = "solid";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_solid_def d = pl_default_solid_def();
    if (!lua_isnoneornil(L, 2)) {
        pl_lua_check_def(L, 2, fn);
        lua_getfield(L, 2, "formulation");
        const int is_str = lua_type(L, -1) == LUA_TSTRING;
        lua_pop(L, 1);
        if (is_str) {
            const int f = pl_lua_field_option(L, 2, fn, "formulation", d.formulation, FORMS);
            lua_pushinteger(L, f);
            lua_setfield(L, 2, "formulation");
        }
        pl_lua_read_params(L, 2, fn, pl_solid_params, PL_SOLID_PARAM_COUNT, &d);
    }
    pl_lua_check_status(L, lw->w, pl_world_attach_solid(lw->w, &d), fn);
    return 0;
}

static int push_index(lua_State *L, pl_lua_world *lw, int k, const char *fn) {
    if (k < 0) pl_lua_check_status(L, lw->w, k, fn);
    lua_pushinteger(L, k + 1);
    return 1;
}

static int s_rectangle(lua_State *L) {
    const char *fn = "solid_rectangle";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    static const char *const valid[] = {"x0", "y0", "x1", "y1", "nx", "ny", NULL};
    pl_lua_check_fields(L, 2, fn, valid);
    const double x0 = pl_lua_field_number(L, 2, fn, "x0", 0), y0 = pl_lua_field_number(L, 2, fn, "y0", 0);
    const double x1 = pl_lua_field_number(L, 2, fn, "x1", 1), y1 = pl_lua_field_number(L, 2, fn, "y1", 1);
    const int nx = pl_lua_field_int(L, 2, fn, "nx", 10), ny = pl_lua_field_int(L, 2, fn, "ny", 10);
    return push_index(L, lw, pl_world_solid_rectangle(lw->w, x0, y0, x1, y1, nx, ny), fn);
}

static int read_points(lua_State *L, int t, const char *fn, const char *field, pl_vec2 *out, int cap) {
    lua_getfield(L, t, field);
    if (!lua_istable(L, -1)) pl_lua_error(L, "%s: %s must be a list of points {{x, y}, ...}", fn, field);
    const int n = (int)lua_rawlen(L, -1);
    if (n > cap) pl_lua_error(L, "%s: %s has %d points, at most %d", fn, field, n, cap);
    for (int k = 0; k < n; k++) {
        lua_rawgeti(L, -1, k + 1);
        if (!pl_lua_to_vec2(L, -1, &out[k])) pl_lua_error(L, "%s: %s[%d] must be a point {x, y}", fn, field, k + 1);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return n;
}

static int s_quad(lua_State *L) {
    const char *fn = "solid_quad";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    static const char *const valid[] = {"corners", "nx", "ny", NULL};
    pl_lua_check_fields(L, 2, fn, valid);
    pl_vec2 c[4];
    if (read_points(L, 2, fn, "corners", c, 4) != 4) pl_lua_error(L, "%s: corners must hold 4 points", fn);
    const int nx = pl_lua_field_int(L, 2, fn, "nx", 10), ny = pl_lua_field_int(L, 2, fn, "ny", 10);
    return push_index(L, lw, pl_world_solid_quad(lw->w, c, nx, ny), fn);
}

static int s_annulus(lua_State *L) {
    const char *fn = "solid_annulus";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    static const char *const valid[] = {"cx", "cy", "ri", "ro", "a0", "a1", "nr", "nt", NULL};
    pl_lua_check_fields(L, 2, fn, valid);
    const double cx = pl_lua_field_number(L, 2, fn, "cx", 0), cy = pl_lua_field_number(L, 2, fn, "cy", 0);
    const double ri = pl_lua_field_number(L, 2, fn, "ri", 0.5), ro = pl_lua_field_number(L, 2, fn, "ro", 1);
    const double a0 = pl_lua_field_number(L, 2, fn, "a0", 0), a1 = pl_lua_field_number(L, 2, fn, "a1", 2 * M_PI);
    const int nr = pl_lua_field_int(L, 2, fn, "nr", 4), nt = pl_lua_field_int(L, 2, fn, "nt", 32);
    return push_index(L, lw, pl_world_solid_annulus(lw->w, cx, cy, ri, ro, a0, a1, nr, nt), fn);
}

static int s_polygon(lua_State *L) {
    const char *fn = "solid_polygon";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    static const char *const valid[] = {"points", "h", NULL};
    pl_lua_check_fields(L, 2, fn, valid);
    pl_vec2 p[256];
    const int n = read_points(L, 2, fn, "points", p, 256);
    const double h = pl_lua_field_number(L, 2, fn, "h", 0);
    return push_index(L, lw, pl_world_solid_polygon(lw->w, p, n, h), fn);
}

/* w:solid_mesh{file = "part.msh"}: a part from a gmsh mesh file, inside the scene's folder or
   the output folder (the sandbox's input rule). */
static int s_mesh(lua_State *L) {
    const char *fn = "solid_mesh";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    static const char *const valid[] = {"file", NULL};
    pl_lua_check_fields(L, 2, fn, valid);
    const char *file = pl_lua_field_string(L, 2, fn, "file", NULL);
    if (!file) pl_lua_error(L, "%s: file is required (a gmsh .msh file beside the scene)", fn);
    char resolved[4096];
    pl_lua_input_path(L, file, resolved, sizeof resolved, fn);
    return push_index(L, lw, pl_world_solid_mesh_file(lw->w, resolved), fn);
}

static void read_box(lua_State *L, const char *fn, double b[4]) {
    lua_getfield(L, 2, "box");
    if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 4) pl_lua_error(L, "%s: box must be {x0, y0, x1, y1}", fn);
    for (int k = 0; k < 4; k++) {
        lua_rawgeti(L, -1, k + 1);
        if (!lua_isnumber(L, -1)) pl_lua_error(L, "%s: box[%d] must be a number", fn, k + 1);
        b[k] = lua_tonumber(L, -1);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (!(b[2] >= b[0] && b[3] >= b[1])) pl_lua_error(L, "%s: box needs x1 >= x0 and y1 >= y0", fn);
}

static int s_fix(lua_State *L) {
    const char *fn = "solid_fix";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    static const char *const valid[] = {"box", "x", "y", NULL};
    pl_lua_check_fields(L, 2, fn, valid);
    double b[4];
    read_box(L, fn, b);
    const int mask = (pl_lua_field_bool(L, 2, fn, "x", 1) ? 1 : 0) | (pl_lua_field_bool(L, 2, fn, "y", 1) ? 2 : 0);
    return push_index(L, lw, pl_world_solid_fix(lw->w, b[0], b[1], b[2], b[3], mask), fn);
}

static int s_velocity(lua_State *L) {
    const char *fn = "solid_velocity";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    static const char *const valid[] = {"box", "vx", "vy", NULL};
    pl_lua_check_fields(L, 2, fn, valid);
    double b[4];
    read_box(L, fn, b);
    const int mask = (pl_lua_has_field(L, 2, "vx") ? 1 : 0) | (pl_lua_has_field(L, 2, "vy") ? 2 : 0);
    if (!mask) pl_lua_error(L, "%s: give vx, vy or both (m/s)", fn);
    const double vx = pl_lua_field_number(L, 2, fn, "vx", 0), vy = pl_lua_field_number(L, 2, fn, "vy", 0);
    return push_index(L, lw, pl_world_solid_velocity(lw->w, b[0], b[1], b[2], b[3], mask, vx, vy), fn);
}

static int s_initial_velocity(lua_State *L) {
    const char *fn = "solid_initial_velocity";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    static const char *const valid[] = {"box", "vx", "vy", NULL};
    pl_lua_check_fields(L, 2, fn, valid);
    double b[4];
    read_box(L, fn, b);
    const double vx = pl_lua_field_number(L, 2, fn, "vx", 0), vy = pl_lua_field_number(L, 2, fn, "vy", 0);
    const int n = pl_world_solid_initial_velocity(lw->w, b[0], b[1], b[2], b[3], vx, vy);
    if (n < 0) pl_lua_check_status(L, lw->w, n, fn);
    lua_pushinteger(L, n);
    return 1;
}

static int s_traction(lua_State *L) {
    const char *fn = "solid_traction";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    static const char *const valid[] = {"box", "tx", "ty", "pressure", NULL};
    pl_lua_check_fields(L, 2, fn, valid);
    double b[4];
    read_box(L, fn, b);
    const double tx = pl_lua_field_number(L, 2, fn, "tx", 0), ty = pl_lua_field_number(L, 2, fn, "ty", 0);
    const double pn = pl_lua_field_number(L, 2, fn, "pressure", 0);
    const int n = pl_world_solid_traction(lw->w, b[0], b[1], b[2], b[3], tx, ty, pn);
    if (n < 0) pl_lua_check_status(L, lw->w, n, fn);
    lua_pushinteger(L, n);
    return 1;
}

static int s_reaction(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const int set = (int)luaL_checkinteger(L, 2);
    pl_vec2 f;
    if (pl_world_solid_reaction(lw->w, set - 1, &f) != PL_OK)
        pl_lua_error(L, "solid_reaction: no node set %d (sets are numbered from 1 by solid_fix/solid_velocity)", set);
    lua_pushnumber(L, f.x);
    lua_pushnumber(L, f.y);
    return 2;
}

static int s_displacement(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const pl_vec2 X = {luaL_checknumber(L, 2), luaL_checknumber(L, 3)};
    pl_vec2 u;
    if (pl_world_solid_displacement(lw->w, X, &u) != PL_OK)
        pl_lua_error(L, "solid_displacement: the world has no solid part");
    lua_pushnumber(L, u.x);
    lua_pushnumber(L, u.y);
    return 2;
}

static int s_energy(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_solid_energy e;
    if (pl_world_solid_energy(lw->w, &e) != PL_OK) pl_lua_error(L, "solid_energy: the world has no solid part");
    lua_createtable(L, 0, 7);
    const double v[7] = {e.kinetic, e.elastic, e.internal, e.external, e.damping, e.plastic, e.contact};
    const char *k[7] = {"kinetic", "elastic", "internal", "external", "damping", "plastic", "contact"};
    for (int i = 0; i < 7; i++) {
        lua_pushnumber(L, v[i]);
        lua_setfield(L, -2, k[i]);
    }
    return 1;
}

static int s_info(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    lua_createtable(L, 0, 5);
    double fe_s, ct_s;
    pl_world_solid_cost(lw->w, &fe_s, &ct_s);
    lua_pushnumber(L, fe_s);
    lua_setfield(L, -2, "solid_seconds");
    lua_pushnumber(L, ct_s);
    lua_setfield(L, -2, "contact_seconds");
    lua_pushinteger(L, pl_world_solid_node_count(lw->w));
    lua_setfield(L, -2, "nodes");
    lua_pushinteger(L, pl_world_solid_element_count(lw->w));
    lua_setfield(L, -2, "elements");
    lua_pushnumber(L, pl_world_solid_critical_dt(lw->w, NULL));
    lua_setfield(L, -2, "critical_dt");
    return 1;
}

static int s_extremes(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    double a, b;
    if (pl_world_solid_extremes(lw->w, &a, &b) != PL_OK) pl_lua_error(L, "solid_extremes: the world has no solid part");
    lua_pushnumber(L, a);
    lua_pushnumber(L, b);
    return 2;
}

static int s_contact_force(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const pl_vec2 f = pl_world_solid_contact_force(lw->w);
    lua_pushnumber(L, f.x);
    lua_pushnumber(L, f.y);
    return 2;
}

/* Reads and removes field k of the table at idx (the rest goes to a parameter table). */
static double take_number(lua_State *L, int idx, const char *fn, const char *k, double dflt) {
    const double v = pl_lua_field_number(L, idx, fn, k, dflt);
    lua_pushnil(L);
    lua_setfield(L, idx, k);
    return v;
}

static int s_bond(lua_State *L) {
    const char *fn = "solid_bond";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    static const char *const laws[] = {"brittle", "plastic", "damage", NULL};
    pl_bond_def d = pl_default_bond_def();
    d.law = (pl_bond_law_kind)pl_lua_field_option(L, 2, fn, "law", 0, laws);
    lua_pushnil(L);
    lua_setfield(L, 2, "law");
    const double gap = take_number(L, 2, fn, "gap", 0);
    pl_lua_read_params(L, 2, fn, pl_bond_params, PL_BOND_PARAM_COUNT, &d);
    const int n = pl_world_solid_bond(lw->w, &d, gap);
    pl_lua_check_status(L, lw->w, n, fn);
    lua_pushinteger(L, n);
    return 1;
}

static int s_bonds(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    int intact;
    lua_pushinteger(L, pl_world_solid_bond_count(lw->w, &intact));
    lua_pushinteger(L, intact);
    return 2;
}

static int s_thermal(lua_State *L) {
    const char *fn = "solid_thermal";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    const double fraction = take_number(L, 2, fn, "fraction", 1), t0 = take_number(L, 2, fn, "initial", 293.15);
    pl_thermal_def d = pl_default_thermal_def();
    pl_lua_read_params(L, 2, fn, pl_thermal_params, PL_THERMAL_PARAM_COUNT, &d);
    pl_lua_check_status(L, lw->w, pl_world_solid_thermal(lw->w, &d, fraction, t0), fn);
    return 0;
}

static int s_heat(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    double q, v, t;
    pl_lua_check_status(L, lw->w, pl_world_solid_thermal_totals(lw->w, &q, &v, &t), "solid_heat");
    lua_pushnumber(L, q);
    lua_pushnumber(L, v);
    lua_pushnumber(L, t);
    return 3;
}

const luaL_Reg pl_lua_solid_methods[] = {{"solid", s_solid},
                                         {"solid_rectangle", s_rectangle},
                                         {"solid_quad", s_quad},
                                         {"solid_annulus", s_annulus},
                                         {"solid_polygon", s_polygon},
                                         {"solid_fix", s_fix},
                                         {"solid_velocity", s_velocity},
                                         {"solid_traction", s_traction},
                                         {"solid_initial_velocity", s_initial_velocity},
                                         {"solid_reaction", s_reaction},
                                         {"solid_displacement", s_displacement},
                                         {"solid_energy", s_energy},
                                         {"solid_info", s_info},
                                         {"solid_mesh", s_mesh},
                                         {"solid_extremes", s_extremes},
                                         {"solid_contact_force", s_contact_force},
                                         {"solid_bond", s_bond},
                                         {"solid_bonds", s_bonds},
                                         {"solid_thermal", s_thermal},
                                         {"solid_heat", s_heat},
                                         {NULL, NULL}};
