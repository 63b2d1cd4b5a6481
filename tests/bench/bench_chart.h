/* Error-against-CPU-time charts of the benchmarks, drawn by the charts of the app
 * (app/render/charts.c: the house chart style, PLplot text escapes such as c#dD#u).
 * Available when the benchmark links porelab_render (BENCH_CHART=1). */
#ifndef PORELAB_BENCH_CHART_H
#define PORELAB_BENCH_CHART_H

/* One series per entry: x[s][0..n[s]-1] CPU seconds, y[s][...] errors (both > 0), drawn as
   lines with markers on log-log axes; legend as pl_chart_def.legend (1 top right, 2 top left,
   3 bottom right, 4 bottom left). Prints "wrote PATH" or the error;
   returns 0 or -1. */
int bench_error_cpu_chart(const char *path, const char *title, const char *xlabel, const char *ylabel, int legend,
                          int nseries, const char *const names[], const double *const x[], const double *const y[],
                          const int n[]);

#endif
