/* Scene loader: one Lua state per scene, run under lua_pcall with a traceback handler. */
#define _GNU_SOURCE /* timer_create with SIGEV_THREAD_ID */
#include "fluid_auto.h"
#include "scene.h"
#include "context.h"
#include "lua_util.h"
#include "sandbox.h"
#include "scene_internal.h"
#include "run_inputs.h"
#include "wrap.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#if defined(__linux__) && defined(SIGEV_THREAD_ID)
#define PL_CPU_TIMER 1 /* a CPU-time timer on the Lua thread; else a count hook polls */
#endif

struct pl_scene {
    lua_State *L;
    pl_lua_context ctx;
    int result_ref;  /* registry reference of the result table, or LUA_NOREF */
    int world_ref;   /* registry reference of the world userdata, or LUA_NOREF */
    int declarative;
    char error[4096];
    char traceback[8192];
    /* limits (0: none) */
    double max_cpu;      /* s per call into the scene */
    size_t mem_limit;    /* bytes of Lua data */
    /* accounting */
    size_t mem_used;
    int mem_over;        /* past the limit by a small allocation: the hook raises the error */
    int mem_refused;     /* an allocation was refused */
    char mem_where[PATH_MAX + 32]; /* "file:line: " where it was refused, or "" */
    int depth;           /* nesting of protected calls */
    double cpu_deadline; /* thread CPU time at which the current call runs out */
    int cpu_hit;         /* the current call ran out: every instruction raises again */
    volatile sig_atomic_t cpu_fired; /* the CPU timer went off */
    int cpu_polling;     /* no timer: the count hook checks the clock */
    int timer_armed;
    volatile sig_atomic_t hook_seen; /* the hook ran since the timer last went off */
    char stop_msg[512];  /* the message written when a C call does not return */
#ifdef PL_CPU_TIMER
    timer_t timer;
#endif
    int in_main;         /* running the scene file (for messages) */
    int return_line;     /* line of the scene's final return, 0 when unknown */
    char result_where[PATH_MAX + 32];
    pl_lua_run_inputs run; /* --param, --seed and the declared parameters */
};

/* Copies src into dst with control characters shown as \xNN (terminal escape codes in a
 * scene's message must not reach the terminal); newlines and tabs are kept. */
static void sanitize(char *dst, size_t n, const char *src)
{
    size_t k = 0;
    for (const unsigned char *p = (const unsigned char *)src; *p && k + 5 < n; p++) {
        int c1 = p[0] == 0xc2 && p[1] >= 0x80 && p[1] <= 0x9f; /* UTF-8 C1 control */
        if ((*p < 0x20 && *p != '\n' && *p != '\t') || *p == 0x7f || c1) {
            k += (size_t)snprintf(dst + k, n - k, "\\x%02x", c1 ? p[1] : *p);
            if (c1) p++;
        } else {
            dst[k++] = (char)*p;
        }
    }
    dst[k] = '\0';
}

void pl_scene_set_error(pl_scene *s, const char *fmt, ...)
{
    char raw[sizeof s->error];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(raw, sizeof raw, fmt, ap);
    va_end(ap);
    sanitize(s->error, sizeof s->error, raw);
}

/* ------------------------------------------------------------------ limits */

