/* porelab.csv(path, columns [, units]): a CSV writer for time series, writing inside the
 * output folder. The file starts with a metadata comment ("# porelab VERSION, scene PATH,
 * state hash HASH at t = T s, written DATE") and the header ("t (s),fn (N)" with units). csv:row(v1, v2, ...) or csv:row{v1, v2, ...}; csv:close().
 *
 * Survives faults: rows are kept in memory as whole lines and written with write(2) only as
 * whole lines - when 64 KiB have gathered or a second has passed since the last write, when
 * the program flushes every open CSV (after each output frame, pl_lua_csv_flush_all), and
 * at close (the program closes every CSV when a run ends or stops) - so a kill leaves a
 * file that ends in a whole line. A write that fails (full disk, file size limit)
 * cuts the file back to its last whole line and is reported: by csv:row/csv:close as a Lua
 * error, by pl_lua_csv_flush_all/pl_lua_csv_close_all to the program, which then exits
 * non-zero even when the scene never calls close. */
#include "wrap_csv.h"
#include "wrap.h"
#include "lua_util.h"
#include "sandbox.h"
#include "context.h"
#include "scene_internal.h"
#include "porelab/core.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define CSV_FLUSH_BYTES (64 * 1024)
#define CSV_FLUSH_SECONDS 1.0 /* also without frames (imperative scripts, the window) */

static double monotonic_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct csv_ud csv_ud;

/* Per Lua state: the open CSV files (a C list, so the program can flush them without Lua
 * calls that could raise) and the first failure of a file closed by the collector. */
typedef struct csv_registry {
    csv_ud *open;
    char failure[PATH_MAX + 256];
} csv_registry;

struct csv_ud {
    int fd;          /* -1 when closed */
    int columns;
    char *buf;       /* whole lines not yet written */
    size_t len, cap;
    long long written; /* bytes in the file, all whole lines */
    double last_flush; /* monotonic s */
    int failed;      /* errno of the write that failed, 0 when none */
    int reported;    /* the failure was reported (each failure is reported once) */
    csv_registry *reg;
    csv_ud *next, **pprev;
    char path[PATH_MAX];
};

static const char registry_key = 0; /* its address keys the registry in LUA_REGISTRYINDEX */

static csv_registry *get_registry(lua_State *L)
{
    lua_rawgetp(L, LUA_REGISTRYINDEX, &registry_key);
    csv_registry *r = lua_touserdata(L, -1);
    lua_pop(L, 1);
    return r;
}

/* ---- buffered whole lines ---- */

static int reserve(csv_ud *c, size_t extra)
{
    if (c->len + extra <= c->cap) return 0;
    size_t cap = c->cap ? c->cap : 4096;
    while (cap < c->len + extra) cap *= 2;
    char *b = realloc(c->buf, cap);
    if (!b) return -1;
    c->buf = b, c->cap = cap;
    return 0;
}

static void put(csv_ud *c, const char *s, size_t n)
{
    memcpy(c->buf + c->len, s, n);
    c->len += n;
}

/* Appends one field (the caller reserved room via field_size). */
static size_t field_size(lua_State *L, int idx)
{
    if (lua_type(L, idx) == LUA_TNUMBER) return 40;
    size_t n;
    lua_tolstring(L, idx, &n);
    return 2 * n + 2;
}

static void put_field(csv_ud *c, lua_State *L, int idx)
{
    char num[48];
    if (lua_type(L, idx) == LUA_TNUMBER) {
        int k = lua_isinteger(L, idx)
                    ? snprintf(num, sizeof num, "%lld", (long long)lua_tointeger(L, idx))
                    : snprintf(num, sizeof num, "%.12g", lua_tonumber(L, idx));
        put(c, num, (size_t)k);
        return;
    }
    size_t n;
    const char *s = lua_tolstring(L, idx, &n);
    if (!strpbrk(s, ",\"\n\r")) {
        put(c, s, n);
        return;
    }
    put(c, "\"", 1);
    for (size_t i = 0; i < n; i++) {
        if (s[i] == '"') put(c, "\"", 1);
        put(c, s + i, 1);
    }
    put(c, "\"", 1);
}

