/* Image-diff tests: each case of render_scenes.c is rendered and compared with its golden PNG
 * in tests/golden/ (tolerance: image_compare.h, docs/rendering.md). On a mismatch the diff
 * image goes next to the output (build/tests/render-out/<case>.diff.png) and the measured
 * numbers are printed. Negative tests prove the comparison fails when a colour, a layer or a
 * body position changes. `test_render_golden --update DIR` writes the goldens (used by
 * tools/update-goldens.sh; never by ctest). */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <math.h>

#include "harness.h"
#include "backend_cairo.h"
#include "draw_world.h"
#include "image_compare.h"
#include "render_scenes.h"

static int write_case(int i, const render_tweak *tw, const char *path, int level) {
    pl_draw_list dl;
    pl_draw_list_init(&dl);
    char err[512];
    int rc = render_case(i, tw, &dl, err, sizeof err);
    if (rc == 0) rc = pl_cairo_write_file(&dl, path, level, err, sizeof err);
    if (rc) fprintf(stderr, "%s: %s\n", render_case_at(i)->name, err);
    pl_draw_list_free(&dl);
    return rc;
}

static int find_case(const char *name) {
    for (int i = 0; i < render_case_count(); i++)
        if (strcmp(render_case_at(i)->name, name) == 0) return i;
    return -1;
}

/* Renders case i (with a tweak) and compares with its golden; returns the comparison result
 * (1 match, 0 mismatch, -1 error). */
static int compare_case(int i, const render_tweak *tw, const char *suffix) {
    const char *name = render_case_at(i)->name;
    char out[1024], golden[1024], diff[1024], msg[1024];
    snprintf(out, sizeof out, "%s/%s%s.png", PL_RENDER_OUT_DIR, name, suffix);
    snprintf(golden, sizeof golden, "%s/%s.png", PL_GOLDEN_DIR, name);
    snprintf(diff, sizeof diff, "%s/%s%s.diff.png", PL_RENDER_OUT_DIR, name, suffix);
    if (write_case(i, tw, out, 1)) return -1;
    pl_compare_tolerance tol = pl_default_compare_tolerance();
    int rc = pl_png_compare(golden, out, &tol, diff, NULL, msg, sizeof msg);
    fprintf(stderr, "  %-16s%-14s %s: %s\n", name, suffix, rc == 1 ? "match" : (rc == 0 ? "DIFFERS" : "ERROR"), msg);
    return rc;
}

static int test_goldens_match(void) {
    int bad = 0;
    for (int i = 0; i < render_case_count(); i++)
        if (compare_case(i, NULL, "") != 1) bad++;
    ENSURE(bad == 0);
    return 0;
}

/* The comparison must fail on a changed colour, a missing layer and moved geometry. */
static int test_changes_detected(void) {
    int forces = find_case("forces");
    ENSURE(forces >= 0);
    render_tweak colour = {1, 0, 0}, layer = {0, PL_LAYER_FORCES, 0}, shift = {0, 0, 1};
    ENSURE(compare_case(forces, &colour, "-colour") == 0);
    ENSURE(compare_case(forces, &layer, "-nolayer") == 0);
    ENSURE(compare_case(forces, &shift, "-shifted") == 0);
    int combined = find_case("combined");
    render_tweak no_iso = {0, PL_LAYER_ISOLINES, 0};
    ENSURE(compare_case(combined, &no_iso, "-noisolines") == 0);
    return 0;
}

static int read_file(const char *path, unsigned char **buf, long *len) {
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    fseek(f, 0, SEEK_END);
    *len = ftell(f);
    fseek(f, 0, SEEK_SET);
    *buf = malloc((size_t)*len + 1);
    size_t got = fread(*buf, 1, (size_t)*len, f);
    fclose(f);
    return got == (size_t)*len ? 0 : -1;
}

static int same_bytes(const char *a, const char *b) {
    unsigned char *x = NULL, *y = NULL;
    long nx = 0, ny = 0;
    int same = read_file(a, &x, &nx) == 0 && read_file(b, &y, &ny) == 0 && nx == ny && nx > 0 &&
               memcmp(x, y, (size_t)nx) == 0;
    free(x);
    free(y);
    return same;
}

/* Writes case i to path in a fresh child process (cairo numbers SVG/PDF objects with
 * process-wide counters, so "same input" means the same program run). */
static int write_case_in_child(int i, const char *path) {
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) _exit(write_case(i, NULL, path, 1) ? 1 : 0);
    int status = 0;
    if (pid < 0 || waitpid(pid, &status, 0) < 0) return -1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

/* Same input, identical bytes: PNG, SVG and PDF written by two separate runs. PNG is also
 * compared within one process. */
