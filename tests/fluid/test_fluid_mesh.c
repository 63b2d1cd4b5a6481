/* Fluid meshing (seed 000 §3.5): quads into four triangles per cell with the bilinear map
 * (eqs. 3.6-3.7), merged quads without hanging nodes (§3.5.2), invalid quads refused.
 * A hanging node is a node lying strictly inside an edge of a triangle it is not a vertex of:
 * checked by brute force over all nodes and edges, independent of the mesher's own search.
 * Every edge must be used by two triangles in opposite directions or lie on the outer boundary
 * (checked by probing both sides of its midpoint against the quads). */
#include "harness.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include <stdlib.h>
#include <string.h>

typedef struct { pl_vec2 c[4]; int nx, ny; } quad;

static pl_world *make(const quad *q, int nq) {
    pl_world_def wd = pl_default_world_def();
    pl_world *w = pl_world_create(&wd);
    for (int k = 0; k < nq; k++) {
        pl_fluid_quad_def d = pl_default_fluid_quad_def();
        memcpy(d.corners, q[k].c, sizeof d.corners);
        d.ndivx = q[k].nx;
        d.ndivy = q[k].ny;
        d.id = 1000 + k;
        if (pl_world_add_fluid_quad(w, &d) < 0) {
            fprintf(stderr, "add quad %d: %s\n", k, pl_world_last_error(w));
            pl_world_destroy(&w);
            return NULL;
        }
    }
    return w;
}

static int inside_quad(const quad *q, pl_vec2 p) {
    for (int k = 0; k < 4; k++) {
        pl_vec2 a = q->c[k], b = q->c[(k + 1) % 4];
        if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < 0) return 0;
    }
    return 1;
}
static int inside_any(const quad *q, int nq, pl_vec2 p) {
    for (int k = 0; k < nq; k++)
        if (inside_quad(&q[k], p)) return 1;
    return 0;
}
static double quad_area(const quad *q) {
    double a = 0;
    for (int k = 0; k < 4; k++) a += q->c[k].x * q->c[(k + 1) % 4].y - q->c[(k + 1) % 4].x * q->c[k].y;
    return 0.5 * a;
}

/* Returns the number of defects found; prints them. */
static int check_conforming(pl_world *w, const quad *q, int nq, double *area_out) {
    pl_world_prepare(w); /* queries read only: build first */
    int nn = pl_world_fluid_node_count(w), ne = pl_world_fluid_triangle_count(w);
    pl_vec2 *xy = malloc(sizeof(pl_vec2) * nn);
    int *t = malloc(sizeof(int) * 3 * ne);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_nodes(w, xy, nn);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_triangles(w, t, ne);
    double scale = 0, area = 0;
    for (int i = 0; i < nn; i++) scale = fmax(scale, fmax(fabs(xy[i].x), fabs(xy[i].y)));
    int defects = 0;
    for (int e = 0; e < ne; e++) {
        pl_vec2 a = xy[t[3 * e]], b = xy[t[3 * e + 1]], c = xy[t[3 * e + 2]];
        double A = 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
        if (!(A > 0)) { fprintf(stderr, "triangle %d not counter-clockwise (area %g)\n", e, A); defects++; }
        area += A;
        for (int k = 0; k < 3; k++) {
            int ia = t[3 * e + k], ib = t[3 * e + (k + 1) % 3];
            pl_vec2 p = xy[ia], r = xy[ib];
            double dx = r.x - p.x, dy = r.y - p.y, L = hypot(dx, dy);
            /* hanging nodes: brute force */
            for (int n = 0; n < nn; n++) {
                if (n == ia || n == ib) continue;
                double u = ((xy[n].x - p.x) * dx + (xy[n].y - p.y) * dy) / (L * L);
                double dist = fabs((xy[n].x - p.x) * dy - (xy[n].y - p.y) * dx) / L;
                if (u > 1e-9 && u < 1 - 1e-9 && dist < 1e-9 * scale) {
                    fprintf(stderr, "hanging node %d (%g %g) on edge %d-%d\n", n, xy[n].x, xy[n].y, ia, ib);
                    defects++;
                }
            }
            /* edge use: count the reverse edge */
            int rev = 0, same = 0;
            for (int f = 0; f < ne; f++)
                for (int m = 0; m < 3; m++) {
                    int fa = t[3 * f + m], fb = t[3 * f + (m + 1) % 3];
                    if (fa == ib && fb == ia) rev++;
                    if (fa == ia && fb == ib) same++;
                }
            if (same != 1 || rev > 1) { fprintf(stderr, "edge %d-%d used %d/%d times\n", ia, ib, same, rev); defects++; }
            if (rev == 0) { /* must be on the outer boundary: outside on the right, inside on the left */
                pl_vec2 mid = {0.5 * (p.x + r.x), 0.5 * (p.y + r.y)};
                double h = 1e-6 * L;
                pl_vec2 out = {mid.x + h * dy / L, mid.y - h * dx / L}, in = {mid.x - h * dy / L, mid.y + h * dx / L};
                if (inside_any(q, nq, out) || !inside_any(q, nq, in)) {
                    fprintf(stderr, "edge %d-%d (%g %g)-(%g %g) used once but not on the outer boundary\n", ia, ib, p.x, p.y,
                            r.x, r.y);
                    defects++;
                }
            }
        }
    }
    *area_out = area;
    free(xy);
    free(t);
    return defects;
}

