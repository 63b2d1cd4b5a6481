/// Colour maps. Both maps are built here from the OKLab colour space (Ottosson 2020), so that
/// equal steps of the mapped value give equal perceived steps of colour:
///  - PL_CMAP_SEQUENTIAL ("viridis-like"): lightness rises linearly from dark violet-blue
///    through teal and green to light yellow; for magnitudes (speed, stress, |velocity|).
///  - PL_CMAP_DIVERGING: dark blue -> near white -> dark red with lightness symmetric about
///    the middle; for signed fields (excess pore pressure), centred on zero.
/// Colours are tabulated in 256 entries and interpolated linearly between them.
#ifndef PORELAB_COLORMAP_H
#define PORELAB_COLORMAP_H

#include "render.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum pl_colormap {
    PL_CMAP_SEQUENTIAL = 0,
    PL_CMAP_DIVERGING = 1
} pl_colormap;

/// Colour at t in [0, 1] (clamped; NaN gives mid grey).
pl_rgba pl_colormap_eval(pl_colormap map, double t);

/// Colour of value v on [vmin, vmax] (a diverging map should be given symmetric bounds).
pl_rgba pl_colormap_value(pl_colormap map, double v, double vmin, double vmax);

/// OKLab coordinates (L, a, b) of an sRGB colour (components 0..1); for tests and docs.
void pl_srgb_to_oklab(const pl_rgba *c, double lab[3]);

/// Qualitative palette for materials (index cycled): soft, distinguishable fills.
pl_rgba pl_material_palette(int index);

#ifdef __cplusplus
}
#endif
#endif
