/* world{fluid = "auto", needs = ..., water = {...}}: porelab picks the cheapest fluid model
 * that answers the scene's question (docs/compare.md §"fluid = auto"), from dimensionless
 * groups it computes from the grains and the water:
 *   - particle Reynolds number Re_p = rho_f U d / mu, with U the larger of the grains'
 *     settling speed (Stokes, capped by the Newton drag regime) and the seepage speed K i / n;
 *   - consolidation time t_c = H^2 / c_v, c_v = K / (rho_f g (1/M + n/K_f)) (M the skeleton's
 *     constrained modulus, taken as the contact stiffness kn per unit depth), against the
 *     scene's duration;
 *   - porosity n of the water region and the grains per element of a Darcy mesh.
 * The choice is made when the scene is loaded (or at its first step), before anything runs,
 * and explained (with the rejected alternatives) in porelab info and the run summary. A scene
 * that fixes Darcy where its assumptions break (Re_p > 10) gets a warning with the number.
 * For the flow between grains auto attaches a resolved model: Stokes by boundary elements for
 * creeping flow (Re_p < 1; the container is the scene's walls, closed by a lid at the water level
 * when the tank is open, the grains shrunk by an artificial gap so that touching grains leave a
 * channel), Navier-Stokes otherwise (the water region as its box, open at the top). A scene that
 * fixes Stokes flow where inertia matters (Re_p > 1) gets a warning with the number. */
#include "fluid_auto.h"
#include "lua_util.h"
#include "porelab/darcy.h"
#include "porelab/fluid.h"
#include "porelab/hydrostatic.h"
#include "porelab/navier_stokes.h"
#include "porelab/stokes.h"
#include "wrap.h"

#include <lauxlib.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define NOTES_KEY "porelab.fluid_notes"

/* The rungs of the ladder, cheapest first. available = 0: "auto" cannot set the model up (it
   then falls back to the closest one that it can, and says so). */
enum { M_HYDROSTATIC, M_DARCY, M_DARCY_CONS, M_STOKES, M_NAVIER_STOKES, M_COUNT };
static const struct {
    const char *name, *what;
    int available;
} MODELS[M_COUNT] = {
    {"hydrostatic", "still water, exact buoyancy, no mesh (w:water)", 1},
    {"darcy", "Darcy seepage on a mesh (w:darcy)", 1},
    {"darcy+consolidation", "Darcy with pore pressure from skeleton volume change", 1},
    {"stokes", "resolved Stokes flow by boundary elements (w:stokes)", 1},
    {"navier_stokes", "resolved Navier-Stokes flow (w:navier_stokes)", 1},
};

static const char *const NEEDS[] = {"buoyancy", "seepage", "pore_pressure", "flow_between_grains", NULL};
enum { N_BUOYANCY, N_SEEPAGE, N_PORE_PRESSURE, N_FLOW };

static const char *const WATER_FIELDS[] = {"x_min", "x_max", "bottom", "level", "density", "viscosity",
                                           "conductivity", "bulk_modulus", "head_difference", "duration",
                                           NULL};

