/* What porelab compare writes from its runs: results.csv, the error-against-cost chart of
 * each problem (Pareto front marked), the stability charts and the summary table. */
#ifndef PL_APP_COMPARE_REPORT_H
#define PL_APP_COMPARE_REPORT_H

typedef struct pl_cmp_problem {
    char name[64], title[160], quantity[160], unit[32], source[256];
    double reference;
    int stability;
} pl_cmp_problem;

typedef struct pl_cmp_row {
    int problem; /* index into pl_cmp_results.problems */
    char method[64], label[128], knob[96], knob_unit[32];
    double knob_value;
    double value, error, cpu; /* measured value, relative error, CPU s per run */
    int reps;
    /* stability sweeps */
    double ratio, limit;
    int failed;
    char note[256];
} pl_cmp_row;

typedef struct pl_cmp_results {
    pl_cmp_problem *problems;
    int nproblems, cap_problems;
    pl_cmp_row *rows;
    int nrows, cap_rows;
} pl_cmp_results;

pl_cmp_problem *pl_cmp_add_problem(pl_cmp_results *r);
pl_cmp_row *pl_cmp_add_row(pl_cmp_results *r);
void pl_cmp_free(pl_cmp_results *r);
int pl_cmp_mkdirs(const char *dir);
/* Marks the Pareto front of one problem's rows: keep[i] = 1 when no other run is both
 * cheaper (or as cheap) and more accurate. */
void pl_cmp_pareto(const pl_cmp_results *r, int problem, int *keep);
/* Writes results.csv, the charts and summary.md into dir; with doc, replaces its summary
 * block. Returns 0, or -1 after printing the error. */
int pl_cmp_write_all(const pl_cmp_results *r, const char *dir, const char *doc);

#endif
