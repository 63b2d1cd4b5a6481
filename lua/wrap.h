/* Internal interface between the Lua wrappers (one wrap_<type>.c per exposed type).
 * Userdata hold engine indices, never raw pointers into the world; the world pointer itself
 * is owned by the world userdata and freed by its __gc. Bodies and materials keep their
 * world userdata alive through a user value. */
#ifndef PL_LUA_WRAP_H
#define PL_LUA_WRAP_H

#include <lua.h>
#include <lauxlib.h>
#include "porelab/world.h"
#include "context.h"

#define PL_LUA_WORLD_MT "porelab.world"
#define PL_LUA_BODY_MT "porelab.body"
#define PL_LUA_MATERIAL_MT "porelab.material"
#define PL_LUA_CSV_MT "porelab.csv"

typedef struct pl_lua_world {
    pl_world *w;
    unsigned char *flag_set; /* flag_set[i] = 1 when the scene set flag pl_flag_at(i) */
    int flag_count;
} pl_lua_world;

/* Registers each type's metatable (called once by the module opener). */
void pl_lua_register_world(lua_State *L);
void pl_lua_register_body(lua_State *L);
void pl_lua_register_material(lua_State *L);
void pl_lua_register_csv(lua_State *L);

/* porelab.world{...} and porelab.csv(path, columns): module-level constructors. */
int pl_lua_world_new(lua_State *L);
int pl_lua_csv_new(lua_State *L);

/* The world userdata at idx (raises when it is not a world). */
pl_lua_world *pl_lua_check_world(lua_State *L, int idx);

/* Pushes a handle for body (engine index) / material of the world userdata at world_idx. */
void pl_lua_push_body(lua_State *L, int world_idx, int body);
void pl_lua_push_material(lua_State *L, int world_idx, int material);

/* Resolves the material given at value_idx (a material handle or a name) to its index;
 * raises "fn: unknown material 'x' (known: ...)" otherwise. */
int pl_lua_material_index(lua_State *L, int world_idx, int value_idx, const char *fn);

/* Turns an engine status into a Lua error "file:line: fn: <engine message>"; returns
 * normally when s == PL_OK (or s >= 0). */
void pl_lua_check_status(lua_State *L, const pl_world *w, int s, const char *fn);

/* Adds the body described by def, returns its handle on the stack (used by wrap_world's
 * disc/rectangle/polygon/wall constructors). Applies a prescribed velocity when asked. */
void pl_lua_add_body(lua_State *L, int world_idx, const pl_body_def *def, const char *fn);

/* Body constructor helpers shared by wrap_body.c and wrap_shapes.c: the common fields of the
 * def table at index 2 (material, motion, fixed, velocity, omega, angle, id), and required
 * fields. COMMON_BODY_FIELDS lists the common names for pl_lua_check_fields. */
#define PL_LUA_COMMON_BODY_FIELDS "material", "motion", "fixed", "velocity", "omega", "angle", "id", \
    "fixed_rotation", "guide"
pl_body_def pl_lua_read_common(lua_State *L, const char *fn, pl_motion_type motion);
pl_vec2 pl_lua_required_vec2(lua_State *L, const char *fn, const char *field);
double pl_lua_required_positive(lua_State *L, const char *fn, const char *field);
/* w:ngon{...}, w:superquad{...}, w:random_polygon{...} (wrap_shapes.c) */
int pl_lua_w_ngon(lua_State *L);
int pl_lua_w_superquad(lua_State *L);
int pl_lua_w_random_polygon(lua_State *L);

/* The body handle at idx: returns its engine index and sets *w to its world. */
int pl_lua_check_body(lua_State *L, int idx, pl_world **w);

/* Body methods for boundary motions (wrap_motion.c) and world diagnostics (wrap_diag.c). */
extern const luaL_Reg pl_lua_motion_methods[];
extern const luaL_Reg pl_lua_diag_methods[];

/* Records that flag `name` was set by the scene (for porelab info). */
void pl_lua_mark_flag(pl_lua_world *lw, const char *name);

#endif
