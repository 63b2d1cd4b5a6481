/* Bodies: world:disc/rectangle/polygon/wall{...} and the body handle (an index plus its
 * world; bodies are never removed, so the index stays valid). */
#include "wrap.h"
#include "lua_util.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct body_ud {
    int index;
} body_ud;

static const char *const motion_names[] = {"dynamic", "fixed", "prescribed", NULL};
static const char *const shape_names[] = {"disc", "polygon", "wall", NULL};

void pl_lua_push_body(lua_State *L, int world_idx, int body)
{
    world_idx = lua_absindex(L, world_idx);
    body_ud *b = lua_newuserdatauv(L, sizeof *b, 1);
    b->index = body;
    lua_pushvalue(L, world_idx);
    lua_setiuservalue(L, -2, 1);
    luaL_setmetatable(L, PL_LUA_BODY_MT);
}

int pl_lua_check_body(lua_State *L, int idx, pl_world **w)
{
    body_ud *b = luaL_checkudata(L, idx, PL_LUA_BODY_MT);
    lua_getiuservalue(L, idx, 1);
    *w = pl_lua_check_world(L, -1)->w;
    lua_pop(L, 1);
    return b->index;
}

void pl_lua_add_body(lua_State *L, int world_idx, const pl_body_def *def, const char *fn)
{
    pl_world *w = pl_lua_check_world(L, world_idx)->w;
    int index = pl_world_add_body(w, def);
    pl_lua_check_status(L, w, index, fn);
    if (def->motion == PL_MOTION_PRESCRIBED)
        pl_lua_check_status(L, w, pl_world_prescribe_velocity(w, index, def->velocity,
                                                              def->omega), fn);
    pl_lua_push_body(L, world_idx, index);
}

/* ------------------------------------------------------------ constructors */

/* Fields every body accepts, followed by the shape's own. */
#define COMMON_FIELDS PL_LUA_COMMON_BODY_FIELDS

/* Reads the common fields of the def table at index 2. */
pl_body_def pl_lua_read_common(lua_State *L, const char *fn, pl_motion_type motion)
{
    pl_body_def d = pl_default_body_def();
    if (!pl_lua_has_field(L, 2, "material"))
        pl_lua_error(L, "%s: material is required (a material or its name)", fn);
    lua_getfield(L, 2, "material");
    d.material = pl_lua_material_index(L, 1, -1, fn);
    lua_pop(L, 1);
    d.motion = motion;
    if (pl_lua_field_bool(L, 2, fn, "fixed", 0)) d.motion = PL_MOTION_FIXED;
    d.motion = pl_lua_field_option(L, 2, fn, "motion", (int)d.motion, motion_names);
    d.velocity = pl_lua_field_vec2(L, 2, fn, "velocity", d.velocity);
    d.omega = pl_lua_field_number(L, 2, fn, "omega", d.omega);
    d.angle = pl_lua_field_number(L, 2, fn, "angle", d.angle);
    pl_lua_check_vec2_range(L, fn, "velocity", d.velocity, PL_LUA_MAX_SPEED, "m/s");
    pl_lua_check_range(L, fn, "omega", d.omega, -PL_LUA_MAX_SPIN, PL_LUA_MAX_SPIN, PL_LUA_CLOSED, "rad/s");
    pl_lua_check_range(L, fn, "angle", d.angle, -PL_LUA_MAX_ANGLE, PL_LUA_MAX_ANGLE, PL_LUA_CLOSED, "rad");
    d.user_id = pl_lua_field_int(L, 2, fn, "id", d.user_id);
    d.fixed_rotation = pl_lua_field_bool(L, 2, fn, "fixed_rotation", 0);
    d.guide = pl_lua_field_vec2(L, 2, fn, "guide", d.guide);
    pl_lua_check_vec2_range(L, fn, "guide", d.guide, 1e6, "");
    if (d.guide.x != 0 || d.guide.y != 0) {
        if (motion == PL_MOTION_PRESCRIBED || d.motion == PL_MOTION_PRESCRIBED)
            pl_lua_error(L, "%s: guide is for bodies that move under forces (not prescribed ones)", fn);
    }
    return d;
}

