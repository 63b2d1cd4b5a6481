/* Output paths: stills in PNG/SVG/PDF through pl_render_to_file, the frame writer (numbered
 * PNGs, MP4/GIF through ffmpeg when installed, the one-line note when it is not), error
 * messages for bad names, and a PLplot chart compared with its golden. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "harness.h"
#include "backend_cairo.h"
#include "charts.h"
#include "drawlist.h"
#include "image_compare.h"
#include "render_scenes.h"

static long file_size(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

static int starts_with(const char *path, const char *magic) {
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    char buf[64] = {0};
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    return n >= strlen(magic) && memcmp(buf, magic, strlen(magic)) == 0;
}

/* 1 when the file contains the byte string (binary-safe). */
static int file_contains(const char *path, const char *needle) {
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)n + 1);
    int found = 0;
    if (buf && fread(buf, 1, (size_t)n, f) == (size_t)n) {
        size_t k = strlen(needle);
        for (long i = 0; i + (long)k <= n && !found; i++) found = memcmp(buf + i, needle, k) == 0;
    }
    free(buf);
    fclose(f);
    return found;
}

static int test_stills_three_formats(void) {
    pl_world *w = make_pile_world();
    ENSURE(w != NULL);
    pl_render_options o = pl_default_render_options();
    o.layers |= PL_LAYER_SCALEBAR | PL_LAYER_COLORBAR;
    char err[512];
    ENSURE(pl_render_to_file(w, &o, PL_RENDER_OUT_DIR "/still.png", err, sizeof err) == 0);
    ENSURE(pl_render_to_file(w, &o, PL_RENDER_OUT_DIR "/still.svg", err, sizeof err) == 0);
    ENSURE(pl_render_to_file(w, &o, PL_RENDER_OUT_DIR "/still.pdf", err, sizeof err) == 0);
    ENSURE(starts_with(PL_RENDER_OUT_DIR "/still.png", "\x89PNG"));
    ENSURE(starts_with(PL_RENDER_OUT_DIR "/still.svg", "<?xml"));
    ENSURE(starts_with(PL_RENDER_OUT_DIR "/still.pdf", "%PDF-"));
    /* real text: <text> elements in the SVG (its words readable in the file), an embedded
     * TrueType font with a Unicode map in the PDF */
    ENSURE(file_contains(PL_RENDER_OUT_DIR "/still.svg", "<text "));
    ENSURE(file_contains(PL_RENDER_OUT_DIR "/still.svg", ">t = 0.000 s</text>") ||
           file_contains(PL_RENDER_OUT_DIR "/still.svg", "> s</text>"));
    ENSURE(file_contains(PL_RENDER_OUT_DIR "/still.svg", "font-family=\"DejaVu Sans\""));
    ENSURE(file_contains(PL_RENDER_OUT_DIR "/still.pdf", "/FontFile"));
    ENSURE(file_contains(PL_RENDER_OUT_DIR "/still.pdf", "/ToUnicode"));
    ENSURE(file_contains(PL_RENDER_OUT_DIR "/still.pdf", "DejaVuSans"));
    pl_image img = {0, 0, NULL};
    ENSURE(pl_png_read(PL_RENDER_OUT_DIR "/still.png", &img, err, sizeof err) == 0);
    ENSURE(img.width == 800 && img.height == 600);
    pl_image_free(&img);
    /* the RGBA entry point gives the same pixels as the PNG */
    unsigned char *rgba = NULL;
    ENSURE(pl_render_to_rgba(w, &o, &rgba, err, sizeof err) == 0);
    ENSURE(pl_png_read(PL_RENDER_OUT_DIR "/still.png", &img, err, sizeof err) == 0);
    ENSURE(memcmp(rgba, img.rgba, 800 * 600 * 4) == 0);
    free(rgba);
    pl_image_free(&img);
    /* bad names give messages listing the valid choices */
    ENSURE(pl_render_to_file(w, &o, PL_RENDER_OUT_DIR "/still.jpg", err, sizeof err) == -1);
    ENSURE(strstr(err, ".png") && strstr(err, ".svg") && strstr(err, ".pdf"));
    ENSURE(pl_render_to_file(w, &o, "/nonexistent-dir/x.png", err, sizeof err) == -1);
    ENSURE(strstr(err, "/nonexistent-dir/x.png") != NULL);
    o.width = 4;
    ENSURE(pl_render_to_file(w, &o, PL_RENDER_OUT_DIR "/tiny.png", err, sizeof err) == -1);
    ENSURE(strstr(err, "4x600") != NULL);
    pl_world_destroy(&w);
    return 0;
}

