/* The scene sandbox: which functions a shared scene may call and where it may read and
 * write. Lifted by --trust (the context's trust flag); path resolution stays the same so
 * that a scene behaves identically with and without --trust. */
#ifndef PL_LUA_SANDBOX_H
#define PL_LUA_SANDBOX_H

#include <lua.h>
#include <stddef.h>

/* Installs the sandbox into the global table of L (call after opening the standard
 * libraries and storing the context). With trust, only the path-resolving wrappers are
 * installed. */
void pl_lua_install_sandbox(lua_State *L);

/* Resolves a path for writing: relative paths are taken inside the output folder (created
 * on demand); in the sandbox the result must lie inside it. Raises a Lua error naming fn. */
void pl_lua_output_path(lua_State *L, const char *path, char *out, size_t n, const char *fn);

/* Resolves a path for reading: relative paths are taken inside the scene's folder; in the
 * sandbox the result must lie inside it or inside the output folder. Raises a Lua error
 * naming fn. */
void pl_lua_input_path(lua_State *L, const char *path, char *out, size_t n, const char *fn);

/* Opens a file for writing like fopen(path, mode) after pl_lua_output_path, never through
 * a symbolic link (O_NOFOLLOW): the one checked open for files a scene writes. Raises a
 * Lua error naming fn for a refused path or an invalid mode; returns NULL (errno set) when
 * the open itself fails. The resolved path is left in resolved. */
#include <stdio.h>
FILE *pl_lua_output_fopen(lua_State *L, const char *path, const char *mode, char *resolved,
                          size_t n, const char *fn);

#endif