static double thread_cpu(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

#define HOOK_COUNT 10000          /* instructions between CPU-time checks */
#define MEM_SMALL (32u << 20)     /* allocations up to this may pass the limit a little ... */
#define MEM_HEADROOM (64u << 20)  /* ... by this much, until the next instruction raises */
#define MEM_SAFE_WHERE (32u << 20) /* larger requests are never the Lua stack: safe to locate */

/* Pushes "file:line: " of the innermost scene line; the scene path alone when none. */
static void push_where(pl_scene *s, lua_State *L, int level)
{
    if (!pl_lua_where_from(L, level)) lua_pushfstring(L, "%s: ", s->ctx.scene_path);
}

static void scene_hook(lua_State *L, lua_Debug *ar);

/* Installs the hook the limits need: none while the CPU timer runs (no cost per
 * instruction), a count hook when the clock must be polled, or count 1 to raise an error
 * at the next instruction. */
static void set_hook(pl_scene *s, int count)
{
    if (count == 1 || s->cpu_polling)
        lua_sethook(s->L, scene_hook, LUA_MASKCOUNT, count);
    else
        lua_sethook(s->L, NULL, 0, 0);
}

static void scene_hook(lua_State *L, lua_Debug *ar)
{
    (void)ar;
    void *ud;
    lua_getallocf(L, &ud);
    pl_scene *s = ud;
    s->hook_seen = 1;
    if (s->mem_over && s->mem_used <= s->mem_limit) s->mem_over = 0; /* collected since */
    if (s->mem_over && s->mem_used > s->mem_limit) {
        s->mem_over = 0;
        set_hook(s, HOOK_COUNT);
        push_where(s, L, 0);
        lua_pushfstring(L, "out of memory: the scene's Lua data passed the limit of %d MB "
                        "(--max-memory MB raises it; --trust lifts the sandbox's default)",
                        (int)(s->mem_limit >> 20));
        lua_concat(L, 2);
        lua_error(L);
    }
    if (s->max_cpu > 0 && s->depth > 0 &&
        (s->cpu_hit || s->cpu_fired || (s->cpu_polling && thread_cpu() > s->cpu_deadline))) {
        /* stays armed at count 1: a pcall that catches this gets it again at once */
        lua_sethook(L, scene_hook, LUA_MASKCOUNT, 1);
        s->cpu_hit = 1;
        push_where(s, L, 0);
        char secs[32];
        snprintf(secs, sizeof secs, "%g", s->max_cpu);
        lua_pushfstring(L, "the scene ran out of CPU time: more than %s s %s (--max-cpu "
                        "SECONDS raises it; --trust lifts the sandbox's default)", secs,
                        s->in_main ? "running the scene file"
                                   : "in one call from porelab into the scene (a hook)");
        lua_concat(L, 2);
        lua_error(L);
    }
    if (!s->cpu_hit) set_hook(s, HOOK_COUNT); /* a wake-up with nothing to report */
}

#ifdef PL_CPU_TIMER
static pl_scene *volatile timed_scene; /* the scene whose CPU timer is armed */

/* SIGVTALRM from the CPU timer, delivered to the Lua thread: lua_sethook is safe to call
 * from a signal handler (lua.c stops scripts on Ctrl-C the same way). */
static size_t append(char *buf, size_t k, size_t n, const char *text)
{
    while (*text && k + 1 < n) buf[k++] = *text++;
    buf[k] = '\0';
    return k;
}

/* The timer went off again and the hook has not run since: the scene is inside one C call
 * (a porelab function such as w:step with a huge count) that will not return in time.
 * Stops the program with the scene's line, using only async-signal-safe calls (the Lua
 * stack is not changing while the C function runs, so reading it is safe). */
static void stop_in_c_call(pl_scene *s)
{
    char msg[1024];
    size_t k = append(msg, 0, sizeof msg, "porelab: ");
    lua_Debug ar;
    int found = 0;
    for (int level = 0; !found && lua_getstack(s->L, level, &ar); level++) {
        lua_getinfo(s->L, "Sl", &ar);
        if (ar.currentline > 0 && ar.source[0] == '@') {
            char num[16];
            int i = (int)sizeof num - 1;
            num[i] = '\0';
            for (int v = ar.currentline; v > 0 && i > 0; v /= 10) num[--i] = (char)('0' + v % 10);
            k = append(msg, k, sizeof msg, ar.short_src);
            k = append(msg, k, sizeof msg, ":");
            k = append(msg, k, sizeof msg, num + i);
            k = append(msg, k, sizeof msg, ": ");
            found = 1;
        }
    }
    if (!found) {
        k = append(msg, k, sizeof msg, s->ctx.scene_path);
        k = append(msg, k, sizeof msg, ": ");
    }
    k = append(msg, k, sizeof msg, s->stop_msg);
    ssize_t w = write(STDERR_FILENO, msg, k);
    (void)w;
    _exit(1);
}

static void cpu_alarm(int sig)
{
    (void)sig;
    pl_scene *s = timed_scene;
    if (!s || !s->L) return;
    if (s->cpu_fired && !s->hook_seen) stop_in_c_call(s);
    s->hook_seen = 0;
    s->cpu_fired = 1;
    lua_sethook(s->L, scene_hook, LUA_MASKCOUNT, 1);
}
#endif

/* Starts the CPU budget of one call into the scene. */
static void arm_cpu(pl_scene *s)
{
    s->cpu_hit = 0;
    s->cpu_fired = 0;
    s->cpu_polling = 0;
    if (s->max_cpu <= 0) return;
    s->cpu_deadline = thread_cpu() + s->max_cpu;
#ifdef PL_CPU_TIMER
    static int installed;
    if (!installed) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = cpu_alarm;
        sa.sa_flags = SA_RESTART;
        sigemptyset(&sa.sa_mask);
        installed = sigaction(SIGVTALRM, &sa, NULL) == 0;
    }
    struct sigevent ev;
    memset(&ev, 0, sizeof ev);
    ev.sigev_notify = SIGEV_THREAD_ID;
    ev.sigev_signo = SIGVTALRM;
    ev._sigev_un._tid = (pid_t)syscall(SYS_gettid);
    if (installed && timer_create(CLOCK_THREAD_CPUTIME_ID, &ev, &s->timer) == 0) {
        struct itimerspec it;
        memset(&it, 0, sizeof it);
        it.it_value.tv_sec = (time_t)s->max_cpu;
        it.it_value.tv_nsec = (long)((s->max_cpu - (double)(time_t)s->max_cpu) * 1e9);
        if (it.it_value.tv_sec == 0 && it.it_value.tv_nsec == 0) it.it_value.tv_nsec = 1;
        /* then again after a grace period: if the hook has not run by then, a C call is
         * not returning and the program stops (stop_in_c_call) */
        double grace = s->max_cpu < 10 ? s->max_cpu : 10;
        it.it_interval.tv_sec = (time_t)grace;
        it.it_interval.tv_nsec = (long)((grace - (double)(time_t)grace) * 1e9);
        if (it.it_interval.tv_sec == 0 && it.it_interval.tv_nsec == 0) it.it_interval.tv_nsec = 1;
        snprintf(s->stop_msg, sizeof s->stop_msg,
                 "the scene ran out of CPU time: more than %g s, then %g s more inside one "
                 "call of a porelab function (such as w:step or w:run_until with a huge "
                 "count) that did not return; porelab stopped (--max-cpu SECONDS raises the "
                 "limit; --trust lifts the sandbox's default)\n", s->max_cpu, grace);
        s->hook_seen = 0;
        timed_scene = s;
        if (timer_settime(s->timer, 0, &it, NULL) == 0) {
            s->timer_armed = 1;
            return;
        }
        timed_scene = NULL;
        timer_delete(s->timer);
    }
#endif
    s->cpu_polling = 1;
}

static void disarm_cpu(pl_scene *s)
{
#ifdef PL_CPU_TIMER
    if (s->timer_armed) {
        timed_scene = NULL;
        timer_delete(s->timer);
        s->timer_armed = 0;
    }
#endif
    s->cpu_polling = 0;
    s->cpu_hit = 0;
    s->cpu_fired = 0;
}

