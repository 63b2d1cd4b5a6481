/* OpenGL backend, headless through OSMesa (llvmpipe):
 * 1. image-diff against its own goldens tests/golden/gl/<case>.png (the render cases of
 *    tests/render/render_scenes.c; tolerance of image_compare.h: channel 8, 0.1 % pixels);
 *    negative tests prove a changed colour, a missing layer and a moved body are caught;
 * 2. cross-check against the cairo backend on the same draw lists: PSNR >= PL_GL_PSNR_MIN
 *    (documented in docs/classroom.md, "Two renderers, one picture") - and a missing layer
 *    drops it below;
 * 3. unit checks of the rasterization: exact coverage of pixel-aligned rectangles, disc area,
 *    single coverage of translucent strokes, Gouraud interpolation, text width against cairo.
 * `test_gl_render --update` rewrites the GL goldens (never run by ctest). */
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "backend_cairo.h"
#include "gl_psnr.h"
#include "image_compare.h"
#include "osmesa_context.h"
#include "render_scenes.h"

/* Lowest PSNR accepted between GL and cairo renders of the same list, dB. Measured on the
 * render cases (Mesa 22.3 llvmpipe, 1 sample = the default, every edge antialiased in the
 * shaders; cairo 1.16), draw lists and cairo backend of 1 Dec 2026 17:45 UTC: 30.9 dB
 * (combined: fields, isoline labels on boxes, forces, text) .. 49.5 dB (bodies); the
 * differences are glyph rasterization (cairo's glyphs are a little lighter), the unsmoothed
 * outer edges of field meshes, and the colour interpolation of cairo's mesh patches. (The
 * earlier 4x multisampled backend against the same cairo images: 30.9 .. 49.3 dB.) Removing
 * the force layer gives 23.5 dB, so 28 dB separates "same picture" from "a layer is
 * missing" with some room for library versions. */
#define PL_GL_PSNR_MIN 28.0

static pl_osmesa *gl;

static int gl_case(int i, const render_tweak *tw, pl_image *img)
{
    pl_draw_list dl;
    pl_draw_list_init(&dl);
    char err[512];
    int rc = render_case(i, tw, &dl, err, sizeof err);
    if (rc == 0) rc = pl_osmesa_rasterize(gl, &dl, img, err, sizeof err);
    if (rc) fprintf(stderr, "%s: %s\n", render_case_at(i)->name, err);
    pl_draw_list_free(&dl);
    return rc;
}

static int cairo_case(int i, const render_tweak *tw, pl_image *img)
{
    pl_draw_list dl;
    pl_draw_list_init(&dl);
    char err[512];
    int rc = render_case(i, tw, &dl, err, sizeof err);
    if (rc == 0) rc = pl_cairo_rasterize(&dl, img, err, sizeof err);
    if (rc) fprintf(stderr, "%s: %s\n", render_case_at(i)->name, err);
    pl_draw_list_free(&dl);
    return rc;
}

static int find_case(const char *name)
{
    for (int i = 0; i < render_case_count(); i++)
        if (strcmp(render_case_at(i)->name, name) == 0) return i;
    return -1;
}

/* 1 match, 0 mismatch, -1 error */
static int compare_golden(int i, const render_tweak *tw, const char *suffix)
{
    const char *name = render_case_at(i)->name;
    char out[1024], golden[1024], diff[1024], msg[1024], err[512];
    snprintf(out, sizeof out, "%s/gl_%s%s.png", PL_GL_OUT_DIR, name, suffix);
    snprintf(golden, sizeof golden, "%s/gl/%s.png", PL_GOLDEN_DIR, name);
    snprintf(diff, sizeof diff, "%s/gl_%s%s.diff.png", PL_GL_OUT_DIR, name, suffix);
    pl_image img = {0, 0, NULL};
    int rc = gl_case(i, tw, &img);
    if (rc == 0) rc = pl_png_write(out, &img, 1, 0, err, sizeof err);
    pl_image_free(&img);
    if (rc) return -1;
    pl_compare_tolerance tol = pl_default_compare_tolerance();
    rc = pl_png_compare(golden, out, &tol, diff, NULL, msg, sizeof msg);
    fprintf(stderr, "  %-16s%-12s %s: %s\n", name, suffix,
            rc == 1 ? "match" : (rc == 0 ? "DIFFERS" : "ERROR"), msg);
    return rc;
}

