/* Label placement: pixel-space obstacles and the collision test of rotated label boxes. */
#include "label_place.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void pl_obstacles_init(pl_obstacles *o) { memset(o, 0, sizeof *o); }

void pl_obstacles_free(pl_obstacles *o) {
    free(o->verts); free(o->first); free(o->circ); free(o->circ_r);
    free(o->boxes); free(o->pts); free(o->pt_tag); free(o->grain); free(o->grain_r);
    memset(o, 0, sizeof *o);
}

void pl_obstacles_clear(pl_obstacles *o) {
    o->vert_count = o->poly_count = o->circ_count = o->box_count = o->pt_count = 0;
    o->grain_count = 0;
    o->failed = 0;
}

static int grow(void **p, int *cap, int need, size_t size) {
    if (need <= *cap) return 0;
    int nc = *cap ? *cap : 16;
    while (nc < need) nc *= 2;
    void *q = realloc(*p, (size_t)nc * size);
    if (!q) return -1;
    *p = q;
    *cap = nc;
    return 0;
}

void pl_obstacles_add_polygon(pl_obstacles *o, const pl_vec2 *px, int n) {
    if (n < 2) return;
    int pc = o->poly_cap;
    if (grow((void **)&o->verts, &o->vert_cap, o->vert_count + n, sizeof *o->verts) ||
        grow((void **)&o->first, &pc, o->poly_count + 2, sizeof *o->first)) {
        o->failed = 1;
        return;
    }
    o->poly_cap = pc;
    if (o->poly_count == 0) o->first[0] = 0;
    memcpy(o->verts + o->vert_count, px, (size_t)n * sizeof *px);
    o->vert_count += n;
    o->first[++o->poly_count] = o->vert_count;
}

void pl_obstacles_add_circle(pl_obstacles *o, pl_vec2 c, double r) {
    int cap = o->circ_cap;
    if (grow((void **)&o->circ, &cap, o->circ_count + 1, sizeof *o->circ)) { o->failed = 1; return; }
    int cap2 = o->circ_cap;
    if (grow((void **)&o->circ_r, &cap2, o->circ_count + 1, sizeof *o->circ_r)) { o->failed = 1; return; }
    o->circ_cap = cap < cap2 ? cap : cap2;
    o->circ[o->circ_count] = c;
    o->circ_r[o->circ_count++] = r;
}

void pl_obstacles_add_grain(pl_obstacles *o, pl_vec2 c, double r) {
    int cap = o->grain_cap;
    if (grow((void **)&o->grain, &cap, o->grain_count + 1, sizeof *o->grain)) { o->failed = 1; return; }
    int cap2 = o->grain_cap;
    if (grow((void **)&o->grain_r, &cap2, o->grain_count + 1, sizeof *o->grain_r)) { o->failed = 1; return; }
    o->grain_cap = cap < cap2 ? cap : cap2;
    o->grain[o->grain_count] = c;
    o->grain_r[o->grain_count++] = r;
}

void pl_obstacles_add_box(pl_obstacles *o, pl_label_box b) {
    if (grow((void **)&o->boxes, &o->box_cap, o->box_count + 1, sizeof *o->boxes)) {
        o->failed = 1;
        return;
    }
    o->boxes[o->box_count++] = b;
}

void pl_obstacles_add_point(pl_obstacles *o, pl_vec2 p, int tag) {
    int cap = o->pt_cap;
    if (grow((void **)&o->pts, &cap, o->pt_count + 1, sizeof *o->pts)) { o->failed = 1; return; }
    int cap2 = o->pt_cap;
    if (grow((void **)&o->pt_tag, &cap2, o->pt_count + 1, sizeof *o->pt_tag)) { o->failed = 1; return; }
    o->pt_cap = cap < cap2 ? cap : cap2;
    o->pts[o->pt_count] = p;
    o->pt_tag[o->pt_count++] = tag;
}

/* Point inside a convex outline (either orientation; a 2-point outline is a thin band). */
static int in_convex(const pl_vec2 *v, int n, pl_vec2 p, double pad) {
    if (n == 2) {
        double dx = v[1].x - v[0].x, dy = v[1].y - v[0].y, l2 = dx * dx + dy * dy;
        double t = l2 > 0 ? ((p.x - v[0].x) * dx + (p.y - v[0].y) * dy) / l2 : 0.0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        return hypot(p.x - v[0].x - t * dx, p.y - v[0].y - t * dy) <= pad + 2.0;
    }
    double area = 0.0;
    for (int i = 0; i < n; i++) {
        const pl_vec2 *a = &v[i], *b = &v[(i + 1) % n];
        area += a->x * b->y - b->x * a->y;
    }
    double sgn = area >= 0 ? 1.0 : -1.0;
    for (int i = 0; i < n; i++) {
        const pl_vec2 *a = &v[i], *b = &v[(i + 1) % n];
        double ex = b->x - a->x, ey = b->y - a->y, len = hypot(ex, ey);
        if (len <= 0) continue;
        double cr = sgn * (ex * (p.y - a->y) - ey * (p.x - a->x)) / len;
        if (cr < -pad) return 0;
    }
    return 1;
}

