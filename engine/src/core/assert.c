/* The assertion handler (porelab/assert.h, core/assert.h). */
#include "core/assert.h"
#include <stdio.h>
#include <stdlib.h>

static void default_handler(const char *file, int line, const char *expr, void *ctx) {
    (void)ctx;
    fprintf(stderr, "%s:%d: assertion failed: %s\n", file, line, expr);
    fflush(stderr);
    abort();
}

static pl_assert_fn handler = default_handler;
static void *handler_ctx = NULL;

pl_assert_fn pl_set_assert_handler(pl_assert_fn fn, void *ctx) {
    pl_assert_fn old = handler;
    handler = fn ? fn : default_handler;
    handler_ctx = fn ? ctx : NULL;
    return old;
}

void pl__assert_fail(const char *file, int line, const char *expr) {
    handler(file, line, expr, handler_ctx);
}

int pl_asserts_enabled(void) {
    return PL_ASSERTS_ON;
}
