/* The pore fluid (porelab/fluid.h) as world methods: w:fluid_quad{...}, w:fluid_bc{...},
 * w:fluid_flux{...}, solves, field queries for plots, and output files. Line and quad indices
 * are 1-based in Lua. Registered into the world metatable with
 *     luaL_setfuncs(L, pl_lua_fluid_methods, 0);
 * next to the body and material constructors (see pl_lua_register_world). */
#include "wrap.h"
#include "lua_util.h"
#include "sandbox.h"
#include "porelab/fluid.h"
#include "porelab/soil.h"

#include <stdlib.h>
#include <string.h>

static pl_vec2 vec_field(lua_State *L, int t, const char *fn, const char *field)
{
    if (!pl_lua_has_field(L, t, field)) pl_lua_error(L, "%s: %s is required (a vector {x, y} in m)", fn, field);
    return pl_lua_field_vec2(L, t, fn, field, (pl_vec2){0, 0});
}

/* w:fluid_quad{corners = {{x, y} x 4, counter-clockwise}, ndivx = 4, ndivy = 4, id = n,
 *              anisotropy = 1} -> quad index (1-based) */
/* Queries read the field as it stands; a scene reading it before the first step (or after
   changing quads or lines) gets it built first, as the engine's explicit prepare step. */
static void prepare(lua_State *L, pl_lua_world *lw) {
    pl_lua_check_status(L, lw->w, pl_world_prepare(lw->w), "fluid");
}

static int f_quad(lua_State *L)
{
    static const char *const fields[] = {"corners", "ndivx", "ndivy", "id", "anisotropy", NULL};
    const char *fn = "fluid_quad";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    pl_fluid_quad_def d = pl_default_fluid_quad_def();
    lua_getfield(L, 2, "corners");
    if (!lua_istable(L, -1) || luaL_len(L, -1) != 4)
        pl_lua_error(L, "%s: corners must be a list of 4 vectors {x, y}, counter-clockwise", fn);
    for (int k = 0; k < 4; k++) {
        lua_geti(L, -1, k + 1);
        if (!pl_lua_to_vec2(L, -1, &d.corners[k]))
            pl_lua_error(L, "%s: corners[%d] must be a vector {x, y}", fn, k + 1);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    d.ndivx = pl_lua_field_int(L, 2, fn, "ndivx", d.ndivx);
    d.ndivy = pl_lua_field_int(L, 2, fn, "ndivy", d.ndivy);
    d.id = pl_lua_field_int(L, 2, fn, "id", d.id);
    d.anisotropy = pl_lua_field_number(L, 2, fn, "anisotropy", d.anisotropy);
    int q = pl_world_add_fluid_quad(lw->w, &d);
    pl_lua_check_status(L, lw->w, q, fn);
    lua_pushinteger(L, q + 1);
    return 1;
}

/* w:fluid_bc{from = {x, y}, to = {x, y}, head = pressure head (m)} -> line index */
static int f_bc(lua_State *L)
{
    static const char *const fields[] = {"from", "to", "head", NULL};
    const char *fn = "fluid_bc";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    pl_vec2 a = vec_field(L, 2, fn, "from"), b = vec_field(L, 2, fn, "to");
    if (a.x == b.x && a.y == b.y)
        pl_lua_error(L, "%s: from and to must differ (a boundary line needs a length > 0)", fn);
    if (!pl_lua_has_field(L, 2, "head")) pl_lua_error(L, "%s: head is required (pressure head, m)", fn);
    int l = pl_world_add_fluid_bc(lw->w, a, b, pl_lua_field_number(L, 2, fn, "head", 0));
    pl_lua_check_status(L, lw->w, l, fn);
    lua_pushinteger(L, l + 1);
    return 1;
}

/* w:fluid_flux{from = {x, y}, to = {x, y}, inflow = m/s into the domain} -> line index */
static int f_flux(lua_State *L)
{
    static const char *const fields[] = {"from", "to", "inflow", NULL};
    const char *fn = "fluid_flux";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    pl_vec2 a = vec_field(L, 2, fn, "from"), b = vec_field(L, 2, fn, "to");
    if (!pl_lua_has_field(L, 2, "inflow")) pl_lua_error(L, "%s: inflow is required (m/s, positive into the fluid)", fn);
    int l = pl_world_add_fluid_flux(lw->w, a, b, pl_lua_field_number(L, 2, fn, "inflow", 0));
    pl_lua_check_status(L, lw->w, l, fn);
    lua_pushinteger(L, l + 1);
    return 1;
}

static int f_clear_bcs(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_status(L, lw->w, pl_world_clear_fluid_bcs(lw->w), "clear_fluid_bcs");
    return 0;
}

static int f_change_id(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    int a = (int)luaL_checkinteger(L, 2), b = (int)luaL_checkinteger(L, 3);
    pl_lua_check_status(L, lw->w, pl_world_change_fluid_id(lw->w, a, b), "change_fluid_id");
    return 0;
}

static int f_solve_static(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_status(L, lw->w, pl_world_fluid_solve_static(lw->w), "fluid_solve_static");
    return 0;
}

static int f_advance(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    double dt = luaL_checknumber(L, 2);
    pl_lua_check_status(L, lw->w, pl_world_fluid_advance(lw->w, dt), "fluid_advance");
    return 0;
}

static int f_set_head(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    double psi = luaL_checknumber(L, 2);
    pl_lua_check_status(L, lw->w, pl_world_fluid_set_pressure_head(lw->w, psi), "fluid_set_pressure_head");
    return 0;
}

/* w:fluid_nodes() -> {{x, y}, ...}; w:fluid_triangles() -> {{i, j, k} (1-based), ...} */
static int f_nodes(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    prepare(L, lw);
    int n = pl_world_fluid_node_count(lw->w);
    pl_vec2 *xy = malloc(sizeof(pl_vec2) * (size_t)(n > 0 ? n : 1));
    if (!xy) return luaL_error(L, "fluid_nodes: out of memory");
    n = pl_world_fluid_copy_nodes(lw->w, xy, n);
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; i++) {
        pl_lua_push_vec2(L, xy[i]);
        lua_rawseti(L, -2, i + 1);
    }
    free(xy);
    return 1;
}

