/* Unit tests of the renderer's pieces: camera fit, colour maps, marching triangles, nice
 * levels, layer parsing, draw-list storage, mean stress, PNG round trip, image comparison. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "backend_cairo.h"
#include "colormap.h"
#include "draw_world.h"
#include "image_compare.h"
#include "isolines.h"
#include "porelab/fluid.h"

static int test_camera_fit(void) {
    pl_px_rect area = {0, 0, 400, 400};
    pl_camera c = pl_camera_fit((pl_vec2){0, 0}, (pl_vec2){2, 1}, 400, 400, area, 0.05);
    /* width 2 + 2 x 0.1 margin = 2.2 m over 400 px */
    ENSURE_NEAR(c.scale, 400.0 / 2.2, 1e-9);
    pl_vec2 mid = pl_camera_to_px(&c, (pl_vec2){1, 0.5});
    ENSURE_NEAR(mid.x, 200.0, 1e-9);
    ENSURE_NEAR(mid.y, 200.0, 1e-9);
    /* y up: a higher world point is higher on screen (smaller pixel y) */
    pl_vec2 lo = pl_camera_to_px(&c, (pl_vec2){1, 0}), hi = pl_camera_to_px(&c, (pl_vec2){1, 1});
    ENSURE(hi.y < lo.y);
    ENSURE_NEAR(lo.y - hi.y, c.scale * 1.0, 1e-9); /* same scale on both axes */
    /* all of the bounds inside the image, with the margin on the limiting side */
    pl_vec2 left = pl_camera_to_px(&c, (pl_vec2){0, 0.5});
    ENSURE_NEAR(left.x, 0.1 * c.scale, 1e-9);
    /* round trip */
    pl_vec2 p = {0.37, 0.81}, q = pl_camera_to_world(&c, pl_camera_to_px(&c, p));
    ENSURE_NEAR(q.x, p.x, 1e-12);
    ENSURE_NEAR(q.y, p.y, 1e-12);
    /* a tall scene in a wide image with a reserved right band: limited by height, centred */
    pl_px_rect a2 = {0, 40, 700, 600};
    pl_camera t = pl_camera_fit((pl_vec2){-1, 0}, (pl_vec2){1, 4}, 800, 600, a2, 0.0);
    ENSURE_NEAR(t.scale, 560.0 / 4.0, 1e-9);
    pl_vec2 top = pl_camera_to_px(&t, (pl_vec2){0, 4});
    ENSURE_NEAR(top.y, 40.0, 1e-9);
    ENSURE_NEAR(top.x, 350.0, 1e-9);
    /* degenerate bounds give a finite 1 m view */
    pl_camera d = pl_camera_fit((pl_vec2){3, 3}, (pl_vec2){3, 3}, 100, 100, area, 0.05);
    ENSURE(isfinite(d.scale) && d.scale > 0.0);
    return 0;
}

static double lightness(pl_rgba c) {
    double lab[3];
    pl_srgb_to_oklab(&c, lab);
    return lab[0];
}