static int test_deterministic_bytes(void) {
    int combined = find_case("combined");
    const char *ext[3] = {"png", "svg", "pdf"};
    char a[1024], b[1024];
    snprintf(a, sizeof a, "%s/determinism-same-process-1.png", PL_RENDER_OUT_DIR);
    snprintf(b, sizeof b, "%s/determinism-same-process-2.png", PL_RENDER_OUT_DIR);
    ENSURE(write_case(combined, NULL, a, 1) == 0);
    ENSURE(write_case(combined, NULL, b, 1) == 0);
    ENSURE(same_bytes(a, b));
    for (int k = 0; k < 3; k++) {
        snprintf(a, sizeof a, "%s/determinism-1.%s", PL_RENDER_OUT_DIR, ext[k]);
        snprintf(b, sizeof b, "%s/determinism-2.%s", PL_RENDER_OUT_DIR, ext[k]);
        ENSURE(write_case_in_child(combined, a) == 0);
        ENSURE(write_case_in_child(combined, b) == 0);
        if (!same_bytes(a, b)) {
            fprintf(stderr, "  %s and %s differ\n", a, b);
            return 1;
        }
    }
    return 0;
}

/* A dense picture of small primitives (the kind the backend rasterizes itself: discs and
 * hexagons of a few pixels with outlines and marks, force segments, tangential arrows, a
 * Gouraud field with mesh and colour bar), 48 x 24 bodies at 640 x 400. */
static void dense_scene(pl_render_scene *s) {
    enum { NX = 48, NY = 24 };
    const double r = 0.5;
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            pl_body_info b;
            memset(&b, 0, sizeof b);
            int poly = (i * 7 + j * 3) % 5 == 0;
            b.shape = poly ? PL_SHAPE_POLYGON : PL_SHAPE_DISC;
            b.material = (i / 6 + j / 6) % 3;
            b.position = (pl_vec2){0.99 * i + r * (j % 2), 0.99 * 0.866 * j};
            b.radius = r * (0.85 + 0.15 * sin(i * 0.37 + j));
            b.area = 3.14159 * b.radius * b.radius;
            b.angle = 0.1 * i + 0.2 * j;
            pl_vec2 v[6];
            int nv = 0;
            if (poly) {
                for (int k = 0; k < 6; k++)
                    v[k] = (pl_vec2){b.position.x + b.radius * cos(b.angle + k * 1.0471975512),
                                     b.position.y + b.radius * sin(b.angle + k * 1.0471975512)};
                nv = b.vertex_count = 6;
            }
            pl_render_scene_add_body(s, &b, v, nv);
        }
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            int a = j * NX + i, nb[2] = {i + 1 < NX ? a + 1 : -1, j + 1 < NY ? a + NX : -1};
            for (int k = 0; k < 2; k++) {
                if (nb[k] < 0) continue;
                pl_contact_info c;
                memset(&c, 0, sizeof c);
                c.a = a;
                c.b = nb[k];
                pl_vec2 pa = s->bodies[c.a].position, pb = s->bodies[c.b].position;
                c.point = (pl_vec2){0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y)};
                double d = hypot(pb.x - pa.x, pb.y - pa.y);
                c.normal = (pl_vec2){(pb.x - pa.x) / d, (pb.y - pa.y) / d};
                c.fn = 1000.0 * (1.0 + sin(0.13 * i + 0.29 * j + k));
                c.ft = 200.0 * sin(0.7 * i + k);
                pl_render_scene_add_contact(s, &c);
            }
        }
    s->lo = (pl_vec2){-1.0, -1.0};
    s->hi = (pl_vec2){NX + 0.5, NY * 0.866 + 0.5};
set_grid_field(s, 24, 12, 0.3, 0.4, 0);
}

/* Renders the dense scene with the given layers by the backend's own rasterizers and by cairo
 * alone (PORELAB_CAIRO_ONLY) and compares them with tol; 0 when they match. */