static int run_frames(const char *dir, const char *video, int nframes, char *err, size_t errlen) {
    pl_world *w = make_pile_world();
    if (!w) return -1;
    pl_render_options o = pl_default_render_options();
    o.width = 321; /* odd width: the MP4 path must pad to even dimensions */
    o.height = 240;
    pl_frame_writer *fw = pl_frame_writer_open(dir, video, 10, err, errlen);
    if (!fw) {
        pl_world_destroy(&w);
        return -1;
    }
    int rc = 0;
    for (int i = 0; i < nframes && rc == 0; i++) {
        rc = pl_frame_writer_add(fw, w, &o, err, errlen);
        if (rc == 0 && pl_world_step(w, 20) != PL_OK) rc = -1;
    }
    if (rc == 0 && pl_frame_writer_count(fw) != nframes) rc = -1;
    int rc2 = pl_frame_writer_close(&fw, err, errlen);
    pl_world_destroy(&w);
    return rc ? rc : rc2;
}

static int ffmpeg_available(void) { return system("ffmpeg -version >/dev/null 2>&1") == 0; }

static int test_frame_writer(void) {
    char err[512];
    const char *dir = PL_RENDER_OUT_DIR "/frames/nested";
    ENSURE(run_frames(dir, NULL, 3, err, sizeof err) == 0);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/nested/frame_000000.png") > 1000);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/nested/frame_000002.png") > 1000);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/nested/frame_000003.png") < 0);
    /* bad arguments */
    ENSURE(pl_frame_writer_open(dir, PL_RENDER_OUT_DIR "/x.avi", 10, err, sizeof err) == NULL);
    ENSURE(strstr(err, ".mp4") && strstr(err, ".gif"));
    ENSURE(pl_frame_writer_open(dir, NULL, 0, err, sizeof err) == NULL);
    return 0;
}


/* A rerun into a folder that holds more frames of an earlier run leaves none of them: the
 * summary's frame count is the folder's. */
static int test_stale_frames_removed(void) {
    char err[512];
    const char *dir = PL_RENDER_OUT_DIR "/frames/stale";
    ENSURE(run_frames(dir, NULL, 5, err, sizeof err) == 0);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/stale/frame_000004.png") > 1000);
    /* something that only looks like a frame stays */
    FILE *f = fopen(PL_RENDER_OUT_DIR "/frames/stale/frame_000009.png.keep", "w");
    ENSURE(f != NULL);
    fclose(f);
    ENSURE(run_frames(dir, NULL, 2, err, sizeof err) == 0);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/stale/frame_000001.png") > 1000);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/stale/frame_000002.png") < 0);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/stale/frame_000004.png") < 0);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/stale/frame_000009.png.keep") == 0);
    /* a resumed run (numbering from 3) keeps the frames before it */
    ENSURE(run_frames(dir, NULL, 4, err, sizeof err) == 0);
    ENSURE(pl_frames_remove_stale(dir, 2, NULL) == 2);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/stale/frame_000001.png") > 1000);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/stale/frame_000002.png") < 0);
    return 0;
}

/* render.record_from: frames before it are not written, numbering starts at the first one
 * written. */
static int test_record_from(void) {
    char err[512];
    pl_world *w = make_moving_world();
    ENSURE(w != NULL);
    pl_render_options o = pl_default_render_options();
    o.width = 160;
    o.height = 120;
    double dt = pl_world_dt(w);
    o.record_from = pl_world_time(w) + 25.5 * dt;
    const char *dir = PL_RENDER_OUT_DIR "/frames/record_from";
    pl_frame_writer *fw = pl_frame_writer_open(dir, NULL, 10, err, sizeof err);
    ENSURE(fw != NULL);
    for (int i = 0; i < 6; i++) { /* frames at 0, 10, ..., 50 steps: 30, 40, 50 written */
        ENSURE(pl_frame_writer_add(fw, w, &o, err, sizeof err) == 0);
        ENSURE(pl_world_step(w, 10) == PL_OK);
    }
    ENSURE(pl_frame_writer_count(fw) == 3);
    ENSURE(pl_frame_writer_close(&fw, err, sizeof err) == 0);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/record_from/frame_000002.png") > 100);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/frames/record_from/frame_000003.png") < 0);
    pl_world_destroy(&w);
    return 0;
}