static int test_colormaps(void) {
    /* sequential: lightness linear in t (0.30 -> 0.94), steps perceptually even */
    double prev[3] = {0, 0, 0}, dmin = 1e9, dmax = 0;
    for (int i = 0; i <= 32; i++) {
        double t = i / 32.0, lab[3];
        pl_rgba c = pl_colormap_eval(PL_CMAP_SEQUENTIAL, t);
        pl_srgb_to_oklab(&c, lab);
        ENSURE_NEAR(lab[0], 0.30 + 0.64 * t, 0.006);
        if (i > 0) {
            double de = sqrt(pow(lab[0] - prev[0], 2) + pow(lab[1] - prev[1], 2) + pow(lab[2] - prev[2], 2));
            if (de < dmin) dmin = de;
            if (de > dmax) dmax = de;
        }
        memcpy(prev, lab, sizeof prev);
    }
    fprintf(stderr, "  sequential: OKLab step between 1/32 samples %.4f .. %.4f\n", dmin, dmax);
    ENSURE(dmax < 1.6 * dmin); /* even steps (viridis itself is within about 1.5) */
    /* starts violet-blue (b < 0), ends yellow (b > 0, high L) */
    double lab0[3], lab1[3];
    pl_rgba c0 = pl_colormap_eval(PL_CMAP_SEQUENTIAL, 0.0), c1 = pl_colormap_eval(PL_CMAP_SEQUENTIAL, 1.0);
    pl_srgb_to_oklab(&c0, lab0);
    pl_srgb_to_oklab(&c1, lab1);
    ENSURE(lab0[2] < -0.05 && lab1[2] > 0.1);
    /* diverging: light neutral middle, symmetric lightness, blue low end, red high end */
    double labm[3];
    pl_rgba cm = pl_colormap_eval(PL_CMAP_DIVERGING, 0.5);
    pl_srgb_to_oklab(&cm, labm);
    ENSURE(labm[0] > 0.93);
    ENSURE(hypot(labm[1], labm[2]) < 0.03);
    for (int i = 0; i <= 16; i++) {
        double t = i / 32.0;
        ENSURE_NEAR(lightness(pl_colormap_eval(PL_CMAP_DIVERGING, t)),
                    lightness(pl_colormap_eval(PL_CMAP_DIVERGING, 1.0 - t)), 0.006);
    }
    pl_rgba lo = pl_colormap_eval(PL_CMAP_DIVERGING, 0.0), hi = pl_colormap_eval(PL_CMAP_DIVERGING, 1.0);
    ENSURE(lo.b > lo.r && hi.r > hi.b);
    /* values map through the range; clamped outside; NaN grey */
    pl_rgba v = pl_colormap_value(PL_CMAP_SEQUENTIAL, 5.0, 0.0, 10.0);
    pl_rgba e = pl_colormap_eval(PL_CMAP_SEQUENTIAL, 0.5);
    ENSURE(v.r == e.r && v.g == e.g && v.b == e.b);
    pl_rgba over = pl_colormap_value(PL_CMAP_SEQUENTIAL, 50.0, 0.0, 10.0);
    ENSURE(over.r == c1.r && over.g == c1.g);
    pl_rgba nanc = pl_colormap_eval(PL_CMAP_SEQUENTIAL, NAN);
    ENSURE(nanc.r == 0.5f && nanc.g == 0.5f);
    return 0;
}

/* Structured mesh on [0,1]x[0,1], nx x ny cells, alternating diagonals, optional jitter of
 * interior nodes (deterministic). */
static int make_mesh(int nx, int ny, double jitter, pl_vec2 *nodes, int *tris) {
    for (int j = 0; j <= ny; j++)
        for (int i = 0; i <= nx; i++) {
            double x = (double)i / nx, y = (double)j / ny;
            if (i > 0 && i < nx && j > 0 && j < ny) {
                x += jitter / nx * sin(12.9898 * i + 78.233 * j);
                y += jitter / ny * cos(39.3468 * i + 11.135 * j);
            }
            nodes[j * (nx + 1) + i] = (pl_vec2){x, y};
        }
    int t = 0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
            int q[6];
            if ((i + j) % 2 == 0) { int q0[6] = {a, b, d, a, d, c}; memcpy(q, q0, sizeof q); }
            else { int q0[6] = {a, b, c, b, d, c}; memcpy(q, q0, sizeof q); }
            memcpy(tris + 6 * t, q, sizeof q);
            t++;
        }
    return 2 * t;
}

static int test_isolines_linear(void) {
    enum { NX = 12, NY = 9 };
    pl_vec2 nodes[(NX + 1) * (NY + 1)];
    int tris[NX * NY * 6];
    double val[(NX + 1) * (NY + 1)];
    int nt = make_mesh(NX, NY, 0.25, nodes, tris);
    /* f = 2x + 3y: the level c isoline is the straight line 2x + 3y = c */
    for (int i = 0; i < (NX + 1) * (NY + 1); i++) val[i] = 2.0 * nodes[i].x + 3.0 * nodes[i].y;
    double level = 2.2;
    pl_isolines iso;
    pl_isolines_init(&iso);
    ENSURE(pl_isolines_extract(nodes, (NX + 1) * (NY + 1), tris, nt, val, &level, 1, &iso) == 0);
    ENSURE(iso.line_count == 1); /* one connected polyline */
    ENSURE(iso.closed[0] == 0);
    double len = 0.0;
    for (int k = iso.starts[0]; k < iso.starts[1]; k++) {
        pl_vec2 p = iso.points[k];
        ENSURE_NEAR(2.0 * p.x + 3.0 * p.y, level, 1e-12);
        if (k > iso.starts[0]) len += hypot(p.x - iso.points[k - 1].x, p.y - iso.points[k - 1].y);
    }
    /* ends on the boundary: (0, c/3) and (1, (c-2)/3); exact chord length */
    pl_vec2 a = iso.points[iso.starts[0]], b = iso.points[iso.starts[1] - 1];
    if (a.x > b.x) { pl_vec2 t = a; a = b; b = t; }
    ENSURE_NEAR(a.x, 0.0, 1e-12);
    ENSURE_NEAR(a.y, 2.2 / 3.0, 1e-12);
    ENSURE_NEAR(b.x, 1.0, 1e-12);
    ENSURE_NEAR(b.y, 0.2 / 3.0, 1e-12);
    ENSURE_NEAR(len, hypot(1.0, 2.0 / 3.0), 1e-12);
    pl_isolines_free(&iso);
    return 0;
}