/* Writes the buffered whole lines. Returns 0, or -1 with c->failed set; a partial write is
 * cut back so the file still ends in a whole line. */
static int csv_flush(csv_ud *c)
{
    if (c->fd < 0 || c->failed) return c->failed ? -1 : 0;
    size_t done = 0;
    while (done < c->len) {
        ssize_t k = write(c->fd, c->buf + done, c->len - done);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) {
            c->failed = k < 0 ? errno : EIO;
            /* keep the whole lines that got through, drop the piece of the next one */
            size_t whole = done;
            while (whole > 0 && c->buf[whole - 1] != '\n') whole--;
            if (ftruncate(c->fd, (off_t)(c->written + (long long)whole)) != 0) {
                /* nothing better to do: the first cause is the one reported */
            }
            c->written += (long long)whole;
            c->len = 0;
            return -1;
        }
        done += (size_t)k;
    }
    c->written += (long long)c->len;
    c->len = 0;
    c->last_flush = monotonic_seconds();
    return 0;
}

static void unlink_open(csv_ud *c)
{
    if (c->pprev) {
        *c->pprev = c->next;
        if (c->next) c->next->pprev = c->pprev;
        c->pprev = NULL, c->next = NULL;
    }
}

/* Flushes and closes; 0, or -1 with c->failed set. */
static int csv_close(csv_ud *c)
{
    if (c->fd < 0) return c->failed ? -1 : 0;
    int rc = csv_flush(c);
    if (close(c->fd) != 0 && rc == 0) {
        c->failed = errno;
        rc = -1;
    }
    c->fd = -1;
    free(c->buf);
    c->buf = NULL, c->len = c->cap = 0;
    unlink_open(c);
    return rc;
}

static void failure_message(csv_ud *c, char *err, size_t errlen)
{
    c->reported = 1;
    snprintf(err, errlen, "writing the CSV file '%s' failed: %s (the file holds the rows "
                          "up to the failure)", c->path, strerror(c->failed));
}

static void raise_failure(lua_State *L, const char *fn, csv_ud *c)
{
    char msg[PATH_MAX + 256];
    failure_message(c, msg, sizeof msg);
    pl_lua_error(L, "%s: %s", fn, msg);
}

/* "# porelab 0.1.0, scene <path>, state hash <16 hex> at t = <s> s, written <UTC date>\n";
 * the date is SOURCE_DATE_EPOCH when set (reproducible files). */
static void csv_metadata(lua_State *L, char *out, size_t n)
{
    pl_lua_context *ctx = pl_lua_get_context(L);
    const char *scene = ctx && ctx->scene_path[0] ? ctx->scene_path : "(none)";
    char hash[64] = "";
    pl_lua_scene_push_last_world(L);
    pl_lua_world *lw = lua_isnil(L, -1) ? NULL : luaL_testudata(L, -1, PL_LUA_WORLD_MT);
    if (lw && lw->w)
        snprintf(hash, sizeof hash, ", state hash %016llx at t = %.6g s",
                 (unsigned long long)pl_world_state_hash(lw->w), pl_world_time(lw->w));
    lua_pop(L, 1);
    time_t now = time(NULL);
    const char *sde = getenv("SOURCE_DATE_EPOCH");
    if (sde && *sde) now = (time_t)strtoll(sde, NULL, 10);
    struct tm tm;
    char date[32] = "";
    if (gmtime_r(&now, &tm)) strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &tm);
    snprintf(out, n, "# porelab %s, scene %s%s, written %s\n", PL_VERSION_STRING, scene, hash, date);
    for (char *p = out + 2; *p && p[1]; p++)
        if (*p == '\n' || *p == '\r') *p = ' ';
}

/* ---- the Lua functions ---- */

