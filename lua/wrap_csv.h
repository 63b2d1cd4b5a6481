/* The program's side of porelab.csv (wrap_csv.c): CSV files are written as whole lines, and
 * the program decides when they reach the disk and hears of every failed write. */
#ifndef PORELAB_LUA_WRAP_CSV_H
#define PORELAB_LUA_WRAP_CSV_H

#include <lua.h>
#include <stddef.h>

/* Writes the whole lines every open CSV file of the state holds (call after each output
 * frame and when a run stops). Returns 0, or -1 with "writing the CSV file '...' failed:
 * <reason> ..." in err (also for a file the collector closed with a failed write). Makes no
 * Lua call that could raise. Each failure is reported once (by csv:row, csv:close or
 * these), so a later call does not repeat it. */
int pl_lua_csv_flush_all(lua_State *L, char *err, size_t errlen);

/* Flushes and closes every CSV file still open (the scene need not call csv:close). Returns
 * 0, or -1 with the first failure in err. Call before closing the Lua state. */
int pl_lua_csv_close_all(lua_State *L, char *err, size_t errlen);

#endif
