/// Glyph atlas for the GL backend: DejaVu Sans (the cairo backend's font, fonts-dejavu-core)
/// rasterized by FreeType with hinting off at the exact pixel size asked for, packed into
/// one 8-bit coverage texture. Halo glyphs (the outline stroked by FreeType's stroker, the
/// same width as cairo's halo) are separate entries. The atlas lives on the CPU; the GL
/// backend uploads it when it changed.
#ifndef PORELAB_GL_TEXT_H
#define PORELAB_GL_TEXT_H

#include <stddef.h>
#include <stdint.h>

#define PL_ATLAS_SIZE 1024

typedef struct pl_glyph {
    uint32_t code;       /* Unicode code point */
    uint32_t size_q;     /* pixel size x 4, rounded */
    uint32_t halo;       /* 1 = halo glyph */
    int x, y, w, h;      /* rectangle in the atlas, texels */
    int left, top;       /* bitmap offset from the pen position (top is up), px */
    double advance;      /* unhinted advance, px */
} pl_glyph;

typedef struct pl_glyph_atlas {
    uint8_t *pixels;     /* PL_ATLAS_SIZE^2 coverage, row 0 at the top */
    int dirty;           /* pixels changed since the last upload */
    int shelf_x, shelf_y, shelf_h;
    pl_glyph *glyphs;
    int count, cap;
    int *table; int table_cap; /* open-addressing hash: index + 1, 0 = empty */
    void *ft_lib, *ft_face, *ft_stroker;
    double ascender, descender; /* per pixel of size (descender negative) */
    int generation;      /* incremented when the atlas is cleared */
} pl_glyph_atlas;

/// Loads the font. Returns 0, or -1 with a message.
int pl_glyph_atlas_init(pl_glyph_atlas *a, char *err, size_t errlen);
void pl_glyph_atlas_free(pl_glyph_atlas *a);
/// The glyph for code point code at size px (halo: outline stroked with radius 0.11 size).
/// Returns NULL only when the atlas is full even after clearing (a glyph larger than it).
/// May clear the atlas (generation changes): callers re-fetch glyphs of a string after that.
const pl_glyph *pl_glyph_get(pl_glyph_atlas *a, uint32_t code, float size, int halo);
/// Decodes one UTF-8 code point at *s and advances *s (invalid bytes give U+FFFD).
uint32_t pl_utf8_next(const char **s);
/// Width of a string (sum of unhinted advances, no kerning, as cairo's toy text API), px.
double pl_text_advance(pl_glyph_atlas *a, const char *s, float size);

#endif