pl_vec2 pl_lua_required_vec2(lua_State *L, const char *fn, const char *field)
{
    if (!pl_lua_has_field(L, 2, field))
        pl_lua_error(L, "%s: %s is required (a vector {x, y} in m)", fn, field);
    pl_vec2 v = pl_lua_field_vec2(L, 2, fn, field, (pl_vec2){0, 0});
    pl_lua_check_vec2_range(L, fn, field, v, PL_LUA_MAX_COORD, "m");
    return v;
}

double pl_lua_required_positive(lua_State *L, const char *fn, const char *field)
{
    if (!pl_lua_has_field(L, 2, field))
        pl_lua_error(L, "%s: %s is required (m, > 0)", fn, field);
    double v = pl_lua_field_number(L, 2, fn, field, 0);
    pl_lua_check_range(L, fn, field, v, 0, PL_LUA_MAX_COORD, PL_LUA_OPEN_LO, "m");
    return v;
}

static int w_disc(lua_State *L)
{
    static const char *const fields[] = {COMMON_FIELDS, "center", "radius", NULL};
    const char *fn = "disc";
    pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    pl_body_def d = pl_lua_read_common(L, fn, PL_MOTION_DYNAMIC);
    d.shape = PL_SHAPE_DISC;
    d.position = pl_lua_required_vec2(L, fn, "center");
    d.radius = pl_lua_required_positive(L, fn, "radius");
    pl_lua_add_body(L, 1, &d, fn);
    return 1;
}

static int w_rectangle(lua_State *L)
{
    static const char *const fields[] = {COMMON_FIELDS, "center", "width", "height", NULL};
    const char *fn = "rectangle";
    pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    pl_body_def d = pl_lua_read_common(L, fn, PL_MOTION_DYNAMIC);
    pl_vec2 c = pl_lua_required_vec2(L, fn, "center");
    double hw = 0.5 * pl_lua_required_positive(L, fn, "width");
    double hh = 0.5 * pl_lua_required_positive(L, fn, "height");
    /* Axis-aligned corners, counter-clockwise; the engine applies d.angle about the
     * centroid. */
    pl_vec2 v[4] = {{c.x - hw, c.y - hh}, {c.x + hw, c.y - hh}, {c.x + hw, c.y + hh},
                    {c.x - hw, c.y + hh}};
    d.shape = PL_SHAPE_POLYGON;
    d.position = c;
    d.vertices = v;
    d.vertex_count = 4;
    pl_lua_add_body(L, 1, &d, fn);
    return 1;
}

