/// Software rasterizer for Gouraud triangles into a premultiplied ARGB32 pixel buffer (the
/// layout of a cairo image surface). The cairo backend uses it for filled fields on image
/// surfaces: one pass over the pixels of each triangle instead of a cairo mesh pattern
/// (which tessellates every patch into sub-patches), with the same coverage rule as cairo's
/// mesh rasterizer: a pixel is painted when the triangle touches it (no antialiasing), in
/// the colour interpolated at the pixel centre, later triangles over earlier ones.
#ifndef PORELAB_RASTER_GOURAUD_H
#define PORELAB_RASTER_GOURAUD_H

#include <stdint.h>
#include "drawlist.h"

/// Paints n triangles (pts[3 t + k] in pixels, colours col[3 t + k], non-premultiplied
/// RGBA in 0..1) into buf, a w x h premultiplied ARGB32 image whose pixel (0, 0) sits at
/// pixel (ox, oy) of the picture; stride in bytes. Pixels are replaced, not blended.
void pl_raster_gouraud(uint8_t *buf, int w, int h, int stride, int ox, int oy,
                       const pl_vec2 *pts, const pl_rgba *col, int n);

#endif