/* The Lua allocator: counts the Lua data and refuses to pass mem_limit. */
static void *scene_alloc(void *ud, void *ptr, size_t osize, size_t nsize)
{
    pl_scene *s = ud;
    if (!ptr) osize = 0; /* osize is then the kind of object */
    if (nsize == 0) {
        free(ptr);
        s->mem_used -= osize;
        return NULL;
    }
    /* Only while the scene's code runs (depth > 0): the host's own pushes between calls
     * must not fail outside a protected call. */
    if (s->mem_limit > 0 && s->depth > 0 && nsize > osize &&
        s->mem_used + (nsize - osize) > s->mem_limit) {
        size_t grow = nsize - osize;
        if (grow <= MEM_SMALL && s->mem_used + grow <= s->mem_limit + MEM_HEADROOM && s->L) {
            /* let it through; the next Lua instruction raises a located error */
            if (!s->mem_over) {
                s->mem_over = 1;
                lua_sethook(s->L, scene_hook, LUA_MASKCOUNT, 1);
            }
        } else {
            if (!s->mem_refused && s->L && grow > MEM_SAFE_WHERE) {
                /* a large block (a string or table, never the stack): the call stack is
                 * consistent, so its scene line can be read */
                lua_Debug ar;
                for (int level = 0; lua_getstack(s->L, level, &ar); level++) {
                    lua_getinfo(s->L, "Sl", &ar);
                    if (ar.currentline > 0 && ar.source[0] == '@') {
                        snprintf(s->mem_where, sizeof s->mem_where, "%s:%d: ", ar.short_src,
                                 ar.currentline);
                        break;
                    }
                }
            }
            s->mem_refused = 1;
            return NULL;
        }
    }
    void *p = realloc(ptr, nsize);
    if (!p) {
        s->mem_refused = 1;
        return NULL;
    }
    s->mem_used += nsize - osize;
    return p;
}

/* coroutine.create: the new thread gets the count hook, so that the CPU timer's signal
 * (which arms the main thread) and the memory limit reach code running inside it. */
static int co_create(lua_State *L)
{
    int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, 1);
    lua_State *co = lua_tothread(L, -1);
    if (co) lua_sethook(co, scene_hook, LUA_MASKCOUNT, HOOK_COUNT);
    return 1;
}

/* coroutine.wrap in terms of the create above (errors propagate as with the original). */
static const char co_wrap_lua[] =
    "local create, resume, pack, unpack, error = ...\n"
    "return function(f)\n"
    "  local co = create(f)\n"
    "  return function(...)\n"
    "    local r = pack(resume(co, ...))\n"
    "    if r[1] then return unpack(r, 2, r.n) end\n"
    "    error(r[2], 0)\n"
    "  end\n"
    "end\n";

static void hook_coroutines(lua_State *L)
{
    if (lua_getglobal(L, "coroutine") != LUA_TTABLE) {
        lua_pop(L, 1);
        return;
    }
    int co = lua_gettop(L);
    lua_getfield(L, co, "create");
    lua_pushcclosure(L, co_create, 1);
    lua_pushvalue(L, -1);
    lua_setfield(L, co, "create");
    if (luaL_loadbufferx(L, co_wrap_lua, sizeof co_wrap_lua - 1, "=porelab.coroutine", "t") ==
        LUA_OK) {
        lua_insert(L, -2);             /* chunk, create */
        lua_getfield(L, co, "resume");
        lua_getglobal(L, "table");
        lua_getfield(L, -1, "pack");
        lua_getfield(L, -2, "unpack");
        lua_remove(L, -3);             /* chunk, create, resume, pack, unpack */
        lua_getglobal(L, "error");
        lua_call(L, 5, 1);
        lua_setfield(L, co, "wrap");
    } else {
        lua_pop(L, 2);
    }
    lua_pop(L, 1);
}

void pl_scene_set_limits(pl_scene *s, double max_cpu, double max_memory_mb)
{
    if (max_cpu > 0) s->max_cpu = max_cpu;
    else if (max_cpu < 0) s->max_cpu = 0;
    if (max_memory_mb > 0) s->mem_limit = (size_t)(max_memory_mb * 1048576.0);
    else if (max_memory_mb < 0) s->mem_limit = 0;
}

static int panic(lua_State *L)
{
    const char *msg = lua_tostring(L, -1);
    fprintf(stderr, "porelab: PANIC: unprotected error in call to Lua API (%s)\n",
            msg ? msg : "error object is not a string");
    return 0;
}

/* Length of a leading "chunk:line: " (as Lua prefixes errors raised in scene code), 0 when
 * msg does not start with one. */
static size_t location_len(const char *msg)
{
    const char *colon = strchr(msg, ':');
    if (!colon || colon == msg || colon[1] < '0' || colon[1] > '9') return 0;
    const char *p = colon + 1;
    while (*p >= '0' && *p <= '9') p++;
    if (*p != ':') return 0;
    p++;
    if (*p == ' ') p++;
    return (size_t)(p - msg);
}

static int has_location(const char *msg) { return location_len(msg) > 0; }

/* Message handler: keeps the message as the one-line error and the traceback apart. */
static int message_handler(lua_State *L)
{
    pl_scene *s = lua_touserdata(L, lua_upvalueindex(1));
    const char *msg = lua_tostring(L, 1);
    if (!msg) {
        if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING)
            msg = lua_tostring(L, -1);
        else
            msg = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
    }
    luaL_traceback(L, L, NULL, 1);
    sanitize(s->traceback, sizeof s->traceback, lua_tostring(L, -1));
    lua_pop(L, 1);
    /* An error without a scene line (raised in C: "C stack overflow", require, out of
     * memory; or located in an embedded helper, "porelab.mimes:246: ...") gets the line of
     * the innermost scene frame, the line the user wrote. */
    if ((!has_location(msg) || strncmp(msg, "porelab.", 8) == 0) && pl_lua_where_from(L, 1)) {
        lua_pushstring(L, msg);
        lua_concat(L, 2);
        return 1;
    }
    lua_pushstring(L, msg);
    return 1;
}