int pl_lua_csv_new(lua_State *L)
{
    const char *fn = "csv";
    const char *path = luaL_checkstring(L, 1);
    luaL_checktype(L, 2, LUA_TTABLE);
    int n = (int)luaL_len(L, 2);
    if (n < 1) pl_lua_error(L, "%s: columns must be a non-empty list of names", fn);
    if (!lua_isnoneornil(L, 3)) {
        if (!lua_istable(L, 3) || (int)luaL_len(L, 3) != n)
            pl_lua_error(L, "%s: units must be a list of %d strings (one per column, \"\" for "
                            "none), e.g. {\"s\", \"m\"}", fn, n);
        for (int i = 1; i <= n; i++) {
            if (lua_geti(L, 3, i) != LUA_TSTRING)
                pl_lua_error(L, "%s: unit %d must be a string (got %s)", fn, i, luaL_typename(L, -1));
            size_t len;
            const char *u = lua_tolstring(L, -1, &len);
            if (len > 32 || strpbrk(u, ",\"\n\r"))
                pl_lua_error(L, "%s: unit %d '%s' must be at most 32 characters without commas, "
                                "quotes or line breaks", fn, i, u);
            lua_pop(L, 1);
        }
    }
    size_t need = 1;
    for (int i = 1; i <= n; i++) {
        if (lua_geti(L, 2, i) != LUA_TSTRING)
            pl_lua_error(L, "%s: column %d must be a string (got %s)", fn, i,
                         luaL_typename(L, -1));
        need += field_size(L, -1) + 1;
        lua_pop(L, 1);
    }
    csv_ud *c = lua_newuserdatauv(L, sizeof *c, 0);
    memset(c, 0, sizeof *c);
    c->fd = -1;
    luaL_setmetatable(L, PL_LUA_CSV_MT);
    /* the one checked open for files a scene writes (inside the output folder, never through
       a symbolic link); the rows are then written with write(2) on its descriptor */
    FILE *fp = pl_lua_output_fopen(L, path, "w", c->path, sizeof c->path, fn);
    if (!fp) pl_lua_error(L, "%s: cannot write '%s': %s", fn, c->path, strerror(errno));
    c->fd = fcntl(fileno(fp), F_DUPFD_CLOEXEC, 0);
    int dup_errno = errno;
    fclose(fp); /* nothing buffered in it */
    if (c->fd < 0) pl_lua_error(L, "%s: cannot write '%s': %s", fn, c->path, strerror(dup_errno));
    if (reserve(c, need) != 0) {
        close(c->fd);
        c->fd = -1;
        pl_lua_error(L, "%s: out of memory", fn);
    }
    c->columns = n;
    c->last_flush = monotonic_seconds();
    /* a metadata comment, then the header: "name (unit)" when the scene gives units */
    char meta[PATH_MAX + 256];
    csv_metadata(L, meta, sizeof meta);
    put(c, meta, strlen(meta));
    int has_units = lua_istable(L, 3);
    for (int i = 1; i <= n; i++) {
        lua_geti(L, 2, i);
        if (i > 1) put(c, ",", 1);
        if (has_units && lua_geti(L, 3, i) == LUA_TSTRING && lua_rawlen(L, -1) > 0) {
            lua_pushfstring(L, "%s (%s)", lua_tostring(L, -2), lua_tostring(L, -1));
            put_field(c, L, -1);
            lua_pop(L, 2);
        } else {
            if (has_units) lua_pop(L, 1);
            put_field(c, L, -1);
        }
        lua_pop(L, 1);
    }
    put(c, "\n", 1);
    if (csv_flush(c) != 0) { /* the header at once: the file is never empty */
        int e = c->failed;
        close(c->fd);
        c->fd = -1;
        free(c->buf);
        c->buf = NULL;
        pl_lua_error(L, "%s: cannot write '%s': %s", fn, c->path, strerror(e));
    }
    csv_registry *r = get_registry(L);
    if (r) {
        c->reg = r;
        c->next = r->open;
        if (r->open) r->open->pprev = &c->next;
        r->open = c;
        c->pprev = &r->open;
    }
    return 1;
}

static csv_ud *check_open(lua_State *L, const char *fn)
{
    csv_ud *c = luaL_checkudata(L, 1, PL_LUA_CSV_MT);
    if (c->fd < 0) pl_lua_error(L, "%s: the CSV file '%s' is closed", fn, c->path);
    if (c->failed) raise_failure(L, fn, c);
    return c;
}

