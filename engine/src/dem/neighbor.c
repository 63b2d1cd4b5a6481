/* Broadphase and Verlet neighbour list with a skin (seed 003 §2.2.4.5, "boxes" sized to the
 * largest body, with the DNTOL margin playing the role of the skin).
 *
 * Bodies up to a few typical grain sizes go into a uniform grid whose cell is the largest of
 * their diameters plus the skin, so each body only meets the 3x3 cells around it and the cost
 * grows linearly with the number of bodies. Larger bodies (walls, blocks, containers) are
 * tested against every other body. The list is rebuilt when some body has moved (or turned)
 * by more than half the skin since the last build. Pairs are kept sorted by (a, b); the
 * contact history (shear spring, previous overlap area) is carried over by merging. */
#include "core/alloc.h"
#include "dem/world_internal.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void pl__neighbor_mark_dirty(pl_world *w) { w->need_rebuild = 1; }

static int grow_i32(int32_t **p, int *cap, int need) {
    if (need <= *cap) return 1;
    int c = *cap ? *cap : 64;
    while (c < need) c *= 2;
    void *q = pl_realloc(*p, (size_t)c * sizeof **p);
    if (!q) return 0;
    *p = q;
    *cap = c;
    return 1;
}

static int grow_pairs(pl_pair **p, int *cap, int need) {
    if (need <= *cap) return 1;
    int c = *cap ? *cap : 256;
    while (c < need) c *= 2;
    void *q = pl_realloc(*p, (size_t)c * sizeof **p);
    if (!q) return 0;
    *p = q;
    *cap = c;
    return 1;
}