/* Calls the function below nargs arguments with the handler; on error stores the message
 * (prefixed with the scene path when it carries no location) and returns -1. */
static int protected_call(pl_scene *s, int nargs, int nresults)
{
    lua_State *L = s->L;
    int base = lua_gettop(L) - nargs;
    lua_pushlightuserdata(L, s);
    lua_pushcclosure(L, message_handler, 1);
    lua_insert(L, base);
    if (s->depth++ == 0) { /* each call from porelab into the scene has its own budget */
        s->mem_over = 0;
        s->mem_refused = 0;
        s->mem_where[0] = '\0';
        arm_cpu(s);
        set_hook(s, HOOK_COUNT);
    }
    int rc = lua_pcall(L, nargs, nresults, base);
    if (--s->depth == 0) {
        disarm_cpu(s);
        s->in_main = 0;
        set_hook(s, HOOK_COUNT);
    }
    lua_remove(L, base);
    if (rc == LUA_OK) return 0;
    const char *msg = lua_tostring(L, -1);
    if (!msg) msg = "unknown error";
    if (s->mem_refused && (rc == LUA_ERRMEM || strstr(msg, "not enough memory"))) {
        char where[sizeof s->mem_where];
        if (s->mem_where[0])
            snprintf(where, sizeof where, "%s", s->mem_where);
        else if (has_location(msg))
            snprintf(where, sizeof where, "%.*s", (int)location_len(msg), msg);
        else
            snprintf(where, sizeof where, "%s: ", s->ctx.scene_path);
        if (s->mem_limit > 0)
            pl_scene_set_error(s, "%sout of memory: the scene's Lua data would pass the limit "
                               "of %d MB (--max-memory MB raises it; --trust lifts the "
                               "sandbox's default)", where, (int)(s->mem_limit >> 20));
        else
            pl_scene_set_error(s, "%sout of memory (the system refused %s)", where,
                               "to give the scene's Lua data more memory");
    } else if (has_location(msg)) {
        pl_scene_set_error(s, "%s", msg);
    } else {
        /* raised outside the scene's code: by the checks on the returned table (render,
         * run, params, hooks) */
        pl_scene_set_error(s, "%s: %s", pl_scene_result_location(s), msg);
    }
    lua_pop(L, 1);
    return -1;
}

const char *pl_scene_result_location(const pl_scene *s)
{
    pl_scene *m = (pl_scene *)s;
    if (s->return_line > 0)
        snprintf(m->result_where, sizeof m->result_where, "%s:%d", s->ctx.scene_path,
                 s->return_line);
    else
        snprintf(m->result_where, sizeof m->result_where, "%s", s->ctx.scene_path);
    return s->result_where;
}

pl_scene *pl_scene_create(const pl_scene_options *opt)
{
    pl_scene *s = calloc(1, sizeof *s);
    if (!s) return NULL;
    s->result_ref = s->world_ref = LUA_NOREF;
    snprintf(s->ctx.scene_path, sizeof s->ctx.scene_path, "%s", opt->path);
    char dir[PATH_MAX];
    pl_path_dirname(opt->path, dir, sizeof dir);
    if (!realpath(dir, s->ctx.scene_dir)) snprintf(s->ctx.scene_dir, PATH_MAX, "%s", dir);
    char cwd[PATH_MAX];
    if (opt->out_dir[0] == '/' || !getcwd(cwd, sizeof cwd))
        snprintf(s->ctx.out_dir, PATH_MAX, "%s", opt->out_dir);
    else
        pl_path_join(s->ctx.out_dir, PATH_MAX, cwd, opt->out_dir);
    s->ctx.trust = opt->trust;
    s->ctx.run = &s->run;
    s->run.seed = opt->seed;
    for (int i = 0; i < opt->nparams && i < PL_RUN_MAX_OVERRIDES; i++) {
        snprintf(s->run.over_name[i], sizeof s->run.over_name[i], "%s", opt->param_names[i]);
        s->run.over_value[i] = opt->param_values[i];
        s->run.n_over = i + 1;
    }
    if (!opt->trust) pl_scene_set_limits(s, PL_SCENE_DEFAULT_MAX_CPU, PL_SCENE_DEFAULT_MAX_MEMORY);
    s->L = lua_newstate(scene_alloc, s);
    if (!s->L) {
        free(s);
        return NULL;
    }
    lua_atpanic(s->L, panic);
    pl_lua_set_context(s->L, &s->ctx);
    pl_lua_open_porelab(s->L);
    hook_coroutines(s->L);
    pl_lua_install_sandbox(s->L);
    /* math.random follows the run seed too (Lua seeds it from the clock otherwise) */
    if (lua_getglobal(s->L, "math") == LUA_TTABLE && lua_getfield(s->L, -1, "randomseed") == LUA_TFUNCTION) {
        lua_pushinteger(s->L, (lua_Integer)pl_lua_mix_seed(s->L, 1));
        lua_pcall(s->L, 1, 0, 0);
    } else {
        lua_pop(s->L, 1);
    }
    lua_pop(s->L, 1);
    return s;
}

static const char *const result_fields[] = {"world", "render", "run", "on_frame",
                                            "on_finish", "params", "results", NULL};

static const char *const param_fields[] = {"name", "unit", "value", "min", "max", "step",
                                           "set", "doc", NULL};

/* Validates the parameter list at index t (a list of {name, value, min, max, step, unit,
 * set}) and copies it into out (when not NULL). Raises Lua errors naming the entry and the
 * field; returns the count. */