static int test_isolines_circle_and_nodes(void) {
    enum { N = 24 };
    pl_vec2 nodes[(N + 1) * (N + 1)];
    int tris[N * N * 6];
    double val[(N + 1) * (N + 1)];
    int nt = make_mesh(N, N, 0.0, nodes, tris);
    /* f = (x-.5)^2 + (y-.5)^2: level 0.09 is a circle of radius 0.3 (closed loop). P1
     * interpolation error of a quadratic is at most h^2/8 x |f''| = h^2 / 4 in value,
     * i.e. about h^2 / (4 x 2 r) in radius. */
    for (int i = 0; i < (N + 1) * (N + 1); i++)
        val[i] = pow(nodes[i].x - 0.5, 2) + pow(nodes[i].y - 0.5, 2);
    double level = 0.09, h = 1.0 / N;
    pl_isolines iso;
    pl_isolines_init(&iso);
    ENSURE(pl_isolines_extract(nodes, (N + 1) * (N + 1), tris, nt, val, &level, 1, &iso) == 0);
    ENSURE(iso.line_count == 1);
    ENSURE(iso.closed[0] == 1);
    for (int k = iso.starts[0]; k < iso.starts[1]; k++) {
        double r = hypot(iso.points[k].x - 0.5, iso.points[k].y - 0.5);
        ENSURE_NEAR(r, 0.3, 2.0 * h * h / (4.0 * 0.6));
    }
    pl_isolines_free(&iso);
    /* f = x with the level exactly on a column of nodes: one straight line x = 0.5 through
     * N + 1 nodes, no repeated points */
    for (int i = 0; i < (N + 1) * (N + 1); i++) val[i] = nodes[i].x;
    level = 0.5;
    pl_isolines_init(&iso);
    ENSURE(pl_isolines_extract(nodes, (N + 1) * (N + 1), tris, nt, val, &level, 1, &iso) == 0);
    ENSURE(iso.line_count == 1);
    ENSURE(iso.starts[1] - iso.starts[0] == N + 1);
    for (int k = iso.starts[0]; k < iso.starts[1]; k++) ENSURE_NEAR(iso.points[k].x, 0.5, 1e-15);
    pl_isolines_free(&iso);
    /* out-of-range triangle indices are refused */
    int bad[3] = {0, 1, 999};
    pl_isolines_init(&iso);
    ENSURE(pl_isolines_extract(nodes, 3, bad, 1, val, &level, 1, &iso) == -1);
    pl_isolines_free(&iso);
    return 0;
}

static int test_nice_levels(void) {
    double lv[16], step;
    int n = pl_nice_levels(0.0, 1.0, 5, lv, 16, &step);
    ENSURE(n == 4);
    ENSURE_NEAR(step, 0.2, 1e-15);
    ENSURE_NEAR(lv[0], 0.2, 1e-12);
    ENSURE_NEAR(lv[3], 0.8, 1e-12);
    n = pl_nice_levels(-1234.0, 5678.0, 8, lv, 16, &step);
    ENSURE_NEAR(step, 1000.0, 1e-9);
    ENSURE(n == 7 && lv[0] == -1000.0 && lv[1] == 0.0);
    ENSURE(pl_nice_levels(1.0, 1.0, 5, lv, 16, &step) == 0);
    ENSURE_NEAR(pl_nice_number(0.37, 1), 0.5, 1e-15);
    ENSURE_NEAR(pl_nice_number(0.13, 1), 0.1, 1e-15);
    return 0;
}

static int test_parse_layers(void) {
    unsigned m = PL_LAYERS_DEFAULT;
    char err[512];
    ENSURE(pl_render_parse_layers("bodies,forces", &m, err, sizeof err) == 0);
    ENSURE(m == (PL_LAYER_BODIES | PL_LAYER_FORCES));
    ENSURE(pl_render_parse_layers("+mesh,-forces", &m, err, sizeof err) == 0);
    ENSURE(m == (PL_LAYER_BODIES | PL_LAYER_MESH));
    ENSURE(pl_render_parse_layers("all,-title", &m, err, sizeof err) == 0);
    ENSURE((m & PL_LAYER_TANGENTIAL) && !(m & PL_LAYER_TITLE));
    ENSURE(pl_render_parse_layers("none", &m, err, sizeof err) == 0 && m == 0);
    unsigned keep = m = PL_LAYER_BODIES;
    ENSURE(pl_render_parse_layers("bodies,presure", &m, err, sizeof err) == -1);
    ENSURE(m == keep); /* unchanged on error */
    ENSURE(strstr(err, "presure") && strstr(err, "pressure") && strstr(err, "isolines"));
    ENSURE(strcmp(pl_render_layer_name(11), "tangential") == 0);
    return 0;
}

