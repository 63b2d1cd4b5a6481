/* Bodies near a box through the neighbour grid of the last build (dem/neighbor.c): the cells
 * the box meets, grown by one cell (a cell is at least the largest grid body's diameter plus
 * the skin, and no body has moved more than half the skin since it was binned), then the exact
 * test on the current position; the large bodies (walls, blocks) are tested one by one. */
#include "dem/box_query.h"
#include <math.h>
#include <stdlib.h>

static int touches(const pl_world *w, int i, pl_vec2 lo, pl_vec2 hi) {
    const pl_vec2 p = w->pos[i];
    const double dx = p.x < lo.x ? lo.x - p.x : (p.x > hi.x ? p.x - hi.x : 0);
    const double dy = p.y < lo.y ? lo.y - p.y : (p.y > hi.y ? p.y - hi.y : 0);
    return dx * dx + dy * dy < w->radius[i] * w->radius[i];
}

static int cmp_i32(const void *a, const void *b) {
    const int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

int pl__bodies_in_box(const pl_world *w, pl_vec2 lo, pl_vec2 hi, int32_t *out, int cap) {
    int n = 0;
    const int grid_ok = !w->need_rebuild && w->grid_nx > 0 && w->grid_n == w->n && w->cell_start && w->is_large;
    if (!grid_ok) {
        for (int i = 0; i < w->n; i++)
            if (touches(w, i, lo, hi)) {
                if (out && n < cap) out[n] = i;
                n++;
            }
        return n;
    }
    const double h = w->grid_h;
    int cx0 = (int)floor((lo.x - h - w->grid_lo_x) / h), cx1 = (int)floor((hi.x + h - w->grid_lo_x) / h);
    int cy0 = (int)floor((lo.y - h - w->grid_lo_y) / h), cy1 = (int)floor((hi.y + h - w->grid_lo_y) / h);
    cx0 = cx0 < 0 ? 0 : cx0;
    cy0 = cy0 < 0 ? 0 : cy0;
    cx1 = cx1 >= w->grid_nx ? w->grid_nx - 1 : cx1;
    cy1 = cy1 >= w->grid_ny ? w->grid_ny - 1 : cy1;
    for (int cy = cy0; cy <= cy1; cy++)
        for (int cx = cx0; cx <= cx1; cx++) {
            const int c = cy * w->grid_nx + cx;
            for (int k = w->cell_start[c]; k < w->cell_start[c + 1]; k++) {
                const int i = w->cell_items[k];
                if (touches(w, i, lo, hi)) {
                    if (out && n < cap) out[n] = i;
                    n++;
                }
            }
        }
    for (int k = 0; k < w->large_n; k++) {
        const int i = w->large_list[k];
        if (touches(w, i, lo, hi)) {
            if (out && n < cap) out[n] = i;
            n++;
        }
    }
    if (out) qsort(out, (size_t)(n < cap ? n : cap), sizeof *out, cmp_i32);
    return n;
}
