/* porelab compare PROBLEM.lua... : runs every method that answers each benchmark problem at
 * each of its resolutions, measures the error against the problem's reference and the CPU
 * time of each run, and writes results.csv, one error-against-cost chart per problem (Pareto
 * front marked), one chart per stability sweep and summary.md (docs/compare.md).
 *
 * A problem file returns a table {name, title, quantity, unit, reference = {value, source},
 * run = function(method, res) ... return value end}; a method file returns {name, label,
 * problems = {<problem name> = {knob, unit, values}}, <functions the problems call>}. A
 * stability problem has kind = "stability", sweep = {knob, unit, values} and run(nil, res)
 * returns {ratio = knob / computed limit, measure = growth, failed = true|false, limit = ...}.
 * Every run gets a fresh Lua state (lua/scene.h) so runs do not share state. */
#include "commands.h"
#include "compare_report.h"
#include "options.h"
#include "scene.h"

#include <dirent.h>
#include <errno.h>
#include <lauxlib.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#define MAX_METHOD_FILES 64

static const char *const HELP =
    "usage: porelab compare PROBLEM.lua... [--methods FILE|DIR,...] [--out DIR]\n"
    "                       [--only NAME,...] [--quick] [--update-doc FILE.md]\n\n"
    "Runs every method that answers each benchmark problem at each of its resolutions,\n"
    "measures the error against the problem's reference (analytic or published) and the CPU\n"
    "time of each run, and writes into DIR (default out/compare):\n"
    "  results.csv           one row per run (second line: units)\n"
    "  <problem>.png         error against CPU time, log-log, one curve per method, Pareto front\n"
    "  stability_<name>.png  a stability sweep: growth against step / computed limit\n"
    "  summary.md            per problem the cheapest run within 1 %, 5 %, 20 %\n\n"
    "options:\n"
    "  --methods LIST    method files or folders (comma-separated); default: the folder\n"
    "                    'methods' beside the problem's folder (tests/compare/methods)\n"
    "  --only LIST       run only these method names\n"
    "  --out DIR         output folder (default out/compare)\n"
    "  --quick           only the first two resolutions of each method (smoke test)\n"
    "  --update-doc F    replace the text between '<!-- compare:summary -->' and\n"
    "                    '<!-- /compare:summary -->' in F with the summary table\n\n"
    "docs/compare.md describes the problem and method files and how to add a method.\n"
    "example: porelab compare tests/compare/problems/*.lua --out docs/compare "
    "--update-doc docs/compare.md\n";

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int traceback(lua_State *L)
{
    const char *msg = lua_tostring(L, 1);
    luaL_traceback(L, L, msg ? msg : "(error object is not a string)", 1);
    return 1;
}

/* Runs the chunk in file with the scene's globals; leaves its first result on the stack. */
static int load_table(lua_State *L, const char *file, char *err, size_t n)
{
    lua_pushcfunction(L, traceback);
    int h = lua_gettop(L);
    if (luaL_loadfilex(L, file, "t") != LUA_OK || lua_pcall(L, 0, 1, h) != LUA_OK) {
        snprintf(err, n, "%s", lua_tostring(L, -1));
        lua_pop(L, 2);
        return -1;
    }
    lua_remove(L, h);
    if (!lua_istable(L, -1)) {
        snprintf(err, n, "%s: must return a table (got %s)", file, luaL_typename(L, -1));
        lua_pop(L, 1);
        return -1;
    }
    return 0;
}

static void str_field(lua_State *L, int t, const char *k, char *dst, size_t n, const char *def)
{
    lua_getfield(L, t, k);
    snprintf(dst, n, "%s", lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : def);
    lua_pop(L, 1);
}

static double num_field(lua_State *L, int t, const char *k, double def)
{
    lua_getfield(L, t, k);
    double v = lua_type(L, -1) == LUA_TNUMBER ? lua_tonumber(L, -1) : def;
    lua_pop(L, 1);
    return v;
}

static int ends_with(const char *s, const char *suf)
{
    size_t a = strlen(s), b = strlen(suf);
    return a >= b && strcmp(s + a - b, suf) == 0;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* Adds file, or every *.lua of a folder (sorted), to the list. */
static int add_method_path(const char *p, char **list, int *n)
{
    struct stat st;
    if (stat(p, &st) != 0) {
        fprintf(stderr, "porelab compare: --methods: cannot open '%s': %s\n", p, strerror(errno));
        return -1;
    }
    if (!S_ISDIR(st.st_mode)) {
        if (*n >= MAX_METHOD_FILES) return -1;
        list[(*n)++] = strdup(p);
        return 0;
    }
    DIR *d = opendir(p);
    if (!d) return -1;
    int first = *n;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (!ends_with(e->d_name, ".lua") || *n >= MAX_METHOD_FILES) continue;
        size_t len = strlen(p) + strlen(e->d_name) + 2;
        char *f = malloc(len);
        if (!f) break;
        snprintf(f, len, "%s/%s", p, e->d_name);
        list[(*n)++] = f;
    }
    closedir(d);
    qsort(list + first, (size_t)(*n - first), sizeof *list, cmp_str);
    return 0;
}

