/* PNG reading and writing with libpng. Writing uses a low zlib level and no row filters by
 * default for frames, so encoding does not dominate short runs. A PNG is written under a
 * temporary name and renamed into place when complete (atomic_file.h). */
#include "atomic_file.h"
#include "backend_cairo.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct png_err_ctx {
    char msg[256];
} png_err_ctx;

static void on_png_error(png_structp png, png_const_charp msg) {
    png_err_ctx *ctx = png_get_error_ptr(png);
    snprintf(ctx->msg, sizeof ctx->msg, "%s", msg);
    png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp msg) {
    (void)png;
    (void)msg;
}

static int all_opaque(const pl_image *img) {
    size_t n = (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++)
        if (img->rgba[4 * i + 3] != 255) return 0;
    return 1;
}

int pl_png_write(const char *path, const pl_image *img, int level, int filter, char *err,
                 size_t errlen) {
    const int w = img->width, h = img->height;
    const int op = all_opaque(img);
    volatile int opaque = op; /* read after setjmp */
    volatile int channels = op ? 3 : 4;
    volatile int zlevel = level < 0 ? 0 : (level > 9 ? 9 : level);
    pl_atomic_file af;
    if (pl_atomic_file_begin(&af, path, err, errlen)) return -1;
    uint8_t *row = malloc((size_t)w * 4u);
    FILE *f = fopen(af.tmp_path, "wb");
    if (!f || !row) {
        snprintf(err, errlen, "cannot write %s: %s", path, f ? "out of memory" : strerror(errno));
        if (f) fclose(f);
        free(row);
        return pl_atomic_file_end(&af, 0, err, errlen);
    }
    png_err_ctx ctx;
    ctx.msg[0] = 0;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx, on_png_error, on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info) {
        snprintf(err, errlen, "cannot write %s: libpng could not start", path);
        png_destroy_write_struct(&png, &info);
        fclose(f);
        free(row);
        return pl_atomic_file_end(&af, 0, err, errlen);
    }
    if (setjmp(png_jmpbuf(png))) {
        /* libpng's "Write Error" says nothing of the cause; errno still holds it */
        int e = errno;
        snprintf(err, errlen, "cannot write %s: %s%s%s", path, ctx.msg, e ? ": " : "",
                 e ? strerror(e) : "");
        png_destroy_write_struct(&png, &info);
        fclose(f);
        free(row);
        return pl_atomic_file_end(&af, 0, err, errlen);
    }
    errno = 0;
    png_init_io(png, f);
    png_set_compression_level(png, zlevel);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, filter ? PNG_ALL_FILTERS : PNG_FILTER_NONE);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8,
                 opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    for (int y = 0; y < h; y++) {
        const uint8_t *src = img->rgba + (size_t)y * (size_t)w * 4u;
        if (channels == 4) {
            png_write_row(png, src);
        } else {
            for (int x = 0; x < w; x++) {
                row[3 * x] = src[4 * x];
                row[3 * x + 1] = src[4 * x + 1];
                row[3 * x + 2] = src[4 * x + 2];
            }
            png_write_row(png, row);
        }
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row);
    int bad = fflush(f) != 0 || ferror(f);
    int e = errno;
    if (fclose(f) != 0 && !bad) bad = 1, e = errno;
    if (bad) {
        snprintf(err, errlen, "cannot write %s: %s", path, strerror(e));
        return pl_atomic_file_end(&af, 0, err, errlen);
    }
    return pl_atomic_file_end(&af, 1, err, errlen);
}

int pl_png_read(const char *path, pl_image *img, char *err, size_t errlen) {
    img->rgba = NULL;
    img->width = img->height = 0;
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "cannot read %s: %s", path, strerror(errno));
        return -1;
    }
    unsigned char sig[8];
    if (fread(sig, 1, 8, f) != 8 || png_sig_cmp(sig, 0, 8)) {
        snprintf(err, errlen, "%s is not a PNG file", path);
        fclose(f);
        return -1;
    }
    png_err_ctx ctx;
    ctx.msg[0] = 0;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, on_png_error, on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    uint8_t *volatile buf = NULL;
    if (!png || !info) {
        snprintf(err, errlen, "cannot read %s: libpng could not start", path);
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        snprintf(err, errlen, "cannot read %s: %s", path, ctx.msg);
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        free(buf);
        return -1;
    }
    png_init_io(png, f);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    int ct = png_get_color_type(png, info);
    png_set_expand(png);
    png_set_strip_16(png);
    if (ct == PNG_COLOR_TYPE_GRAY || ct == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != (size_t)w * 4u || w > 32768 || h > 32768) {
        snprintf(err, errlen, "cannot read %s: unsupported PNG layout", path);
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        return -1;
    }
    buf = malloc((size_t)w * (size_t)h * 4u);
    if (!buf) {
        snprintf(err, errlen, "cannot read %s: out of memory", path);
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        return -1;
    }
    for (int pass = 0; pass < passes; pass++)
        for (png_uint_32 y = 0; y < h; y++) png_read_row(png, buf + (size_t)y * w * 4u, NULL);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    fclose(f);
    img->rgba = buf;
    img->width = (int)w;
    img->height = (int)h;
    return 0;
}