void pl_lua_fluid_auto_note(lua_State *L, const char *fmt, ...)
{
    char buf[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    lua_getfield(L, LUA_REGISTRYINDEX, NOTES_KEY);
    const char *old = lua_tostring(L, -1);
    lua_pushfstring(L, "%s%s\n", old ? old : "", buf);
    lua_setfield(L, LUA_REGISTRYINDEX, NOTES_KEY);
    lua_pop(L, 1);
}

const char *pl_lua_fluid_notes(lua_State *L)
{
    lua_getfield(L, LUA_REGISTRYINDEX, NOTES_KEY);
    const char *s = lua_tostring(L, -1);
    lua_pop(L, 1); /* the string stays referenced by the registry */
    return s ? s : "";
}

int pl_lua_fluid_auto_read(lua_State *L, int t, int world_idx)
{
    if (lua_isnoneornil(L, t)) return 0;
    lua_getfield(L, t, "fluid");
    if (lua_isnil(L, -1)) {
        lua_pop(L, 1);
        lua_getfield(L, t, "needs");
        lua_getfield(L, t, "water");
        if (!lua_isnil(L, -1) || !lua_isnil(L, -2))
            pl_lua_error(L, "world: needs and water go with fluid = \"auto\"");
        lua_pop(L, 2);
        return 0;
    }
    if (lua_type(L, -1) != LUA_TSTRING || strcmp(lua_tostring(L, -1), "auto") != 0)
        pl_lua_error(L, "world: fluid must be \"auto\" (porelab picks the model; or leave it out and "
                        "attach one with w:water, w:darcy) (got %s)",
                     lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : luaL_typename(L, -1));
    lua_pop(L, 1);
    lua_createtable(L, 0, 4);
    int q = lua_gettop(L);
    lua_getfield(L, t, "needs");
    if (lua_type(L, -1) != LUA_TSTRING)
        pl_lua_error(L, "world: fluid = \"auto\" needs needs = \"buoyancy\", \"seepage\", \"pore_pressure\" "
                        "or \"flow_between_grains\" (what the scene must know; got %s)",
                     luaL_typename(L, -1));
    int k = 0;
    while (NEEDS[k] && strcmp(NEEDS[k], lua_tostring(L, -1)) != 0) k++;
    if (!NEEDS[k])
        pl_lua_error(L, "world: needs must be \"buoyancy\", \"seepage\", \"pore_pressure\" or "
                        "\"flow_between_grains\" (got '%s')", lua_tostring(L, -1));
    lua_setfield(L, q, "needs");
    lua_getfield(L, t, "water");
    if (!lua_istable(L, -1))
        pl_lua_error(L, "world: fluid = \"auto\" needs water = {x_min, x_max, bottom, level, ...} "
                        "(the water's region; got %s)", luaL_typename(L, -1));
    pl_lua_check_fields(L, lua_gettop(L), "world.water", WATER_FIELDS);
    const char *req[4] = {"x_min", "x_max", "bottom", "level"};
    for (int i = 0; i < 4; i++) {
        lua_getfield(L, -1, req[i]);
        if (lua_type(L, -1) != LUA_TNUMBER || !isfinite(lua_tonumber(L, -1)))
            pl_lua_error(L, "world.water: %s must be a finite number, m (got %s)", req[i], luaL_typename(L, -1));
        lua_pop(L, 1);
    }
    lua_setfield(L, q, "water");
    lua_setiuservalue(L, world_idx, 1);
    return 1;
}

static double wnum(lua_State *L, int t, const char *k, double def, double lo, double hi, const char *unit)
{
    lua_getfield(L, t, k);
    double v = def;
    if (!lua_isnil(L, -1)) {
        if (lua_type(L, -1) != LUA_TNUMBER) pl_lua_error(L, "world.water: %s must be a number, %s", k, unit);
        v = lua_tonumber(L, -1);
        if (!(v >= lo && v <= hi))
            pl_lua_error(L, "world.water: %s must be in [%g, %g] %s (got %g)", k, lo, hi, unit, v);
    }
    lua_pop(L, 1);
    return v;
}

typedef struct groups {
    int grains;
    double d, rho_s, n, kn;       /* mean diameter m, density kg/m^3, porosity, stiffness N/m */
    double U_settle, U_seep, Re_p; /* m/s, m/s, 1 */
    double t_c;                    /* s */
    int loose;                     /* 1: grains apart (n >= 0.7), they settle through the water */
} groups;

static groups compute(const pl_world *w, double x0, double x1, double y0, double y1, double rho_f,
                      double mu, double K, double Kf, double dh, double g)
{
    groups G;
    memset(&G, 0, sizeof G);
    double dsum = 0, msum = 0, asum = 0, solid = 0;
    double bx0 = INFINITY, bx1 = -INFINITY, by0 = INFINITY, by1 = -INFINITY; /* grains in the water */
    const int nb = pl_world_body_count(w);
    for (int i = 0; i < nb; i++) {
        pl_body_info b;
        if (pl_world_body_info(w, i, &b) != PL_OK || b.motion != PL_MOTION_DYNAMIC || !(b.area > 0)) continue;
        G.grains++;
        dsum += 2 * sqrt(b.area / M_PI);
        msum += b.mass;
        asum += b.area;
        if (b.position.x >= x0 && b.position.x <= x1 && b.position.y >= y0 && b.position.y <= y1) {
            solid += b.area;
            bx0 = fmin(bx0, b.position.x - b.radius);
            bx1 = fmax(bx1, b.position.x + b.radius);
            by0 = fmin(by0, b.position.y - b.radius);
            by1 = fmax(by1, b.position.y + b.radius);
        }
        const double kn = pl_world_material(w, b.material).kn;
        if (kn > G.kn) G.kn = kn;
    }
    /* the porosity of the part of the water the grains occupy (a bed, not the whole tank) */
    const double region = solid > 0 ? (fmin(bx1, x1) - fmax(bx0, x0)) * (fmin(by1, y1) - fmax(by0, y0)) : 0;
    G.n = region > 0 ? fmax(0.0, 1 - solid / region) : 1;
    if (G.grains == 0) {
        G.t_c = 0;
        return G;
    }
    G.d = dsum / G.grains;
    G.rho_s = msum / asum;
    const double drho = fabs(G.rho_s - rho_f);
    const double stokes = drho * g * G.d * G.d / (18 * mu);
    const double newton = sqrt(4 * drho * g * G.d / (3 * 0.44 * rho_f));
    G.U_settle = fmin(stokes, newton);
    const double H = fmax(y1 - y0, 1e-12);
    G.U_seep = dh > 0 ? K * (dh / H) / fmax(G.n, 0.05) : 0;
    /* grains far apart settle through the water; in a packing (n < 0.7) they move with the
       skeleton and the water's speed relative to them is the seepage speed */
    G.loose = G.n >= 0.7 || G.grains < 5;
    G.Re_p = rho_f * (G.loose ? fmax(G.U_settle, G.U_seep) : G.U_seep) * G.d / mu;
    const double M = G.kn > 0 ? G.kn : 1e8;
    const double mv = 1 / M + (Kf > 0 ? G.n / Kf : 0);
    G.t_c = K > 0 ? H * H * rho_f * g * mv / K : INFINITY;
    return G;
}

static void attach_hydrostatic(lua_State *L, pl_world *w, double x0, double x1, double y0, double lvl, double rho)
{
    pl_hydrostatic_def d = pl_default_hydrostatic_def();
    d.x_min = x0;
    d.x_max = x1;
    d.bottom = y0;
    d.level = lvl;
    d.density = rho;
    pl_lua_check_status(L, w, pl_world_attach_hydrostatic(w, &d), "world (fluid = \"auto\")");
}

static int attach_darcy(lua_State *L, pl_world *w, double x0, double x1, double y0, double lvl, double rho,
                        double mu, double K, double Kf, double dh, double d, int cons)
{
    /* elements about 2.5 grain diameters (several grains per element, the porosity averages
       over them; docs/fluid.md), 4 to 64 cells a side */
    const double h = d > 0 ? 2.5 * d : (lvl - y0) / 8;
    int nx = (int)fmin(64, fmax(4, floor((x1 - x0) / h + 0.5)));
    int ny = (int)fmin(64, fmax(4, floor((lvl - y0) / h + 0.5)));
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){x0, y0};
    q.corners[1] = (pl_vec2){x1, y0};
    q.corners[2] = (pl_vec2){x1, lvl};
    q.corners[3] = (pl_vec2){x0, lvl};
    q.ndivx = nx;
    q.ndivy = ny;
    if (pl_world_add_fluid_quad(w, &q) < 0) pl_lua_check_status(L, w, PL_ERR_ARG, "world (fluid = \"auto\")");
    /* the free surface at the level; with a head difference the floor is held dh higher */
    pl_world_add_fluid_bc(w, (pl_vec2){x0, lvl}, (pl_vec2){x1, lvl}, 0.0);
    if (dh > 0) pl_world_add_fluid_bc(w, (pl_vec2){x0, y0}, (pl_vec2){x1, y0}, lvl - y0 + dh);
    pl_darcy_def dd;
    pl_world_get_darcy(w, &dd);
    dd.on = 1;
    dd.density = rho;
    dd.viscosity = mu;
    dd.perm_mode = 0;
    dd.perm_high = K;
    dd.storage = 0;
    dd.consolidation = cons;
    dd.bulk_modulus = Kf;
    pl_lua_check_status(L, w, pl_world_set_darcy(w, &dd), "world (fluid = \"auto\")");
    return nx * ny * 2;
}

