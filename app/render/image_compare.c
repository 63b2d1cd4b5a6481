/* Pixel comparison with a per-channel tolerance and an allowed fraction of differing pixels. */
#include "image_compare.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

pl_compare_tolerance pl_default_compare_tolerance(void) {
    pl_compare_tolerance t = {8, 0.001};
    return t;
}

pl_compare_result pl_image_compare(const pl_image *a, const pl_image *b,
                                   const pl_compare_tolerance *tol, pl_image *diff) {
    pl_compare_result r;
    memset(&r, 0, sizeof r);
    r.same_size = a->width == b->width && a->height == b->height;
    if (diff) {
        diff->width = b->width;
        diff->height = b->height;
        diff->rgba = calloc((size_t)b->width * (size_t)b->height * 4u, 1);
    }
    if (!r.same_size) {
        r.max_channel_diff = 255;
        r.fraction = 1.0;
        r.total = (long)b->width * b->height;
        r.differing = r.total;
        return r;
    }
    long n = (long)a->width * a->height;
    double sum = 0.0;
    for (long i = 0; i < n; i++) {
        const uint8_t *p = a->rgba + 4 * i, *q = b->rgba + 4 * i;
        int m = 0;
        for (int k = 0; k < 4; k++) {
            int d = abs((int)p[k] - (int)q[k]);
            sum += d;
            if (d > m) m = d;
        }
        if (m > r.max_channel_diff) r.max_channel_diff = m;
        int bad = m > tol->channel_tolerance;
        if (bad) r.differing++;
        if (diff && diff->rgba) {
            uint8_t *o = diff->rgba + 4 * i;
            if (bad) {
                o[0] = (uint8_t)(128 + m / 2);
                o[1] = 0;
                o[2] = 0;
            } else {
                int g = (q[0] + q[1] + q[2]) / 3;
                g = 200 + g / 5; /* faded context */
                o[0] = o[1] = o[2] = (uint8_t)(g > 255 ? 255 : g);
            }
            o[3] = 255;
        }
    }
    r.total = n;
    r.fraction = n > 0 ? (double)r.differing / (double)n : 0.0;
    r.mean_abs_diff = n > 0 ? sum / (4.0 * (double)n) : 0.0;
    r.match = r.fraction <= tol->max_fraction;
    return r;
}

int pl_png_compare(const char *expected, const char *actual, const pl_compare_tolerance *tol,
                   const char *diff_path, pl_compare_result *res, char *msg, size_t msglen) {
    pl_image a = {0, 0, NULL}, b = {0, 0, NULL};
    char err[512];
    if (pl_png_read(expected, &a, err, sizeof err)) {
        snprintf(msg, msglen, "%s", err);
        return -1;
    }
    if (pl_png_read(actual, &b, err, sizeof err)) {
        snprintf(msg, msglen, "%s", err);
        pl_image_free(&a);
        return -1;
    }
    pl_image d = {0, 0, NULL};
    pl_compare_result r = pl_image_compare(&a, &b, tol, diff_path ? &d : NULL);
    if (res) *res = r;
    if (!r.same_size) {
        snprintf(msg, msglen, "size differs: expected %dx%d, got %dx%d", a.width, a.height,
                 b.width, b.height);
    } else {
        snprintf(msg, msglen,
                 "max channel diff %d, %ld of %ld pixels (%.3f %%) differ by more than %d, mean "
                 "abs diff %.4f; allowed %.3f %%",
                 r.max_channel_diff, r.differing, r.total, 100.0 * r.fraction,
                 tol->channel_tolerance, r.mean_abs_diff, 100.0 * tol->max_fraction);
    }
    int rc = r.match ? 1 : 0;
    if (!r.match && diff_path && d.rgba) {
        if (pl_png_write(diff_path, &d, 6, 1, err, sizeof err) == 0) {
            size_t used = strlen(msg);
            snprintf(msg + used, msglen - used, "; diff image: %s", diff_path);
        }
    }
    pl_image_free(&a);
    pl_image_free(&b);
    pl_image_free(&d);
    return rc;
}
