/* Per-scene context stored in the Lua registry: where the scene lives, where output goes,
 * whether the sandbox is lifted. Also the path rules the sandbox enforces. */
#ifndef PL_LUA_CONTEXT_H
#define PL_LUA_CONTEXT_H

#include <lua.h>
#include <limits.h>
#include <stddef.h>

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

typedef struct pl_lua_context {
    char scene_path[PATH_MAX]; /* as given on the command line (used in messages) */
    char scene_dir[PATH_MAX];  /* absolute, resolved */
    char out_dir[PATH_MAX];    /* absolute (may not exist until first written) */
    int trust;                 /* 1: sandbox lifted (--trust) */
    struct pl_lua_run_inputs *run; /* --param and --seed, and the declared params (run_inputs.h) */
} pl_lua_context;

/* Stores ctx (owned by the caller, must outlive L) / fetches it. */
void pl_lua_set_context(lua_State *L, pl_lua_context *ctx);
pl_lua_context *pl_lua_get_context(lua_State *L);

/* Creates dir and its parents (mkdir -p). Returns 0 or -1 (errno set). */
int pl_path_mkdirs(const char *dir);

/* Joins base and a relative path (absolute paths are kept) into out. */
void pl_path_join(char *out, size_t n, const char *base, const char *path);

/* Resolves path to an absolute, symlink-free path even when the file itself does not exist
 * yet (its directory must). Returns 0 or -1. */
int pl_path_resolve(const char *path, char *out, size_t n);

/* 1 when path itself (its last component, not followed) is a symbolic link. */
int pl_path_is_link(const char *path);

/* 1 when resolved path `p` equals or lies under resolved directory `dir`. */
int pl_path_inside(const char *p, const char *dir);

/* Directory part of a path ("scenes/x.lua" -> "scenes", "x.lua" -> "."). */
void pl_path_dirname(const char *path, char *out, size_t n);

/* Scene name: file name without directory and extension ("scenes/demo.lua" -> "demo"). */
void pl_path_stem(const char *path, char *out, size_t n);

#endif