int pl_lua_check_param_list(lua_State *L, int t, pl_scene_param *out, int need_set)
{
    t = lua_absindex(L, t);
    if (!lua_istable(L, t))
        return luaL_error(L, "params must be a list of parameter tables {name = ..., value = ..., "
                             "min = ..., max = ..., set = function(world, value) ... end} (got %s)",
                          luaL_typename(L, t));
    lua_Integer n = luaL_len(L, t);
    if (n > PL_SCENE_MAX_PARAMS)
        return luaL_error(L, "params: at most %d parameters (got %d)", PL_SCENE_MAX_PARAMS, (int)n);
    for (lua_Integer i = 1; i <= n; i++) {
        char what[32];
        snprintf(what, sizeof what, "params[%d]", (int)i);
        lua_geti(L, t, i);
        int e = lua_gettop(L);
        if (!lua_istable(L, e))
            return luaL_error(L, "%s must be a table {name = ..., value = ..., min = ..., max = ..., "
                                 "set = ...} (got %s)", what, luaL_typename(L, e));
        pl_lua_check_fields(L, e, what, param_fields);
        pl_scene_param p;
        memset(&p, 0, sizeof p);
        if (lua_getfield(L, e, "name") != LUA_TSTRING)
            return luaL_error(L, "%s: name must be a string (got %s)", what, luaL_typename(L, -1));
        snprintf(p.name, sizeof p.name, "%s", lua_tostring(L, -1));
        lua_pop(L, 1);
        int ut = lua_getfield(L, e, "unit");
        if (ut != LUA_TNIL && ut != LUA_TSTRING)
            return luaL_error(L, "%s (%s): unit must be a string (got %s)", what, p.name,
                              luaL_typename(L, -1));
        snprintf(p.unit, sizeof p.unit, "%s", ut == LUA_TSTRING ? lua_tostring(L, -1) : "");
        lua_pop(L, 1);
        const char *num[4] = {"value", "min", "max", "step"};
        double *dst[4] = {&p.value, &p.min, &p.max, &p.step};
        int has_step = 0;
        for (int k = 0; k < 4; k++) {
            int ty = lua_getfield(L, e, num[k]);
            if (k == 3) has_step = ty != LUA_TNIL;
            if (k == 3 && ty == LUA_TNIL) {
                *dst[k] = 0.0;
            } else if (ty != LUA_TNUMBER || !isfinite(lua_tonumber(L, -1))) {
                return luaL_error(L, "%s (%s): %s must be a finite number (got %s)", what, p.name,
                                  num[k], ty == LUA_TNUMBER ? "a non-finite number" : luaL_typename(L, -1));
            } else {
                *dst[k] = lua_tonumber(L, -1);
            }
            lua_pop(L, 1);
        }
        if (!(p.max > p.min))
            return luaL_error(L, "%s (%s): max must be > min (got min %f, max %f)", what, p.name,
                              p.min, p.max);
        if (p.value < p.min || p.value > p.max)
            return luaL_error(L, "%s (%s): value must be in [min, max] = [%f, %f] (got %f)", what,
                              p.name, p.min, p.max, p.value);
        if (has_step && !(p.step > 0.0 && p.step <= p.max - p.min))
            return luaL_error(L, "%s (%s): step must be in (0, max - min] = (0, %f] (got %f)", what,
                              p.name, p.max - p.min, p.step);
        if (!has_step) p.step = (p.max - p.min) / 20.0;
        int st = lua_getfield(L, e, "set");
        if (st != LUA_TFUNCTION && (need_set || st != LUA_TNIL))
            return luaL_error(L, "%s (%s): set must be a function(world, value) (got %s)", what,
                              p.name, luaL_typename(L, -1));
        lua_pop(L, 2);
        if (out) out[i - 1] = p;
    }
    return (int)n;
}

/* Checks the scene's return value (at index 2; index 1 is the scene) and stores it. */
static int check_result(lua_State *L)
{
    pl_scene *s = lua_touserdata(L, 1);
    if (luaL_testudata(L, 2, PL_LUA_WORLD_MT)) { /* return w  ==  return {world = w} */
        lua_createtable(L, 0, 1);
        lua_pushvalue(L, 2);
        lua_setfield(L, -2, "world");
        lua_replace(L, 2);
    }
    if (!lua_istable(L, 2))
        return luaL_error(L, "the scene must return nothing (imperative script), a world, or "
                             "a table {world = ..., render = ..., run = ...} (got %s)",
                          luaL_typename(L, 2));
    pl_lua_check_fields(L, 2, "scene result", result_fields);
    if (lua_getfield(L, 2, "world") == LUA_TNIL || !luaL_testudata(L, -1, PL_LUA_WORLD_MT))
        return luaL_error(L, "scene result: world must be the world built by porelab.world "
                             "(got %s)", luaL_typename(L, -1));
    lua_getfield(L, 2, "params");
    if (!lua_isnil(L, -1)) pl_lua_check_param_list(L, -1, NULL, 1);
    lua_pop(L, 1);
    s->world_ref = luaL_ref(L, LUA_REGISTRYINDEX);
    lua_pushvalue(L, 2);
    s->result_ref = luaL_ref(L, LUA_REGISTRYINDEX);
    s->declarative = 1;
    return 0;
}

/* The line of the scene's final return (the statement that returned the result table):
 * at the top level `return` must be the last statement, and scenes write it at the left
 * margin, so it is the last line that starts with "return". */
static void find_return_statement(pl_scene *s)
{
    FILE *f = fopen(s->ctx.scene_path, "r");
    if (!f) return;
    char buf[512];
    int line = 1, found = 0, line_start = 1;
    while (fgets(buf, sizeof buf, f)) {
        if (line_start && strncmp(buf, "return", 6) == 0 &&
            (buf[6] == '\0' || strchr(" \t{(\r\n", buf[6])))
            found = line;
        line_start = strchr(buf, '\n') != NULL;
        if (line_start) line++;
    }
    fclose(f);
    s->return_line = found;
}