int pl_obstacles_contain(const pl_obstacles *o, pl_vec2 p) {
    for (int k = 0; k < o->poly_count; k++)
        if (in_convex(o->verts + o->first[k], o->first[k + 1] - o->first[k], p, 0.0)) return 1;
    for (int k = 0; k < o->circ_count; k++)
        if (hypot(p.x - o->circ[k].x, p.y - o->circ[k].y) <= o->circ_r[k]) return 1;
    return 0;
}

/* Point in box coordinates (u along the box, v across). */
static void to_box(pl_label_box b, pl_vec2 p, double *u, double *v) {
    double c = cos(b.angle), s = sin(b.angle), dx = p.x - b.c.x, dy = -(p.y - b.c.y);
    *u = dx * c + dy * s;
    *v = -dx * s + dy * c;
}

static pl_vec2 from_box(pl_label_box b, double u, double v) {
    double c = cos(b.angle), s = sin(b.angle);
    return (pl_vec2){b.c.x + u * c - v * s, b.c.y - (u * s + v * c)};
}

static int in_box(pl_label_box b, pl_vec2 p, double pad) {
    double u, v;
    to_box(b, p, &u, &v);
    return fabs(u) <= b.hw + pad && fabs(v) <= b.hh + pad;
}

static int boxes_overlap(pl_label_box a, pl_label_box b, double pad) {
    /* separating axes of two rectangles */
    pl_label_box r[2] = {a, b};
    for (int k = 0; k < 2; k++) {
        for (int ax = 0; ax < 2; ax++) {
            double ang = r[k].angle + ax * 1.5707963267948966;
            double dx = cos(ang), dy = sin(ang);
            double lo[2], hi[2];
            for (int m = 0; m < 2; m++) {
                lo[m] = INFINITY; hi[m] = -INFINITY;
                for (int cu = -1; cu <= 1; cu += 2)
                    for (int cv = -1; cv <= 1; cv += 2) {
                        pl_vec2 q = from_box(r[m], cu * (r[m].hw + (m ? pad : 0)), cv * (r[m].hh + (m ? pad : 0)));
                        double pr = q.x * dx - q.y * dy;
                        if (pr < lo[m]) lo[m] = pr;
                        if (pr > hi[m]) hi[m] = pr;
                    }
            }
            if (hi[0] < lo[1] || hi[1] < lo[0]) return 0;
        }
    }
    return 1;
}

int pl_obstacles_hit(const pl_obstacles *o, pl_label_box b, double pad, int own_tag) {
    /* the box's corners, edge midpoints and centre inside an outline or circle */
    for (int cu = -2; cu <= 2; cu++)
        for (int cv = -1; cv <= 1; cv++) {
            pl_vec2 q = from_box(b, 0.5 * cu * (b.hw + pad), cv * (b.hh + pad));
            for (int k = 0; k < o->poly_count; k++)
                if (in_convex(o->verts + o->first[k], o->first[k + 1] - o->first[k], q, 0.0))
                    return 1;
            for (int k = 0; k < o->circ_count; k++)
                if (hypot(q.x - o->circ[k].x, q.y - o->circ[k].y) <= o->circ_r[k]) return 1;
        }
    /* an outline's vertices inside the box (a thin wall crossing it) */
    for (int k = 0; k < o->vert_count; k++)
        if (in_box(b, o->verts[k], pad)) return 1;
    for (int k = 0; k < o->poly_count; k++)
        if (o->first[k + 1] - o->first[k] == 2) { /* segment walls: sample along them */
            pl_vec2 a = o->verts[o->first[k]], c = o->verts[o->first[k] + 1];
            double len = hypot(c.x - a.x, c.y - a.y);
            int n = (int)(len / fmax(2.0, b.hh)) + 1;
            for (int i = 0; i <= n; i++) {
                double t = (double)i / n;
                if (in_box(b, (pl_vec2){a.x + t * (c.x - a.x), a.y + t * (c.y - a.y)}, pad + 2.0)) return 1;
            }
        }
    for (int k = 0; k < o->box_count; k++)
        if (boxes_overlap(o->boxes[k], b, pad)) return 1;
    for (int k = 0; k < o->pt_count; k++)
        if (o->pt_tag[k] != own_tag && in_box(b, o->pts[k], pad)) return 1;
    return 0;
}

int pl_obstacles_grains(const pl_obstacles *o, pl_label_box b, double pad) {
    int n = 0;
    for (int k = 0; k < o->grain_count; k++) {
        double u, v;
        to_box(b, o->grain[k], &u, &v);
        double du = fmax(fabs(u) - b.hw - pad, 0.0), dv = fmax(fabs(v) - b.hh - pad, 0.0);
        if (du * du + dv * dv <= o->grain_r[k] * o->grain_r[k]) n++;
    }
    return n;
}