static int test_goldens_match(void)
{
    int bad = 0;
    for (int i = 0; i < render_case_count(); i++)
        if (compare_golden(i, NULL, "") != 1) bad++;
    ENSURE(bad == 0);
    return 0;
}

static int test_changes_detected(void)
{
    int forces = find_case("forces");
    ENSURE(forces >= 0);
    render_tweak colour = {1, 0, 0}, layer = {0, PL_LAYER_FORCES, 0}, shift = {0, 0, 1};
    ENSURE(compare_golden(forces, &colour, "-colour") == 0);
    ENSURE(compare_golden(forces, &layer, "-nolayer") == 0);
    ENSURE(compare_golden(forces, &shift, "-shifted") == 0);
    return 0;
}

static int test_agrees_with_cairo(void)
{
    int bad = 0;
    double worst = INFINITY;
    for (int i = 0; i < render_case_count(); i++) {
        pl_image a = {0, 0, NULL}, b = {0, 0, NULL};
        if (gl_case(i, NULL, &a) || cairo_case(i, NULL, &b)) {
            bad++;
        } else {
            double p = pl_psnr(&a, &b);
            if (p < worst) worst = p;
            fprintf(stderr, "  %-16s GL vs cairo PSNR %.2f dB (minimum %.1f)\n",
                    render_case_at(i)->name, p, PL_GL_PSNR_MIN);
            if (!(p >= PL_GL_PSNR_MIN)) bad++;
        }
        pl_image_free(&a);
        pl_image_free(&b);
    }
    fprintf(stderr, "  worst case %.2f dB\n", worst);
    ENSURE(bad == 0);
    return 0;
}

/* The cross-check can fail: GL without the force layer vs cairo with it. */
static int test_cross_check_detects_missing_layer(void)
{
    int forces = find_case("forces");
    ENSURE(forces >= 0);
    render_tweak layer = {0, PL_LAYER_FORCES, 0};
    pl_image a = {0, 0, NULL}, b = {0, 0, NULL};
    ENSURE(gl_case(forces, &layer, &a) == 0);
    ENSURE(cairo_case(forces, NULL, &b) == 0);
    double p = pl_psnr(&a, &b);
    fprintf(stderr, "  forces without the layer vs cairo: %.2f dB\n", p);
    pl_image_free(&a);
    pl_image_free(&b);
    ENSURE(p < PL_GL_PSNR_MIN);
    return 0;
}

/* ------------------------------------------------------------ unit checks */

static void small_list(pl_draw_list *dl, int w, int h)
{
    pl_draw_list_init(dl);
    dl->camera = pl_camera_fit((pl_vec2){0, 0}, (pl_vec2){w, h}, w, h, (pl_px_rect){0, 0, w, h}, 0);
    dl->background = pl_rgb(1, 1, 1);
}

static const uint8_t *px(const pl_image *img, int x, int y)
{
    return img->rgba + 4 * ((size_t)y * (size_t)img->width + (size_t)x);
}

/* An opaque pixel-aligned rectangle covers exactly its pixels. */
static int test_rectangle_exact(void)
{
    pl_draw_list dl;
    small_list(&dl, 64, 48);
    pl_vec2 r[4] = {{10, 8}, {30, 8}, {30, 20}, {10, 20}};
    pl_style st = pl_style_fill(pl_rgb(0, 0, 1));
    pl_dl_polygon(&dl, PL_SPACE_PIXEL, r, 4, &st);
    pl_image img = {0, 0, NULL};
    char err[256];
    ENSURE(pl_osmesa_rasterize(gl, &dl, &img, err, sizeof err) == 0);
    int inside = 0, wrong = 0;
    for (int y = 0; y < 48; y++)
        for (int x = 0; x < 64; x++) {
            const uint8_t *p = px(&img, x, y);
            int in = x >= 10 && x < 30 && y >= 8 && y < 20;
            inside += in;
            if (in ? !(p[0] == 0 && p[1] == 0 && p[2] == 255) : !(p[0] == 255 && p[2] == 255))
                wrong++;
        }
    pl_image_free(&img);
    pl_draw_list_free(&dl);
    ENSURE(inside == 240);
    ENSURE(wrong == 0);
    return 0;
}