static int test_single_quad(void) {
    /* a skewed convex quad: (nx+1)(ny+1) + nx ny nodes, 4 nx ny triangles, exact area */
    quad q = {{{0, 0}, {3, 0.5}, {2.5, 2}, {-0.5, 1.5}}, 5, 3};
    pl_world *w = make(&q, 1);
    ENSURE(w);
    pl_world_prepare(w); /* queries read only: build first */
    ENSURE(pl_world_fluid_node_count(w) == 6 * 4 + 5 * 3);
    pl_world_prepare(w); /* queries read only: build first */
    ENSURE(pl_world_fluid_triangle_count(w) == 4 * 5 * 3);
    double area;
    ENSURE(check_conforming(w, &q, 1, &area) == 0);
    ENSURE_REL(area, quad_area(&q), 1e-12);
    /* centre node of the first cell = average of its four corners (bilinear map at the cell centre) */
    pl_vec2 xy[64];
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_nodes(w, xy, 64);
    pl_vec2 c = xy[24]; /* first centre node follows the 24 corner nodes */
    pl_vec2 avg = {(xy[0].x + xy[1].x + xy[6].x + xy[7].x) / 4, (xy[0].y + xy[1].y + xy[6].y + xy[7].y) / 4};
    ENSURE_NEAR(c.x, avg.x, 1e-12);
    ENSURE_NEAR(c.y, avg.y, 1e-12);
    pl_world_destroy(&w);
    return 0;
}

static int test_dam_quads(void) {
    /* seed 000 Appendix C.1: three quads A, B, C with 4 x 4 divisions of different sizes */
    quad q[3] = {{{{50, 50}, {250, 50}, {250, 300}, {50, 300}}, 4, 4},
                 {{{250, 50}, {350, 50}, {350, 100}, {250, 100}}, 4, 4},
                 {{{350, 50}, {480, 50}, {480, 300}, {350, 300}}, 4, 4}};
    pl_world *w = make(q, 3);
    ENSURE(w);
    double area;
    pl_world_prepare(w); /* queries read only: build first */
    int nn = pl_world_fluid_node_count(w);
    ENSURE(nn > 0);
    ENSURE(check_conforming(w, q, 3, &area) == 0);
    ENSURE_REL(area, quad_area(&q[0]) + quad_area(&q[1]) + quad_area(&q[2]), 1e-12);
    /* merged: the 3 quads alone have 3 x 41 nodes; the corners (250, 50) and (350, 50) are
       shared, B's face nodes at y = 62.5, 75, 87.5, 100 hang on A's and C's faces and are
       resolved by re-meshing, which adds no node */
    ENSURE(nn == 3 * 41 - 2);
    pl_world_prepare(w); /* queries read only: build first */
    fprintf(stderr, "  dam mesh: %d nodes, %d triangles\n", nn, pl_world_fluid_triangle_count(w));
    pl_validation("fluid.mesh_conforming", "meshes of several quads: no hanging node", "conformity", "exact",
                  "conforming (dam: %d nodes, %d triangles)", nn, pl_world_fluid_triangle_count(w));
    pl_world_destroy(&w);
    return 0;
}

