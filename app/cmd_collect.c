/* porelab collect DIR...: gathers the manifest.json of runs (a run's folder, or a sweep's
 * folder holding job folders) into one CSV with a header of units and provenance, and charts
 * one result against one parameter with the ensemble's spread (PLplot, render/charts.h). */
#include "cli_common.h"
#include "commands.h"
#include "manifest.h"
#include "render/charts.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define MAX_COLS 128

static const pl_opt_spec collect_specs[] = {
    {"--out", "-o", "FILE", "CSV to write (default: DIR/results.csv for one folder, else results.csv)"},
    {"--chart", NULL, "RESULT:PARAM", "chart RESULT against PARAM: each run, the mean and +-1 s.d. per value"},
    {"--chart-out", NULL, "FILE", "chart file, .png/.svg/.pdf (default: beside the CSV, RESULT_vs_PARAM.png)"},
    {"--title", NULL, "TEXT", "chart title (default: scene, result and parameter)"},
    {"--xlabel", NULL, "TEXT", "chart x-axis label (default: the parameter's name and unit)"},
    {"--ylabel", NULL, "TEXT", "chart y-axis label (default: the result's name and unit)"},
    {"--line", NULL, "VALUE:LABEL", "a horizontal reference line at VALUE (e.g. a criterion), named LABEL in the legend"},
    {NULL, NULL, NULL, NULL}};

static const pl_command_help collect_help = {
    "collect", "DIR... [options]",
    "Reads DIR/manifest.json, or DIR/*/manifest.json for a sweep folder, and writes one CSV:\n"
    "a row per run with its parameters, seed, exit status, results, wall and CPU time and\n"
    "state hash, below '#' lines with the scene, the build and the units. --chart draws a\n"
    "result against a parameter: every run as a point, the mean over the runs at each value\n"
    "(seeds) as a line, and the mean +- one standard deviation dashed. Runs that differ in\n"
    "other parameters get a line each (at most 4; with 3 or 4 the +- s.d. lines are left out).",
    collect_specs};

typedef struct col {
    char name[48];
    char unit[24];
    int is_param;
} col;

typedef struct run {
    pl_json_doc d;
    char dir[PATH_MAX];
} run;

typedef struct table {
    run *runs;
    int n, cap;
    col cols[MAX_COLS];
    int ncols;
} table;

static int cmp_str(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static int add_run(table *t, const char *dir)
{
    char path[PATH_MAX + 16], err[512];
    snprintf(path, sizeof path, "%s/manifest.json", dir);
    if (t->n == t->cap) {
        int cap = t->cap ? 2 * t->cap : 64;
        run *r = realloc(t->runs, (size_t)cap * sizeof *r);
        if (!r) return -1;
        t->runs = r;
        t->cap = cap;
    }
    run *r = &t->runs[t->n];
    if (pl_json_read(path, &r->d, err, sizeof err) != 0) {
        fprintf(stderr, "porelab collect: %s\n", err);
        return -1;
    }
    const pl_json_item *f = pl_json_get(&r->d, "format");
    if (!f || f->type != 3 || strcmp(f->str, PL_MANIFEST_FORMAT) != 0) {
        fprintf(stderr, "porelab collect: %s: not a porelab manifest (format '%s', expected '%s')\n", path,
                f && f->type == 3 ? f->str : "?", PL_MANIFEST_FORMAT);
        pl_json_free(&r->d);
        return -1;
    }
    snprintf(r->dir, sizeof r->dir, "%s", dir);
    t->n++;
    return 0;
}

/* a run's folder, or a folder of run folders (sorted by name) */
static int add_dir(table *t, const char *dir)
{
    char path[PATH_MAX + 16];
    struct stat st;
    snprintf(path, sizeof path, "%s/manifest.json", dir);
    if (stat(path, &st) == 0) return add_run(t, dir);
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "porelab collect: cannot read %s: %s\n", dir, strerror(errno));
        return -1;
    }
    char **names = NULL;
    int n = 0, cap = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.') continue;
        snprintf(path, sizeof path, "%s/%s/manifest.json", dir, e->d_name);
        if (stat(path, &st) != 0) continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 64;
            char **nn = realloc(names, (size_t)cap * sizeof *nn);
            if (!nn) break;
            names = nn;
        }
        names[n++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof *names, cmp_str);
    int rc = 0, found = n;
    for (int i = 0; i < n; i++) {
        char sub[PATH_MAX];
        snprintf(sub, sizeof sub, "%s/%s", dir, names[i]);
        if (rc == 0 && add_run(t, sub) != 0) rc = -1;
        free(names[i]);
    }
    free(names);
    if (rc == 0 && found == 0) {
        fprintf(stderr, "porelab collect: %s holds no manifest.json (nor do its sub-folders): run porelab run or "
                        "porelab sweep --run first\n", dir);
        return -1;
    }
    return rc;
}