static int cmp_double(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Splits bodies into grid bodies and large bodies; sets the cell size. */
static int classify(pl_world *w) {
    const int n = w->n;
    if (n > w->class_cap) {
        int c = w->class_cap ? w->class_cap : 64;
        while (c < n) c *= 2;
        uint8_t *a = pl_realloc(w->is_large, (size_t)c);
        if (!a) return 0;
        w->is_large = a;
        int32_t *b = pl_realloc(w->large_list, (size_t)c * sizeof *b);
        if (!b) return 0;
        w->large_list = b;
        w->class_cap = c;
    }
    /* typical size: median radius of the non-segment bodies */
    double *r = pl_malloc((size_t)(n > 0 ? n : 1) * sizeof *r);
    if (!r) return 0;
    int m = 0;
    for (int i = 0; i < n; i++)
        if (w->shape[i] != PL_SHAPE_SEGMENT) r[m++] = w->radius[i];
    double med = 0;
    if (m > 0) {
        qsort(r, (size_t)m, sizeof *r, cmp_double);
        med = r[m / 2];
    }
    pl_free(r);
    const double limit = 4.0 * med;
    double rmax = 0, rmin = INFINITY;
    w->large_n = 0;
    for (int i = 0; i < n; i++) {
        const int large = w->shape[i] == PL_SHAPE_SEGMENT || w->radius[i] > limit;
        w->is_large[i] = (uint8_t)large;
        if (large)
            w->large_list[w->large_n++] = i;
        else
            rmax = fmax(rmax, w->radius[i]);
        if (w->shape[i] != PL_SHAPE_SEGMENT && w->motion[i] == PL_MOTION_DYNAMIC) rmin = fmin(rmin, w->radius[i]);
    }
    if (w->def.skin > 0)
        w->skin = w->def.skin;
    else
        w->skin = isfinite(rmin) ? 0.2 * rmin : 0.2 * med;
    w->cell_size = 2 * rmax + w->skin;
    return 1;
}

static uint8_t pair_kind(const pl_world *w, int a, int b, uint8_t *swapped) {
    const int sa = w->shape[a], sb = w->shape[b];
    *swapped = 0;
    if (w->motion[a] != PL_MOTION_DYNAMIC && w->motion[b] != PL_MOTION_DYNAMIC) return PL_PAIR_NONE;
    if (w->removed[a] || w->removed[b]) return PL_PAIR_NONE; /* worn away (heat.c) */
    if (sa == PL_SHAPE_DISC && sb == PL_SHAPE_DISC) return PL_PAIR_DISC_DISC;
    if (sa == PL_SHAPE_SEGMENT && sb == PL_SHAPE_SEGMENT) return PL_PAIR_NONE;
    if (sa == PL_SHAPE_DISC && sb == PL_SHAPE_SEGMENT) return PL_PAIR_DISC_SEGMENT;
    if (sa == PL_SHAPE_SEGMENT && sb == PL_SHAPE_DISC) {
        *swapped = 1;
        return PL_PAIR_DISC_SEGMENT;
    }
    if (sa == PL_SHAPE_POLYGON && sb == PL_SHAPE_POLYGON) return PL_PAIR_POLY_POLY;
    if (sa == PL_SHAPE_POLYGON && sb == PL_SHAPE_DISC) return PL_PAIR_POLY_DISC;
    if (sa == PL_SHAPE_DISC && sb == PL_SHAPE_POLYGON) {
        *swapped = 1;
        return PL_PAIR_POLY_DISC;
    }
    if (sa == PL_SHAPE_POLYGON && sb == PL_SHAPE_SEGMENT) return PL_PAIR_POLY_SEGMENT;
    *swapped = 1; /* segment a, polygon b */
    return PL_PAIR_POLY_SEGMENT;
}

/* Distance from p to the segment [a, b]. */
static double seg_distance(pl_vec2 p, pl_vec2 a, pl_vec2 b) {
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double l2 = ex * ex + ey * ey;
    double t = l2 > 0 ? ((p.x - a.x) * ex + (p.y - a.y) * ey) / l2 : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    return hypot(p.x - (a.x + t * ex), p.y - (a.y + t * ey));
}

static int near_enough(const pl_world *w, int a, int b) {
    const double skin = w->skin;
    if (w->shape[b] == PL_SHAPE_SEGMENT || w->shape[a] == PL_SHAPE_SEGMENT) {
        const int s = w->shape[b] == PL_SHAPE_SEGMENT ? b : a, o = s == b ? a : b;
        const pl_vec2 *v = &w->verts_world[w->vert_offset[s]];
        return seg_distance(w->pos[o], v[0], v[1]) < w->radius[o] + skin;
    }
    const double dx = w->pos[b].x - w->pos[a].x, dy = w->pos[b].y - w->pos[a].y;
    const double r = w->radius[a] + w->radius[b] + skin;
    if (!(dx * dx + dy * dy < r * r)) return 0;
    if (w->shape[a] + w->shape[b] != PL_SHAPE_DISC + PL_SHAPE_POLYGON) return 1;
    /* disc and convex polygon: the bounding circle of a long polygon (a wall slab, a lid)
       takes in every disc within its half-length. The disc is out of reach when its centre
       lies beyond some edge's line by r + skin or more (separating axis; a lower bound of the
       gap, so no pair that can touch before the next build is dropped: between builds every
       point of an outline moves by less than half the skin, turning included). */
    const int d = w->shape[a] == PL_SHAPE_DISC ? a : b, q = d == a ? b : a;
    const pl_vec2 c = w->pos[d], *v = &w->verts_world[w->vert_offset[q]];
    const int n = w->vert_count[q];
    const double reach = w->radius[d] + skin;
    for (int i = 0; i < n; i++) {
        const pl_vec2 p = v[i], q1 = v[i + 1 < n ? i + 1 : 0], e = {q1.x - p.x, q1.y - p.y};
        const double out = e.y * (c.x - p.x) - e.x * (c.y - p.y); /* |e| x distance outside (CCW) */
        if (out > 0 && out * out >= reach * reach * (e.x * e.x + e.y * e.y)) return 0;
    }
    return 1;
}

static void sort_small(int32_t *v, int n) {
    for (int i = 1; i < n; i++) {
        int32_t x = v[i];
        int j = i - 1;
        while (j >= 0 && v[j] > x) {
            v[j + 1] = v[j];
            j--;
        }
        v[j + 1] = x;
    }
}

static pl_status rebuild(pl_world *w) {
    const int n = w->n;
    if (w->classify_dirty || w->n > w->class_cap) {
        if (!classify(w)) return pl__error(w, PL_ERR_NOMEM, "neighbour list: out of memory");
        w->classify_dirty = 0;
    }
    /* grid over the grid bodies */
    double lox = INFINITY, loy = INFINITY, hix = -INFINITY, hiy = -INFINITY;
    for (int i = 0; i < n; i++) {
        if (w->is_large[i]) continue;
        lox = fmin(lox, w->pos[i].x);
        loy = fmin(loy, w->pos[i].y);
        hix = fmax(hix, w->pos[i].x);
        hiy = fmax(hiy, w->pos[i].y);
    }
    double h = w->cell_size > 0 ? w->cell_size : 1;
    int nx = 1, ny = 1;
    if (isfinite(lox)) {
        /* cap the cell count at a few per body so scattered scenes do not waste memory */
        for (;;) {
            double fx = floor((hix - lox) / h) + 1, fy = floor((hiy - loy) / h) + 1;
            if (fx * fy <= 4.0 * n + 1024) {
                nx = (int)fx;
                ny = (int)fy;
                break;
            }
            h *= 1.5;
        }
    } else {
        lox = loy = 0;
    }
    const int ncell = nx * ny;
    w->grid_lo_x = lox, w->grid_lo_y = loy, w->grid_h = h, w->grid_nx = nx, w->grid_ny = ny, w->grid_n = n;
    int tmp_cap = w->cell_cap;
    if (!grow_i32(&w->cell_start, &tmp_cap, ncell + 1)) return pl__error(w, PL_ERR_NOMEM, "neighbour list: out of memory");
    w->cell_cap = tmp_cap;
    if (!grow_i32(&w->cell_items, &w->cell_items_cap, n) || !grow_i32(&w->body_cell, &w->body_cell_cap, n) ||
        !grow_i32(&w->cursor, &w->cursor_cap, ncell) || !grow_i32(&w->cand, &w->cand_cap, n))
        return pl__error(w, PL_ERR_NOMEM, "neighbour list: out of memory");
    memset(w->cell_start, 0, (size_t)(ncell + 1) * sizeof *w->cell_start);
    for (int i = 0; i < n; i++) {
        if (w->is_large[i]) {
            w->body_cell[i] = -1;
            continue;
        }
        int cx = (int)((w->pos[i].x - lox) / h), cy = (int)((w->pos[i].y - loy) / h);
        cx = cx < 0 ? 0 : (cx >= nx ? nx - 1 : cx);
        cy = cy < 0 ? 0 : (cy >= ny ? ny - 1 : cy);
        w->body_cell[i] = cy * nx + cx;
        w->cell_start[w->body_cell[i] + 1]++;
    }
    for (int c = 0; c < ncell; c++) w->cell_start[c + 1] += w->cell_start[c];
    /* stable fill: bodies appear in index order within each cell */
    int32_t *cursor = w->cursor;
    memcpy(cursor, w->cell_start, (size_t)ncell * sizeof *cursor);
    for (int i = 0; i < n; i++)
        if (w->body_cell[i] >= 0) w->cell_items[cursor[w->body_cell[i]]++] = i;

    /* new pair list into the scratch buffer, in (a, b) order, history merged from the old list */
    int np = 0, old = 0;
    for (int a = 0; a < n; a++) {
        int nc = 0;
        if (!w->is_large[a]) {
            const int c = w->body_cell[a], cx = c % nx, cy = c / nx;
            for (int dy = -1; dy <= 1; dy++) {
                const int yy = cy + dy;
                if (yy < 0 || yy >= ny) continue;
                for (int dx = -1; dx <= 1; dx++) {
                    const int xx = cx + dx;
                    if (xx < 0 || xx >= nx) continue;
                    const int cc = yy * nx + xx;
                    for (int k = w->cell_start[cc]; k < w->cell_start[cc + 1]; k++) {
                        const int b = w->cell_items[k];
                        if (b > a && near_enough(w, a, b)) w->cand[nc++] = b;
                    }
                }
            }
            for (int k = 0; k < w->large_n; k++) {
                const int b = w->large_list[k];
                if (b > a && near_enough(w, a, b)) w->cand[nc++] = b;
            }
        } else {
            for (int b = a + 1; b < n; b++)
                if (near_enough(w, a, b)) w->cand[nc++] = b;
        }
        sort_small(w->cand, nc);
        if (!grow_pairs(&w->pairs_scratch, &w->pair_scratch_cap, np + nc))
            return pl__error(w, PL_ERR_NOMEM, "neighbour list: out of memory");
        for (int k = 0; k < nc; k++) {
            const int b = w->cand[k];
            uint8_t swapped;
            const uint8_t kind = pair_kind(w, a, b, &swapped);
            if (kind == PL_PAIR_NONE) continue;
            pl_pair *p = &w->pairs_scratch[np++];
            memset(p, 0, sizeof *p);
            p->a = a;
            p->b = b;
            p->kind = kind;
            p->swapped = swapped;
            p->params = w->material[a] * w->material_count + w->material[b];
            {
                /* dashpots: from restitution with the pair's reduced mass, or given directly */
                const pl_pair_params *pp = &w->pair_params[p->params];
                const double s = w->inv_mass[a] + w->inv_mass[b];
                const double meff = s > 0 ? 1.0 / s : 0;
                const double cn = pp->zeta >= 0 ? 2 * pp->zeta * sqrt(meff * pp->kn) : pp->cn;
                p->cs = pp->zeta >= 0 ? (pp->kn > 0 ? cn * pp->ks / pp->kn : 0) : pp->cs;
                /* the normal dashpot sees the previous half step's velocity (seed 003
                   eq. 2.31): F = -c v(t - dt/2) = -c v + (c dt/2) a, i.e. the pair moves as if
                   its mass were m* - c dt/2, a damping ratio larger by ~zeta omega dt/2 (-0.75 %
                   on e at zeta = 0.5, 0.01 x critical). The dashpot used, c' = c (sqrt(1 + q^2)
                   - q) with q = c dt / (4 m*), solves c' / sqrt(m* - c' dt/2) = c / sqrt(m*):
                   the damping ratio, and so the restitution, of the continuous law
                   (docs/method-dem.md, Time step). */
                const double q = meff > 0 && w->dt > 0 ? cn * w->dt / (4 * meff) : 0;
                p->cn = cn * (sqrt(1 + q * q) - q);
            }
            while (old < w->pair_n && (w->pairs[old].a < a || (w->pairs[old].a == a && w->pairs[old].b < b))) old++;
            if (old < w->pair_n && w->pairs[old].a == a && w->pairs[old].b == b) {
                const pl_pair *q = &w->pairs[old];
                p->fs = q->fs;
                p->mr = q->mr;
                p->fn = q->fn;
                p->ft = q->ft;
                p->overlap = q->overlap;
                p->area_prev = q->area_prev;
                p->touching = q->touching;
                p->elastic = q->elastic;
                p->point = q->point;
                p->normal = q->normal;
            }
        }
    }
    /* swap buffers */
    pl_pair *t = w->pairs;
    w->pairs = w->pairs_scratch;
    w->pairs_scratch = t;
    int tc = w->pair_cap;
    w->pair_cap = w->pair_scratch_cap;
    w->pair_scratch_cap = tc;
    w->pair_n = np;
    for (int i = 0; i < n; i++) {
        w->pos_at_build[i] = w->pos[i];
        w->angle_at_build[i] = w->angle[i];
    }
    w->need_rebuild = 0;
    w->rebuilds++;
    return PL_OK;
}

/* The integrator flags a rebuild when some body has moved (or turned) by more than half the
   skin since the last build (see integrate.c); setters flag it when they move bodies. */
pl_status pl__neighbor_update(pl_world *w) { return w->need_rebuild ? rebuild(w) : PL_OK; }
