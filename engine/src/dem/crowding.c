/* Bodies are numbered from 1 in messages, as scenes number them (the C API indexes from 0).
 * Set-up check before the neighbour list is built for new or changed bodies: bodies piled on
 * top of each other. A grain whose centre lies within half the smaller radius of another's
 * overlaps it by more than 150 % of that radius, so the overlap guard stops the run after the
 * first step anyway; but when many bodies share a spot (a loop that never moves the centre:
 * 20,000 discs at one point) that first step meets every pair among them (N^2 / 2 contacts) and
 * takes minutes. A body with more than PL_CROWD_MAX such partners refuses the step at once, with
 * the bodies and the place named. The check costs O(N) for a sensible scene: a grid of cells
 * of the median radius, each body scanning the 3 x 3 cells around it, and it stops counting a
 * body's partners at PL_CROWD_MAX + 1. It runs only when bodies were added or changed (the
 * neighbour list's classification is stale). */
#include "core/alloc.h"
#include "dem/world_internal.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* More partners than this within half the smaller radius: a pile, not a packing (a disc among
   equal discs has none in any packing; the guard handles a few). */
#define PL_CROWD_MAX 64

static int cmp_d(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static const char *shape_name(int s) { return s == PL_SHAPE_DISC ? "disc" : "polygon"; }

pl_status pl__check_crowding(pl_world *w) {
    const int n = w->n;
    if (n < PL_CROWD_MAX + 2) return PL_OK;
    int32_t *idx = pl_malloc((size_t)n * sizeof *idx);
    double *r = pl_malloc((size_t)n * sizeof *r);
    if (!idx || !r) {
        pl_free(idx);
        pl_free(r);
        return pl__error(w, PL_ERR_NOMEM, "step: out of memory checking the bodies' placement");
    }
    /* grains (discs and polygons, by their bounding radius) with a finite place */
    int m = 0;
    double lox = INFINITY, loy = INFINITY, hix = -INFINITY, hiy = -INFINITY;
    for (int i = 0; i < n; i++) {
        if (w->shape[i] == PL_SHAPE_SEGMENT || !(w->radius[i] > 0)) continue;
        const pl_vec2 p = w->pos[i];
        if (!isfinite(p.x) || !isfinite(p.y)) continue;
        idx[m] = i;
        r[m++] = w->radius[i];
        lox = fmin(lox, p.x), loy = fmin(loy, p.y), hix = fmax(hix, p.x), hiy = fmax(hiy, p.y);
    }
    pl_status st = PL_OK;
    int32_t *start = NULL, *item = NULL, *cell = NULL;
    if (m < PL_CROWD_MAX + 2) goto done;
    qsort(r, (size_t)m, sizeof *r, cmp_d);
    /* cells of the median radius: a partner of a body no larger than twice that lies in the
       3 x 3 cells around it (larger bodies are checked as partners of the smaller ones) */
    double h = r[m / 2];
    int nx, ny;
    for (;;) {
        const double fx = floor((hix - lox) / h) + 1, fy = floor((hiy - loy) / h) + 1;
        if (fx * fy <= 4.0 * m + 1024) {
            nx = (int)fx;
            ny = (int)fy;
            break;
        }
        h *= 1.5;
    }
    const int nc = nx * ny;
    start = pl_calloc((size_t)nc + 1, sizeof *start);
    item = pl_malloc((size_t)m * sizeof *item);
    cell = pl_malloc((size_t)m * sizeof *cell);
    if (!start || !item || !cell) {
        st = pl__error(w, PL_ERR_NOMEM, "step: out of memory checking the bodies' placement");
        goto done;
    }
    for (int k = 0; k < m; k++) {
        const pl_vec2 p = w->pos[idx[k]];
        int cx = (int)((p.x - lox) / h), cy = (int)((p.y - loy) / h);
        cx = cx < 0 ? 0 : cx >= nx ? nx - 1 : cx;
        cy = cy < 0 ? 0 : cy >= ny ? ny - 1 : cy;
        cell[k] = cy * nx + cx;
        start[cell[k] + 1]++;
    }
    for (int c = 0; c < nc; c++) start[c + 1] += start[c];
    int32_t *fill = pl_malloc((size_t)nc * sizeof *fill);
    if (!fill) {
        st = pl__error(w, PL_ERR_NOMEM, "step: out of memory checking the bodies' placement");
        goto done;
    }
    memcpy(fill, start, (size_t)nc * sizeof *fill);
    for (int k = 0; k < m; k++) item[fill[cell[k]]++] = k; /* index order within a cell */
    pl_free(fill);
    for (int k = 0; k < m; k++) {
        const int a = idx[k];
        if (w->radius[a] > 2 * h) continue;
        const pl_vec2 pa = w->pos[a];
        const int cx = cell[k] % nx, cy = cell[k] / nx;
        int deep = 0, first = -1;
        for (int dy = -1; dy <= 1 && deep <= PL_CROWD_MAX; dy++) {
            const int yy = cy + dy;
            if (yy < 0 || yy >= ny) continue;
            for (int dx = -1; dx <= 1 && deep <= PL_CROWD_MAX; dx++) {
                const int xx = cx + dx;
                if (xx < 0 || xx >= nx) continue;
                const int c = yy * nx + xx;
                for (int q = start[c]; q < start[c + 1] && deep <= PL_CROWD_MAX; q++) {
                    const int b = idx[item[q]];
                    if (b == a) continue;
                    if (w->motion[a] != PL_MOTION_DYNAMIC && w->motion[b] != PL_MOTION_DYNAMIC) continue;
                    const double lim = 0.5 * fmin(w->radius[a], w->radius[b]);
                    const double ex = w->pos[b].x - pa.x, ey = w->pos[b].y - pa.y;
                    if (ex * ex + ey * ey < lim * lim) {
                        if (first < 0 || b < first) first = b;
                        deep++;
                    }
                }
            }
        }
        if (deep > PL_CROWD_MAX) {
            /* how many bodies share the spot: those with their centre in the body's cell */
            const int here = start[cell[k] + 1] - start[cell[k]];
            st = pl__error(w, PL_ERR_STATE,
                           "bodies piled on top of each other: body %d (%s, radius %.3g m, at (%.4g, %.4g)) has "
                           "more than %d bodies (body %d among them) with their centre within half the smaller "
                           "radius of its own (each overlapping it by more than 150%% of that radius), and %d "
                           "bodies have their centre in the %.3g m square around it; the first step would "
                           "compute every contact among them. Likely cause: bodies created at the same place "
                           "(a loop that does not move the centre); spread them out, e.g. with porelab.packing",
                           a + 1, shape_name(w->shape[a]), w->radius[a], pa.x, pa.y, PL_CROWD_MAX, first + 1,
                           here, h);
            goto done;
        }
    }
done:
    pl_free(start);
    pl_free(item);
    pl_free(cell);
    pl_free(idx);
    pl_free(r);
    return st;
}