static int in_list(const char *name, const char *csv)
{
    if (!csv) return 1;
    size_t len = strlen(name);
    for (const char *p = csv; *p;) {
        const char *c = strchr(p, ',');
        size_t l = c ? (size_t)(c - p) : strlen(p);
        if (l == len && strncmp(p, name, l) == 0) return 1;
        if (!c) break;
        p = c + 1;
    }
    return 0;
}

static pl_scene *fresh_scene(const char *problem, const char *out)
{
    pl_scene_options so = {problem, out, 0, 0, 0, NULL, NULL};
    pl_scene *s = pl_scene_create(&so);
    return s;
}

typedef struct run_ctx {
    const char *problem_file, *method_file, *out;
    int stability;
    double value;
    int index;
} run_ctx;

/* One run in a fresh Lua state. Times problem.run(method, res), repeating cheap runs until
 * 0.1 s of CPU time or 1000 repetitions (cost = the mean). Fills the row. */
static int one_run(const run_ctx *c, pl_cmp_row *row, char *err, size_t n)
{
    pl_scene *s = fresh_scene(c->problem_file, c->out);
    if (!s) {
        snprintf(err, n, "out of memory");
        return -1;
    }
    lua_State *L = pl_scene_lua(s);
    int rc = -1;
    if (load_table(L, c->problem_file, err, n) != 0) goto done;
    int pt = lua_gettop(L);
    if (c->method_file) {
        if (load_table(L, c->method_file, err, n) != 0) goto done;
    } else {
        lua_pushnil(L);
    }
    int mt = lua_gettop(L);
    double total = 0;
    int reps = 0;
    do {
        lua_pushcfunction(L, traceback);
        int h = lua_gettop(L);
        lua_getfield(L, pt, "run");
        if (!lua_isfunction(L, -1)) {
            snprintf(err, n, "%s: the problem table has no run function", c->problem_file);
            goto done;
        }
        lua_pushvalue(L, mt);
        lua_createtable(L, 0, 2);
        lua_pushnumber(L, c->value);
        lua_setfield(L, -2, "value");
        lua_pushinteger(L, c->index + 1);
        lua_setfield(L, -2, "index");
        lua_gc(L, LUA_GCCOLLECT, 0);
        double t0 = cpu_now();
        int st = lua_pcall(L, 2, 1, h);
        total += cpu_now() - t0;
        reps++;
        if (st != LUA_OK) {
            snprintf(err, n, "%s", lua_tostring(L, -1));
            goto done;
        }
        if (c->stability) {
            if (!lua_istable(L, -1)) {
                snprintf(err, n, "%s: a stability run must return {ratio, measure, failed, limit}",
                         c->problem_file);
                goto done;
            }
            row->ratio = num_field(L, -1, "ratio", NAN);
            row->value = num_field(L, -1, "measure", NAN);
            row->limit = num_field(L, -1, "limit", NAN);
            lua_getfield(L, -1, "failed");
            row->failed = lua_toboolean(L, -1);
            lua_pop(L, 1);
            str_field(L, -1, "message", row->note, sizeof row->note, "");
        } else {
            if (lua_type(L, -1) != LUA_TNUMBER) {
                snprintf(err, n, "%s: run must return the measured value (a number), got %s",
                         c->problem_file, luaL_typename(L, -1));
                goto done;
            }
            row->value = lua_tonumber(L, -1);
        }
        lua_settop(L, mt);
    } while (!c->stability && total < 0.1 && reps < 1000);
    row->cpu = total / reps;
    row->reps = reps;
    rc = 0;
done:
    pl_scene_destroy(&s);
    return rc;
}

typedef struct method_info {
    char file[1024];
    char name[64], label[128];
    char knob[96], unit[32];
    double values[64];
    int nvalues;
} method_info;