static int w_polygon(lua_State *L)
{
    static const char *const fields[] = {COMMON_FIELDS, "vertices", NULL};
    const char *fn = "polygon";
    pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    pl_body_def d = pl_lua_read_common(L, fn, PL_MOTION_DYNAMIC);
    if (lua_getfield(L, 2, "vertices") != LUA_TTABLE)
        pl_lua_error(L, "%s: vertices is required (a list of {x, y} in m, counter-clockwise)",
                     fn);
    int n = (int)luaL_len(L, -1);
    if (n < 3 || n > PL_MAX_POLY_VERTICES) {
        char range[64];
        snprintf(range, sizeof range, "in 3..%d", PL_MAX_POLY_VERTICES);
        pl_lua_range_error(L, fn, "vertex count", range, n);
    }
    pl_vec2 v[PL_MAX_POLY_VERTICES];
    for (int i = 0; i < n; i++) {
        lua_geti(L, -1, i + 1);
        if (!pl_lua_to_vec2(L, -1, &v[i]) || !isfinite(v[i].x) || !isfinite(v[i].y) ||
            fabs(v[i].x) > PL_LUA_MAX_COORD || fabs(v[i].y) > PL_LUA_MAX_COORD)
            pl_lua_error(L, "%s: vertices[%d] must be a vector {x, y} of two finite numbers "
                         "within +-1e6 m", fn, i + 1);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    d.shape = PL_SHAPE_POLYGON;
    d.vertices = v;
    d.vertex_count = n;
    pl_lua_add_body(L, 1, &d, fn);
    return 1;
}

static int w_wall(lua_State *L)
{
    static const char *const fields[] = {COMMON_FIELDS, "from", "to", NULL};
    const char *fn = "wall";
    pl_lua_check_world(L, 1);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    /* A wall is kinematic: fixed, or prescribed when it is given a velocity. */
    int moving = pl_lua_has_field(L, 2, "velocity") || pl_lua_has_field(L, 2, "omega");
    pl_body_def d = pl_lua_read_common(L, fn, moving ? PL_MOTION_PRESCRIBED : PL_MOTION_FIXED);
    if (d.motion == PL_MOTION_DYNAMIC)
        pl_lua_error(L, "%s: motion must be fixed or prescribed (walls do not respond to "
                     "forces)", fn);
    d.shape = PL_SHAPE_SEGMENT;
    d.a = pl_lua_required_vec2(L, fn, "from");
    d.b = pl_lua_required_vec2(L, fn, "to");
    if (d.a.x == d.b.x && d.a.y == d.b.y)
        pl_lua_error(L, "%s: from and to must differ (a wall needs a length > 0)", fn);
    d.position = (pl_vec2){0.5 * (d.a.x + d.b.x), 0.5 * (d.a.y + d.b.y)};
    pl_lua_add_body(L, 1, &d, fn);
    return 1;
}

const luaL_Reg pl_lua_body_constructors[] = {{"disc", w_disc},
                                             {"rectangle", w_rectangle},
                                             {"polygon", w_polygon},
                                             {"wall", w_wall},
                                             {"ngon", pl_lua_w_ngon},
                                             {"superquad", pl_lua_w_superquad},
                                             {"random_polygon", pl_lua_w_random_polygon},
                                             {NULL, NULL}};

/* ----------------------------------------------------------------- queries */

static pl_body_info body_info(lua_State *L, int idx, pl_world **w, int *index)
{
    pl_body_info info;
    *index = pl_lua_check_body(L, idx, w);
    pl_lua_check_status(L, *w, pl_world_body_info(*w, *index, &info), "body");
    return info;
}

static int b_index(lua_State *L)
{
    pl_world *w;
    lua_pushinteger(L, pl_lua_check_body(L, 1, &w) + 1);
    return 1;
}

static int b_position(lua_State *L)
{
    pl_world *w;
    int i;
    pl_body_info b = body_info(L, 1, &w, &i);
    lua_pushnumber(L, b.position.x);
    lua_pushnumber(L, b.position.y);
    return 2;
}

static int b_velocity(lua_State *L)
{
    pl_world *w;
    int i;
    pl_body_info b = body_info(L, 1, &w, &i);
    lua_pushnumber(L, b.velocity.x);
    lua_pushnumber(L, b.velocity.y);
    return 2;
}

static int b_force(lua_State *L)
{
    pl_world *w;
    int i;
    pl_body_info b = body_info(L, 1, &w, &i);
    lua_pushnumber(L, b.force.x);
    lua_pushnumber(L, b.force.y);
    return 2;
}

/* Scalar fields read through pl_body_info, one small function each. */
#define BODY_SCALAR(fname, expr)                                                           \
    static int fname(lua_State *L)                                                         \
    {                                                                                      \
        pl_world *w;                                                                       \
        int i;                                                                             \
        pl_body_info b = body_info(L, 1, &w, &i);                                          \
        lua_pushnumber(L, (expr));                                                         \
        return 1;                                                                          \
    }
BODY_SCALAR(b_angle, b.angle)
BODY_SCALAR(b_omega, b.omega)
BODY_SCALAR(b_mass, b.mass)
BODY_SCALAR(b_inertia, b.inertia)
BODY_SCALAR(b_radius, b.radius)
BODY_SCALAR(b_area, b.area)
BODY_SCALAR(b_torque, b.torque)

static int b_id(lua_State *L)
{
    pl_world *w;
    int i;
    lua_pushinteger(L, body_info(L, 1, &w, &i).user_id);
    return 1;
}

static int b_shape(lua_State *L)
{
    pl_world *w;
    int i;
    lua_pushstring(L, shape_names[body_info(L, 1, &w, &i).shape]);
    return 1;
}

static int b_motion(lua_State *L)
{
    pl_world *w;
    int i;
    lua_pushstring(L, motion_names[body_info(L, 1, &w, &i).motion]);
    return 1;
}

static int b_material(lua_State *L)
{
    pl_world *w;
    int i;
    pl_body_info b = body_info(L, 1, &w, &i);
    lua_getiuservalue(L, 1, 1);
    pl_lua_push_material(L, -1, b.material);
    return 1;
}

static int b_vertices(lua_State *L)
{
    pl_world *w;
    int i = pl_lua_check_body(L, 1, &w);
    pl_vec2 v[PL_MAX_POLY_VERTICES];
    int n = pl_world_body_vertices(w, i, v, PL_MAX_POLY_VERTICES);
    lua_createtable(L, n, 0);
    for (int k = 0; k < n; k++) {
        pl_lua_push_vec2(L, v[k]);
        lua_rawseti(L, -2, k + 1);
    }
    return 1;
}

/* ----------------------------------------------------------------- setters */

/* body:set_velocity(vx, vy [, omega]): MIMES set_velocity, the body becomes prescribed. */
static int b_set_velocity(lua_State *L)
{
    pl_world *w;
    int i = pl_lua_check_body(L, 1, &w);
    pl_vec2 v = {luaL_checknumber(L, 2), luaL_checknumber(L, 3)};
    double omega = luaL_optnumber(L, 4, 0);
    pl_lua_check_vec2_range(L, "set_velocity", "velocity", v, PL_LUA_MAX_SPEED, "m/s");
    pl_lua_check_range(L, "set_velocity", "omega", omega, -PL_LUA_MAX_SPIN, PL_LUA_MAX_SPIN, PL_LUA_CLOSED, "rad/s");
    pl_lua_check_status(L, w, pl_world_prescribe_velocity(w, i, v, omega), "set_velocity");
    return 0;
}

/* body:set_state{position =, angle =, velocity =, omega =}: instantaneous change. */
static int b_set_state(lua_State *L)
{
    static const char *const fields[] = {"position", "angle", "velocity", "omega", NULL};
    const char *fn = "set_state";
    pl_world *w;
    int i;
    pl_body_info b = body_info(L, 1, &w, &i);
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, fields);
    if (pl_lua_has_field(L, 2, "position") || pl_lua_has_field(L, 2, "angle")) {
        pl_vec2 p = pl_lua_field_vec2(L, 2, fn, "position", b.position);
        double a = pl_lua_field_number(L, 2, fn, "angle", b.angle);
        pl_lua_check_vec2_range(L, fn, "position", p, PL_LUA_MAX_COORD, "m");
        pl_lua_check_range(L, fn, "angle", a, -PL_LUA_MAX_ANGLE, PL_LUA_MAX_ANGLE, PL_LUA_CLOSED, "rad");
        pl_lua_check_status(L, w, pl_world_set_body_position(w, i, p, a), fn);
    }
    if (pl_lua_has_field(L, 2, "velocity") || pl_lua_has_field(L, 2, "omega")) {
        pl_vec2 v = pl_lua_field_vec2(L, 2, fn, "velocity", b.velocity);
        double om = pl_lua_field_number(L, 2, fn, "omega", b.omega);
        pl_lua_check_vec2_range(L, fn, "velocity", v, PL_LUA_MAX_SPEED, "m/s");
        pl_lua_check_range(L, fn, "omega", om, -PL_LUA_MAX_SPIN, PL_LUA_MAX_SPIN, PL_LUA_CLOSED, "rad/s");
        pl_lua_check_status(L, w, pl_world_set_body_velocity(w, i, v, om), fn);
    }
    return 0;
}

