/// cairo backend: rasterizes a draw list onto a cairo context (image, SVG or PDF surface).
/// Text uses DejaVu Sans loaded explicitly from fonts-dejavu-core through FreeType, with
/// hinting off and grey antialiasing, so the same list gives the same pixels everywhere the
/// same cairo/pixman/FreeType versions run (and nearly the same pixels elsewhere).
#ifndef PORELAB_BACKEND_CAIRO_H
#define PORELAB_BACKEND_CAIRO_H

#include <stddef.h>
#include <stdint.h>
#include <cairo.h>
#include "drawlist.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Path of the font used for all text.
#define PL_FONT_PATH "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

/// Returns the shared DejaVu Sans font face (loaded once, kept for the process), or NULL
/// with a message in err when the font file cannot be loaded.
cairo_font_face_t *pl_cairo_font_face(char *err, size_t errlen);

/// Draws the list (background first) onto cr, whose user space is pixels of size
/// dl->camera.width x dl->camera.height. Returns 0, or -1 with a message.
int pl_cairo_draw(cairo_t *cr, const pl_draw_list *dl, char *err, size_t errlen);

/// An 8-bit RGBA image (not premultiplied), rows top to bottom, stride = 4 * width.
typedef struct pl_image {
    int width, height;
    uint8_t *rgba;
} pl_image;

void pl_image_free(pl_image *img);

/// Rasterizes the list into img (allocated or reused when the size matches).
/// Returns 0, or -1 with a message.
int pl_cairo_rasterize(const pl_draw_list *dl, pl_image *img, char *err, size_t errlen);

/// Writes the list to path: .png (raster), .svg or .pdf (vector, same drawing code).
/// png_level is the zlib level for PNG (1 = fast, 6 = smaller files).
int pl_cairo_write_file(const pl_draw_list *dl, const char *path, int png_level, char *err,
                        size_t errlen);

/// Writes an RGBA image as PNG with libpng at the given zlib level (0..9). When every pixel
/// is opaque the file is RGB. filter = 0 writes no row filters (fastest), 1 lets libpng
/// choose (smaller files). Returns 0, or -1 with a message.
int pl_png_write(const char *path, const pl_image *img, int level, int filter, char *err,
                 size_t errlen);

/// Reads any 8/16-bit PNG (grey, palette, RGB, with or without alpha) into RGBA 8-bit.
int pl_png_read(const char *path, pl_image *img, char *err, size_t errlen);

/// SVG text: cairo's SVG surface writes text as glyph outlines, so porelab's SVG stills get
/// their text as <text> elements (DejaVu Sans, same size, position and rotation) inserted
/// into the finished file before </svg>, above the drawing. Returns 0 or -1 with a message.
int pl_svg_append_text(const pl_draw_list *dl, const char *path, char *err, size_t errlen);

/// Baseline start of a text primitive relative to its anchor (px, before rotation).
void pl_cairo_text_origin(cairo_t *cr, const pl_prim *p, const char *s, double *ox, double *oy);

/// Format of a file name: 0 png, 1 svg, 2 pdf, -1 unknown (case-insensitive extension).
int pl_file_format(const char *path);

#ifdef __cplusplus
}
#endif
#endif
