/* Lua readers driven by an engine parameter table (porelab/params.h): every model's wrap file
 * reads its def through these, so Lua and C share one list of names, ranges and defaults. */
#ifndef PL_LUA_PARAMS_H
#define PL_LUA_PARAMS_H
#include <lua.h>
#include "porelab/params.h"

/* Reads the fields of the table at index t into def (which holds the current values): unknown
   names are refused with the list of valid ones; each value must be a number (booleans for
   0/1 fields too) in the row's range, else "file:line: fn: <name> must be ... (got v)". */
void pl_lua_read_params(lua_State *L, int t, const char *fn, const pl_param *table, int n, void *def);
/* Pushes a table {name = value, ...} of def. */
void pl_lua_push_params(lua_State *L, const pl_param *table, int n, const void *def);
#endif
