/* gl_psnr A.png B.png [MIN_DB]: prints the PSNR of two PNGs (RGB channels); exits 1 when it
 * is below MIN_DB (or the sizes differ), 2 on a read error. "inf" for identical images. */
#include <stdio.h>
#include <stdlib.h>

#include "backend_cairo.h"
#include "gl_psnr.h"

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: gl_psnr A.png B.png [MIN_DB]\n");
        return 2;
    }
    pl_image a = {0, 0, NULL}, b = {0, 0, NULL};
    char err[512];
    if (pl_png_read(argv[1], &a, err, sizeof err) || pl_png_read(argv[2], &b, err, sizeof err)) {
        fprintf(stderr, "gl_psnr: %s\n", err);
        return 2;
    }
    double p = pl_psnr(&a, &b);
    if (p < 0) {
        printf("sizes differ: %dx%d vs %dx%d\n", a.width, a.height, b.width, b.height);
        return 1;
    }
    printf("%.3f\n", p);
    double min = argc > 3 ? atof(argv[3]) : 0.0;
    return p >= min ? 0 : 1;
}