static int f_triangles(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    prepare(L, lw);
    int n = pl_world_fluid_triangle_count(lw->w);
    int *t = malloc(sizeof(int) * 3 * (size_t)(n > 0 ? n : 1));
    if (!t) return luaL_error(L, "fluid_triangles: out of memory");
    n = pl_world_fluid_copy_triangles(lw->w, t, n);
    lua_createtable(L, n, 0);
    for (int e = 0; e < n; e++) {
        lua_createtable(L, 3, 0);
        for (int k = 0; k < 3; k++) {
            lua_pushinteger(L, t[3 * e + k] + 1);
            lua_rawseti(L, -2, k + 1);
        }
        lua_rawseti(L, -2, e + 1);
    }
    free(t);
    return 1;
}

static const char *const node_fields[] = {"head", "pressure_head", "pressure", "excess_pressure", NULL};
static const char *const elem_fields[] = {"vx", "vy", "porosity", "void_ratio", "perm_x", "perm_y", "solid_area", NULL};

static int push_array(lua_State *L, const double *v, int n)
{
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; i++) {
        lua_pushnumber(L, v[i]);
        lua_rawseti(L, -2, i + 1);
    }
    return 1;
}

/* w:fluid_node_field("head" | "pressure_head" | "pressure" | "excess_pressure") -> array */
static int f_node_field(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    prepare(L, lw);
    int which = luaL_checkoption(L, 2, NULL, node_fields);
    int n = pl_world_fluid_node_count(lw->w);
    double *v = malloc(sizeof(double) * (size_t)(n > 0 ? n : 1));
    if (!v) return luaL_error(L, "fluid_node_field: out of memory");
    n = pl_world_fluid_copy_node_field(lw->w, (pl_fluid_node_field)which, v, n);
    push_array(L, v, n);
    free(v);
    return 1;
}

/* w:fluid_element_field("vx" | "vy" | "porosity" | "void_ratio" | "perm_x" | "perm_y" |
 * "solid_area") -> array */
static int f_element_field(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    prepare(L, lw);
    int which = luaL_checkoption(L, 2, NULL, elem_fields);
    int n = pl_world_fluid_triangle_count(lw->w);
    double *v = malloc(sizeof(double) * (size_t)(n > 0 ? n : 1));
    if (!v) return luaL_error(L, "fluid_element_field: out of memory");
    n = pl_world_fluid_copy_element_field(lw->w, (pl_fluid_element_field)which, v, n);
    push_array(L, v, n);
    free(v);
    return 1;
}

/* w:fluid_pressure_at(x, y) -> pressure (Pa), total head (m); nil outside the mesh */
static int f_pressure_at(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    prepare(L, lw);
    pl_vec2 p = {luaL_checknumber(L, 2), luaL_checknumber(L, 3)};
    double pr, h;
    if (!pl_world_fluid_pressure_at(lw->w, p, &pr, &h)) {
        lua_pushnil(L);
        return 1;
    }
    lua_pushnumber(L, pr);
    lua_pushnumber(L, h);
    return 2;
}