/* Stokes by boundary elements: the container is the world's walls; an open tank gets a lid at
   the water level (a no-slip lid: Stokes flow needs a closed container, docs/stokes.md). The
   grains' outlines shrink by gap / 2 (Tan's artificial gap, seed 003 §3.4): a tenth of the mean
   grain radius, so that grains in contact leave a channel. Returns 1 when a lid was added. */
static int attach_stokes(lua_State *L, pl_world *w, double x0, double x1, double lvl, double rho, double mu, double d,
                         double *dt_cap)
{
    int lid = 1, mat = -1;
    const int nb = pl_world_body_count(w);
    for (int i = 0; i < nb; i++) {
        pl_body_info b;
        if (pl_world_body_info(w, i, &b) != PL_OK || b.shape != PL_SHAPE_SEGMENT) continue;
        pl_vec2 e[2];
        if (pl_world_body_vertices(w, i, e, 2) != 2) continue;
        if (mat < 0) mat = b.material;
        const double tol = 1e-6 * fmax(1.0, x1 - x0);
        /* a wall already closes the top at or below the water level */
        if (fabs(e[0].y - e[1].y) < tol && e[0].y <= lvl + tol && e[0].y > lvl - 0.5 * (x1 - x0) &&
            fmin(e[0].x, e[1].x) <= x0 + tol && fmax(e[0].x, e[1].x) >= x1 - tol)
            lid = 0;
    }
    if (lid) {
        pl_body_def b = pl_default_body_def();
        b.shape = PL_SHAPE_SEGMENT;
        b.motion = PL_MOTION_FIXED;
        b.material = mat >= 0 ? mat : 0;
        const double e = 0.01 * (x1 - x0);
        b.a = (pl_vec2){x1 + e, lvl};
        b.b = (pl_vec2){x0 - e, lvl};
        if (pl_world_add_body(w, &b) < 0) pl_lua_check_status(L, w, PL_ERR_ARG, "world (fluid = \"auto\")");
    }
    pl_stokes_def sd = pl_default_stokes_def();
    sd.viscosity = mu;
    sd.density = rho;
    if (d > 0) sd.gap = 0.05 * d;
    pl_lua_check_status(L, w, pl_world_attach_stokes(w, &sd), "world (fluid = \"auto\")");
    /* the explicit drag's limit (docs/stokes.md): one solve gives every grain's 2 m / K; the
       grain step is capped at half the smallest (MAX_DT_CR) */
    pl_lua_check_status(L, w, pl_world_stokes_solve(w), "world (fluid = \"auto\")");
    double safe = INFINITY;
    for (int i = 0; i < pl_world_body_count(w); i++) {
        pl_body_info b;
        pl_stokes_body_result r;
        if (pl_world_body_info(w, i, &b) != PL_OK || b.motion != PL_MOTION_DYNAMIC) continue;
        if (pl_world_stokes_body(w, i, &r) == PL_OK && r.dt_safe > 0) safe = fmin(safe, r.dt_safe);
    }
    *dt_cap = 0;
    double cap = 0;
    pl_world_get_flag(w, "MAX_DT_CR", &cap);
    if (isfinite(safe) && (!(cap > 0) || cap > 0.5 * safe)) {
        *dt_cap = 0.5 * safe;
        pl_world_set_flag(w, "MAX_DT_CR", *dt_cap);
    }
    return lid;
}

