/* Porosity and permeability per element (seed 000 §3.6):
 * - exact solid areas: disc-triangle (whole disc, whole triangle, half and quarter discs on an
 *   edge and a right-angle corner, Monte Carlo for random cases) and polygon-triangle clipping;
 * - the element solid areas of a packing sum to the grains' area (exact method, 1e-10);
 * - the thesis's pixellation converges to the exact areas as the resolution grows (error and
 *   cost printed: the data of the accuracy-against-cost chart);
 * - Kozeny-Carman interpolation ends at FLUID_PERM_LOW (e = 0.01) and FLUID_PERM_HIGH (e = 99);
 * - the 2D -> 3D porosity mapping sends hexagonal discs (n = 1 - pi / (2 sqrt 3)) to FCC
 *   spheres (n = 1 - pi / (3 sqrt 2)) exactly. */
#include "harness.h"
#include "fluid/darcy/darcy_world.h"
#include "fluid/darcy/darcy_internal.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define PI 3.141592653589793

static uint64_t rng = 88172645463325252ull;
static double urand(void) {
    rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

static int test_disc_triangle_area(void) {
    pl_vec2 t[3] = {{0, 0}, {10, 0}, {0, 10}};
    ENSURE_REL(pl_fl_tri_disc_area(t, (pl_vec2){2, 2}, 1), PI, 1e-13);      /* whole disc */
    ENSURE_REL(pl_fl_tri_disc_area(t, (pl_vec2){3, 3}, 100), 50, 1e-13);    /* whole triangle */
    ENSURE_REL(pl_fl_tri_disc_area(t, (pl_vec2){5, 0}, 1), PI / 2, 1e-13);  /* half disc on an edge */
    ENSURE_REL(pl_fl_tri_disc_area(t, (pl_vec2){0, 0}, 1), PI / 4, 1e-13);  /* quarter at the right angle */
    ENSURE_NEAR(pl_fl_tri_disc_area(t, (pl_vec2){20, 20}, 1), 0, 1e-15);    /* apart */
    /* random cases against Monte Carlo (400k samples: 3 sigma about 0.5% of the box) */
    for (int k = 0; k < 20; k++) {
        pl_vec2 a = {urand(), urand()}, b = {a.x + 0.2 + urand(), a.y + urand() * 0.3}, c = {a.x + urand() * 0.5, a.y + 0.3 + urand()};
        pl_vec2 tri[3] = {a, b, c};
        pl_vec2 ctr = {a.x + urand(), a.y + urand()};
        double r = 0.1 + 0.6 * urand();
        double exact = pl_fl_tri_disc_area(tri, ctr, r);
        double lx = ctr.x - r, ly = ctr.y - r, box = 4 * r * r;
        int hit = 0, N = 400000;
        for (int s = 0; s < N; s++) {
            pl_vec2 p = {lx + 2 * r * urand(), ly + 2 * r * urand()};
            if ((p.x - ctr.x) * (p.x - ctr.x) + (p.y - ctr.y) * (p.y - ctr.y) > r * r) continue;
            double d1 = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
            double d2 = (c.x - b.x) * (p.y - b.y) - (c.y - b.y) * (p.x - b.x);
            double d3 = (a.x - c.x) * (p.y - c.y) - (a.y - c.y) * (p.x - c.x);
            if (d1 >= 0 && d2 >= 0 && d3 >= 0) hit++;
        }
        ENSURE_NEAR(exact, box * hit / N, 0.006 * box);
    }
    return 0;
}

static int test_polygon_triangle_area(void) {
    pl_vec2 t[3] = {{0, 0}, {1, 0}, {0, 1}};
    pl_vec2 sq[4] = {{0.5, 0}, {1.5, 0}, {1.5, 1}, {0.5, 1}};
    ENSURE_REL(pl_fl_tri_poly_area(t, sq, 4), 0.125, 1e-13);
    pl_vec2 big[4] = {{-1, -1}, {2, -1}, {2, 2}, {-1, 2}};
    ENSURE_REL(pl_fl_tri_poly_area(t, big, 4), 0.5, 1e-13);
    pl_vec2 far[4] = {{3, 3}, {4, 3}, {4, 4}, {3, 4}};
    ENSURE(pl_fl_tri_poly_area(t, far, 4) == 0);
    return 0;
}

static int test_maps(void) {
    pl_fl_params p = pl_fl_default_params();
    p.perm_low = 1e-4;
    p.perm_high = 2;
    ENSURE_REL(pl_fl_kc_map(&p, 0.01), 1e-4, 1e-12);
    ENSURE_REL(pl_fl_kc_map(&p, 99), 2, 1e-12);
    ENSURE(pl_fl_kc_map(&p, 0.5) > pl_fl_kc_map(&p, 0.4));
    double hex = 1 - PI / (2 * sqrt(3.0)), fcc = 1 - PI / (3 * sqrt(2.0));
    ENSURE_NEAR(pl_fl_porosity_3d(hex), fcc, 1e-14);
    ENSURE_NEAR(pl_fl_porosity_3d(1.0), 1.0, 1e-14);
    return 0;
}

/* A packing of discs and rotated squares over a 12 x 8 quad. */
static pl_world *packing(void) {
    pl_world_def wd = pl_default_world_def();
    pl_world *w = pl_world_create(&wd);
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){1.2, 0};
    q.corners[2] = (pl_vec2){1.2, 0.8};
    q.corners[3] = (pl_vec2){0, 0.8};
    q.ndivx = 12;
    q.ndivy = 8;
    pl_world_add_fluid_quad(w, &q);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){1.2, 0}, 0.8);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0.8}, (pl_vec2){1.2, 0.8}, 0);
    pl_world_set_flag(w, "FLUID_PERM", 1);
    pl_material_def md = pl_default_material_def();
    md.name = "g";
    md.density = 2650;
    md.kn = 1e6;
    pl_world_add_material(w, &md);
    for (int j = 0; j < 14; j++)
        for (int i = 0; i < 22; i++) {
            pl_body_def b = pl_default_body_def();
            b.material = 0;
            b.motion = PL_MOTION_FIXED;
            pl_vec2 c = {0.04 + i * 0.052 + (j % 2) * 0.02, 0.04 + j * 0.052};
            if ((i + j) % 3 == 0) {
                pl_vec2 v[4];
                double a = 0.3 * i + 0.7 * j;
                for (int k = 0; k < 4; k++) v[k] = (pl_vec2){c.x + 0.022 * cos(a + k * PI / 2), c.y + 0.022 * sin(a + k * PI / 2)};
                b.shape = PL_SHAPE_POLYGON;
                b.vertices = v;
                b.vertex_count = 4;
                pl_world_add_body(w, &b);
            } else {
                b.shape = PL_SHAPE_DISC;
                b.position = c;
                b.radius = 0.018 + 0.006 * ((i * 7 + j * 3) % 4) / 3.0;
                pl_world_add_body(w, &b);
            }
        }
    return w;
}

