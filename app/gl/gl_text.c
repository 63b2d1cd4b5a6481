/* Glyph atlas: FreeType rasterization into a shelf-packed coverage texture. */
#include "gl_text.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_GLYPH_H
#include FT_STROKER_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "backend_cairo.h" /* PL_FONT_PATH: one font for both backends */

#define PAD 1

int pl_glyph_atlas_init(pl_glyph_atlas *a, char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    FT_Library lib;
    FT_Face face;
    if (FT_Init_FreeType(&lib)) {
        snprintf(err, errlen, "FreeType could not be initialised");
        return -1;
    }
    if (FT_New_Face(lib, PL_FONT_PATH, 0, &face)) {
        snprintf(err, errlen, "cannot load the font %s (install the Debian package "
                 "fonts-dejavu-core)", PL_FONT_PATH);
        FT_Done_FreeType(lib);
        return -1;
    }
    FT_Stroker stroker;
    if (FT_Stroker_New(lib, &stroker)) {
        snprintf(err, errlen, "FreeType could not create a stroker");
        FT_Done_Face(face);
        FT_Done_FreeType(lib);
        return -1;
    }
    a->pixels = calloc((size_t)PL_ATLAS_SIZE * PL_ATLAS_SIZE, 1);
    a->table_cap = 4096;
    a->table = calloc((size_t)a->table_cap, sizeof *a->table);
    if (!a->pixels || !a->table) {
        snprintf(err, errlen, "out of memory for the glyph atlas");
        free(a->pixels);
        free(a->table);
        FT_Stroker_Done(stroker);
        FT_Done_Face(face);
        FT_Done_FreeType(lib);
        return -1;
    }
    a->ft_lib = lib;
    a->ft_face = face;
    a->ft_stroker = stroker;
    a->ascender = (double)face->ascender / face->units_per_EM;
    a->descender = (double)face->descender / face->units_per_EM;
    a->dirty = 1;
    return 0;
}

void pl_glyph_atlas_free(pl_glyph_atlas *a)
{
    if (a->ft_stroker) FT_Stroker_Done((FT_Stroker)a->ft_stroker);
    if (a->ft_face) FT_Done_Face((FT_Face)a->ft_face);
    if (a->ft_lib) FT_Done_FreeType((FT_Library)a->ft_lib);
    free(a->pixels);
    free(a->glyphs);
    free(a->table);
    memset(a, 0, sizeof *a);
}

static void atlas_clear(pl_glyph_atlas *a)
{
    memset(a->pixels, 0, (size_t)PL_ATLAS_SIZE * PL_ATLAS_SIZE);
    memset(a->table, 0, (size_t)a->table_cap * sizeof *a->table);
    a->count = 0;
    a->shelf_x = a->shelf_y = a->shelf_h = 0;
    a->dirty = 1;
    a->generation++;
}

static uint32_t hash3(uint32_t c, uint32_t s, uint32_t h)
{
    uint32_t x = c * 0x9E3779B1u ^ (s + 0x7F4A7C15u) * 0x85EBCA77u ^ h * 0xC2B2AE3Du;
    x ^= x >> 15;
    x *= 0x2C1B3C6Du;
    x ^= x >> 12;
    return x;
}

static int table_find(const pl_glyph_atlas *a, uint32_t c, uint32_t s, uint32_t h, int *slot)
{
    uint32_t mask = (uint32_t)a->table_cap - 1u;
    for (uint32_t i = hash3(c, s, h) & mask;; i = (i + 1u) & mask) {
        int v = a->table[i];
        if (v == 0) {
            *slot = (int)i;
            return -1;
        }
        const pl_glyph *g = &a->glyphs[v - 1];
        if (g->code == c && g->size_q == s && g->halo == h) return v - 1;
    }
}

/* Reserves a w x h rectangle on the shelves; 0 or -1 when full. */
static int place(pl_glyph_atlas *a, int w, int h, int *x, int *y)
{
    if (w + PAD > PL_ATLAS_SIZE || h + PAD > PL_ATLAS_SIZE) return -1;
    if (a->shelf_x + w + PAD > PL_ATLAS_SIZE) {
        a->shelf_y += a->shelf_h;
        a->shelf_x = 0;
        a->shelf_h = 0;
    }
    if (a->shelf_y + h + PAD > PL_ATLAS_SIZE) return -1;
    *x = a->shelf_x + PAD;
    *y = a->shelf_y + PAD;
    a->shelf_x += w + PAD;
    if (h + PAD > a->shelf_h) a->shelf_h = h + PAD;
    return 0;
}

