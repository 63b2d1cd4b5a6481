/* PSNR between two RGBA images over the R, G, B channels (dB; INFINITY when identical). */
#ifndef PL_TEST_GL_PSNR_H
#define PL_TEST_GL_PSNR_H
#include <math.h>
#include "backend_cairo.h"

static inline double pl_psnr(const pl_image *a, const pl_image *b)
{
    if (a->width != b->width || a->height != b->height) return -1.0;
    double se = 0.0;
    size_t n = (size_t)a->width * (size_t)a->height;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            double d = (double)a->rgba[4 * i + k] - (double)b->rgba[4 * i + k];
            se += d * d;
        }
    double mse = se / (3.0 * (double)n);
    return mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
}
#endif
