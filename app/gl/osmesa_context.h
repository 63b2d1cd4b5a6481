/// Headless OpenGL through OSMesa (Debian libosmesa6-dev; Mesa's llvmpipe): the GL backend
/// without a window or display, for `--renderer gl`, the GL tests and benchmarks.
#ifndef PORELAB_OSMESA_CONTEXT_H
#define PORELAB_OSMESA_CONTEXT_H

#include <stddef.h>
#include "backend_gl.h"

typedef struct pl_osmesa pl_osmesa;

/// Creates an OSMesa context (compatibility profile) and the GL renderer in it.
/// samples as in pl_gl_create. NULL with a message.
pl_osmesa *pl_osmesa_create(int samples, char *err, size_t errlen);
void pl_osmesa_destroy(pl_osmesa **o);
/// Makes the context current on this thread (after another context was used).
int pl_osmesa_make_current(pl_osmesa *o, char *err, size_t errlen);
pl_gl *pl_osmesa_gl(pl_osmesa *o);

/// Rasterizes a draw list into img (allocated or reused). Returns 0, or -1 with a message.
int pl_osmesa_rasterize(pl_osmesa *o, const pl_draw_list *dl, pl_image *img, char *err,
                        size_t errlen);
/// Rasterizes and writes a PNG (zlib level png_level). Returns 0, or -1 with a message.
int pl_osmesa_write_png(pl_osmesa *o, const pl_draw_list *dl, const char *path, int png_level,
                        char *err, size_t errlen);

/// The process-wide headless renderer used by the CLI (created on first use, freed at exit).
pl_osmesa *pl_osmesa_shared(char *err, size_t errlen);

#endif