static int test_draw_list(void) {
    pl_draw_list a, b;
    pl_draw_list_init(&a);
    pl_draw_list_init(&b);
    pl_style st = pl_style_fill(pl_rgb(1, 0, 0));
    pl_dl_circle(&a, PL_SPACE_WORLD, (pl_vec2){1, 2}, 0.5, &st);
    pl_dl_text(&a, PL_SPACE_PIXEL, (pl_vec2){3, 4}, "abc", 12.0f, 0, 0.0f, pl_rgb(0, 0, 0), NULL);
    pl_vec2 tri[3] = {{0, 0}, {1, 0}, {0, 1}};
    pl_rgba col[3] = {pl_rgb(1, 0, 0), pl_rgb(0, 1, 0), pl_rgb(0, 0, 1)};
    pl_dl_triangles_begin(&b, PL_SPACE_WORLD);
    pl_dl_triangle_add(&b, tri, col);
    pl_dl_triangle_add(&b, tri, col);
    pl_dl_text(&b, PL_SPACE_PIXEL, (pl_vec2){5, 6}, "xyz", 12.0f, 0, 0.0f, pl_rgb(0, 0, 0), NULL);
    pl_draw_list_append(&a, &b);
    ENSURE(a.prim_count == 4);
    const pl_prim *t = &a.prims[2];
    ENSURE(t->kind == PL_PRIM_TRIANGLES && t->count == 6 && t->color_first == 0);
    ENSURE(a.colors[t->color_first + 4].g == 1.0f);
    ENSURE(a.points[t->first + 1].x == 1.0);
    ENSURE(strcmp(a.text + a.prims[3].text, "xyz") == 0);
    ENSURE(a.points[a.prims[3].first].y == 6.0);
    pl_draw_list_clear(&a);
    ENSURE(a.prim_count == 0 && a.prim_cap > 0); /* memory kept for reuse */
    pl_draw_list_free(&a);
    pl_draw_list_free(&b);
    return 0;
}

/* Mean stress (Love-Weber, compression positive): a disc of radius R squeezed by two equal
 * and opposite normal forces F at the ends of a diameter has sigma = 2 F R / (2 pi R^2). */
static int test_mean_stress(void) {
    pl_render_scene s;
    pl_render_scene_init(&s);
    const double R = 0.2, F = 1000.0;
    pl_body_info b;
    memset(&b, 0, sizeof b);
    b.shape = PL_SHAPE_DISC;
    b.radius = R;
    b.area = 3.14159265358979323846 * R * R;
    b.position = (pl_vec2){0, 0};
    pl_render_scene_add_body(&s, &b, NULL, 0);  /* 0: the squeezed disc */
    b.position = (pl_vec2){2 * R, 0};
    pl_render_scene_add_body(&s, &b, NULL, 0);  /* 1: right neighbour */
    b.position = (pl_vec2){-2 * R, 0};
    pl_render_scene_add_body(&s, &b, NULL, 0);  /* 2: left neighbour */
    pl_contact_info c;
    memset(&c, 0, sizeof c);
    c.a = 0; c.b = 1; c.point = (pl_vec2){R, 0}; c.normal = (pl_vec2){1, 0}; c.fn = F;
    pl_render_scene_add_contact(&s, &c);
    c.a = 0; c.b = 2; c.point = (pl_vec2){-R, 0}; c.normal = (pl_vec2){-1, 0}; c.fn = F;
    pl_render_scene_add_contact(&s, &c);
    ENSURE(pl_render_scene_stress(&s) == 0);
    double expect = 2.0 * F * R / (2.0 * b.area);
    ENSURE_REL(s.stress[0], expect, 1e-12);
    ENSURE_REL(s.stress[1], F * R / (2.0 * b.area), 1e-12); /* one contact each */
    ENSURE(s.stress[0] > 0.0);
    /* a tangential force through the contact point adds nothing to the trace here (t . l = 0) */
    s.contacts[0].ft = 500.0;
    pl_render_scene_stress(&s);
    ENSURE_REL(s.stress[0], expect, 1e-12);
    /* tension (negative fn, cohesive) gives negative mean stress */
    s.contacts[0].fn = s.contacts[1].fn = -F;
    s.contacts[0].ft = 0.0;
    pl_render_scene_stress(&s);
    ENSURE_REL(s.stress[0], -expect, 1e-12);
    pl_render_scene_free(&s);
    return 0;
}

