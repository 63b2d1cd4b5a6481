/* State files from Lua (issue 12): w:save(path) writes the world's whole state (a restart file,
 * pl_world_save_state) and w:load(path) / porelab.load(w, path) reads one into a world built by
 * the same scene. Both paths are resolved by the sandbox's output-folder check
 * (pl_lua_output_path): relative paths are inside the output folder, and in the sandbox every
 * path must be. Files are written whole (path.tmp, then a rename). */
#include "lua_util.h"
#include "sandbox.h"
#include "wrap.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int w_save(lua_State *L)
{
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    char path[PATH_MAX], tmp[PATH_MAX + 8];
    pl_lua_output_path(L, luaL_checkstring(L, 2), path, sizeof path, "save");
    void *bytes = NULL;
    size_t len = 0;
    pl_lua_check_status(L, lw->w, pl_world_save_state(lw->w, &bytes, &len), "save");
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *f = fopen(tmp, "wb");
    int ok = f && fwrite(bytes, 1, len, f) == len;
    if (f) ok = fclose(f) == 0 && ok;
    pl_state_free(bytes);
    if (!ok || rename(tmp, path) != 0) {
        const int e = errno;
        remove(tmp);
        return pl_lua_error(L, "save: cannot write '%s': %s", path, strerror(e));
    }
    lua_pushstring(L, path);
    return 1;
}

/* load(world at wi, path at wi + 1) */
static int load_into(lua_State *L, int wi)
{
    pl_lua_world *lw = pl_lua_check_world(L, wi);
    char path[PATH_MAX];
    pl_lua_output_path(L, luaL_checkstring(L, wi + 1), path, sizeof path, "load");
    FILE *f = fopen(path, "rb");
    if (!f) return pl_lua_error(L, "load: cannot open '%s': %s", path, strerror(errno));
    size_t cap = 1 << 16, len = 0;
    unsigned char *buf = malloc(cap);
    for (;;) {
        if (!buf) break;
        if (len == cap) {
            unsigned char *p = realloc(buf, cap * 2);
            if (!p) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = p;
            cap *= 2;
        }
        const size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0) break;
    }
    const int bad = ferror(f);
    fclose(f);
    if (!buf || bad) {
        free(buf);
        return pl_lua_error(L, "load: cannot read '%s'", path);
    }
    const pl_status st = pl_world_load_state(lw->w, buf, len);
    free(buf);
    if (st != PL_OK) return pl_lua_error(L, "load: %s: %s", path, pl_world_last_error(lw->w));
    lua_pushvalue(L, wi);
    return 1;
}

static int w_load(lua_State *L) { return load_into(L, 1); }
int pl_lua_state_load(lua_State *L) { return load_into(L, 1); } /* porelab.load(w, path) */

const luaL_Reg pl_lua_state_methods[] = {{"save", w_save}, {"load", w_load}, {NULL, NULL}};
