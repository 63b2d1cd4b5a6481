/* The layout of a state image buffer (world/image.c). */
#ifndef PL_IMAGE_INTERNAL_H
#define PL_IMAGE_INTERNAL_H
#include "world/model.h"
#include <stdint.h>

struct pl_image {
    unsigned char *data;
    size_t len, cap;  /* bytes written / allocated */
    size_t pos;       /* read cursor */
    int failed;       /* a put ran out of memory or a get ran past the end: every later call fails */
};

void pl__image_free(pl_image *img);
#endif