static int test_png_roundtrip_and_compare(void) {
    pl_image a = {64, 48, calloc(64 * 48 * 4, 1)}, b = {0, 0, NULL};
    for (int i = 0; i < 64 * 48; i++) {
        a.rgba[4 * i] = (uint8_t)(i * 7);
        a.rgba[4 * i + 1] = (uint8_t)(i / 3);
        a.rgba[4 * i + 2] = (uint8_t)(255 - i);
        a.rgba[4 * i + 3] = 255;
    }
    char err[512];
    const char *path = PL_RENDER_OUT_DIR "/roundtrip.png";
    ENSURE(pl_png_write(path, &a, 1, 0, err, sizeof err) == 0);
    ENSURE(pl_png_read(path, &b, err, sizeof err) == 0);
    ENSURE(b.width == 64 && b.height == 48);
    ENSURE(memcmp(a.rgba, b.rgba, 64 * 48 * 4) == 0);
    pl_compare_tolerance tol = pl_default_compare_tolerance();
    pl_compare_result r = pl_image_compare(&a, &b, &tol, NULL);
    ENSURE(r.match && r.differing == 0 && r.max_channel_diff == 0);
    /* one pixel far off among 3072: 0.033 % differs -> within 0.1 % */
    b.rgba[4 * 100] ^= 0x80;
    r = pl_image_compare(&a, &b, &tol, NULL);
    ENSURE(r.match && r.differing == 1 && r.max_channel_diff == 128);
    /* every pixel off by 8 (= tolerance): equal; by 9: all differ */
    for (int i = 0; i < 64 * 48; i++) b.rgba[4 * i + 2] = (uint8_t)(a.rgba[4 * i + 2] ^ 0);
    b.rgba[4 * 100] = a.rgba[4 * 100];
    for (int i = 0; i < 64 * 48; i++) b.rgba[4 * i + 3] = 247;
    r = pl_image_compare(&a, &b, &tol, NULL);
    ENSURE(r.match && r.max_channel_diff == 8);
    for (int i = 0; i < 64 * 48; i++) b.rgba[4 * i + 3] = 246;
    r = pl_image_compare(&a, &b, &tol, NULL);
    ENSURE(!r.match && r.differing == 64 * 48);
    /* a size change never matches */
    pl_image c = {32, 48, a.rgba};
    r = pl_image_compare(&a, &c, &tol, NULL);
    ENSURE(!r.match && !r.same_size);
    ENSURE(pl_png_read(PL_RENDER_OUT_DIR "/does-not-exist.png", &c, err, sizeof err) == -1);
    ENSURE(strstr(err, "does-not-exist.png") != NULL);
    pl_image_free(&a);
    pl_image_free(&b);
    return 0;
}

/* Round-off drawn as zero (docs/rendering.md, house style rule 3): below the absolute floor
 * (0.01 Pa) or 1e-6 of the field's span, whichever is larger; values above stay. */
static int test_denoise_scales_with_range(void) {
    double big[4] = {0.0, 2e6, 1.5, 2.5}; /* span 2e6 Pa: threshold 2 Pa */
    double small[4] = {0.0, 100.0, 0.005, 0.02}; /* span 100 Pa: the 0.01 Pa floor */
    double neg[4] = {-1e6, 1e6, -1.9, 2.1};      /* signed, span 2e6 Pa */
    double *cases[3] = {big, small, neg};
    const double expect[3][4] = {{0.0, 2e6, 0.0, 2.5}, {0.0, 100.0, 0.0, 0.02}, {-1e6, 1e6, 0.0, 2.1}};
    for (int k = 0; k < 3; k++) {
        pl_render_scene s;
        memset(&s, 0, sizeof s);
        s.fluid_values = cases[k];
        s.fluid_node_count = 4;
        s.fluid_field = PL_FLUID_EXCESS_PRESSURE;
        pl_render_scene_denoise_fluid(&s);
        for (int i = 0; i < 4; i++) ENSURE_NEAR(cases[k][i], expect[k][i], 0.0);
    }
    return 0;
}

int main(void) {
    RUN(test_camera_fit);
    RUN(test_colormaps);
    RUN(test_isolines_linear);
    RUN(test_isolines_circle_and_nodes);
    RUN(test_nice_levels);
    RUN(test_parse_layers);
    RUN(test_draw_list);
    RUN(test_mean_stress);
    RUN(test_png_roundtrip_and_compare);
    RUN(test_denoise_scales_with_range);
    return pl_test_report();
}
