/* Built instead of charts.c when PLplot (libplplot-dev) is not installed: charts are refused
 * with a clear message; everything else in the renderer works. */
#include "charts.h"

#include <stdio.h>
#include <string.h>

pl_chart_def pl_default_chart_def(void) {
    pl_chart_def d;
    memset(&d, 0, sizeof d);
    d.width = 800;
    d.height = 560;
    d.legend = 1;
    d.grid = 1;
    return d;
}

int pl_chart_write(const char *path, const pl_chart_def *def, char *err, size_t errlen) {
    (void)def;
    snprintf(err, errlen,
             "%s: charts need PLplot, which this build does not have (install the Debian "
             "packages libplplot-dev and plplot-driver-cairo, then rebuild)", path);
    return -1;
}
