/* Resolved Navier–Stokes water (porelab/navier_stokes.h) as world methods:
 *     w:navier_stokes{ x_min = , y_min = , x_max = , y_max = , density = , viscosity = ,
 *                      core_fraction = , h_near = , h_far = , grade_distance = , element = ,
 *                      solve_every = , lid_velocity = , inflow_velocity = , open_right = ,
 *                      open_top = , newton_tol = , force_relaxation = , remesh_angle = , disc_sides = ,
 *                      newton_max = , project = , stability_every = }
 *     w:navier_stokes_at(x, y)      -> u, v (m/s), p (Pa), or nil outside the fluid mesh
 *     w:navier_stokes_force(body)   -> fx, fy (N per m), moment (N m) of the last fluid step
 *     w:navier_stokes_stats()       -> table of counters and CPU times (pl_ns_stats)
 * The fields are read through the model's parameter table (pl_navier_stokes_params). */
#include "wrap.h"
#include "lua_util.h"
#include "lua_params.h"
#include "porelab/navier_stokes.h"
#include "porelab/world.h"

static int n_attach(lua_State *L)
{
    const char *fn = "navier_stokes";
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    pl_navier_stokes_def d = pl_default_navier_stokes_def();
    pl_lua_check_def(L, 2, fn);
    pl_lua_read_params(L, 2, fn, pl_navier_stokes_params, PL_NAVIER_STOKES_PARAM_COUNT, &d);
    pl_lua_check_status(L, lw->w, pl_world_attach_navier_stokes(lw->w, &d), fn);
    return 0;
}

static void need(lua_State *L, pl_lua_world *lw, const char *fn)
{
    if (!pl_world_has_navier_stokes(lw->w))
        pl_lua_error(L, "%s: the world has no Navier-Stokes water (add it with w:navier_stokes{...})", fn);
}

static int n_at(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    need(L, lw, "navier_stokes_at");
    const pl_vec2 p = {luaL_checknumber(L, 2), luaL_checknumber(L, 3)};
    pl_vec2 v;
    double pr;
    if (!pl_world_navier_stokes_at(lw->w, p, &v, &pr)) {
        lua_pushnil(L);
        return 1;
    }
    lua_pushnumber(L, v.x);
    lua_pushnumber(L, v.y);
    lua_pushnumber(L, pr);
    return 3;
}

static int n_force(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    need(L, lw, "navier_stokes_force");
    int b;
    if (lua_isinteger(L, 2)) {
        b = (int)lua_tointeger(L, 2) - 1;
    } else {
        pl_world *bw = NULL;
        b = pl_lua_check_body(L, 2, &bw);
    }
    luaL_argcheck(L, b >= 0 && b < pl_world_body_count(lw->w), 2, "body index out of range");
    pl_vec2 F;
    double M;
    pl_lua_check_status(L, lw->w, pl_world_navier_stokes_body_force(lw->w, b, &F, &M), "navier_stokes_force");
    lua_pushnumber(L, F.x);
    lua_pushnumber(L, F.y);
    lua_pushnumber(L, M);
    return 3;
}

static void setn(lua_State *L, const char *k, double v)
{
    lua_pushnumber(L, v);
    lua_setfield(L, -2, k);
}

static int n_stats(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    need(L, lw, "navier_stokes_stats");
    pl_ns_stats s;
    pl_lua_check_status(L, lw->w, pl_world_navier_stokes_stats(lw->w, &s), "navier_stokes_stats");
    lua_newtable(L);
    setn(L, "fluid_steps", (double)s.fluid_steps);
    setn(L, "remeshes", (double)s.remeshes);
    setn(L, "relocations", (double)s.relocations);
    setn(L, "newton_iters", (double)s.newton_iters);
    setn(L, "symbolic", (double)s.symbolic);
    setn(L, "numeric", (double)s.numeric);
    setn(L, "vertices", s.vertices);
    setn(L, "triangles", s.triangles);
    setn(L, "unknowns", s.unknowns);
    setn(L, "min_angle", s.min_angle);
    setn(L, "nnz_matrix", s.nnz_matrix);
    setn(L, "nnz_lu", s.nnz_lu);
    setn(L, "t_mesh", s.t_mesh);
    setn(L, "t_relocate", s.t_relocate);
    setn(L, "t_interp", s.t_interp);
    setn(L, "t_assembly", s.t_assembly);
    setn(L, "t_factor", s.t_factor);
    setn(L, "t_solve", s.t_solve);
    setn(L, "t_forces", s.t_forces);
    setn(L, "t_stability", s.t_stability);
    setn(L, "t_project", s.t_project);
    setn(L, "coupling_ratio", s.coupling_ratio);
    setn(L, "coupling_body", s.coupling_body + 1);
    setn(L, "coupling_translation", s.coupling_translation);
    setn(L, "coupling_rotation", s.coupling_rotation);
    return 1;
}

const luaL_Reg pl_lua_navier_stokes_methods[] = {{"navier_stokes", n_attach},
                                                 {"navier_stokes_at", n_at},
                                                 {"navier_stokes_force", n_force},
                                                 {"navier_stokes_stats", n_stats},
                                                 {NULL, NULL}};