static int fluid_choice(lua_State *L)
{
    pl_scene *s = lua_touserdata(L, 1);
    pl_scene_run r = {0};
    if (pl_scene_run_settings(s, &r) != 0) return 0; /* the run command reports it */
    lua_rawgeti(L, LUA_REGISTRYINDEX, s->world_ref);
    const double dt = pl_world_dt(pl_scene_world(s));
    const double dur = r.t_end > 0 ? r.t_end : (r.steps > 0 && dt > 0 ? (double)r.steps * dt : 0);
    pl_lua_fluid_auto_apply(L, -1, dur);
    pl_lua_fluid_check_assumptions(L, -1);
    return 0;
}

int pl_scene_load(pl_scene *s)
{
    lua_State *L = s->L;
    FILE *f = fopen(s->ctx.scene_path, "rb");
    if (!f) {
        pl_scene_set_error(s, "cannot open scene '%s': %s", s->ctx.scene_path,
                           strerror(errno));
        return -1;
    }
    int first = fgetc(f);
    fclose(f);
    if (first == LUA_SIGNATURE[0]) {
        pl_scene_set_error(s, "%s:1: the scene is a precompiled (binary) chunk; scenes must "
                           "be Lua source text", s->ctx.scene_path);
        return -1;
    }
    if (luaL_loadfilex(L, s->ctx.scene_path, "t") != LUA_OK) {
        const char *msg = lua_tostring(L, -1);
        if (has_location(msg)) pl_scene_set_error(s, "%s", msg);
        else pl_scene_set_error(s, "%s:1: %s", s->ctx.scene_path, msg ? msg : "cannot load");
        lua_pop(L, 1);
        return -1;
    }
    s->in_main = 1;
    if (protected_call(s, 0, 1) != 0) return -1;
    find_return_statement(s);
    if (lua_isnil(L, -1)) { /* imperative script: describe its last world, if any */
        lua_pop(L, 1);
        pl_lua_scene_push_last_world(L);
        s->world_ref = lua_isnil(L, -1) ? (lua_pop(L, 1), LUA_NOREF)
                                        : luaL_ref(L, LUA_REGISTRYINDEX);
        return 0;
    }
    lua_pushcfunction(L, check_result);
    lua_insert(L, -2);
    lua_pushlightuserdata(L, s);
    lua_insert(L, -2);
    if (protected_call(s, 2, 0) != 0) return -1;
    /* fluid = "auto": choose the model before anything runs, for the run's length */
    lua_pushcfunction(L, fluid_choice);
    lua_pushlightuserdata(L, s);
    return protected_call(s, 1, 0);
}

const char *pl_scene_fluid_notes(pl_scene *s) { return pl_lua_fluid_notes(s->L); }

const char *pl_scene_error(const pl_scene *s) { return s->error; }
const char *pl_scene_traceback(const pl_scene *s) { return s->traceback; }
const char *pl_scene_path(const pl_scene *s) { return s->ctx.scene_path; }
lua_State *pl_scene_lua(pl_scene *s) { return s->L; }
int pl_scene_declarative(const pl_scene *s) { return s->declarative; }

static pl_lua_world *scene_lua_world(pl_scene *s)
{
    if (s->world_ref == LUA_NOREF) return NULL;
    lua_rawgeti(s->L, LUA_REGISTRYINDEX, s->world_ref);
    pl_lua_world *lw = luaL_testudata(s->L, -1, PL_LUA_WORLD_MT);
    lua_pop(s->L, 1);
    return lw;
}

pl_world *pl_scene_world(pl_scene *s)
{
    pl_lua_world *lw = scene_lua_world(s);
    return lw ? lw->w : NULL;
}

int pl_scene_push_result_field(pl_scene *s, const char *field)
{
    if (s->result_ref == LUA_NOREF) {
        lua_pushnil(s->L);
        return LUA_TNIL;
    }
    lua_rawgeti(s->L, LUA_REGISTRYINDEX, s->result_ref);
    int t = lua_getfield(s->L, -1, field);
    lua_remove(s->L, -2);
    return t;
}

static const char *const run_fields[] = {"t_end", "steps", "fps", "every", NULL};

static int read_run(lua_State *L)
{
    const char *fn = "run";
    pl_scene_run *r = lua_touserdata(L, 1);
    if (lua_isnil(L, 2)) return 0;
    pl_lua_check_def(L, 2, fn);
    pl_lua_check_fields(L, 2, fn, run_fields);
    if (pl_lua_has_field(L, 2, "t_end") && pl_lua_has_field(L, 2, "steps"))
        return luaL_error(L, "run: give t_end or steps, not both");
    if (pl_lua_has_field(L, 2, "fps") && pl_lua_has_field(L, 2, "every"))
        return luaL_error(L, "run: give fps or every, not both");
    r->t_end = pl_lua_field_number(L, 2, fn, "t_end", 0);
    PL_LUA_CHECK(L, r->t_end >= 0, fn, "t_end", "> 0 s", r->t_end);
    r->steps = pl_lua_field_int(L, 2, fn, "steps", 0);
    PL_LUA_CHECK(L, r->steps >= 0, fn, "steps", ">= 1", (double)r->steps);
    r->fps = pl_lua_field_number(L, 2, fn, "fps", 0);
    PL_LUA_CHECK(L, r->fps >= 0 && r->fps <= 10000, fn, "fps", "in (0, 10000] frames/s",
                 r->fps);
    r->every = pl_lua_field_int(L, 2, fn, "every", 0);
    PL_LUA_CHECK(L, r->every >= 0, fn, "every", ">= 1 step", (double)r->every);
    return 0;
}

