/* Formatted output into memory for the host's file writer (core/out.h). */
#include "core/out.h"
#include "core/alloc.h"
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

void pl_out_printf(pl_out *o, const char *fmt, ...) {
    if (o->failed) return;
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        const size_t room = o->cap - o->len;
        const int n = vsnprintf(o->buf ? o->buf + o->len : NULL, o->buf ? room : 0, fmt, ap);
        va_end(ap);
        if (n < 0) {
            o->failed = 1;
            return;
        }
        if (o->buf && (size_t)n < room) {
            o->len += (size_t)n;
            return;
        }
        size_t nc = o->cap ? 2 * o->cap : 65536;
        while (nc < o->len + (size_t)n + 1) nc *= 2;
        char *p = pl_realloc(o->buf, nc);
        if (!p) {
            o->failed = 1;
            return;
        }
        o->buf = p;
        o->cap = nc;
    }
}

void pl_out_free(pl_out *o) {
    pl_free(o->buf);
    o->buf = NULL;
    o->len = o->cap = 0;
    o->failed = 0;
}

pl_status pl_out_write(pl_out *o, const pl_file_writer *fw, const char *path, int append, char *msg, size_t msglen) {
    pl_status st = PL_OK;
    if (o->failed) {
        snprintf(msg, msglen, "out of memory formatting '%s'", path);
        st = PL_ERR_NOMEM;
    } else if (!fw || !fw->write) {
        snprintf(msg, msglen, "cannot write '%s': this program gives the engine no file writer "
                              "(pl_world_set_file_writer)", path);
        st = PL_ERR_IO;
    } else if (fw->write(fw->ctx, path, append, o->buf ? o->buf : "", o->len, msg, msglen) != 0) {
        st = PL_ERR_IO;
    }
    pl_out_free(o);
    return st;
}