static int find_col(const table *t, const char *name, int is_param)
{
    for (int i = 0; i < t->ncols; i++)
        if (t->cols[i].is_param == is_param && strcmp(t->cols[i].name, name) == 0) return i;
    return -1;
}

/* the columns: every parameter (in the order first seen), every result (sorted) */
static int make_cols(table *t)
{
    for (int pass = 0; pass < 2; pass++) {
        const char *prefix = pass == 0 ? "params." : "results.";
        size_t pl = strlen(prefix);
        for (int r = 0; r < t->n; r++)
            for (int i = 0; i < t->runs[r].d.n; i++) {
                const pl_json_item *it = &t->runs[r].d.items[i];
                size_t len = strlen(it->path);
                if (strncmp(it->path, prefix, pl) != 0 || len < pl + 7 || strcmp(it->path + len - 6, ".value") != 0)
                    continue;
                char name[48];
                size_t nl = len - 6 - pl;
                if (nl >= sizeof name) continue;
                memcpy(name, it->path + pl, nl);
                name[nl] = '\0';
                if (find_col(t, name, pass == 0) >= 0) continue;
                if (t->ncols >= MAX_COLS) {
                    fprintf(stderr, "porelab collect: more than %d parameters and results\n", MAX_COLS);
                    return -1;
                }
                col *c = &t->cols[t->ncols++];
                snprintf(c->name, sizeof c->name, "%s", name);
                c->is_param = pass == 0;
                char up[200];
                snprintf(up, sizeof up, "%s%s.unit", prefix, name);
                const pl_json_item *u = pl_json_get(&t->runs[r].d, up);
                snprintf(c->unit, sizeof c->unit, "%.23s", u && u->type == 3 ? u->str : "");
            }
        if (pass == 1) { /* results sorted by name (they are sorted within a manifest already) */
            int first = 0;
            while (first < t->ncols && t->cols[first].is_param) first++;
            for (int i = first + 1; i < t->ncols; i++)
                for (int j = i; j > first && strcmp(t->cols[j - 1].name, t->cols[j].name) > 0; j--) {
                    col tmp = t->cols[j];
                    t->cols[j] = t->cols[j - 1];
                    t->cols[j - 1] = tmp;
                }
        }
    }
    return 0;
}

static const pl_json_item *value_of(const run *r, const col *c)
{
    char path[200];
    snprintf(path, sizeof path, "%s%s.value", c->is_param ? "params." : "results.", c->name);
    return pl_json_get(&r->d, path);
}

static double num_of(const run *r, const col *c)
{
    const pl_json_item *v = value_of(r, c);
    if (!v) return NAN;
    return v->type == 2 || v->type == 1 ? v->num : NAN;
}

static void put_num(FILE *f, double v)
{
    if (!isfinite(v)) return; /* empty cell */
    char b[40];
    snprintf(b, sizeof b, "%.15g", v);
    if (strtod(b, NULL) != v) snprintf(b, sizeof b, "%.17g", v);
    fputs(b, f);
}

