/// Image comparison for the render tests (image-diff against golden PNGs).
///
/// Tolerance (documented in docs/rendering.md): a pixel differs when any of its R, G, B, A
/// channels differs by more than `channel_tolerance` (default 8 of 255); two images match
/// when they have the same size and at most `max_fraction` of their pixels differ (default
/// 0.001 = 0.1 %). The defaults absorb antialiasing noise between cairo/pixman/FreeType
/// versions but catch a changed colour, a missing layer or moved geometry.
#ifndef PORELAB_IMAGE_COMPARE_H
#define PORELAB_IMAGE_COMPARE_H

#include <stddef.h>
#include "backend_cairo.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pl_compare_tolerance {
    int channel_tolerance; ///< largest per-channel difference that still counts as equal, 0..255
    double max_fraction;   ///< fraction of pixels allowed to differ, 0..1
} pl_compare_tolerance;

pl_compare_tolerance pl_default_compare_tolerance(void);

typedef struct pl_compare_result {
    int same_size;
    int max_channel_diff;  ///< largest per-channel difference over all pixels
    long differing;        ///< pixels differing by more than the channel tolerance
    long total;            ///< pixels compared
    double fraction;       ///< differing / total
    double mean_abs_diff;  ///< mean absolute channel difference (0..255)
    int match;             ///< 1 when within tolerance
} pl_compare_result;

/// Compares two images. When diff is not NULL, it receives a diff image (same size as b):
/// b in faded grey, differing pixels in red (brighter = larger difference).
pl_compare_result pl_image_compare(const pl_image *a, const pl_image *b,
                                   const pl_compare_tolerance *tol, pl_image *diff);

/// Compares two PNG files; on mismatch and when diff_path is not NULL, writes the diff
/// image there. Prints nothing; summary in msg ("max channel diff 37, 1204 of 240000 pixels
/// (0.502 %) differ; tolerance 8 and 0.100 %"). Returns 1 match, 0 mismatch, -1 error.
int pl_png_compare(const char *expected, const char *actual, const pl_compare_tolerance *tol,
                   const char *diff_path, pl_compare_result *res, char *msg, size_t msglen);

#ifdef __cplusplus
}
#endif
#endif
