/* Formatted output into memory, handed whole to the host's file writer (porelab/core.h). */
#ifndef PL_CORE_OUT_H
#define PL_CORE_OUT_H
#include "porelab/core.h"
#include <stddef.h>

typedef struct pl_out {
    char *buf;
    size_t len, cap;
    int failed; /* out of memory: the file is refused when written */
} pl_out;

void pl_out_printf(pl_out *o, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* Hands the text to fw (NULL: refused) and frees it. PL_OK, PL_ERR_NOMEM, or PL_ERR_IO with
   the writer's message in msg. */
pl_status pl_out_write(pl_out *o, const pl_file_writer *fw, const char *path, int append, char *msg, size_t msglen);
void pl_out_free(pl_out *o);
#endif