/* w:fluid_line_inflow(line) -> m^2/s entering through a head line (1-based index) */
static int f_line_inflow(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    prepare(L, lw);
    int line = (int)luaL_checkinteger(L, 2) - 1;
    double q = pl_world_fluid_line_inflow(lw->w, line);
    if (q != q) pl_lua_error(L, "fluid_line_inflow: no boundary line %d", line + 1);
    lua_pushnumber(L, q);
    return 1;
}

/* Body given as a handle (b:index()) or a 1-based index. */
static int body_arg(lua_State *L, int idx)
{
    if (lua_isinteger(L, idx)) return (int)lua_tointeger(L, idx) - 1;
    if (luaL_testudata(L, idx, PL_LUA_BODY_MT)) {
        lua_getfield(L, idx, "index");
        lua_pushvalue(L, idx);
        lua_call(L, 1, 1);
        int i = (int)lua_tointeger(L, -1) - 1;
        lua_pop(L, 1);
        return i;
    }
    return luaL_argerror(L, idx, "a body or a body index");
}

/* w:fluid_body_force(body) -> fx, fy (N per m), moment (N m) */
static int f_body_force(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    prepare(L, lw);
    int b = body_arg(L, 2);
    pl_vec2 F;
    double M;
    pl_lua_check_status(L, lw->w, pl_world_fluid_body_force(lw->w, b, &F, &M), "fluid_body_force");
    lua_pushnumber(L, F.x);
    lua_pushnumber(L, F.y);
    lua_pushnumber(L, M);
    return 3;
}

/* w:fluid_frame(body) / w:fluid_frame(nil): the pore water shares that prescribed body's
   acceleration (a shaking table), Darcy's law in its frame; nil: a fixed frame */
static int f_frame(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    const int b = lua_isnoneornil(L, 2) ? -1 : body_arg(L, 2);
    pl_lua_check_status(L, lw->w, pl_world_fluid_set_frame(lw->w, b), "fluid_frame");
    return 0;
}

static int f_stats(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_fluid_stats s;
    pl_world_fluid_stats(lw->w, &s);
    lua_createtable(L, 0, 14);
    const struct { const char *k; double v; } f[] = {
        {"updates", (double)s.updates},         {"factorizations", (double)s.factorizations},
        {"analyses", (double)s.analyses},       {"solves", (double)s.solves},
        {"skipped", (double)s.skipped},         {"substeps", (double)s.substeps},
        {"last_substeps", s.last_substeps},     {"explicit_dt_limit", s.explicit_dt_limit},
        {"stagger_dt_limit", s.stagger_dt_limit},   {"stagger_stiffness", s.stagger_stiffness},
        {"t_porosity", s.t_porosity},           {"t_assembly", s.t_assembly},
        {"t_factor", s.t_factor},               {"t_solve", s.t_solve},
        {"t_forces", s.t_forces}};
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++) {
        lua_pushnumber(L, f[i].v);
        lua_setfield(L, -2, f[i].k);
    }
    return 1;
}

/* w:fluid_write_vtu(path), w:fluid_write_geometry(path): inside the output folder */
static int f_write_vtu(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    char path[PATH_MAX];
    pl_lua_output_path(L, luaL_checkstring(L, 2), path, sizeof path, "fluid_write_vtu");
    pl_lua_check_status(L, lw->w, pl_world_fluid_write_vtu(lw->w, path), "fluid_write_vtu");
    lua_pushstring(L, path);
    return 1;
}

static int f_write_geometry(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    char path[PATH_MAX];
    pl_lua_output_path(L, luaL_checkstring(L, 2), path, sizeof path, "fluid_write_geometry");
    prepare(L, lw);
    pl_lua_check_status(L, lw->w, pl_world_fluid_write_geometry(lw->w, path), "fluid_write_geometry");
    lua_pushstring(L, path);
    return 1;
}

/* w:fluid_write_pvd(path, {files...}, {times...}) */
static int f_write_pvd(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    char path[PATH_MAX];
    pl_lua_output_path(L, luaL_checkstring(L, 2), path, sizeof path, "fluid_write_pvd");
    luaL_checktype(L, 3, LUA_TTABLE);
    luaL_checktype(L, 4, LUA_TTABLE);
    int n = (int)luaL_len(L, 3);
    if (luaL_len(L, 4) != n) pl_lua_error(L, "fluid_write_pvd: %d files but %d times", n, (int)luaL_len(L, 4));
    const char **files = malloc(sizeof(char *) * (size_t)(n > 0 ? n : 1));
    double *times = malloc(sizeof(double) * (size_t)(n > 0 ? n : 1));
    if (!files || !times) { free(files); free(times); return luaL_error(L, "fluid_write_pvd: out of memory"); }
    for (int i = 0; i < n; i++) {
        lua_geti(L, 3, i + 1);
        files[i] = lua_tostring(L, -1); /* kept alive by the table */
        lua_pop(L, 1);
        lua_geti(L, 4, i + 1);
        times[i] = lua_tonumber(L, -1);
        lua_pop(L, 1);
        if (!files[i]) { free(files); free(times); pl_lua_error(L, "fluid_write_pvd: files[%d] must be a string", i + 1); }
    }
    pl_status st = pl_world_fluid_write_pvd(lw->w, path, files, times, n);
    free(files);
    free(times);
    if (st != PL_OK) pl_lua_error(L, "%s", pl_world_last_error(lw->w));
    return 0;
}

