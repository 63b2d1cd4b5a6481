/* porelab compare's outputs (compare_report.h): CSV with a units line, PLplot charts through
 * render/charts.h, and the summary table (markdown) that docs/compare.md embeds. */
#include "compare_report.h"
#include "render/charts.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

pl_cmp_problem *pl_cmp_add_problem(pl_cmp_results *r)
{
    if (r->nproblems == r->cap_problems) {
        int cap = r->cap_problems ? 2 * r->cap_problems : 16;
        void *p = realloc(r->problems, sizeof *r->problems * (size_t)cap);
        if (!p) return NULL;
        r->problems = p;
        r->cap_problems = cap;
    }
    pl_cmp_problem *p = &r->problems[r->nproblems++];
    memset(p, 0, sizeof *p);
    return p;
}

pl_cmp_row *pl_cmp_add_row(pl_cmp_results *r)
{
    if (r->nrows == r->cap_rows) {
        int cap = r->cap_rows ? 2 * r->cap_rows : 64;
        void *p = realloc(r->rows, sizeof *r->rows * (size_t)cap);
        if (!p) return NULL;
        r->rows = p;
        r->cap_rows = cap;
    }
    pl_cmp_row *w = &r->rows[r->nrows++];
    memset(w, 0, sizeof *w);
    return w;
}

void pl_cmp_free(pl_cmp_results *r)
{
    free(r->problems);
    free(r->rows);
    memset(r, 0, sizeof *r);
}

int pl_cmp_mkdirs(const char *dir)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", dir);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/') continue;
        *p = 0;
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) return -1;
        *p = '/';
    }
    return mkdir(buf, 0777) != 0 && errno != EEXIST ? -1 : 0;
}

void pl_cmp_pareto(const pl_cmp_results *r, int problem, int *keep)
{
    for (int i = 0; i < r->nrows; i++) {
        const pl_cmp_row *a = &r->rows[i];
        keep[i] = 0;
        if (a->problem != problem || !isfinite(a->error)) continue;
        keep[i] = 1;
        for (int j = 0; j < r->nrows && keep[i]; j++) {
            const pl_cmp_row *b = &r->rows[j];
            if (j == i || b->problem != problem || !isfinite(b->error)) continue;
            if (b->cpu <= a->cpu && b->error <= a->error && (b->cpu < a->cpu || b->error < a->error))
                keep[i] = 0;
        }
    }
}

static void csv_text(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"') fputc('"', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

static int write_csv(const pl_cmp_results *r, const char *dir)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/results.csv", dir);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "porelab compare: cannot write %s: %s\n", path, strerror(errno));
        return -1;
    }
    fprintf(f, "problem,method,knob,knob_value,value,reference,rel_error,cpu_s,reps,ratio,limit,"
               "failed,unit,knob_unit\n");
    fprintf(f, "#-,-,-,(knob_unit),(unit),(unit),1,s,1,1,(knob_unit),0/1,-,-\n");
    for (int i = 0; i < r->nrows; i++) {
        const pl_cmp_row *w = &r->rows[i];
        const pl_cmp_problem *p = &r->problems[w->problem];
        csv_text(f, p->name);
        fputc(',', f);
        csv_text(f, w->method);
        fputc(',', f);
        csv_text(f, w->knob);
        fprintf(f, ",%.9g,%.12g,%.12g,%.6g,%.6g,%d,%.6g,%.6g,%d,", w->knob_value, w->value,
                p->stability ? NAN : p->reference, p->stability ? NAN : w->error, w->cpu, w->reps,
                w->ratio, w->limit, w->failed);
        csv_text(f, p->unit);
        fputc(',', f);
        csv_text(f, w->knob_unit);
        fputc('\n', f);
    }
    return fclose(f) == 0 ? 0 : -1;
}

static const pl_rgba PALETTE[] = {{0.12, 0.47, 0.71, 1}, {0.84, 0.15, 0.16, 1}, {0.17, 0.63, 0.17, 1},
                                  {0.58, 0.40, 0.74, 1}, {1.00, 0.50, 0.05, 1}, {0.55, 0.34, 0.29, 1},
                                  {0.89, 0.47, 0.76, 1}, {0.09, 0.75, 0.81, 1}};

#define FLOOR_ERR 1e-16

