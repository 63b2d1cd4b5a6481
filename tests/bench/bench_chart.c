/* Error-against-CPU-time charts of the benchmarks through pl_chart_write (see bench_chart.h). */
#include "bench_chart.h"
#include "charts.h"
#include <math.h>
#include <stdio.h>

int bench_error_cpu_chart(const char *path, const char *title, const char *xlabel, const char *ylabel, int legend,
                          int nseries, const char *const names[], const double *const x[], const double *const y[],
                          const int n[]) {
    pl_chart_series se[PL_CHART_MAX_SERIES];
    if (nseries < 1 || nseries > PL_CHART_MAX_SERIES) {
        fprintf(stderr, "%s: %d series (valid: 1 to %d)\n", path, nseries, PL_CHART_MAX_SERIES);
        return -1;
    }
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int s = 0; s < nseries; s++) {
        se[s] = (pl_chart_series){names[s], x[s], y[s], n[s], PL_SERIES_LINE_POINTS, {0, 0, 0, 0}, 0};
        for (int i = 0; i < n[s]; i++) {
            if (!(x[s][i] > 0) || !(y[s][i] > 0)) continue;
            lo[0] = fmin(lo[0], log10(x[s][i]));
            hi[0] = fmax(hi[0], log10(x[s][i]));
            lo[1] = fmin(lo[1], log10(y[s][i]));
            hi[1] = fmax(hi[1], log10(y[s][i]));
        }
    }
    if (!(hi[0] >= lo[0]) || !(hi[1] >= lo[1])) {
        fprintf(stderr, "%s: no positive CPU times and errors to draw\n", path);
        return -1;
    }
    pl_chart_def cd = pl_default_chart_def();
    /* whole decades, so every marker lies inside the frame */
    cd.xmin = pow(10, floor(lo[0]));
    cd.xmax = pow(10, fmax(ceil(hi[0]), floor(lo[0]) + 1));
    cd.ymin = pow(10, floor(lo[1]));
    cd.ymax = pow(10, fmax(ceil(hi[1]), floor(lo[1]) + 1));
    cd.width = 800;
    cd.height = 560;
    cd.title = title;
    cd.xlabel = xlabel;
    cd.ylabel = ylabel;
    cd.series = se;
    cd.series_count = nseries;
    cd.logx = cd.logy = 1;
    cd.legend = legend;
    char err[256];
    if (pl_chart_write(path, &cd, err, sizeof err) != 0) {
        fprintf(stderr, "chart: %s\n", err);
        return -1;
    }
    printf("wrote %s\n", path);
    return 0;
}
