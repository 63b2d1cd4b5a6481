/// Isolines of a piecewise-linear (P1) field on triangles, by marching triangles, chained into
/// polylines; and "nice" level/tick selection. Generic over (node coordinates, triangle node
/// indices, node values), so any triangulated field (fluid pressure, head) can use it.
#ifndef PORELAB_ISOLINES_H
#define PORELAB_ISOLINES_H

#include "porelab/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Polylines of one or more levels. Line k has points [starts[k], starts[k+1]) and level
/// levels[k]; closed[k] is 1 when its last point joins its first.
typedef struct pl_isolines {
    pl_vec2 *points; int point_count, point_cap;
    int *starts;     ///< line_count + 1 entries
    double *levels;
    unsigned char *closed;
    int line_count, line_cap;
} pl_isolines;

void pl_isolines_init(pl_isolines *iso);
void pl_isolines_free(pl_isolines *iso);

/// Extracts the isolines of every level. A node whose value equals the level counts as
/// above it, so lines through nodes are found once. Crossing points are interpolated
/// linearly on mesh edges (exact for P1 fields). Appends to iso (call pl_isolines_free or
/// reuse). Returns 0, or -1 on out of memory or bad arguments (node index out of range).
int pl_isolines_extract(const pl_vec2 *nodes, int node_count, const int *tris, int tri_count,
                        const double *values, const double *levels, int level_count,
                        pl_isolines *iso);

/// Chooses "nice" levels (1, 2, 2.5 or 5 x 10^k steps) strictly inside [vmin, vmax], about
/// `count` of them. Returns how many were written to out (<= cap) and the step in *step.
int pl_nice_levels(double vmin, double vmax, int count, double *out, int cap, double *step);

/// A nice number near x (1, 2, 5 x 10^k); round = 1 picks the nearest, 0 the next above.
double pl_nice_number(double x, int round);

#ifdef __cplusplus
}
#endif
#endif
