/* gl_psnr A.png B.png [MIN_DB [X Y W H]]: prints the PSNR of two PNGs (RGB channels), of the
 * whole images or of the rectangle X, Y, W, H (pixels, clipped); exits 1 when it is below
 * MIN_DB (or the sizes differ), 2 on a read error. "inf" for identical images. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "backend_cairo.h"
#include "gl_psnr.h"

/* Crops both images to the rectangle of argv[4..7] when given; 0, or 2 after a message. */
static int crop(pl_image *a, pl_image *b, int argc, char **argv)
{
    if (argc <= 7 || a->width != b->width || a->height != b->height) return 0;
    int x0 = atoi(argv[4]), y0 = atoi(argv[5]), w = atoi(argv[6]), h = atoi(argv[7]);
    if (x0 < 0) { w += x0; x0 = 0; }
    if (y0 < 0) { h += y0; y0 = 0; }
    if (x0 + w > a->width) w = a->width - x0;
    if (y0 + h > a->height) h = a->height - y0;
    if (w <= 0 || h <= 0) {
        fprintf(stderr, "gl_psnr: the rectangle is outside the images\n");
        return 2;
    }
    pl_image *im[2] = {a, b};
    for (int k = 0; k < 2; k++) {
        for (int y = 0; y < h; y++)
            memmove(im[k]->rgba + (size_t)y * (size_t)w * 4,
                    im[k]->rgba + ((size_t)(y0 + y) * (size_t)im[k]->width + (size_t)x0) * 4,
                    (size_t)w * 4);
        im[k]->width = w;
        im[k]->height = h;
    }
    return 0;
}

static int compare(pl_image *a, pl_image *b, int argc, char **argv)
{
    if (crop(a, b, argc, argv) != 0) return 2;
    double p = pl_psnr(a, b);
    if (p < 0) {
        printf("sizes differ: %dx%d vs %dx%d\n", a->width, a->height, b->width, b->height);
        return 1;
    }
    printf("%.3f\n", p);
    double min = argc > 3 ? atof(argv[3]) : 0.0;
    return p >= min ? 0 : 1;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: gl_psnr A.png B.png [MIN_DB [X Y W H]]\n");
        return 2;
    }
    pl_image a = {0, 0, NULL}, b = {0, 0, NULL};
    char err[512];
    int rc = 2;
    if (pl_png_read(argv[1], &a, err, sizeof err) || pl_png_read(argv[2], &b, err, sizeof err))
        fprintf(stderr, "gl_psnr: %s\n", err);
    else
        rc = compare(&a, &b, argc, argv);
    pl_image_free(&a);
    pl_image_free(&b);
    return rc;
}