/* Ranges are fixed across a run: the automatic range of each frame widens the run's, never
 * narrows it, and the next frame is drawn with the run's; the arrow scale only shrinks. */
static int test_fixed_ranges(void) {
    pl_render_ranges r;
    memset(&r, 0, sizeof r);
    pl_draw_list dl;
    pl_draw_list_init(&dl);
    pl_render_options o = pl_default_render_options(), fixed;
    dl.auto_field_set = 1;
    dl.auto_field_lo = 0.0;
    dl.auto_field_hi = 400.0;
    dl.auto_vscale = 2.0;
    pl_render_ranges_update(&r, &dl);
    pl_render_ranges_apply(&r, &o, &fixed);
    ENSURE(fixed.fluid_min == 0.0 && fixed.fluid_max == 400.0 && fixed.velocity_scale == 2.0);
    ENSURE(!r.field_changed && !r.vscale_changed);
    dl.auto_field_hi = 100.0; /* a quieter frame: the range stays */
    dl.auto_vscale = 5.0;
    pl_render_ranges_update(&r, &dl);
    pl_render_ranges_apply(&r, &o, &fixed);
    ENSURE(fixed.fluid_max == 400.0 && fixed.velocity_scale == 2.0 && !r.field_changed);
    dl.auto_field_lo = -50.0; /* a wider one widens it, and it is reported */
    dl.auto_field_hi = 900.0;
    dl.auto_vscale = 1.0;
    pl_render_ranges_update(&r, &dl);
    pl_render_ranges_apply(&r, &o, &fixed);
    ENSURE(fixed.fluid_min == -50.0 && fixed.fluid_max == 900.0 && fixed.velocity_scale == 1.0);
    ENSURE(r.field_changed && r.vscale_changed);
    /* a scene's own range always wins */
    o.fluid_min = 0.0;
    o.fluid_max = 300.0;
    o.velocity_scale = 7.0;
    pl_render_ranges_apply(&r, &o, &fixed);
    ENSURE(fixed.fluid_max == 300.0 && fixed.velocity_scale == 7.0);
    pl_draw_list_free(&dl);
    return 0;
}

static int test_video(void) {
    char err[512];
    if (!ffmpeg_available()) {
        fprintf(stderr, "  ffmpeg is not installed: video encoding not tested here\n");
        return 0;
    }
    const char *mp4 = PL_RENDER_OUT_DIR "/video/run.mp4", *gif = PL_RENDER_OUT_DIR "/video/run.gif";
    remove(mp4);
    remove(gif);
    if (run_frames(PL_RENDER_OUT_DIR "/video", mp4, 4, err, sizeof err) != 0) {
        fprintf(stderr, "  mp4: %s\n", err);
        return 1;
    }
    ENSURE(file_size(mp4) > 1000);
    if (run_frames(PL_RENDER_OUT_DIR "/video", gif, 4, err, sizeof err) != 0) {
        fprintf(stderr, "  gif: %s\n", err);
        return 1;
    }
    ENSURE(starts_with(gif, "GIF89a"));
    return 0;
}

/* Without ffmpeg on PATH: one note, frames still written, closing succeeds. */
static int test_video_without_ffmpeg(void) {
    char err[512];
    const char *old = getenv("PATH");
    char *saved = old ? strdup(old) : NULL;
    setenv("PATH", "/nonexistent", 1);
    int rc = run_frames(PL_RENDER_OUT_DIR "/noffmpeg", PL_RENDER_OUT_DIR "/noffmpeg/run.mp4", 2,
                        err, sizeof err);
    if (saved) {
        setenv("PATH", saved, 1);
        free(saved);
    }
    ENSURE(rc == 0);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/noffmpeg/frame_000001.png") > 1000);
    ENSURE(file_size(PL_RENDER_OUT_DIR "/noffmpeg/run.mp4") < 0);
    return 0;
}