/* Navier-Stokes: the water region is the box (walls below and at the sides, open at the top);
   the mesh about a sixth of a grain diameter on the grains' cores, growing to a diameter. */
static void attach_navier_stokes(lua_State *L, pl_world *w, double x0, double x1, double y0, double lvl, double rho,
                                 double mu, double d)
{
    pl_navier_stokes_def nd = pl_default_navier_stokes_def();
    nd.x_min = x0;
    nd.x_max = x1;
    nd.y_min = y0;
    nd.y_max = lvl;
    nd.density = rho;
    nd.viscosity = mu;
    nd.open_top = 1;
    if (d > 0) {
        nd.h_near = d / 6;
        nd.h_far = fmax(d, nd.h_near);
        nd.grade_distance = d;
    }
    pl_lua_check_status(L, w, pl_world_attach_navier_stokes(w, &nd), "world (fluid = \"auto\")");
}

static double gravity(const pl_world *w)
{
    double gx = 0, gy = 0;
    pl_world_get_flag(w, "GRAVITY_X", &gx);
    pl_world_get_flag(w, "GRAVITY_Y", &gy);
    return fmax(hypot(gx, gy), 1e-12);
}

int pl_lua_fluid_auto_apply(lua_State *L, int world_idx, double duration)
{
    world_idx = lua_absindex(L, world_idx);
    pl_lua_world *lw = pl_lua_check_world(L, world_idx);
    if (lua_getiuservalue(L, world_idx, 1) != LUA_TTABLE) {
        lua_pop(L, 1);
        return 0;
    }
    int q = lua_gettop(L);
    lua_getfield(L, q, "needs");
    const char *ns = lua_tostring(L, -1);
    int needs = 0;
    while (NEEDS[needs] && strcmp(NEEDS[needs], ns) != 0) needs++;
    lua_pop(L, 1);
    lua_getfield(L, q, "water");
    int t = lua_gettop(L);
    const double x0 = wnum(L, t, "x_min", 0, -1e9, 1e9, "m"), x1 = wnum(L, t, "x_max", 1, -1e9, 1e9, "m");
    const double y0 = wnum(L, t, "bottom", 0, -1e9, 1e9, "m"), lvl = wnum(L, t, "level", 1, -1e9, 1e9, "m");
    if (!(x1 > x0) || !(lvl > y0)) pl_lua_error(L, "world.water: need x_max > x_min and level > bottom");
    const double rho = wnum(L, t, "density", 1000, 1e-6, 1e6, "kg/m^3");
    const double mu = wnum(L, t, "viscosity", 1e-3, 1e-9, 1e9, "Pa s");
    const double Kf = wnum(L, t, "bulk_modulus", 2.2e9, 0, 1e30, "Pa");
    const double dh = wnum(L, t, "head_difference", 0, 0, 1e9, "m");
    const double dur = wnum(L, t, "duration", duration > 0 ? duration : INFINITY, 0, INFINITY, "s");
    const double g = gravity(lw->w);
    /* conductivity: given, or Kozeny-Carman from the grains (K = rho g d^2 n^3 / (180 mu (1-n)^2)) */
    groups G = compute(lw->w, x0, x1, y0, lvl, rho, mu, 1, Kf, dh, g);
    double K = wnum(L, t, "conductivity", 0, 0, 1e30, "m/s");
    const int K_given = K > 0;
    if (!K_given) {
        const double n = fmin(fmax(G.n, 0.2), 0.95);
        K = G.d > 0 ? rho * g * G.d * G.d * n * n * n / (180 * mu * (1 - n) * (1 - n)) : 1.0;
    }
    G = compute(lw->w, x0, x1, y0, lvl, rho, mu, K, Kf, dh, g);
    lua_pop(L, 2);
    lua_pushnil(L); /* decided: the question is consumed */
    lua_setiuservalue(L, world_idx, 1);

    char groups_txt[512];
    snprintf(groups_txt, sizeof groups_txt,
             "%d grains, d = %.3g m, porosity %.2f, Re_p = %.3g (settling %.3g m/s, seepage %.3g m/s), "
             "K = %.3g m/s%s, t_c = %.3g s, duration %.3g s",
             G.grains, G.d, G.n, G.Re_p, G.U_settle, G.U_seep, K, K_given ? "" : " (Kozeny-Carman)", G.t_c, dur);
    int pick = M_HYDROSTATIC;
    char why[768] = "", rejected[1024] = "";
    switch (needs) {
    case N_BUOYANCY:
        if (dh > 0) {
            pick = M_DARCY;
            snprintf(why, sizeof why, "a head difference of %.3g m drives flow, so buoyancy alone is not the answer", dh);
            snprintf(rejected, sizeof rejected, "hydrostatic: would miss the seepage force of the %.3g m head difference", dh);
        } else {
            snprintf(why, sizeof why, "no flow expected (no head difference): buoyancy is the still-water outline integral");
            snprintf(rejected, sizeof rejected,
                     "darcy: the same buoyancy on a mesh, about 100x the cost (docs/compare.md, problem buoyancy); "
                     "stokes, navier_stokes: not needed (they resolve the flow there is none of)");
        }
        break;
    case N_SEEPAGE:
        pick = M_DARCY;
        if (G.Re_p > 10) {
            snprintf(why, sizeof why,
                     "Re_p = %.3g is past Darcy's range (Re_p < 1-10, Bear 1972): the drag grows faster than the flow, "
                     "which Darcy leaves out (expect it too low); Darcy is still the only averaged model; navier_stokes "
                     "resolves it (needs = \"flow_between_grains\"), meshing every pore",
                     G.Re_p);
        } else {
            snprintf(why, sizeof why, "seepage forces at Re_p = %.3g < 10: Darcy's law holds", G.Re_p);
        }
        snprintf(rejected, sizeof rejected,
                 "hydrostatic: has no flow, so no seepage force; stokes, navier_stokes: resolve the pores, "
                 "far more costly than a Darcy mesh of several grains per element (docs/compare.md, problem fixed_bed: "
                 "thousands of times the cost)");
        break;
    case N_PORE_PRESSURE:
        if (G.t_c < 0.1 * dur) {
            pick = dh > 0 ? M_DARCY : M_HYDROSTATIC;
            snprintf(why, sizeof why,
                     "drained: excess pore pressure dissipates in t_c = %.3g s, under 10%% of the duration %.3g s, so "
                     "the water stays %s",
                     G.t_c, dur, dh > 0 ? "in steady seepage" : "hydrostatic");
            snprintf(rejected, sizeof rejected,
                     "darcy+consolidation: would resolve a transient that is over in %.2g%% of the run", 100 * G.t_c / dur);
        } else {
            pick = M_DARCY_CONS;
            snprintf(why, sizeof why,
                     "t_c = %.3g s is %.3g times the duration %.3g s: the pore pressure the loading creates lasts, so "
                     "the water must feel the skeleton's volume change%s",
                     G.t_c, G.t_c / dur, dur, G.t_c > 100 * dur ? " (undrained)" : "");
            snprintf(rejected, sizeof rejected,
                     "hydrostatic, darcy: no pore pressure from loading (drained answers in a partly drained test)");
        }
        break;
    default: /* N_FLOW */
        pick = G.Re_p < 1 ? M_STOKES : M_NAVIER_STOKES; /* creeping flow below Re_p ~ 1 */
        snprintf(why, sizeof why, "the flow between grains needs a resolved model: %s at Re_p = %.3g", MODELS[pick].name,
                 G.Re_p);
        if (pick == M_STOKES)
            snprintf(why, sizeof why,
                     "the flow between grains needs a resolved model; at Re_p = %.3g < 1 inertia is negligible, so "
                     "creeping (Stokes) flow by boundary elements: only the outlines carry unknowns",
                     G.Re_p);
        else
            snprintf(why, sizeof why,
                     "the flow between grains needs a resolved model; at Re_p = %.3g >= 1 inertia matters (Stokes flow "
                     "drops it), so Navier-Stokes on a mesh of the pore space",
                     G.Re_p);
        snprintf(rejected, sizeof rejected,
                 "hydrostatic: no flow; darcy: averages the flow over elements of several grains, and its "
                 "Kozeny-Carman permeability is 2.9 times the resolved one in the fixed bed of docs/compare.md; %s",
                 pick == M_STOKES ? "navier_stokes: the same creeping flow on a mesh of the pore space, about 10 times "
                                    "the cost at the same error (docs/compare.md, problem fixed_bed)"
                                  : "stokes: leaves out inertia, wrong at this Re_p");
        if (!MODELS[pick].available) {
            char tmp[768];
            snprintf(tmp, sizeof tmp, "%s, which auto does not set up yet (attach w:%s{} by hand); falling back to darcy (the flow "
                     "averaged over elements, not between grains)", why, MODELS[pick].name);
            snprintf(why, sizeof why, "%s", tmp);
            pick = M_DARCY;
        }
        break;
    }
    int elements = 0;
    char mesh[256] = "";
    if (pick == M_HYDROSTATIC) attach_hydrostatic(L, lw->w, x0, x1, y0, lvl, rho);
    else if (pick == M_STOKES) {
        double cap = 0;
        const int lid = attach_stokes(L, lw->w, x0, x1, lvl, rho, mu, G.d, &cap);
        char captxt[96] = "";
        if (cap > 0) snprintf(captxt, sizeof captxt, ", grain step <= %.3g s (half the drag limit 2 m/K)", cap);
        snprintf(mesh, sizeof mesh, ", gap %.3g m%s%s", 0.05 * G.d, lid ? ", a lid at the water level closes the tank" : "",
                 captxt);
    } else if (pick == M_NAVIER_STOKES) {
        attach_navier_stokes(L, lw->w, x0, x1, y0, lvl, rho, mu, G.d);
        snprintf(mesh, sizeof mesh, ", mesh %.3g m on the grains, open top", G.d / 6);
    } else
        elements = attach_darcy(L, lw->w, x0, x1, y0, lvl, rho, mu, K, Kf, dh, G.d, pick == M_DARCY_CONS);
    if (elements) snprintf(mesh, sizeof mesh, ", %d elements", elements);
    pl_lua_fluid_auto_note(L, "  fluid auto     needs %s: %s%s: %s", NEEDS[needs], MODELS[pick].name, mesh, why);
    pl_lua_fluid_auto_note(L, "                 groups: %s", groups_txt);
    pl_lua_fluid_auto_note(L, "                 rejected: %s", rejected);
    return 1;
}