int pl_scene_read_field(pl_scene *s, const char *field, lua_CFunction reader, void *ud)
{
    lua_pushcfunction(s->L, reader);
    lua_pushlightuserdata(s->L, ud);
    pl_scene_push_result_field(s, field);
    return protected_call(s, 2, 0);
}

int pl_scene_run_settings(pl_scene *s, pl_scene_run *out)
{
    memset(out, 0, sizeof *out);
    return pl_scene_read_field(s, "run", read_run, out);
}

/* Pushes the global name without metamethods (outside a protected call a scene's erroring
 * __index on _G must not reach the C API unprotected). */
static void raw_global(lua_State *L, const char *name)
{
    lua_pushglobaltable(L);
    lua_pushstring(L, name);
    lua_rawget(L, -2);
    lua_remove(L, -2);
}

/* Pushes the parameter list: result.params, else the global PARAMS (nil when neither). */
static void push_params(pl_scene *s)
{
    if (pl_scene_push_result_field(s, "params") == LUA_TNIL) {
        lua_pop(s->L, 1);
        raw_global(s->L, "PARAMS");
    }
}

typedef struct params_ud {
    pl_scene_param *out;
    int n;
} params_ud;

static int read_params(lua_State *L)
{
    params_ud *ud = lua_touserdata(L, 1);
    ud->n = lua_isnil(L, 2) ? 0 : pl_lua_check_param_list(L, 2, ud->out, 1);
    return 0;
}

int pl_scene_params(pl_scene *s, pl_scene_param out[PL_SCENE_MAX_PARAMS])
{
    params_ud ud = {out, 0};
    lua_pushcfunction(s->L, read_params);
    lua_pushlightuserdata(s->L, &ud);
    push_params(s);
    if (protected_call(s, 2, 0) != 0) return -1;
    return ud.n;
}

int pl_scene_set_param(pl_scene *s, int i, double value)
{
    lua_State *L = s->L;
    int top = lua_gettop(L);
    push_params(s);
    if (!lua_istable(L, -1) || lua_geti(L, -1, i + 1) != LUA_TTABLE ||
        lua_getfield(L, -1, "set") != LUA_TFUNCTION || s->world_ref == LUA_NOREF) {
        pl_scene_set_error(s, "%s: params[%d]: no set function", pl_scene_result_location(s),
                           i + 1);
        lua_settop(L, top);
        return -1;
    }
    lua_rawgeti(L, LUA_REGISTRYINDEX, s->world_ref);
    lua_pushnumber(L, value);
    int rc = protected_call(s, 2, 0);
    if (rc != 0) {
        char msg[sizeof s->error];
        snprintf(msg, sizeof msg, "%s", s->error);
        pl_scene_set_error(s, "params[%d].set: %s", i + 1, msg);
    }
    lua_settop(L, top);
    return rc;
}

int pl_scene_flag_was_set(pl_scene *s, const char *name, double *value)
{
    pl_lua_world *lw = scene_lua_world(s);
    if (!lw) return 0;
    for (int i = 0; i < lw->flag_count; i++) {
        if (strcmp(pl_flag_at(i)->name, name) != 0 || !lw->flag_set[i]) continue;
        return pl_world_get_flag(lw->w, name, value) == PL_OK;
    }
    return 0;
}

int pl_scene_call_hook(pl_scene *s, const char *name, long long arg)
{
    int t = pl_scene_push_result_field(s, name);
    if (t == LUA_TNIL) {
        lua_pop(s->L, 1);
        return 0;
    }
    if (t != LUA_TFUNCTION) {
        pl_scene_set_error(s, "%s: scene result: %s must be a function (got %s)",
                           pl_scene_result_location(s), name, lua_typename(s->L, t));
        lua_pop(s->L, 1);
        return -1;
    }
    lua_rawgeti(s->L, LUA_REGISTRYINDEX, s->world_ref);
    lua_pushinteger(s->L, (lua_Integer)arg);
    return protected_call(s, 2, 0);
}

void pl_scene_destroy(pl_scene **sp)
{
    if (!sp || !*sp) return;
    pl_scene *s = *sp;
    /* Closing runs __gc finalizers, which Lua runs with hooks off: no limit could stop
     * them, so the sandbox refuses them (setmetatable_checked in sandbox.c). */
    lua_close(s->L);
    s->L = NULL;
    free(*sp);
    *sp = NULL;
}

/* ------------------------------------------------------------ run inputs and results */

long long pl_scene_seed(const pl_scene *s) { return s->run.seed; }

static void list_declared(const pl_scene *s, char *buf, size_t n)
{
    size_t k = 0;
    buf[0] = '\0';
    for (int i = 0; i < s->run.ndeclared && k + 1 < n; i++) {
        const pl_scene_param *p = &s->run.declared[i];
        k += (size_t)snprintf(buf + k, n - k, "%s%s in [%g, %g]%s%s", i ? ", " : "", p->name, p->min, p->max,
                              p->unit[0] ? " " : "", p->unit);
    }
}

