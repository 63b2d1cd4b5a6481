/* State images: a growable byte buffer that models write their state into (save) and read it
 * back from (load), with counted arrays so that a damaged or foreign image is refused instead of
 * read past its end. The file format around these sections is in world/snapshot_file.c. */
#include "core/alloc.h"
#include "world/image_internal.h"
#include <stdlib.h>
#include <string.h>

pl_status pl__image_put(pl_image *img, const void *data, size_t bytes) {
    if (img->failed) return PL_ERR_NOMEM;
    if (bytes > SIZE_MAX - img->len) return img->failed = 1, PL_ERR_NOMEM;
    if (img->len + bytes > img->cap) {
        size_t nc = img->cap ? img->cap : 4096;
        while (nc < img->len + bytes) {
            if (nc > SIZE_MAX / 2) return img->failed = 1, PL_ERR_NOMEM;
            nc *= 2;
        }
        unsigned char *p = pl_realloc(img->data, nc);
        if (!p) return img->failed = 1, PL_ERR_NOMEM;
        img->data = p;
        img->cap = nc;
    }
    if (bytes) memcpy(img->data + img->len, data, bytes);
    img->len += bytes;
    return PL_OK;
}

pl_status pl__image_get(pl_image *img, void *data, size_t bytes) {
    if (img->failed || bytes > img->len - img->pos) return img->failed = 1, PL_ERR_IO;
    if (bytes) memcpy(data, img->data + img->pos, bytes);
    img->pos += bytes;
    return PL_OK;
}

pl_status pl__image_put_array(pl_image *img, const void *data, size_t elem, size_t count) {
    const uint64_t n = count, e = elem;
    pl_status st = pl__image_put(img, &n, sizeof n);
    if (st == PL_OK) st = pl__image_put(img, &e, sizeof e);
    if (st == PL_OK && count) st = pl__image_put(img, data, elem * count);
    return st;
}

pl_status pl__image_get_array(pl_image *img, void *data, size_t elem, size_t count) {
    uint64_t n = 0, e = 0;
    if (pl__image_get(img, &n, sizeof n) != PL_OK || pl__image_get(img, &e, sizeof e) != PL_OK) return PL_ERR_IO;
    if (n != count || e != elem) return img->failed = 1, PL_ERR_IO;
    return count ? pl__image_get(img, data, elem * count) : PL_OK;
}

size_t pl__image_left(const pl_image *img) { return img->failed ? 0 : img->len - img->pos; }

void pl__image_free(pl_image *img) {
    pl_free(img->data);
    memset(img, 0, sizeof *img);
}
