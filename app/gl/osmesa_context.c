/* Headless GL context through OSMesa. The context draws into a tiny client buffer; all
 * real rendering goes to the backend's framebuffer objects, so any image size up to the
 * GL limit works without reallocating the OSMesa buffer. */
#include "osmesa_context.h"

#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct pl_osmesa {
    OSMesaContext ctx;
    unsigned char buffer[16 * 16 * 4];
    pl_gl *gl;
    pl_image img;
};

static void *get_proc(const char *name)
{
    OSMESAproc p = OSMesaGetProcAddress(name);
    void *q;
    memcpy(&q, &p, sizeof q);
    return q;
}

int pl_osmesa_make_current(pl_osmesa *o, char *err, size_t errlen)
{
    if (!OSMesaMakeCurrent(o->ctx, o->buffer, GL_UNSIGNED_BYTE, 16, 16)) {
        snprintf(err, errlen, "OSMesaMakeCurrent failed");
        return -1;
    }
    return 0;
}

pl_osmesa *pl_osmesa_create(int samples, char *err, size_t errlen)
{
    pl_osmesa *o = calloc(1, sizeof *o);
    if (!o) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    o->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!o->ctx) {
        snprintf(err, errlen, "OSMesa could not create a GL context (is Mesa's libOSMesa "
                 "installed? Debian package libosmesa6)");
        free(o);
        return NULL;
    }
    if (pl_osmesa_make_current(o, err, errlen) != 0) {
        OSMesaDestroyContext(o->ctx);
        free(o);
        return NULL;
    }
    o->gl = pl_gl_create(get_proc, samples, err, errlen);
    if (!o->gl) {
        OSMesaDestroyContext(o->ctx);
        free(o);
        return NULL;
    }
    return o;
}

void pl_osmesa_destroy(pl_osmesa **op)
{
    if (!op || !*op) return;
    pl_osmesa *o = *op;
    char err[64];
    pl_osmesa_make_current(o, err, sizeof err);
    pl_gl_destroy(&o->gl);
    OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(o->ctx);
    pl_image_free(&o->img);
    free(o);
    *op = NULL;
}

pl_gl *pl_osmesa_gl(pl_osmesa *o) { return o->gl; }

int pl_osmesa_rasterize(pl_osmesa *o, const pl_draw_list *dl, pl_image *img, char *err,
                        size_t errlen)
{
    if (OSMesaGetCurrentContext() != o->ctx && pl_osmesa_make_current(o, err, errlen) != 0)
        return -1;
    if (pl_gl_render(o->gl, dl, err, errlen) != 0) return -1;
    return pl_gl_read(o->gl, img, err, errlen);
}

int pl_osmesa_write_png(pl_osmesa *o, const pl_draw_list *dl, const char *path, int png_level,
                        char *err, size_t errlen)
{
    if (pl_osmesa_rasterize(o, dl, &o->img, err, errlen) != 0) return -1;
    return pl_png_write(path, &o->img, png_level, png_level > 1, err, errlen);
}

static pl_osmesa *shared;

static void free_shared(void) { pl_osmesa_destroy(&shared); }

pl_osmesa *pl_osmesa_shared(char *err, size_t errlen)
{
    if (!shared) {
        shared = pl_osmesa_create(0, err, errlen);
        if (shared) atexit(free_shared);
    }
    return shared;
}