static int chart_accuracy(const pl_cmp_results *r, int pi, const char *dir)
{
    const pl_cmp_problem *p = &r->problems[pi];
    pl_chart_series ser[PL_CHART_MAX_SERIES];
    double *xs = malloc(sizeof(double) * (size_t)(2 * r->nrows + 2));
    double *ys = malloc(sizeof(double) * (size_t)(2 * r->nrows + 2));
    int *keep = malloc(sizeof(int) * (size_t)(r->nrows + 1));
    char names[PL_CHART_MAX_SERIES][256];
    if (!xs || !ys || !keep) return -1;
    int ns = 0, used = 0;
    for (int i = 0; i < r->nrows && ns < PL_CHART_MAX_SERIES - 1; i++) {
        const pl_cmp_row *w = &r->rows[i];
        if (w->problem != pi || (i > 0 && r->rows[i - 1].problem == pi &&
                                  !strcmp(r->rows[i - 1].method, w->method)))
            continue;
        int n0 = used;
        for (int j = i; j < r->nrows && r->rows[j].problem == pi && !strcmp(r->rows[j].method, w->method); j++) {
            xs[used] = r->rows[j].cpu;
            ys[used] = fmax(r->rows[j].error, FLOOR_ERR);
            used++;
        }
        char plain[256];
        snprintf(plain, sizeof plain, "%s (%s)", w->label, w->knob);
        pl_chart_text(plain, names[ns], sizeof names[ns]);
        ser[ns] = (pl_chart_series){names[ns], xs + n0, ys + n0, used - n0, PL_SERIES_LINE_POINTS,
                                    PALETTE[ns % 8], 2};
        ns++;
    }
    /* the Pareto front, cheapest first */
    pl_cmp_pareto(r, pi, keep);
    int n0 = used;
    for (;;) {
        int best = -1;
        for (int i = 0; i < r->nrows; i++)
            if (keep[i] == 1 && (best < 0 || r->rows[i].cpu < r->rows[best].cpu)) best = i;
        if (best < 0) break;
        keep[best] = 2;
        xs[used] = r->rows[best].cpu;
        ys[used] = fmax(r->rows[best].error, FLOOR_ERR);
        used++;
    }
    ser[ns++] = (pl_chart_series){"Pareto front (no run both cheaper and more accurate)", xs + n0,
                                  ys + n0, used - n0, PL_SERIES_DASHED, {0, 0, 0, 1}, 1.5};
    pl_chart_def d = pl_default_chart_def();
    char ylabel[400], title[400], plain[200];
    snprintf(plain, sizeof plain, "relative error of %s", p->quantity);
    pl_chart_text(plain, ylabel, sizeof ylabel);
    pl_chart_text(p->title, title, sizeof title);
    d.title = title;
    d.xlabel = "CPU time per run (s)";
    d.ylabel = ylabel;
    d.series = ser;
    d.series_count = ns;
    d.logx = d.logy = 1;
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    for (int i = 0; i < used; i++) {
        if (!(xs[i] > 0) || !isfinite(ys[i])) continue;
        xlo = fmin(xlo, xs[i]);
        xhi = fmax(xhi, xs[i]);
        ylo = fmin(ylo, ys[i]);
        yhi = fmax(yhi, ys[i]);
    }
    if (xhi > xlo) { /* at least a decade and a half, so that the axis carries labels */
        const double span = fmax(xhi / xlo * 2.56, 31.6), mid = sqrt(xlo * xhi);
        d.xmin = mid / sqrt(span);
        d.xmax = mid * sqrt(span);
    }
    if (yhi >= ylo) { /* room above the data for the legend: it takes a fraction f of the height */
        const double f = 0.06 * ns + 0.06;
        const double decades = log10(fmax(yhi / ylo, 10) * 9);
        d.ymin = ylo / 3;
        d.ymax = d.ymin * pow(10, decades / (1 - f));
    }
    d.legend = 1;
    d.width = 900;
    d.height = 620;
    /* one label per decade on the error axis: give each decade room (about 36 px) */
    if (d.ymax > d.ymin && d.ymin > 0) {
        const int need = (int)(36 * log10(d.ymax / d.ymin)) + 140;
        if (need > d.height) d.height = need > 1400 ? 1400 : need;
    }
    char path[1200], err[256];
    snprintf(path, sizeof path, "%s/%s.png", dir, p->name);
    int rc = pl_chart_write(path, &d, err, sizeof err);
    if (rc != 0) fprintf(stderr, "porelab compare: %s: %s\n", path, err);
    free(xs);
    free(ys);
    free(keep);
    return rc;
}

/* first failed ratio and last stable ratio below it */
static void boundary(const pl_cmp_results *r, int pi, double *stable, double *failed, double *limit)
{
    *stable = NAN;
    *failed = NAN;
    *limit = NAN;
    for (int i = 0; i < r->nrows; i++) {
        const pl_cmp_row *w = &r->rows[i];
        if (w->problem != pi) continue;
        *limit = w->limit;
        if (w->failed && (!isfinite(*failed) || w->ratio < *failed)) *failed = w->ratio;
    }
    for (int i = 0; i < r->nrows; i++) {
        const pl_cmp_row *w = &r->rows[i];
        if (w->problem != pi || w->failed) continue;
        if ((!isfinite(*failed) || w->ratio < *failed) && (!isfinite(*stable) || w->ratio > *stable))
            *stable = w->ratio;
    }
}