/* A scene that fixes Stokes flow where inertia matters: Re_p from the grains' settling speed
   (grains apart) or the fastest body (moving walls, a grain set going) above 1. */
static void check_stokes(lua_State *L, pl_world *w)
{
    pl_stokes_def sd;
    if (!pl_world_has_stokes(w) || pl_world_stokes_def(w, &sd) != PL_OK) return;
    groups G = compute(w, -1e30, 1e30, -1e30, 1e30, sd.density, sd.viscosity, 0, 0, 0, gravity(w));
    if (G.grains == 0) return;
    double vmax = 0;
    const int nb = pl_world_body_count(w);
    for (int i = 0; i < nb; i++) {
        pl_body_info b;
        if (pl_world_body_info(w, i, &b) == PL_OK) vmax = fmax(vmax, hypot(b.velocity.x, b.velocity.y));
    }
    const double U = fmax(G.loose ? G.U_settle : 0, vmax);
    const double re = sd.density * U * G.d / sd.viscosity;
    if (re > 1)
        pl_lua_fluid_auto_note(L,
                               "  warning        Stokes flow at a particle Reynolds number Re_p = %.3g (grains d = %.3g m, "
                               "speed scale %.3g m/s, viscosity %.3g Pa s): Stokes flow leaves out inertia and holds for "
                               "Re_p << 1; suggested model: navier_stokes (w:navier_stokes{}, or fluid = \"auto\" with "
                               "needs = \"flow_between_grains\")",
                               re, G.d, U, sd.viscosity);
}