/* Reads the problem's description and which methods answer it (their resolution ladders). */
static int describe(const char *file, char **mfiles, int nm, const char *only, pl_cmp_problem *p,
                    method_info *mi, int *nmi, char *err, size_t n)
{
    pl_scene *s = fresh_scene(file, "out");
    if (!s) return -1;
    lua_State *L = pl_scene_lua(s);
    int rc = -1;
    if (load_table(L, file, err, n) != 0) goto done;
    int t = lua_gettop(L);
    str_field(L, t, "name", p->name, sizeof p->name, "");
    str_field(L, t, "title", p->title, sizeof p->title, p->name);
    str_field(L, t, "quantity", p->quantity, sizeof p->quantity, "");
    str_field(L, t, "unit", p->unit, sizeof p->unit, "1");
    char kind[32];
    str_field(L, t, "kind", kind, sizeof kind, "accuracy");
    p->stability = strcmp(kind, "stability") == 0;
    if (!p->name[0]) {
        snprintf(err, n, "%s: the problem table needs a name", file);
        goto done;
    }
    if (!p->stability) {
        if (lua_getfield(L, t, "reference") != LUA_TTABLE) {
            snprintf(err, n, "%s: the problem needs reference = {value = ..., source = \"...\"}", file);
            goto done;
        }
        p->reference = num_field(L, -1, "value", NAN);
        str_field(L, -1, "source", p->source, sizeof p->source, "");
        lua_pop(L, 1);
        if (!isfinite(p->reference) || p->reference == 0 || !p->source[0]) {
            snprintf(err, n, "%s: reference.value must be a finite non-zero number and "
                             "reference.source must name where it comes from", file);
            goto done;
        }
    } else {
        str_field(L, t, "source", p->source, sizeof p->source, "");
    }
    *nmi = 0;
    if (p->stability) {
        if (lua_getfield(L, t, "sweep") != LUA_TTABLE) {
            snprintf(err, n, "%s: a stability problem needs sweep = {knob, unit, values}", file);
            goto done;
        }
        method_info *m = &mi[(*nmi)++];
        memset(m, 0, sizeof *m);
        snprintf(m->name, sizeof m->name, "%s", p->name);
        str_field(L, -1, "label", m->label, sizeof m->label, p->title);
        str_field(L, -1, "knob", m->knob, sizeof m->knob, "");
        str_field(L, -1, "unit", m->unit, sizeof m->unit, "1");
        lua_getfield(L, -1, "values");
        for (lua_Integer i = 1; i <= (lua_Integer)luaL_len(L, -1) && m->nvalues < 64; i++) {
            lua_geti(L, -1, i);
            m->values[m->nvalues++] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
        lua_pop(L, 2);
        rc = 0;
        goto done;
    }
    for (int k = 0; k < nm; k++) {
        if (load_table(L, mfiles[k], err, n) != 0) goto done;
        int m = lua_gettop(L);
        method_info *q = &mi[*nmi];
        memset(q, 0, sizeof *q);
        snprintf(q->file, sizeof q->file, "%s", mfiles[k]);
        str_field(L, m, "name", q->name, sizeof q->name, "");
        str_field(L, m, "label", q->label, sizeof q->label, q->name);
        if (!q->name[0]) {
            snprintf(err, n, "%s: the method table needs a name", mfiles[k]);
            goto done;
        }
        if (in_list(q->name, only) && lua_getfield(L, m, "problems") == LUA_TTABLE &&
            lua_getfield(L, -1, p->name) == LUA_TTABLE) {
            str_field(L, -1, "knob", q->knob, sizeof q->knob, "");
            str_field(L, -1, "unit", q->unit, sizeof q->unit, "1");
            lua_getfield(L, -1, "values");
            if (lua_istable(L, -1))
                for (lua_Integer i = 1; i <= (lua_Integer)luaL_len(L, -1) && q->nvalues < 64; i++) {
                    lua_geti(L, -1, i);
                    q->values[q->nvalues++] = lua_tonumber(L, -1);
                    lua_pop(L, 1);
                }
            if (q->nvalues == 0) {
                snprintf(err, n, "%s: problems.%s.values must list the resolutions", mfiles[k],
                         p->name);
                goto done;
            }
            if (*nmi < MAX_METHOD_FILES) (*nmi)++;
        }
        lua_settop(L, t);
    }
    rc = 0;
done:
    pl_scene_destroy(&s);
    return rc;
}

static void default_methods_dir(const char *problem, char *out, size_t n)
{
    /* tests/compare/problems/x.lua -> tests/compare/methods */
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", problem);
    char *slash = strrchr(buf, '/');
    if (slash) *slash = 0; else snprintf(buf, sizeof buf, ".");
    snprintf(out, n, "%s/../methods", buf);
}

int pl_cmd_compare(int argc, char **argv)
{
    const char *out = "out/compare", *methods = NULL, *only = NULL, *doc = NULL;
    int quick = 0;
    const char *problems[64];
    int np = 0;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(HELP, stdout);
            return PL_EXIT_OK;
        }
        if (!strcmp(a, "--quick")) {
            quick = 1;
            continue;
        }
        const char **dst = !strcmp(a, "--out") ? &out : !strcmp(a, "--methods") ? &methods
                         : !strcmp(a, "--only") ? &only : !strcmp(a, "--update-doc") ? &doc : NULL;
        if (dst) {
            if (i + 1 >= argc) {
                fprintf(stderr, "porelab compare: %s needs an argument\n", a);
                return PL_EXIT_USAGE;
            }
            *dst = argv[++i];
            continue;
        }
        if (a[0] == '-') {
            fprintf(stderr, "porelab compare: unknown option '%s'; valid options: --methods, "
                            "--only, --out, --quick, --update-doc, --help\n", a);
            return PL_EXIT_USAGE;
        }
        if (!ends_with(a, ".lua")) {
            fprintf(stderr, "porelab compare: '%s' is not a problem file (PROBLEM.lua)\n", a);
            return PL_EXIT_USAGE;
        }
        if (np >= 64) {
            fprintf(stderr, "porelab compare: at most 64 problem files\n");
            return PL_EXIT_USAGE;
        }
        problems[np++] = a;
    }
    if (np == 0) {
        fputs(HELP, stderr);
        return PL_EXIT_USAGE;
    }
    char *mfiles[MAX_METHOD_FILES];
    int nm = 0;
    char dir[1100];
    if (methods) {
        char buf[4096];
        snprintf(buf, sizeof buf, "%s", methods);
        for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ","))
            if (add_method_path(tok, mfiles, &nm) != 0) return PL_EXIT_USAGE;
    } else {
        default_methods_dir(problems[0], dir, sizeof dir);
        if (add_method_path(dir, mfiles, &nm) != 0) return PL_EXIT_USAGE;
    }
    if (pl_cmp_mkdirs(out) != 0) {
        fprintf(stderr, "porelab compare: cannot create the output folder '%s': %s\n", out,
                strerror(errno));
        return PL_EXIT_FAIL;
    }
    pl_cmp_results res;
    memset(&res, 0, sizeof res);
    int rc = PL_EXIT_OK;
    static method_info mi[MAX_METHOD_FILES];
    char err[2048];
    for (int k = 0; k < np && rc == PL_EXIT_OK; k++) {
        pl_cmp_problem *p = pl_cmp_add_problem(&res);
        int nmi = 0;
        if (!p || describe(problems[k], mfiles, nm, only, p, mi, &nmi, err, sizeof err) != 0) {
            fprintf(stderr, "porelab compare: %s\n", p ? err : "out of memory");
            rc = PL_EXIT_FAIL;
            break;
        }
        if (nmi == 0) fprintf(stderr, "porelab compare: %s: no method answers problem '%s'\n",
                              problems[k], p->name);
        printf("%s: %s\n", p->name, p->title);
        for (int m = 0; m < nmi && rc == PL_EXIT_OK; m++) {
            int nv = quick && mi[m].nvalues > 2 ? 2 : mi[m].nvalues;
            for (int v = 0; v < nv; v++) {
                pl_cmp_row *row = pl_cmp_add_row(&res);
                if (!row) {
                    rc = PL_EXIT_FAIL;
                    break;
                }
                row->problem = (int)(p - res.problems);
                snprintf(row->method, sizeof row->method, "%s", mi[m].name);
                snprintf(row->label, sizeof row->label, "%s", mi[m].label);
                snprintf(row->knob, sizeof row->knob, "%s", mi[m].knob);
                snprintf(row->knob_unit, sizeof row->knob_unit, "%s", mi[m].unit);
                row->knob_value = mi[m].values[v];
                run_ctx c = {problems[k], p->stability ? NULL : mi[m].file, out, p->stability,
                             mi[m].values[v], v};
                if (one_run(&c, row, err, sizeof err) != 0) {
                    fprintf(stderr, "porelab compare: %s, method %s, %s = %g: %s\n", p->name,
                            mi[m].name, mi[m].knob, mi[m].values[v], err);
                    rc = PL_EXIT_FAIL;
                    break;
                }
                if (p->stability)
                    printf("  %-22s ratio %-8.3g measure %-10.3g %s %s\n", mi[m].name,
                           row->ratio, row->value, row->failed ? "FAILED" : "stable", row->note);
                else {
                    row->error = fabs(row->value - p->reference) / fabs(p->reference);
                    printf("  %-22s %s = %-10.4g value %-12.6g error %-10.3g cpu %.3g s\n",
                           mi[m].name, mi[m].knob, row->knob_value, row->value, row->error,
                           row->cpu);
                }
                fflush(stdout);
            }
        }
    }
    if (rc == PL_EXIT_OK) rc = pl_cmp_write_all(&res, out, doc) == 0 ? PL_EXIT_OK : PL_EXIT_FAIL;
    for (int i = 0; i < nm; i++) free(mfiles[i]);
    pl_cmp_free(&res);
    return rc;
}