static void put_csv_str(FILE *f, const char *s)
{
    if (!strpbrk(s, ",\"\n")) {
        fputs(s, f);
        return;
    }
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"') fputc('"', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

static const char *str_of(const run *r, const char *path)
{
    const pl_json_item *v = pl_json_get(&r->d, path);
    return v && v->type == 3 ? v->str : "";
}

static double numf(const run *r, const char *path)
{
    const pl_json_item *v = pl_json_get(&r->d, path);
    return v && v->type == 2 ? v->num : NAN;
}

static int write_csv(const table *t, const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "porelab collect: cannot write %s: %s\n", path, strerror(errno));
        return -1;
    }
    int failed = 0, hashes = 0;
    char first_hash[64] = "";
    for (int r = 0; r < t->n; r++) {
        if (numf(&t->runs[r], "exit_status") != 0) failed++;
        const char *h = str_of(&t->runs[r], "scene.hash");
        if (r == 0) snprintf(first_hash, sizeof first_hash, "%.63s", h);
        else if (strcmp(h, first_hash) != 0) hashes = 1;
    }
    const run *r0 = &t->runs[0];
    fprintf(f, "# porelab collect: %d runs (%d failed) of %s (%s)%s\n", t->n, failed, str_of(r0, "scene.path"),
            first_hash, hashes ? "; NOTE: not all runs had the same scene file (see scene_hash)" : "");
    fprintf(f, "# porelab %s (%s)\n", str_of(r0, "porelab.version"), str_of(r0, "porelab.build"));
    fprintf(f, "# seed 0 = the scene's own seeds; exit_status 0 = finished; state_hash = final state (same inputs and "
               "build give the same hash)\n# units:");
    for (int i = 0; i < t->ncols; i++)
        if (t->cols[i].unit[0]) fprintf(f, " %s [%s];", t->cols[i].name, t->cols[i].unit);
    fprintf(f, " wall_s [s]; cpu_s [s]\n");
    fprintf(f, "run");
    for (int i = 0; i < t->ncols; i++)
        if (t->cols[i].is_param) fprintf(f, ",%s", t->cols[i].name);
    fprintf(f, ",seed,exit_status");
    for (int i = 0; i < t->ncols; i++)
        if (!t->cols[i].is_param) fprintf(f, ",%s", t->cols[i].name);
    fprintf(f, ",wall_s,cpu_s,steps,state_hash,scene_hash\n");
    for (int r = 0; r < t->n; r++) {
        const run *x = &t->runs[r];
        const char *slash = strrchr(x->dir, '/');
        put_csv_str(f, slash ? slash + 1 : x->dir);
        for (int i = 0; i < t->ncols; i++)
            if (t->cols[i].is_param) fputc(',', f), put_num(f, num_of(x, &t->cols[i]));
        fputc(',', f);
        put_num(f, numf(x, "seed"));
        fputc(',', f);
        put_num(f, numf(x, "exit_status"));
        for (int i = 0; i < t->ncols; i++) {
            if (t->cols[i].is_param) continue;
            fputc(',', f);
            const pl_json_item *v = value_of(x, &t->cols[i]);
            if (!v) continue;
            if (v->type == 2) put_num(f, v->num);
            else if (v->type == 1) fputs(v->num != 0 ? "true" : "false", f);
            else if (v->type == 3) put_csv_str(f, v->str);
        }
        fputc(',', f);
        put_num(f, numf(x, "wall_s"));
        fputc(',', f);
        put_num(f, numf(x, "cpu_s"));
        fputc(',', f);
        put_num(f, numf(x, "steps"));
        fprintf(f, ",%s,%s\n", str_of(x, "state_hash"), str_of(x, "scene.hash"));
    }
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        fprintf(stderr, "porelab collect: cannot write %s\n", path);
        return -1;
    }
    printf("porelab collect: %d runs (%d failed) -> %s\n", t->n, failed, path);
    return 0;
}