/* The antialiased disc's total coverage equals its area (pi r^2) within 0.5 %. */
static int test_disc_area(void)
{
    pl_draw_list dl;
    small_list(&dl, 100, 100);
    pl_style st = pl_style_fill(pl_rgb(0, 0, 0));
    double r = 31.3;
    pl_dl_circle(&dl, PL_SPACE_PIXEL, (pl_vec2){50.2, 49.7}, r, &st);
    pl_image img = {0, 0, NULL};
    char err[256];
    ENSURE(pl_osmesa_rasterize(gl, &dl, &img, err, sizeof err) == 0);
    double cover = 0;
    for (int y = 0; y < 100; y++)
        for (int x = 0; x < 100; x++) cover += (255 - px(&img, x, y)[0]) / 255.0;
    pl_image_free(&img);
    pl_draw_list_free(&dl);
    ENSURE_REL(cover, M_PI * r * r, 0.005);
    return 0;
}

/* A translucent polyline that doubles back on itself is drawn once per pixel (cairo strokes
 * one path): where its pieces overlap the colour is the single-coverage blend. */
static int test_translucent_stroke_single_coverage(void)
{
    pl_draw_list dl;
    small_list(&dl, 80, 40);
    pl_vec2 p[3] = {{10, 20}, {70, 20}, {20, 20.5}};
    pl_dl_polyline(&dl, PL_SPACE_PIXEL, p, 3, (pl_rgba){0, 0, 0, 0.5f}, 8.0f);
    pl_image img = {0, 0, NULL};
    char err[256];
    ENSURE(pl_osmesa_rasterize(gl, &dl, &img, err, sizeof err) == 0);
    int v = px(&img, 40, 20)[0]; /* covered by both pieces */
    pl_image_free(&img);
    pl_draw_list_free(&dl);
    ENSURE_NEAR(v, 127.5, 2.0); /* double coverage would give 64 */
    return 0;
}

/* Gouraud triangles: the centroid gets the mean of the corner colours. */
static int test_gouraud(void)
{
    pl_draw_list dl;
    small_list(&dl, 90, 90);
    pl_dl_triangles_begin(&dl, PL_SPACE_PIXEL);
    pl_vec2 t[3] = {{0, 0}, {90, 0}, {0, 90}};
    pl_rgba c[3] = {pl_rgb(1, 0, 0), pl_rgb(0, 1, 0), pl_rgb(0, 0, 1)};
    pl_dl_triangle_add(&dl, t, c);
    pl_image img = {0, 0, NULL};
    char err[256];
    ENSURE(pl_osmesa_rasterize(gl, &dl, &img, err, sizeof err) == 0);
    const uint8_t *q = px(&img, 30, 30); /* centroid (30, 30) */
    int r = q[0], g = q[1], b = q[2];
    pl_image_free(&img);
    pl_draw_list_free(&dl);
    ENSURE_NEAR(r, 85, 4);
    ENSURE_NEAR(g, 85, 4);
    ENSURE_NEAR(b, 85, 4);
    return 0;
}

/* World-space primitives are clipped to dl->clip (the plot area); pixel-space ones are not. */
static int test_clip(void)
{
    pl_draw_list dl;
    small_list(&dl, 64, 48);
    dl.has_clip = 1;
    dl.clip = (pl_px_rect){10, 8, 40, 30};
    pl_style st = pl_style_fill(pl_rgb(0, 0, 1));
    pl_dl_circle(&dl, PL_SPACE_WORLD, (pl_vec2){32, 24}, 100.0, &st); /* covers everything */
    pl_style red = pl_style_fill(pl_rgb(1, 0, 0));
    pl_vec2 r[4] = {{50, 36}, {60, 36}, {60, 44}, {50, 44}};            /* outside, pixel space */
    pl_dl_polygon(&dl, PL_SPACE_PIXEL, r, 4, &red);
    pl_image img = {0, 0, NULL};
    char err[256];
    ENSURE(pl_osmesa_rasterize(gl, &dl, &img, err, sizeof err) == 0);
    int wrong = 0;
    for (int y = 0; y < 48; y++)
        for (int x = 0; x < 64; x++) {
            const uint8_t *p = px(&img, x, y);
            int in = x >= 10 && x < 40 && y >= 8 && y < 30;
            int red_px = x >= 50 && x < 60 && y >= 36 && y < 44;
            int ok = in ? (p[0] == 0 && p[2] == 255) : red_px ? (p[0] == 255 && p[2] == 0)
                                                             : (p[0] == 255 && p[2] == 255);
            wrong += !ok;
        }
    pl_image_free(&img);
    pl_draw_list_free(&dl);
    ENSURE(wrong == 0);
    return 0;
}

