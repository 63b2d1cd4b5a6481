/* A plain stdio file writer for tests that drive the engine without the Lua binding (the
 * engine opens no files itself: porelab/core.h pl_file_writer). */
#ifndef PL_TEST_STDIO_WRITER_H
#define PL_TEST_STDIO_WRITER_H
#include "porelab/core.h"
#include <stdio.h>
#include <string.h>

static int pl_test_stdio_write(void *ctx, const char *path, int append, const void *data, size_t len, char *msg,
                               size_t msglen) {
    (void)ctx;
    FILE *f = fopen(path, append ? "a" : "w");
    if (!f) {
        snprintf(msg, msglen, "cannot open '%s'", path);
        return -1;
    }
    const int bad = fwrite(data, 1, len, f) != len;
    return (fclose(f) != 0 || bad) ? (snprintf(msg, msglen, "cannot write '%s'", path), -1) : 0;
}
static const pl_file_writer pl_test_stdio_writer = {pl_test_stdio_write, NULL};
#endif