static int cmp_dbl(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

#define MAX_GROUPS 4

/* RESULT against PARAM; runs that differ in other parameters go to separate groups (at most 4) */
typedef struct chart_text {
    const char *title, *xlabel, *ylabel, *line; /* NULL = default / no reference line */
} chart_text;

static int write_chart(const table *t, const char *spec, const char *path, const chart_text *txt)
{
    char rname[64], pname[64];
    const char *c = strchr(spec, ':');
    if (!c || c == spec || !c[1] || (size_t)(c - spec) >= sizeof rname || strlen(c + 1) >= sizeof pname) {
        fprintf(stderr, "porelab collect: --chart must be RESULT:PARAM (got '%s')\n", spec);
        return -1;
    }
    memcpy(rname, spec, (size_t)(c - spec));
    rname[c - spec] = '\0';
    snprintf(pname, sizeof pname, "%s", c + 1);
    double line_y = NAN;
    const char *line_label = NULL;
    if (txt->line) {
        char *end;
        line_y = strtod(txt->line, &end);
        if (end == txt->line || *end != ':' || !end[1] || !isfinite(line_y)) {
            fprintf(stderr, "porelab collect: --line must be VALUE:LABEL with a finite number VALUE (got '%s')\n",
                    txt->line);
            return -1;
        }
        line_label = end + 1;
    }
    int ri = find_col(t, rname, 0), pi = find_col(t, pname, 1);
    if (ri < 0 || pi < 0) {
        fprintf(stderr, "porelab collect: --chart %s: %s '%s' is not in the manifests; they have", spec,
                ri < 0 ? "result" : "parameter", ri < 0 ? rname : pname);
        for (int i = 0; i < t->ncols; i++)
            if (t->cols[i].is_param == (ri >= 0)) fprintf(stderr, " %s", t->cols[i].name);
        fprintf(stderr, "\n");
        return -1;
    }
    /* group key: the values of the other parameters that vary */
    int n = t->n, ngroups = 0, dropped = 0;
    char key[MAX_GROUPS][256];
    int *group = calloc((size_t)n, sizeof *group);
    double *xs[MAX_GROUPS] = {0}, *ys[MAX_GROUPS] = {0};
    int cnt[MAX_GROUPS] = {0};
    for (int r = 0; r < n; r++) {
        char k[256] = "";
        size_t kl = 0;
        for (int i = 0; i < t->ncols; i++) {
            if (!t->cols[i].is_param || i == pi) continue;
            double v0 = num_of(&t->runs[0], &t->cols[i]);
            int varies = 0;
            for (int q = 0; q < n; q++) varies |= num_of(&t->runs[q], &t->cols[i]) != v0;
            if (!varies) continue;
            kl += (size_t)snprintf(k + kl, sizeof k - kl, "%s%s = %g%s%s", kl ? ", " : "", t->cols[i].name,
                                   num_of(&t->runs[r], &t->cols[i]), t->cols[i].unit[0] ? " " : "", t->cols[i].unit);
            if (kl >= sizeof k) kl = sizeof k - 1;
        }
        int g = -1;
        for (int q = 0; q < ngroups; q++)
            if (strcmp(key[q], k) == 0) g = q;
        if (g < 0 && ngroups < MAX_GROUPS) {
            g = ngroups++;
            snprintf(key[g], sizeof key[g], "%s", k);
            xs[g] = calloc((size_t)n, sizeof(double));
            ys[g] = calloc((size_t)n, sizeof(double));
        }
        group[r] = g;
        if (g < 0) {
            dropped++;
            continue;
        }
        double x = num_of(&t->runs[r], &t->cols[pi]), y = num_of(&t->runs[r], &t->cols[ri]);
        if (!isfinite(x) || !isfinite(y)) continue; /* failed runs have no result */
        xs[g][cnt[g]] = x;
        ys[g][cnt[g]++] = y;
    }
    pl_chart_series ser[PL_CHART_MAX_SERIES];
    int ns = 0;
    static const pl_rgba pal[MAX_GROUPS] = {{0.12f, 0.47f, 0.71f, 1}, {0.84f, 0.15f, 0.16f, 1},
                                            {0.17f, 0.63f, 0.17f, 1}, {0.58f, 0.40f, 0.74f, 1}};
    double *mx[MAX_GROUPS] = {0}, *mm[MAX_GROUPS] = {0}, *lo[MAX_GROUPS] = {0}, *hi[MAX_GROUPS] = {0};
    char names[MAX_GROUPS][3][300];
    int total = 0;
    /* at most PL_CHART_MAX_SERIES: 4 per group with the +-1 s.d. lines (up to 2 groups), 2 per
       group without them (3-4 groups), and the reference line */
    int with_sd = ngroups <= 2;
    for (int g = 0; g < ngroups; g++) {
        total += cnt[g];
        /* unique x values, mean and sample standard deviation at each */
        double *ux = calloc((size_t)(cnt[g] + 1), sizeof *ux);
        memcpy(ux, xs[g], (size_t)cnt[g] * sizeof *ux);
        qsort(ux, (size_t)cnt[g], sizeof *ux, cmp_dbl);
        int nu = 0;
        for (int i = 0; i < cnt[g]; i++)
            if (nu == 0 || ux[i] != ux[nu - 1]) ux[nu++] = ux[i];
        mx[g] = ux;
        mm[g] = calloc((size_t)(nu + 1), sizeof(double));
        lo[g] = calloc((size_t)(nu + 1), sizeof(double));
        hi[g] = calloc((size_t)(nu + 1), sizeof(double));
        int min_count = n, max_count = 0;
        for (int u = 0; u < nu; u++) {
            double s = 0, s2 = 0;
            int k = 0;
            for (int i = 0; i < cnt[g]; i++)
                if (xs[g][i] == ux[u]) s += ys[g][i], k++;
            double mean = s / k;
            for (int i = 0; i < cnt[g]; i++)
                if (xs[g][i] == ux[u]) s2 += (ys[g][i] - mean) * (ys[g][i] - mean);
            double sd = k > 1 ? sqrt(s2 / (k - 1)) : 0;
            mm[g][u] = mean;
            lo[g][u] = mean - sd;
            hi[g][u] = mean + sd;
            if (k < min_count) min_count = k;
            if (k > max_count) max_count = k;
        }
        const char *gk = key[g][0] ? key[g] : "";
        snprintf(names[g][0], sizeof names[g][0], "%.255s%smean of %d run%s per value", gk, gk[0] ? ": " : "", min_count,
                 min_count == 1 ? "" : "s");
        snprintf(names[g][1], sizeof names[g][1], "mean \u00b1 1 s.d.");
        snprintf(names[g][2], sizeof names[g][2], "each run");
        if (max_count <= 1) { /* one run per value: no mean, no spread to draw */
            snprintf(names[g][0], sizeof names[g][0], "%.255s%sone run per value", gk, gk[0] ? ": " : "");
            ser[ns++] = (pl_chart_series){names[g][0], mx[g], mm[g], nu, PL_SERIES_LINE_POINTS, pal[g], 2};
            continue;
        }
        ser[ns++] = (pl_chart_series){names[g][0], mx[g], mm[g], nu, PL_SERIES_LINE_POINTS, pal[g], 2};
        if (with_sd) {
            ser[ns++] = (pl_chart_series){g == 0 ? names[g][1] : NULL, mx[g], lo[g], nu, PL_SERIES_DASHED, pal[g], 1};
            ser[ns++] = (pl_chart_series){NULL, mx[g], hi[g], nu, PL_SERIES_DASHED, pal[g], 1};
        }
        pl_rgba light = pal[g];
        light.a = 0.6f;
        ser[ns++] = (pl_chart_series){g == 0 ? names[g][2] : NULL, xs[g], ys[g], cnt[g], PL_SERIES_POINTS, light, 1};
    }
    int rc = 0;
    if (total == 0) {
        fprintf(stderr, "porelab collect: --chart %s: no finished run has both values\n", spec);
        rc = -1;
    } else {
        pl_chart_def def = pl_default_chart_def();
        char xl[128], yl[128], title[1024];
        snprintf(xl, sizeof xl, "%s%s%s%s", pname, t->cols[pi].unit[0] ? " (" : "", t->cols[pi].unit,
                 t->cols[pi].unit[0] ? ")" : "");
        snprintf(yl, sizeof yl, "%s%s%s%s", rname, t->cols[ri].unit[0] ? " (" : "", t->cols[ri].unit,
                 t->cols[ri].unit[0] ? ")" : "");
        const char *sp = str_of(&t->runs[0], "scene.path"), *base = strrchr(sp, '/');
        snprintf(title, sizeof title, "%s: %s against %s, %d runs", base ? base + 1 : sp, rname, pname, total);
        double y0 = INFINITY, y1 = -INFINITY;
        for (int g = 0; g < ngroups; g++)
            for (int i = 0; i < cnt[g]; i++) y0 = fmin(y0, ys[g][i]), y1 = fmax(y1, ys[g][i]);
        double line_x[2] = {0, 0}, line_v[2] = {0, 0};
        if (txt->line) {
            y0 = fmin(y0, line_y), y1 = fmax(y1, line_y);
            line_v[0] = line_v[1] = line_y;
            ser[ns++] = (pl_chart_series){line_label, line_x, line_v, 2, PL_SERIES_DASHED, {0.35f, 0.35f, 0.35f, 1}, 1.5};
        }
        def.title = txt->title ? txt->title : title;
        def.xlabel = txt->xlabel ? txt->xlabel : xl;
        def.ylabel = txt->ylabel ? txt->ylabel : yl;
        def.series = ser;
        def.series_count = ns;
        def.legend = 2;
        double x0 = INFINITY, x1 = -INFINITY; /* 5 % margin: the end points are not cut by the frame */
        for (int g = 0; g < ngroups; g++)
            for (int i = 0; i < cnt[g]; i++) x0 = fmin(x0, xs[g][i]), x1 = fmax(x1, xs[g][i]);
        double pad = x1 > x0 ? 0.05 * (x1 - x0) : (x0 != 0 ? 0.05 * fabs(x0) : 1);
        def.xmin = x0 - pad;
        def.xmax = x1 + pad;
        line_x[0] = def.xmin, line_x[1] = def.xmax;
        /* 5 % below the data; above it room for the legend (top left), so it covers no point */
        double span = y1 > y0 ? y1 - y0 : (y0 != 0 ? 0.1 * fabs(y0) : 1);
        def.ymin = y0 - 0.05 * span;
        def.ymax = y1 + 0.4 * span;
        char err[512];
        if (pl_chart_write(path, &def, err, sizeof err) != 0) {
            fprintf(stderr, "porelab collect: chart %s: %s\n", path, err);
            rc = -1;
        } else {
            printf("porelab collect: chart of %s against %s (%d runs%s) -> %s\n", rname, pname, total,
                   ngroups > 1 ? ", one line per combination of the other parameters" : "", path);
            if (dropped)
                printf("porelab collect: note: %d runs left out (more than %d combinations of the other parameters)\n",
                       dropped, MAX_GROUPS);
        }
    }
    for (int g = 0; g < ngroups; g++) {
        free(xs[g]), free(ys[g]), free(mx[g]), free(mm[g]), free(lo[g]), free(hi[g]);
    }
    free(group);
    return rc;
}

int pl_cmd_collect(int argc, char **argv)
{
    pl_opts o;
    int rc = pl_opts_parse(&o, &collect_help, argc, argv, 4);
    if (rc >= 0) return rc;
    if (o.npositional < 1) {
        fprintf(stderr, "porelab collect: give one or more run or sweep folders (usage: porelab collect %s)\n",
                collect_help.usage);
        return PL_EXIT_USAGE;
    }
    table t;
    memset(&t, 0, sizeof t);
    rc = PL_EXIT_FAIL;
    for (int i = 0; i < o.npositional; i++)
        if (add_dir(&t, o.positional[i]) != 0) goto done;
    if (make_cols(&t) != 0) goto done;
    char csv[PATH_MAX];
    if (pl_opts_has(&o, "--out")) snprintf(csv, sizeof csv, "%s", pl_opts_get(&o, "--out"));
    else if (o.npositional == 1) snprintf(csv, sizeof csv, "%s/results.csv", o.positional[0]);
    else snprintf(csv, sizeof csv, "results.csv");
    if (write_csv(&t, csv) != 0) goto done;
    const char *spec = pl_opts_get(&o, "--chart");
    if (spec) {
        char chart[2 * PATH_MAX + 256];
        if (pl_opts_has(&o, "--chart-out")) {
            snprintf(chart, sizeof chart, "%s", pl_opts_get(&o, "--chart-out"));
        } else {
            char d[PATH_MAX], nm[128];
            pl_path_dirname(csv, d, sizeof d);
            snprintf(nm, sizeof nm, "%s", spec);
            char *colon = strchr(nm, ':');
            if (colon) *colon = '\0';
            snprintf(chart, sizeof chart, "%s/%s_vs_%s.png", d, nm, colon ? colon + 1 : "");
        }
        chart_text txt = {pl_opts_get(&o, "--title"), pl_opts_get(&o, "--xlabel"), pl_opts_get(&o, "--ylabel"),
                          pl_opts_get(&o, "--line")};
        if (write_chart(&t, spec, chart, &txt) != 0) goto done;
    }
    rc = PL_EXIT_OK;
done:
    for (int i = 0; i < t.n; i++) pl_json_free(&t.runs[i].d);
    free(t.runs);
    return rc;
}