/* w:fluid_output_file("geometry" | "pressures", path): files written when
 * FLUID_GEOMETRY_FLAG / FLUID_PRESSURES_FLAG are on (thesis names FLUID_*_FILENAME). */
static int f_output_file(lua_State *L)
{
    static const char *const which[] = {"geometry", "pressures", NULL};
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    int k = luaL_checkoption(L, 2, NULL, which);
    char path[PATH_MAX];
    pl_lua_output_path(L, luaL_checkstring(L, 3), path, sizeof path, "fluid_output_file");
    pl_lua_check_status(L, lw->w, pl_world_fluid_set_output_file(lw->w, which[k], path), "fluid_output_file");
    return 0;
}

/* ---- saturated soil (porelab/soil.h, docs/soil.md) ---- */

/* w:soil_region{lo = {x, y}, hi = {x, y}} -> {sxx, syy, sxy, u, u_excess, total_xx, total_yy,
 * count, area, overburden}: effective stress of the grains (contacts, compression positive, Pa),
 * mean pore and excess pore pressure (Pa), total stress sigma' + u, grains counted, wet area
 * (m^2), geostatic vertical effective stress (submerged weight of the column above, Pa) */
static int f_soil_region(lua_State *L)
{
    static const char *const fields[] = {"lo", "hi", NULL};
    const char *fn = "soil_region";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    pl_vec2 lo = vec_field(L, 2, fn, "lo"), hi = vec_field(L, 2, fn, "hi");
    pl_soil_region r;
    pl_lua_check_status(L, lw->w, pl_world_soil_region(lw->w, lo, hi, &r), fn);
    lua_createtable(L, 0, 10);
    const struct { const char *k; double v; } f[] = {
        {"sxx", r.eff[0]}, {"syy", r.eff[3]}, {"sxy", r.eff[1]}, {"u", r.u}, {"u_excess", r.u_excess},
        {"total_xx", r.total[0]}, {"total_yy", r.total[3]}, {"count", (double)r.bodies}, {"area", r.area},
        {"overburden", r.overburden}};
    for (size_t k = 0; k < sizeof f / sizeof f[0]; k++) {
        lua_pushnumber(L, f[k].v);
        lua_setfield(L, -2, f[k].k);
    }
    return 1;
}

/* w:soil_reset(): current positions become the reference of the consolidation source */
static int f_soil_reset(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_lua_check_status(L, lw->w, pl_world_soil_reset(lw->w), "soil_reset");
    return 0;
}

/* w:soil_stats() -> {t_source = s, source_abs = m^2/s} */
static int f_soil_stats(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    double t, a;
    pl_world_soil_stats(lw->w, &t, &a);
    lua_createtable(L, 0, 2);
    lua_pushnumber(L, t);
    lua_setfield(L, -2, "t_source");
    lua_pushnumber(L, a);
    lua_setfield(L, -2, "source_abs");
    return 1;
}

const luaL_Reg pl_lua_fluid_methods[] = {{"fluid_quad", f_quad},
                                         {"soil_region", f_soil_region},
                                         {"soil_reset", f_soil_reset},
                                         {"soil_stats", f_soil_stats},
                                         {"fluid_bc", f_bc},
                                         {"fluid_flux", f_flux},
                                         {"clear_fluid_bcs", f_clear_bcs},
                                         {"change_fluid_id", f_change_id},
                                         {"fluid_solve_static", f_solve_static},
                                         {"fluid_advance", f_advance},
                                         {"fluid_set_pressure_head", f_set_head},
                                         {"fluid_nodes", f_nodes},
                                         {"fluid_triangles", f_triangles},
                                         {"fluid_node_field", f_node_field},
                                         {"fluid_element_field", f_element_field},
                                         {"fluid_pressure_at", f_pressure_at},
                                         {"fluid_line_inflow", f_line_inflow},
                                         {"fluid_body_force", f_body_force},
                                         {"fluid_frame", f_frame},
                                         {"fluid_stats", f_stats},
                                         {"fluid_write_vtu", f_write_vtu},
                                         {"fluid_write_geometry", f_write_geometry},
                                         {"fluid_write_pvd", f_write_pvd},
                                         {"fluid_output_file", f_output_file},
                                         {NULL, NULL}};
