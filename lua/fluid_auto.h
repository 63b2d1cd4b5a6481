/* world{fluid = "auto", needs = ..., water = {...}} (fluid_auto.c): the scene's question is
 * read with the world, the model chosen before the first step, and the choice explained in
 * notes that porelab info and porelab run print. */
#ifndef PL_LUA_FLUID_AUTO_H
#define PL_LUA_FLUID_AUTO_H
#include <lua.h>

/* Reads fluid/needs/water of the world table at t and keeps the question with the world
   userdata at world_idx (user value 1). Returns 1 when fluid = "auto"; raises Lua errors. */
int pl_lua_fluid_auto_read(lua_State *L, int t, int world_idx);
/* Chooses and attaches the model when a question is pending (duration: the scene's run
   length, s, or 0 when unknown). Returns 1 when it chose. Raises Lua errors. */
int pl_lua_fluid_auto_apply(lua_State *L, int world_idx, double duration);
/* Adds a warning note when an attached Darcy model runs past its assumptions (Re_p > 10). */
void pl_lua_fluid_check_assumptions(lua_State *L, int world_idx);
/* Appends one line to the notes; the notes so far ("" when none). */
void pl_lua_fluid_auto_note(lua_State *L, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
const char *pl_lua_fluid_notes(lua_State *L);
#endif
