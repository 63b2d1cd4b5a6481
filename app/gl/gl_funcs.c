/* Loads the GL entry points through the context's get-proc-address function. */
#include "gl_funcs.h"

#include <stdio.h>
#include <string.h>

/* Function pointers and object pointers have the same size on every platform porelab
 * targets (POSIX requires it for dlsym); memcpy avoids the ISO C cast warning. */
static int load_one(void *slot, pl_gl_get_proc get_proc, const char *name)
{
    void *p = get_proc(name);
    if (!p) {
        /* ARB/EXT spellings for drivers that only expose the extension */
        char alt[96];
        snprintf(alt, sizeof alt, "%sARB", name);
        p = get_proc(alt);
        if (!p) {
            snprintf(alt, sizeof alt, "%sEXT", name);
            p = get_proc(alt);
        }
    }
    memcpy(slot, &p, sizeof p);
    return p != NULL;
}

int pl_gl_funcs_load(pl_gl_funcs *f, pl_gl_get_proc get_proc, char *err, unsigned errlen)
{
    memset(f, 0, sizeof *f);
#define PL_GL_LOAD_REQ(ret, name, args)                                                       \
    if (!load_one(&f->name, get_proc, "gl" #name)) {                                          \
        snprintf(err, errlen, "the OpenGL implementation lacks gl" #name                      \
                 " (porelab needs OpenGL 2.1 with framebuffer objects)");                     \
        return -1;                                                                            \
    }
#define PL_GL_LOAD_OPT(ret, name, args) load_one(&f->name, get_proc, "gl" #name);
    PL_GL_REQUIRED(PL_GL_LOAD_REQ)
    PL_GL_OPTIONAL(PL_GL_LOAD_OPT)
#undef PL_GL_LOAD_REQ
#undef PL_GL_LOAD_OPT
    return 0;
}