static const pl_glyph *add_glyph(pl_glyph_atlas *a, uint32_t code, uint32_t size_q, int halo,
                                 int slot)
{
    FT_Face face = (FT_Face)a->ft_face;
    double px = size_q / 4.0;
    if (FT_Set_Char_Size(face, 0, (FT_F26Dot6)lround(px * 64.0), 72, 72)) return NULL;
    FT_UInt gi = FT_Get_Char_Index(face, code);
    if (FT_Load_Glyph(face, gi, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP)) return NULL;
    double advance = (double)face->glyph->linearHoriAdvance / 65536.0;
    FT_Glyph glyph;
    if (FT_Get_Glyph(face->glyph, &glyph)) return NULL;
    if (halo) {
        FT_Stroker_Set((FT_Stroker)a->ft_stroker, (FT_Fixed)lround(0.11 * px * 64.0),
                       FT_STROKER_LINECAP_ROUND, FT_STROKER_LINEJOIN_ROUND, 0);
        if (FT_Glyph_Stroke(&glyph, (FT_Stroker)a->ft_stroker, 1)) {
            FT_Done_Glyph(glyph);
            return NULL;
        }
    }
    if (FT_Glyph_To_Bitmap(&glyph, FT_RENDER_MODE_NORMAL, NULL, 1)) {
        FT_Done_Glyph(glyph);
        return NULL;
    }
    FT_BitmapGlyph bg = (FT_BitmapGlyph)glyph;
    int w = (int)bg->bitmap.width, h = (int)bg->bitmap.rows;
    int x = 0, y = 0;
    if (w > 0 && h > 0 && place(a, w, h, &x, &y) != 0) {
        FT_Done_Glyph(glyph);
        return NULL; /* caller clears and retries */
    }
    if (a->count == a->cap) {
        int nc = a->cap ? 2 * a->cap : 256;
        pl_glyph *ng = realloc(a->glyphs, (size_t)nc * sizeof *ng);
        if (!ng) {
            FT_Done_Glyph(glyph);
            return NULL;
        }
        a->glyphs = ng;
        a->cap = nc;
    }
    for (int r = 0; r < h; r++)
        memcpy(a->pixels + (size_t)(y + r) * PL_ATLAS_SIZE + (size_t)x,
               bg->bitmap.buffer + (ptrdiff_t)r * bg->bitmap.pitch, (size_t)w);
    pl_glyph *g = &a->glyphs[a->count];
    g->code = code;
    g->size_q = size_q;
    g->halo = (uint32_t)halo;
    g->x = x;
    g->y = y;
    g->w = w;
    g->h = h;
    g->left = bg->left;
    g->top = bg->top;
    g->advance = advance;
    a->table[slot] = ++a->count;
    a->dirty = 1;
    FT_Done_Glyph(glyph);
    return g;
}

const pl_glyph *pl_glyph_get(pl_glyph_atlas *a, uint32_t code, float size, int halo)
{
    uint32_t size_q = (uint32_t)lroundf(size * 4.0f);
    if (size_q < 4) size_q = 4;
    if (size_q > 4 * 400) size_q = 4 * 400;
    int slot;
    int i = table_find(a, code, size_q, (uint32_t)halo, &slot);
    if (i >= 0) return &a->glyphs[i];
    if (2 * (a->count + 1) > a->table_cap) { /* keep the table sparse */
        atlas_clear(a);
        table_find(a, code, size_q, (uint32_t)halo, &slot);
    }
    const pl_glyph *g = add_glyph(a, code, size_q, halo, slot);
    if (!g && a->count > 0) {
        atlas_clear(a);
        table_find(a, code, size_q, (uint32_t)halo, &slot);
        g = add_glyph(a, code, size_q, halo, slot);
    }
    return g;
}

uint32_t pl_utf8_next(const char **sp)
{
    const unsigned char *s = (const unsigned char *)*sp;
    uint32_t c = s[0];
    int n = 0;
    if (c < 0x80) n = 0;
    else if ((c & 0xE0) == 0xC0) { c &= 0x1F; n = 1; }
    else if ((c & 0xF0) == 0xE0) { c &= 0x0F; n = 2; }
    else if ((c & 0xF8) == 0xF0) { c &= 0x07; n = 3; }
    else {
        *sp += 1;
        return 0xFFFD;
    }
    for (int k = 1; k <= n; k++) {
        if ((s[k] & 0xC0) != 0x80) {
            *sp += k;
            return 0xFFFD;
        }
        c = (c << 6) | (s[k] & 0x3F);
    }
    *sp += n + 1;
    return c;
}

double pl_text_advance(pl_glyph_atlas *a, const char *s, float size)
{
    double x = 0.0;
    while (*s) {
        uint32_t c = pl_utf8_next(&s);
        const pl_glyph *g = pl_glyph_get(a, c, size, 0);
        if (g) x += g->advance;
    }
    return x;
}
