#define _XOPEN_SOURCE 700
#include "context.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char context_key = 'c';

void pl_lua_set_context(lua_State *L, pl_lua_context *ctx)
{
    lua_pushlightuserdata(L, ctx);
    lua_rawsetp(L, LUA_REGISTRYINDEX, &context_key);
}

pl_lua_context *pl_lua_get_context(lua_State *L)
{
    lua_rawgetp(L, LUA_REGISTRYINDEX, &context_key);
    pl_lua_context *ctx = lua_touserdata(L, -1);
    lua_pop(L, 1);
    return ctx;
}

int pl_path_mkdirs(const char *dir)
{
    char buf[PATH_MAX];
    if (snprintf(buf, sizeof buf, "%s", dir) >= (int)sizeof buf) {
        errno = ENAMETOOLONG;
        return -1;
    }
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/') continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) return -1;
        *p = '/';
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST) return -1;
    struct stat st;
    if (stat(buf, &st) != 0 || !S_ISDIR(st.st_mode)) {
        errno = ENOTDIR;
        return -1;
    }
    return 0;
}

void pl_path_join(char *out, size_t n, const char *base, const char *path)
{
    if (path[0] == '/' || base[0] == '\0')
        snprintf(out, n, "%s", path);
    else
        snprintf(out, n, "%s/%s", base, path);
}

int pl_path_resolve(const char *path, char *out, size_t n)
{
    char tmp[PATH_MAX];
    if (realpath(path, tmp)) {
        if (snprintf(out, n, "%s", tmp) >= (int)n) return -1;
        return 0;
    }
    /* The file may not exist yet: resolve its directory and append the base name. */
    char dir[PATH_MAX];
    pl_path_dirname(path, dir, sizeof dir);
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    if (base[0] == '\0' || strcmp(base, ".") == 0 || strcmp(base, "..") == 0) return -1;
    if (!realpath(dir, tmp)) return -1;
    if (snprintf(out, n, "%s/%s", strcmp(tmp, "/") == 0 ? "" : tmp, base) >= (int)n) return -1;
    return 0;
}

int pl_path_is_link(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0 && S_ISLNK(st.st_mode);
}

int pl_path_inside(const char *p, const char *dir)
{
    size_t k = strlen(dir);
    if (k > 1 && dir[k - 1] == '/') k--;
    return strncmp(p, dir, k) == 0 && (p[k] == '\0' || p[k] == '/');
}

void pl_path_dirname(const char *path, char *out, size_t n)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(out, n, ".");
    else if (slash == path)
        snprintf(out, n, "/");
    else
        snprintf(out, n, "%.*s", (int)(slash - path), path);
}

void pl_path_stem(const char *path, char *out, size_t n)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    const char *dot = strrchr(base, '.');
    int len = dot && dot != base ? (int)(dot - base) : (int)strlen(base);
    snprintf(out, n, "%.*s", len, base);
}