static int b_set_motion(lua_State *L)
{
    pl_world *w;
    int i = pl_lua_check_body(L, 1, &w);
    int m = luaL_checkoption(L, 2, NULL, motion_names);
    pl_lua_check_status(L, w, pl_world_set_body_motion(w, i, (pl_motion_type)m), "set_motion");
    return 0;
}

static int b_set_load(lua_State *L)
{
    pl_world *w;
    int i = pl_lua_check_body(L, 1, &w);
    pl_vec2 f = {luaL_checknumber(L, 2), luaL_checknumber(L, 3)};
    double moment = luaL_optnumber(L, 4, 0);
    pl_lua_check_vec2_range(L, "set_load", "force", f, PL_LUA_MAX_FORCE, "N");
    pl_lua_check_range(L, "set_load", "moment", moment, -PL_LUA_MAX_FORCE, PL_LUA_MAX_FORCE, PL_LUA_CLOSED, "N m");
    pl_lua_check_status(L, w, pl_world_set_body_load(w, i, f, moment), "set_load");
    return 0;
}

static int b_set_density(lua_State *L)
{
    pl_world *w;
    int i = pl_lua_check_body(L, 1, &w);
    double rho = luaL_checknumber(L, 2);
    pl_lua_check_range(L, "set_density", "density", rho, 0, PL_LUA_MAX_DENSITY, PL_LUA_OPEN_LO, "kg/m^3");
    pl_lua_check_status(L, w, pl_world_set_body_density(w, i, rho), "set_density");
    return 0;
}