int pl_scene_apply_params(pl_scene *s)
{
    pl_lua_run_inputs *r = &s->run;
    pl_scene_param live[PL_SCENE_MAX_PARAMS];
    int nlive = 0;
    if (s->declarative) {
        nlive = pl_scene_params(s, live);
        if (nlive < 0) return -1;
    }
    int base = r->ndeclared;
    for (int i = 0; i < nlive && r->ndeclared < 2 * PL_SCENE_MAX_PARAMS; i++) {
        r->declared[r->ndeclared] = live[i];
        r->overridden[r->ndeclared++] = 0;
    }
    for (int k = 0; k < r->n_over; k++) {
        if (r->over_used[k]) continue;
        int found = -1;
        for (int i = base; i < r->ndeclared; i++)
            if (strcmp(r->declared[i].name, r->over_name[k]) == 0) found = i;
        double v = r->over_value[k];
        if (found < 0) {
            char list[2048];
            list_declared(s, list, sizeof list);
            if (r->ndeclared == 0)
                pl_scene_set_error(s, "--param %s=%g: %s declares no parameters (porelab.params{...} or the "
                                   "result's params list; docs/scene-reference.md)", r->over_name[k], v, s->ctx.scene_path);
            else
                pl_scene_set_error(s, "--param %s=%g: %s declares no parameter '%s'; its parameters: %s",
                                   r->over_name[k], v, s->ctx.scene_path, r->over_name[k], list);
            return -1;
        }
        pl_scene_param *p = &r->declared[found];
        if (!(v >= p->min && v <= p->max)) {
            pl_scene_set_error(s, "--param %s=%g: %s must be in [%g, %g]%s%s", p->name, v, p->name, p->min,
                               p->max, p->unit[0] ? " " : "", p->unit);
            return -1;
        }
        if (pl_scene_set_param(s, found - base, v) != 0) return -1;
        p->value = v;
        r->overridden[found] = 1;
        r->over_used[k] = 1;
    }
    return 0;
}

int pl_scene_declared_params(pl_scene *s, pl_scene_param *out, int *overridden, int cap)
{
    int n = s->run.ndeclared < cap ? s->run.ndeclared : cap;
    for (int i = 0; i < n; i++) {
        out[i] = s->run.declared[i];
        if (overridden) overridden[i] = s->run.overridden[i];
    }
    return n;
}

typedef struct results_ud {
    pl_scene_result *out;
    int n;
} results_ud;

static int cmp_result(const void *a, const void *b)
{
    return strcmp(((const pl_scene_result *)a)->name, ((const pl_scene_result *)b)->name);
}

/* index 1: results_ud, 2: the results value (table, function or nil), 3: the world (or nil) */
static int read_results(lua_State *L)
{
    results_ud *ud = lua_touserdata(L, 1);
    ud->n = 0;
    if (lua_isfunction(L, 2)) {
        lua_pushvalue(L, 2);
        lua_pushvalue(L, 3);
        lua_call(L, 1, 1);
        if (!lua_istable(L, -1))
            return luaL_error(L, "results: the function must return a table {name = value, ...} (got %s)",
                              luaL_typename(L, -1));
        lua_replace(L, 2);
    }
    if (lua_isnil(L, 2)) return 0;
    if (!lua_istable(L, 2))
        return luaL_error(L, "results must be a table {name = value, ...} or a function(world) returning one (got %s)",
                          luaL_typename(L, 2));
    lua_pushnil(L);
    while (lua_next(L, 2)) {
        if (lua_type(L, -2) != LUA_TSTRING)
            return luaL_error(L, "results: names must be strings (got a %s key)", luaL_typename(L, -2));
        const char *name = lua_tostring(L, -2);
        size_t len = strlen(name);
        int ok_name = len > 0 && len < 48;
        for (size_t i = 0; i < len; i++)
            if (!((name[i] >= 'a' && name[i] <= 'z') || (name[i] >= 'A' && name[i] <= 'Z') ||
                  (name[i] >= '0' && name[i] <= '9') || name[i] == '_'))
                ok_name = 0;
        if (!ok_name)
            return luaL_error(L, "results: '%s' is not a usable name (letters, digits and _, at most 47)", name);
        if (ud->n >= PL_SCENE_MAX_RESULTS)
            return luaL_error(L, "results: at most %d values", PL_SCENE_MAX_RESULTS);
        pl_scene_result *r = &ud->out[ud->n];
        memset(r, 0, sizeof *r);
        snprintf(r->name, sizeof r->name, "%s", name);
        int v = lua_gettop(L);
        if (lua_istable(L, v)) {
            static const char *const fields[] = {"value", "unit", NULL};
            char what[64];
            snprintf(what, sizeof what, "results.%s", name);
            pl_lua_check_fields(L, v, what, fields);
            if (lua_getfield(L, v, "unit") == LUA_TSTRING)
                snprintf(r->unit, sizeof r->unit, "%s", lua_tostring(L, -1));
            else if (!lua_isnil(L, -1))
                return luaL_error(L, "results.%s: unit must be a string (got %s)", name, luaL_typename(L, -1));
            lua_pop(L, 1);
            lua_getfield(L, v, "value");
            lua_replace(L, v);
        }
        if (lua_type(L, v) == LUA_TNUMBER) {
            r->kind = 0;
            r->value = lua_tonumber(L, v);
        } else if (lua_isboolean(L, v)) {
            r->kind = 1;
            r->value = lua_toboolean(L, v);
        } else if (lua_type(L, v) == LUA_TSTRING) {
            r->kind = 2;
            snprintf(r->text, sizeof r->text, "%s", lua_tostring(L, v));
        } else {
            return luaL_error(L, "results.%s must be a number, a boolean, a string or {value = number, unit = "
                                 "\"...\"} (got %s)", name, luaL_typename(L, v));
        }
        ud->n++;
        lua_settop(L, v - 1);
    }
    qsort(ud->out, (size_t)ud->n, sizeof *ud->out, cmp_result);
    return 0;
}

int pl_scene_results(pl_scene *s, pl_scene_result out[PL_SCENE_MAX_RESULTS])
{
    results_ud ud = {out, 0};
    lua_pushcfunction(s->L, read_results);
    lua_pushlightuserdata(s->L, &ud);
    if (pl_scene_push_result_field(s, "results") == LUA_TNIL) {
        lua_pop(s->L, 1);
        raw_global(s->L, "RESULTS");
    }
    if (s->world_ref != LUA_NOREF) lua_rawgeti(s->L, LUA_REGISTRYINDEX, s->world_ref);
    else lua_pushnil(s->L);
    if (protected_call(s, 3, 0) != 0) return -1;
    return ud.n;
}