static int test_incompatible_faces(void) {
    /* pairs of quads whose common faces have different divisions, a T-junction of three
       quads, and a skewed neighbour sharing a slanted face */
    quad a[3] = {{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 3, 7},
                 {{{1, 0}, {2, 0}, {2, 1}, {1, 1}}, 5, 4},
                 {{{0, 1}, {2, 1}, {2, 1.5}, {0, 1.5}}, 11, 2}};
    pl_world *w = make(a, 3);
    ENSURE(w);
    double area;
    ENSURE(check_conforming(w, a, 3, &area) == 0);
    ENSURE_REL(area, 2 * 1 + 2 * 0.5, 1e-12);
    pl_world_destroy(&w);
    quad b[2] = {{{{0, 0}, {2, 0}, {1.6, 1.2}, {0.1, 1}}, 4, 3}, {{{2, 0}, {3, 0.3}, {3.1, 1.4}, {1.6, 1.2}}, 3, 5}};
    w = make(b, 2);
    ENSURE(w);
    ENSURE(check_conforming(w, b, 2, &area) == 0);
    ENSURE_REL(area, quad_area(&b[0]) + quad_area(&b[1]), 1e-12);
    pl_world_destroy(&w);
    return 0;
}

static int expect_error(const quad *q, int nq, const char *needle) {
    pl_world_def wd = pl_default_world_def();
    pl_world *w = pl_world_create(&wd);
    int fail_at = -1;
    for (int k = 0; k < nq && fail_at < 0; k++) {
        pl_fluid_quad_def d = pl_default_fluid_quad_def();
        memcpy(d.corners, q[k].c, sizeof d.corners);
        d.ndivx = q[k].nx;
        d.ndivy = q[k].ny;
        if (pl_world_add_fluid_quad(w, &d) < 0) fail_at = k;
    }
    if (fail_at < 0 && pl_world_prepare(w) == PL_OK && pl_world_fluid_node_count(w) > 0) {
        fprintf(stderr, "expected an error containing '%s'\n", needle);
        pl_world_destroy(&w);
        return 1;
    }
    const char *msg = pl_world_last_error(w);
    int ok = strstr(msg, needle) != NULL;
    if (!ok) fprintf(stderr, "message '%s' lacks '%s'\n", msg, needle);
    pl_world_destroy(&w);
    return ok ? 0 : 1;
}

static int test_invalid_quads(void) {
    quad cw = {{{0, 0}, {0, 1}, {1, 1}, {1, 0}}, 2, 2};
    ENSURE(expect_error(&cw, 1, "clockwise") == 0);
    quad dart = {{{0, 0}, {2, 0}, {0.5, 0.5}, {0, 2}}, 2, 2};
    ENSURE(expect_error(&dart, 1, "not convex") == 0);
    quad flat = {{{0, 0}, {1, 0}, {2, 0}, {0, 1}}, 2, 2};
    ENSURE(expect_error(&flat, 1, "not convex") == 0);
    quad zero = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0, 2};
    ENSURE(expect_error(&zero, 1, "ndivx") == 0);
    quad ov[2] = {{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 2, 2}, {{{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}}, 2, 2}};
    ENSURE(expect_error(ov, 2, "overlap") == 0);
    return 0;
}

int main(void) {
    RUN(test_single_quad);
    RUN(test_dam_quads);
    RUN(test_incompatible_faces);
    RUN(test_invalid_quads);
    return pl_test_report();
}
