/* Pieces of the scene loader shared with the wrappers. */
#ifndef PL_LUA_SCENE_INTERNAL_H
#define PL_LUA_SCENE_INTERNAL_H

#include <lua.h>

/* Remembers the world userdata at idx as the scene's latest world. */
void pl_lua_scene_note_world(lua_State *L, int idx);
/* Pushes the latest world userdata (or nil). */
void pl_lua_scene_push_last_world(lua_State *L);

/* Opens the standard libraries, the porelab module (global `porelab`, also
 * require "porelab") and the embedded pure-Lua helpers (require "porelab.packing"). */
void pl_lua_open_porelab(lua_State *L);

/* Embedded pure-Lua helpers (generated at build time from lua/lib). */
typedef struct pl_lua_lib {
    const char *name;           /* module name, e.g. "porelab.packing" */
    const unsigned char *code;  /* source text */
    unsigned long size;
} pl_lua_lib;
extern const pl_lua_lib pl_lua_libs[];
extern const int pl_lua_lib_count;

#endif