static int test_exact_vs_pixels(void) {
    pl_world *w = packing();
    ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
    int ne = pl_world_fluid_triangle_count(w);
    double *exact = malloc(sizeof(double) * ne), *pix = malloc(sizeof(double) * ne);
    pl_world_fluid_copy_element_field(w, PL_FLUID_SOLID_AREA, exact, ne);
    double total = 0, grains = 0;
    for (int e = 0; e < ne; e++) total += exact[e];
    for (int i = 0; i < pl_world_body_count(w); i++) {
        pl_body_info bi;
        pl_world_body_info(w, i, &bi);
        grains += bi.area;
    }
    fprintf(stderr, "  exact: element solid areas sum to %.15g, grains %.15g\n", total, grains);
    ENSURE_REL(total, grains, 1e-10);
    struct pl_fluid *f = pl__darcy(w);
    double mean_area = 0.96 / ne, prev = 1e300;
    fprintf(stderr, "  pixellation (seed 000 §3.6) against exact clipping: pixels, mean |error| / element area, time per update\n");
    for (int res = 4; res <= 64; res *= 2) {
        pl_world_set_flag(w, "FLUID_POROSITY_METHOD", 1);
        pl_world_set_flag(w, "FLUID_PIXELS", res);
        double t0 = f->stats.t_porosity;
        ENSURE(pl_world_fluid_advance(w, 1e-3) == PL_OK);
        double t1 = f->stats.t_porosity - t0;
        pl_world_fluid_copy_element_field(w, PL_FLUID_SOLID_AREA, pix, ne);
        double err = 0;
        for (int e = 0; e < ne; e++) err += fabs(pix[e] - exact[e]);
        err /= ne * mean_area;
        fprintf(stderr, "  %4d  %.3e  %.2e s\n", res, err, t1);
        ENSURE(err < prev);
        prev = err;
    }
    ENSURE(prev < 0.01);
    pl_world_set_flag(w, "FLUID_POROSITY_METHOD", 0);
    double t0 = f->stats.t_porosity;
    ENSURE(pl_world_fluid_advance(w, 1e-3) == PL_OK);
    fprintf(stderr, "  exact clipping: %.2e s per update (%d elements, %d grains)\n", f->stats.t_porosity - t0, ne,
            pl_world_body_count(w));
    /* permeability: every element's conductivity lies within [LOW, HIGH] and falls with solids */
    double *k = malloc(sizeof(double) * ne);
    pl_world_fluid_copy_element_field(w, PL_FLUID_PERM_X, k, ne);
    for (int e = 0; e < ne; e++) ENSURE(k[e] >= 0.001 * (1 - 1e-12) && k[e] <= 5.0 * (1 + 1e-12));
    free(k);
    free(exact);
    free(pix);
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(test_disc_triangle_area);
    RUN(test_polygon_triangle_area);
    RUN(test_maps);
    RUN(test_exact_vs_pixels);
    return pl_test_report();
}