static int chart_stability(const pl_cmp_results *r, int pi, const char *dir)
{
    const pl_cmp_problem *p = &r->problems[pi];
    int n = 0;
    double *x = malloc(sizeof(double) * (size_t)(r->nrows + 1)), *y = malloc(sizeof(double) * (size_t)(r->nrows + 1));
    if (!x || !y) return -1;
    double lo = INFINITY, hi = -INFINITY;
    const char *knob = "";
    for (int i = 0; i < r->nrows; i++) {
        const pl_cmp_row *w = &r->rows[i];
        if (w->problem != pi) continue;
        knob = w->knob;
        /* a run the guards or the model stopped before it gave a measure (0 or not finite) has
           no point; the failure line marks it */
        if (!(w->value > 0) || !isfinite(w->value)) continue;
        x[n] = w->ratio;
        y[n] = fmax(w->value, FLOOR_ERR);
        lo = fmin(lo, y[n]);
        hi = fmax(hi, y[n]);
        n++;
    }
    double st, fl, lim;
    boundary(r, pi, &st, &fl, &lim);
    /* the first failure: refused by the run-time check, or measured */
    int refused = 0;
    for (int i = 0; i < r->nrows; i++)
        if (r->rows[i].problem == pi && r->rows[i].failed && r->rows[i].ratio == fl &&
            strncmp(r->rows[i].note, "refused", 7) == 0)
            refused = 1;
    if (!(hi > lo)) {
        lo = 1e-3;
        hi = 1e3;
    }
    double ylo = lo / 3, yhi = hi * 3;
    double lx[2] = {1, 1}, ly[2] = {ylo, yhi}, fx[2] = {fl, fl};
    pl_chart_series ser[3];
    char mname[400];
    pl_chart_text(p->quantity, mname, sizeof mname);
    ser[0] = (pl_chart_series){mname, x, y, n, PL_SERIES_LINE_POINTS, PALETTE[0], 2};
    ser[1] = (pl_chart_series){"computed limit", lx, ly, 2, PL_SERIES_DASHED, {0, 0, 0, 1}, 1.5};
    char fname[96];
    snprintf(fname, sizeof fname, refused ? "refused by the run-time check (from %.3g \u00d7 limit)" : "measured failure (%.3g \u00d7 limit)",
             fl);
    ser[2] = (pl_chart_series){fname, fx, ly, 2, PL_SERIES_LINE, PALETTE[1], 2};
    pl_chart_def d = pl_default_chart_def();
    char xlabel[400], ylabel[400], title[400], plain[400];
    snprintf(plain, sizeof plain, "%s / computed limit (1)", knob);
    pl_chart_text(plain, xlabel, sizeof xlabel);
    snprintf(plain, sizeof plain, "%s (%s)", p->quantity, p->unit);
    pl_chart_text(plain, ylabel, sizeof ylabel);
    pl_chart_text(p->title, title, sizeof title);
    d.title = title;
    d.xlabel = xlabel;
    d.ylabel = ylabel;
    d.series = ser;
    d.series_count = isfinite(fl) ? 3 : 2;
    d.logy = 1; /* the ratio to the limit on a linear axis: the failure sits near 1 */
    d.xmin = 0;
    for (int i = 0; i < n; i++) d.xmax = fmax(d.xmax, x[i] * 1.05);
    d.ymin = ylo;
    d.ymax = yhi;
    d.legend = 2;
    d.width = 900;
    d.height = 620;
    char path[1200], err[256];
    snprintf(path, sizeof path, "%s/stability_%s.png", dir, p->name);
    int rc = pl_chart_write(path, &d, err, sizeof err);
    if (rc != 0) fprintf(stderr, "porelab compare: %s: %s\n", path, err);
    free(x);
    free(y);
    return rc;
}