/* A chart like the ones scenes make: measured points beside an analytic curve. */
static int chart_def_for_test(pl_chart_def *d, pl_chart_series *s, double *x, double *y1,
                              double *y2, double *xp, double *yp) {
    for (int i = 0; i < 101; i++) {
        x[i] = 0.05 * i;                                  /* time, s */
        y1[i] = 12.0 * (1.0 - exp(-x[i] / 1.2));          /* analytic settlement, mm */
        y2[i] = 12.0 * (1.0 - exp(-x[i] / 0.6)) * 0.8;    /* second model */
    }
    for (int i = 0; i < 11; i++) {
        xp[i] = 0.5 * i;
        yp[i] = 12.0 * (1.0 - exp(-xp[i] / 1.2)) + 0.4 * sin(3.0 * i);
    }
    memset(s, 0, 3 * sizeof *s);
    s[0] = (pl_chart_series){"analytic (Terzaghi)", x, y1, 101, PL_SERIES_DASHED, {0, 0, 0, 0}, 0};
    s[1] = (pl_chart_series){"porelab", xp, yp, 11, PL_SERIES_LINE_POINTS, {0, 0, 0, 0}, 0};
    s[2] = (pl_chart_series){"stiffer skeleton", x, y2, 101, PL_SERIES_LINE, {0, 0, 0, 0}, 0};
    *d = pl_default_chart_def();
    d->width = 560;
    d->height = 400;
    d->title = "Settlement of a saturated column";
    d->xlabel = "time (s)";
    d->ylabel = "settlement (mm)";
    d->series = s;
    d->series_count = 3;
    d->legend = 3;
    return 0;
}

static int test_chart(void) {
    pl_chart_def d;
    pl_chart_series s[3];
    static double x[101], y1[101], y2[101], xp[11], yp[11];
    chart_def_for_test(&d, s, x, y1, y2, xp, yp);
    char err[512], msg[1024];
    const char *out = PL_RENDER_OUT_DIR "/chart.png";
    if (pl_chart_write(out, &d, err, sizeof err) != 0) {
        fprintf(stderr, "  %s\n", err);
        return 1;
    }
    ENSURE(pl_chart_write(PL_RENDER_OUT_DIR "/chart.svg", &d, err, sizeof err) == 0);
    /* SVG charts keep their text as text (PLplot's svg device), with the title's words */
    ENSURE(file_contains(PL_RENDER_OUT_DIR "/chart.svg", "<svg"));
    ENSURE(file_contains(PL_RENDER_OUT_DIR "/chart.svg", "<text"));
    ENSURE(pl_chart_write(PL_RENDER_OUT_DIR "/chart.pdf", &d, err, sizeof err) == 0);
    ENSURE(starts_with(PL_RENDER_OUT_DIR "/chart.pdf", "%PDF-"));
    pl_compare_tolerance tol = pl_default_compare_tolerance();
    int rc = pl_png_compare(PL_GOLDEN_DIR "/chart.png", out, &tol, PL_RENDER_OUT_DIR "/chart.diff.png",
                            NULL, msg, sizeof msg);
    fprintf(stderr, "  chart: %s\n", msg);
    ENSURE(rc == 1);
    /* the same chart twice: identical pixels */
    ENSURE(pl_chart_write(PL_RENDER_OUT_DIR "/chart2.png", &d, err, sizeof err) == 0);
    pl_compare_tolerance exact = {0, 0.0};
    ENSURE(pl_png_compare(out, PL_RENDER_OUT_DIR "/chart2.png", &exact, NULL, NULL, msg, sizeof msg) == 1);
    /* a changed series must be detected */
    y1[50] += 4.0;
    ENSURE(pl_chart_write(PL_RENDER_OUT_DIR "/chart-changed.png", &d, err, sizeof err) == 0);
    ENSURE(pl_png_compare(PL_GOLDEN_DIR "/chart.png", PL_RENDER_OUT_DIR "/chart-changed.png", &tol,
                          NULL, NULL, msg, sizeof msg) == 0);
    /* bad definitions are refused with messages */
    d.series_count = 0;
    ENSURE(pl_chart_write(out, &d, err, sizeof err) == -1 && strstr(err, "series"));
    return 0;
}

int main(int argc, char **argv) {
    if (argc == 3 && strcmp(argv[1], "--update-chart") == 0) {
        pl_chart_def d;
        pl_chart_series s[3];
        static double x[101], y1[101], y2[101], xp[11], yp[11];
        chart_def_for_test(&d, s, x, y1, y2, xp, yp);
        char err[512];
        if (pl_chart_write(argv[2], &d, err, sizeof err)) {
            fprintf(stderr, "%s\n", err);
            return 1;
        }
        printf("wrote %s\n", argv[2]);
        return 0;
    }
    RUN(test_stills_three_formats);
    RUN(test_frame_writer);
    RUN(test_stale_frames_removed);
    RUN(test_record_from);
    RUN(test_fixed_ranges);
    RUN(test_video);
    RUN(test_video_without_ffmpeg);
    RUN(test_chart);
    return pl_test_report();
}