void pl_lua_fluid_check_assumptions(lua_State *L, int world_idx)
{
    pl_lua_world *lw = pl_lua_check_world(L, world_idx);
    check_stokes(L, lw->w);
    pl_darcy_def d;
    pl_world_get_darcy(lw->w, &d);
    if (!d.on || d.perm_units || d.perm_mode != 0) return; /* uniform conductivity only: K = FLUID_PERM_HIGH */
    const double g = gravity(lw->w);
    /* the grains' settling speed through the water the Darcy model describes */
    groups G = compute(lw->w, -1e30, 1e30, -1e30, 1e30, d.density, d.viscosity, d.perm_high, d.bulk_modulus, 0, g);
    if (G.grains == 0) return;
    /* loose grains settle through the water; a packing sees the seepage at the critical
       gradient i ~ 1 (quicksand), speed K / n */
    const double U = G.loose ? G.U_settle : d.perm_high / fmax(G.n, 0.05);
    const double re = d.density * U * G.d / d.viscosity;
    if (re > 10)
        pl_lua_fluid_auto_note(L,
                               "  warning        Darcy at a particle Reynolds number Re_p = %.3g (grains d = %.3g m, "
                               "speed scale %.3g m/s, FLUID_VISCOSITY %.3g Pa s): Darcy's law holds to Re_p ~ 1-10 "
                               "(Bear 1972); suggested model: hydrostatic when only buoyancy matters (w:water, or "
                               "fluid = \"auto\" with needs = \"buoyancy\"), navier_stokes for the flow "
                               "(w:navier_stokes{})",
                               re, G.d, U, d.viscosity);
}