static int c_row(lua_State *L)
{
    const char *fn = "csv:row";
    csv_ud *c = check_open(L, fn);
    int first = 2, n = lua_gettop(L) - 1;
    if (n == 1 && lua_istable(L, 2)) { /* csv:row{...} */
        n = (int)luaL_len(L, 2);
        for (int i = 1; i <= n; i++) lua_geti(L, 2, i);
        first = 3;
    }
    if (n != c->columns)
        pl_lua_error(L, "%s: expected %d values (one per column), got %d", fn, c->columns, n);
    size_t need = 1;
    for (int i = 0; i < n; i++) {
        int t = lua_type(L, first + i);
        if (t != LUA_TNUMBER && t != LUA_TSTRING)
            pl_lua_error(L, "%s: value %d must be a number or string (got %s)", fn, i + 1,
                         lua_typename(L, t));
        need += field_size(L, first + i) + 1;
    }
    if (reserve(c, need) != 0) pl_lua_error(L, "%s: out of memory", fn);
    for (int i = 0; i < n; i++) {
        if (i) put(c, ",", 1);
        put_field(c, L, first + i);
    }
    put(c, "\n", 1);
    double now = monotonic_seconds();
    if ((c->len >= CSV_FLUSH_BYTES || now - c->last_flush >= CSV_FLUSH_SECONDS) &&
        csv_flush(c) != 0)
        raise_failure(L, fn, c);
    return 0;
}

static int c_close(lua_State *L)
{
    csv_ud *c = luaL_checkudata(L, 1, PL_LUA_CSV_MT);
    if (c->fd >= 0 && csv_close(c) != 0) raise_failure(L, "csv:close", c);
    return 0;
}

static int c_gc(lua_State *L)
{
    csv_ud *c = luaL_checkudata(L, 1, PL_LUA_CSV_MT);
    if (c->fd >= 0 && csv_close(c) != 0 && !c->reported && c->reg && !c->reg->failure[0])
        failure_message(c, c->reg->failure, sizeof c->reg->failure); /* for close_all */
    return 0;
}

static int c_path(lua_State *L)
{
    lua_pushstring(L, ((csv_ud *)luaL_checkudata(L, 1, PL_LUA_CSV_MT))->path);
    return 1;
}

static const luaL_Reg csv_methods[] = {
    {"row", c_row}, {"close", c_close}, {"path", c_path}, {NULL, NULL}};

void pl_lua_register_csv(lua_State *L)
{
    luaL_newmetatable(L, PL_LUA_CSV_MT);
    lua_pushcfunction(L, c_gc);
    lua_setfield(L, -2, "__gc");
    lua_pushcfunction(L, c_close); /* a to-be-closed CSV reports a failed write */
    lua_setfield(L, -2, "__close");
    luaL_newlib(L, csv_methods);
    lua_setfield(L, -2, "__index");
    lua_pop(L, 1);
    if (lua_rawgetp(L, LUA_REGISTRYINDEX, &registry_key) == LUA_TNIL) {
        csv_registry *r = lua_newuserdatauv(L, sizeof *r, 0);
        memset(r, 0, sizeof *r);
        lua_rawsetp(L, LUA_REGISTRYINDEX, &registry_key);
    }
    lua_pop(L, 1);
}

/* ---- for the program ---- */

int pl_lua_csv_flush_all(lua_State *L, char *err, size_t errlen)
{
    csv_registry *r = L ? get_registry(L) : NULL;
    if (!r) return 0;
    int rc = 0;
    for (csv_ud *c = r->open; c; c = c->next) {
        if (csv_flush(c) != 0 && !c->reported && rc == 0) {
            failure_message(c, err, errlen);
            rc = -1;
        }
    }
    if (rc == 0 && r->failure[0]) {
        snprintf(err, errlen, "%s", r->failure);
        r->failure[0] = '\0';
        rc = -1;
    }
    return rc;
}

int pl_lua_csv_close_all(lua_State *L, char *err, size_t errlen)
{
    csv_registry *r = L ? get_registry(L) : NULL;
    if (!r) return 0;
    int rc = 0;
    if (r->failure[0]) {
        snprintf(err, errlen, "%s", r->failure);
        r->failure[0] = '\0';
        rc = -1;
    }
    while (r->open) {
        csv_ud *c = r->open;
        if (csv_close(c) != 0 && !c->reported && rc == 0) { /* csv_close unlinks c */
            failure_message(c, err, errlen);
            rc = -1;
        }
    }
    return rc;
}
