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

#include "harness.h"
#include "backend_cairo.h"
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
    return pl_test_report();
}