static int own_vs_cairo(const char *name, unsigned layers, pl_compare_tolerance tol,
                        pl_compare_result *out) {
    pl_render_scene s;
    pl_render_scene_init(&s);
    dense_scene(&s);
    pl_render_options o = pl_default_render_options();
    o.width = 640;
    o.height = 400;
    o.layers = layers;
    pl_draw_list dl;
    pl_draw_list_init(&dl);
    char err[512];
    pl_image own = {0, 0, NULL}, ref = {0, 0, NULL};
    ENSURE(pl_render_build_scene(&dl, &s, &o, err, sizeof err) == 0);
    ENSURE(pl_cairo_rasterize(&dl, &own, err, sizeof err) == 0);
    setenv("PORELAB_CAIRO_ONLY", "1", 1);
    int rc = pl_cairo_rasterize(&dl, &ref, err, sizeof err);
    unsetenv("PORELAB_CAIRO_ONLY");
    ENSURE(rc == 0);
    pl_image diff = {0, 0, NULL};
    pl_compare_result res = pl_image_compare(&ref, &own, &tol, &diff);
    fprintf(stderr, "  own rasterizers against cairo, %-22s max channel diff %3d, %5ld of %ld "
                    "pixels (%.3f %%) differ by more than %d, mean abs diff %.4f; allowed %.3f %%\n",
            name, res.max_channel_diff, res.differing, res.total, 100.0 * res.fraction,
            tol.channel_tolerance, res.mean_abs_diff, 100.0 * tol.max_fraction);
    char path[1024];
    snprintf(path, sizeof path, "%s/dense-%s-own.png", PL_RENDER_OUT_DIR, name);
    pl_png_write(path, &own, 1, 0, err, sizeof err);
    snprintf(path, sizeof path, "%s/dense-%s-cairo.png", PL_RENDER_OUT_DIR, name);
    pl_png_write(path, &ref, 1, 0, err, sizeof err);
    if (!res.match) {
        snprintf(path, sizeof path, "%s/dense-%s.diff.png", PL_RENDER_OUT_DIR, name);
        pl_png_write(path, &diff, 1, 0, err, sizeof err);
    }
    *out = res;
    pl_image_free(&own);
    pl_image_free(&ref);
    pl_image_free(&diff);
    pl_draw_list_free(&dl);
    pl_render_scene_free(&s);
    return 0;
}

/* The backend's own rasterizers (small bodies, segments, arrows, Gouraud fields on image
 * surfaces) against cairo's rendering of the same dense picture (docs/rendering.md,
 * Performance). */
static int test_own_rasterizers_match_cairo(void) {
    pl_compare_result res;
    /* bodies (discs, polygons, outlines, marks), the Gouraud field and colour bar: cairo's
     * picture within the golden tolerance */
    ENSURE(own_vs_cairo("bodies-field", PL_LAYER_BODIES | PL_LAYER_PRESSURE | PL_LAYER_COLORBAR,
                        pl_default_compare_tolerance(), &res) == 0);
    ENSURE(res.match);
    ENSURE(res.mean_abs_diff > 0.0); /* the own rasterizers did draw something */
    /* force chains: the segments of a force class form one batch whose pixels take the
     * largest coverage (cairo strokes them in paths of 64 composited one over the other), and
     * round caps are covered by their distance: measured 0.27 % of the pixels differ by
     * more than 8/255 (at joints and crossings), allowed 0.5 % */
    pl_compare_tolerance forces_tol = {8, 0.005};
    ENSURE(own_vs_cairo("forces", PL_LAYER_BODIES | PL_LAYER_FORCES, forces_tol, &res) == 0);
    ENSURE(res.match && res.mean_abs_diff < 1.0);
    /* Where several lines or arrows of one batch overlap, the pictures differ on purpose:
     * a mesh node where 6-8 lines meet is lighter than cairo's (ours: the coverage by the
     * distance to the union of the lines; cairo: the exact area of the union), measured
     * 0.40 % of the pixels, allowed 1 %; overlapping tangential arrows add their coverages
     * (clamped) where cairo composites them one over the other, measured 4.3 % on this
     * picture, where nearly every arrow overlaps others, allowed 6 %. Both bounds, and a mean
     * absolute difference under 1/255, still catch a missing or moved layer (measured: the
     * arrows change 44 % of this picture's pixels, mean 29/255; the mesh about 10 %). */
    pl_compare_tolerance mesh_tol = {8, 0.01}, arrow_tol = {8, 0.06};
    ENSURE(own_vs_cairo("mesh", PL_LAYER_MESH, mesh_tol, &res) == 0);
    ENSURE(res.match && res.mean_abs_diff < 1.0);
    ENSURE(own_vs_cairo("tangential", PL_LAYER_BODIES | PL_LAYER_TANGENTIAL, arrow_tol, &res) == 0);
    ENSURE(res.match && res.mean_abs_diff < 1.0);
    return 0;
}

int main(int argc, char **argv) {
    if (argc == 3 && strcmp(argv[1], "--update") == 0) {
        int rc = 0;
        for (int i = 0; i < render_case_count(); i++) {
            char path[2048];
            snprintf(path, sizeof path, "%s/%s.png", argv[2], render_case_at(i)->name);
            if (write_case(i, NULL, path, 9)) rc = 1;
            else printf("wrote %s  (%s)\n", path, render_case_at(i)->what);
        }
        return rc;
    }
    RUN(test_goldens_match);
    RUN(test_changes_detected);
    RUN(test_deterministic_bytes);
    RUN(test_own_rasterizers_match_cairo);
    return pl_test_report();
}