static void summary(const pl_cmp_results *r, FILE *f)
{
    int any = 0;
    for (int pi = 0; pi < r->nproblems; pi++) any |= !r->problems[pi].stability;
    if (any) {
        fprintf(f, "| problem | within 1 %% | within 5 %% | within 20 %% | most expensive run |\n"
                   "|---|---|---|---|---|\n");
        for (int pi = 0; pi < r->nproblems; pi++) {
            const pl_cmp_problem *p = &r->problems[pi];
            if (p->stability) continue;
            int maxi = -1;
            for (int i = 0; i < r->nrows; i++)
                if (r->rows[i].problem == pi && (maxi < 0 || r->rows[i].cpu > r->rows[maxi].cpu)) maxi = i;
            if (maxi < 0) continue;
            fprintf(f, "| %s |", p->name);
            const double thr[3] = {0.01, 0.05, 0.20};
            for (int t = 0; t < 3; t++) {
                int best = -1;
                for (int i = 0; i < r->nrows; i++) {
                    const pl_cmp_row *w = &r->rows[i];
                    if (w->problem == pi && w->error <= thr[t] && (best < 0 || w->cpu < r->rows[best].cpu))
                        best = i;
                }
                if (best < 0) {
                    fprintf(f, " none |");
                    continue;
                }
                const pl_cmp_row *w = &r->rows[best];
                fprintf(f, " %s, %s = %g: %.2g s (%.2g of the most expensive) |", w->method, w->knob,
                        w->knob_value, w->cpu, w->cpu / r->rows[maxi].cpu);
            }
            const pl_cmp_row *m = &r->rows[maxi];
            fprintf(f, " %s, %s = %g: %.2g s, error %.2g |\n", m->method, m->knob, m->knob_value, m->cpu,
                    m->error);
        }
        fprintf(f, "\n");
    }
    any = 0;
    for (int pi = 0; pi < r->nproblems; pi++) any |= r->problems[pi].stability;
    if (any) {
        fprintf(f, "| scheme | computed limit | last stable / limit | first failure / limit | failure seen as |\n"
                   "|---|---|---|---|---|\n");
        for (int pi = 0; pi < r->nproblems; pi++) {
            const pl_cmp_problem *p = &r->problems[pi];
            if (!p->stability) continue;
            double st, fl, lim;
            boundary(r, pi, &st, &fl, &lim);
            const char *unit = "";
            const char *note = "";
            for (int i = 0; i < r->nrows; i++)
                if (r->rows[i].problem == pi) {
                    unit = r->rows[i].knob_unit;
                    if (r->rows[i].failed && r->rows[i].ratio == fl) note = r->rows[i].note;
                }
            const int bare = unit[0] == '\0' || strcmp(unit, "1") == 0; /* dimensionless: no unit */
            fprintf(f, "| %s | %.3g%s%s | %.3g | %.3g | %s |\n", p->title, lim, bare ? "" : " ", bare ? "" : unit, st,
                    fl, note);
        }
        fprintf(f, "\n");
    }
}

static int update_doc(const char *doc, const char *table)
{
    FILE *f = fopen(doc, "rb");
    if (!f) {
        fprintf(stderr, "porelab compare: --update-doc: cannot open %s: %s\n", doc, strerror(errno));
        return -1;
    }
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = malloc((size_t)n + 1);
    if (!text || fread(text, 1, (size_t)n, f) != (size_t)n) {
        fclose(f);
        free(text);
        return -1;
    }
    fclose(f);
    text[n] = 0;
    /* the markers on lines of their own (the prose may quote them) */
    const char *open = "\n<!-- compare:summary -->\n", *close = "\n<!-- /compare:summary -->";
    char *a = strstr(text, open), *b = a ? strstr(a + strlen(open) - 1, close) : NULL;
    if (b) b++; /* keep the newline before the closing marker in the text written before it */
    if (!a || !b) {
        fprintf(stderr, "porelab compare: --update-doc: %s has no '%s' ... '%s' block\n", doc, open, close);
        free(text);
        return -1;
    }
    f = fopen(doc, "wb");
    if (!f) {
        free(text);
        return -1;
    }
    fwrite(text, 1, (size_t)(a - text) + strlen(open), f);
    fputs(table, f);
    fputs(b, f);
    free(text);
    return fclose(f) == 0 ? 0 : -1;
}

int pl_cmp_write_all(const pl_cmp_results *r, const char *dir, const char *doc)
{
    if (write_csv(r, dir) != 0) return -1;
    for (int pi = 0; pi < r->nproblems; pi++) {
        int rc = r->problems[pi].stability ? chart_stability(r, pi, dir) : chart_accuracy(r, pi, dir);
        if (rc != 0) return -1;
    }
    char *buf = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&buf, &len);
    if (!m) return -1;
    summary(r, m);
    fclose(m);
    char path[1200];
    snprintf(path, sizeof path, "%s/summary.md", dir);
    FILE *f = fopen(path, "w");
    if (!f) {
        free(buf);
        return -1;
    }
    fputs(buf, f);
    fclose(f);
    printf("\n%s", buf);
    int rc = doc ? update_doc(doc, buf) : 0;
    free(buf);
    return rc;
}