/* body:set_fixed_rotation(true|false): a guided body keeps its angle (an oedometer piston). */
static int b_set_fixed_rotation(lua_State *L)
{
    pl_world *w;
    int i = pl_lua_check_body(L, 1, &w);
    luaL_checktype(L, 2, LUA_TBOOLEAN);
    pl_lua_check_status(L, w, pl_world_set_body_fixed_rotation(w, i, lua_toboolean(L, 2)),
                        "set_fixed_rotation");
    return 0;
}

static int b_tostring(lua_State *L)
{
    pl_world *w;
    int i;
    pl_body_info b = body_info(L, 1, &w, &i);
    lua_pushfstring(L, "porelab.body #%d (%s, %s)", i + 1, shape_names[b.shape],
                    motion_names[b.motion]);
    return 1;
}

static int b_eq(lua_State *L)
{
    body_ud *a = luaL_testudata(L, 1, PL_LUA_BODY_MT);
    body_ud *b = luaL_testudata(L, 2, PL_LUA_BODY_MT);
    int same = a && b && a->index == b->index;
    if (same) {
        lua_getiuservalue(L, 1, 1);
        lua_getiuservalue(L, 2, 1);
        same = lua_rawequal(L, -1, -2);
    }
    lua_pushboolean(L, same);
    return 1;
}

static const luaL_Reg body_methods[] = {
    {"index", b_index},         {"id", b_id},
    {"shape", b_shape},         {"motion", b_motion},
    {"material", b_material},   {"position", b_position},
    {"velocity", b_velocity},   {"angle", b_angle},
    {"omega", b_omega},         {"force", b_force},
    {"torque", b_torque},       {"mass", b_mass},
    {"inertia", b_inertia},     {"radius", b_radius},
    {"area", b_area},           {"vertices", b_vertices},
    {"set_velocity", b_set_velocity}, {"set_state", b_set_state},
    {"set_motion", b_set_motion},     {"set_load", b_set_load},
    {"set_density", b_set_density},   {"set_fixed_rotation", b_set_fixed_rotation},
    {NULL, NULL}};

void pl_lua_register_body(lua_State *L)
{
    luaL_newmetatable(L, PL_LUA_BODY_MT);
    lua_pushcfunction(L, b_tostring);
    lua_setfield(L, -2, "__tostring");
    lua_pushcfunction(L, b_eq);
    lua_setfield(L, -2, "__eq");
    luaL_newlib(L, body_methods);
    luaL_setfuncs(L, pl_lua_motion_methods, 0); /* wrap_motion.c */
    lua_setfield(L, -2, "__index");
    lua_pop(L, 1);
}