/* Text: the ink of a string spans the same columns as in cairo (same font and advances). */
static int ink_extent(const pl_image *img, int *x0, int *x1)
{
    *x0 = img->width;
    *x1 = -1;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++)
            if (px(img, x, y)[0] < 128) {
                if (x < *x0) *x0 = x;
                if (x > *x1) *x1 = x;
            }
    return *x1 >= *x0;
}

static int test_text_matches_cairo(void)
{
    pl_draw_list dl;
    small_list(&dl, 400, 60);
    pl_dl_text(&dl, PL_SPACE_PIXEL, (pl_vec2){200, 30}, "Pore pressure 1.25 kPa", 20.0f,
               PL_ANCHOR_CENTER | PL_ANCHOR_MIDDLE, 0.0f, pl_rgb(0, 0, 0), NULL);
    pl_image a = {0, 0, NULL}, b = {0, 0, NULL};
    char err[256];
    ENSURE(pl_osmesa_rasterize(gl, &dl, &a, err, sizeof err) == 0);
    ENSURE(pl_cairo_rasterize(&dl, &b, err, sizeof err) == 0);
    int a0, a1, b0, b1;
    ENSURE(ink_extent(&a, &a0, &a1) && ink_extent(&b, &b0, &b1));
    fprintf(stderr, "  text ink: GL %d..%d, cairo %d..%d, PSNR %.2f dB\n", a0, a1, b0, b1, pl_psnr(&a, &b));
    ENSURE(abs(a0 - b0) <= 1 && abs(a1 - b1) <= 1);
    pl_image_free(&a);
    pl_image_free(&b);
    pl_draw_list_free(&dl);
    return 0;
}

static int update(void)
{
    char err[512], path[1024];
    for (int i = 0; i < render_case_count(); i++) {
        pl_image img = {0, 0, NULL};
        snprintf(path, sizeof path, "%s/gl/%s.png", PL_GOLDEN_DIR, render_case_at(i)->name);
        if (gl_case(i, NULL, &img) || pl_png_write(path, &img, 9, 1, err, sizeof err)) {
            fprintf(stderr, "%s: cannot write %s\n", render_case_at(i)->name, path);
            return 1;
        }
        printf("wrote %s\n", path);
        pl_image_free(&img);
    }
    return 0;
}

int main(int argc, char **argv)
{
    char err[512];
    gl = pl_osmesa_create(1, err, sizeof err); /* the default; the goldens are for it */
    if (!gl) {
        fprintf(stderr, "OSMesa: %s\n", err);
        return 1;
    }
    fprintf(stderr, "GL: %s, %s, %d samples\n", pl_gl_renderer_name(pl_osmesa_gl(gl)),
            pl_gl_version(pl_osmesa_gl(gl)), pl_gl_samples(pl_osmesa_gl(gl)));
    if (argc > 1 && strcmp(argv[1], "--update") == 0) {
        int rc = update();
        pl_osmesa_destroy(&gl);
        return rc;
    }
    RUN(test_rectangle_exact);
    RUN(test_disc_area);
    RUN(test_translucent_stroke_single_coverage);
    RUN(test_gouraud);
    RUN(test_clip);
    RUN(test_text_matches_cairo);
    RUN(test_agrees_with_cairo);
    RUN(test_cross_check_detects_missing_layer);
    RUN(test_goldens_match);
    RUN(test_changes_detected);
    pl_osmesa_destroy(&gl);
    return pl_test_report();
}
