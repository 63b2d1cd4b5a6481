/* Unit tests of engine/src/core: the counting allocator, the growable array and PL_ASSERT
 * with a replaceable handler. No world involved. */
#include "core/alloc.h"
#include "core/array.h"
#include "core/assert.h"
#include "harness.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static int counters_follow_blocks(void) {
    const size_t b0 = pl_alloc_bytes();
    const uint64_t n0 = pl_alloc_count();
    char *a = pl_malloc(100);
    double *c = pl_calloc(10, sizeof *c);
    ENSURE(a && c);
    ENSURE(((uintptr_t)a & 15u) == 0 && ((uintptr_t)c & 15u) == 0);
    ENSURE(pl_alloc_bytes() == b0 + 100 + 10 * sizeof(double));
    ENSURE(pl_alloc_count() == n0 + 2);
    for (int i = 0; i < 10; i++) ENSURE(c[i] == 0.0);
    memset(a, 7, 100);
    a = pl_realloc(a, 1000);
    ENSURE(a && a[99] == 7 && a[0] == 7);
    ENSURE(pl_alloc_bytes() == b0 + 1000 + 10 * sizeof(double));
    ENSURE(pl_alloc_count() == n0 + 3);
    ENSURE(pl_realloc(a, 1000) == a); /* same size: no allocation */
    ENSURE(pl_alloc_count() == n0 + 3);
    pl_free_null(a);
    ENSURE(a == NULL);
    pl_free(c);
    pl_free(NULL);
    ENSURE(pl_alloc_bytes() == b0);
    return 0;
}

static int zero_sizes_and_overflow(void) {
    const size_t b0 = pl_alloc_bytes();
    void *z = pl_malloc(0), *y = pl_calloc(0, 8), *x = pl_malloc(0);
    ENSURE(z && y && x && z != x); /* never NULL unless out of memory, and unique */
    x = pl_realloc(x, 0);
    ENSURE(x != NULL);
    ENSURE(pl_calloc(SIZE_MAX / 4, 8) == NULL);
    ENSURE(pl_malloc(SIZE_MAX - 4) == NULL);
    void *r = pl_malloc(8);
    ENSURE(pl_realloc(r, SIZE_MAX - 4) == NULL); /* the old block stays valid */
    pl_free(r);
    pl_free(z), pl_free(y), pl_free(x);
    ENSURE(pl_alloc_bytes() == b0);
    return 0;
}

/* A backend that counts its own calls and checks it gets back the sizes it handed out. */
typedef struct counting {
    int allocs, frees;
    size_t live;
} counting;
static void *c_alloc(size_t size, void *ctx) {
    counting *c = ctx;
    c->allocs++, c->live += size;
    return malloc(size);
}
static void c_free(void *p, size_t size, void *ctx) {
    counting *c = ctx;
    c->frees++, c->live -= size;
    free(p);
}

static int replaceable_backend(void) {
    counting c = {0};
    ENSURE(pl_alloc_bytes() == 0); /* the backend can only change with nothing live */
    ENSURE(pl_set_allocator(c_alloc, NULL, &c) == PL_ERR_STATE);
    ENSURE(pl_set_allocator(c_alloc, c_free, &c) == PL_OK);
    int *p = pl_malloc(40 * sizeof *p);
    ENSURE(p && c.allocs == 1);
    for (int i = 0; i < 40; i++) p[i] = i;
    ENSURE(pl_set_allocator(NULL, NULL, NULL) == PL_ERR_STATE); /* p is live */
    p = pl_realloc(p, 400 * sizeof *p);
    ENSURE(p && p[39] == 39 && c.allocs == 2 && c.frees == 1);
    pl_free(p);
    ENSURE(c.frees == 2 && c.live == 0);
    ENSURE(pl_set_allocator(NULL, NULL, NULL) == PL_OK);
    void *q = pl_malloc(8);
    ENSURE(c.allocs == 2); /* back on malloc */
    pl_free(q);
    return 0;
}

static int array_grows_and_reuses(void) {
    const size_t b0 = pl_alloc_bytes();
    PL_ARRAY(double) a = {0};
    for (int i = 0; i < 1000; i++) ENSURE(pl_array_push(&a, i * 0.5) == PL_OK);
    ENSURE(a.count == 1000 && a.capacity >= 1000 && a.data[999] == 499.5);
    /* cleared and refilled to the same size: no allocation */
    const uint64_t n0 = pl_alloc_count();
    for (int round = 0; round < 10; round++) {
        pl_array_clear(&a);
        for (int i = 0; i < 1000; i++) ENSURE(pl_array_push(&a, i * 1.0) == PL_OK);
    }
    ENSURE(pl_alloc_count() == n0);
    ENSURE(pl_array_resize(&a, 5000) == PL_OK && a.count == 5000);
    ENSURE(a.data[999] == 999.0);
    const size_t cap = a.capacity;
    ENSURE(pl_array_reserve(&a, SIZE_MAX / 4) == PL_ERR_NOMEM); /* overflow, not a huge block */
    ENSURE(pl_array_reserve(&a, SIZE_MAX) == PL_ERR_NOMEM);
    ENSURE(a.capacity == cap && a.count == 5000 && a.data[4] == 4.0);
    pl_array_free(&a);
    ENSURE(a.data == NULL && a.count == 0 && pl_alloc_bytes() == b0);
    typedef struct { int i; double x, y; } triple;
    PL_ARRAY(triple) t = {0};
    ENSURE(pl_array_push(&t, ((triple){3, 1.5, 2.5})) == PL_OK);
    ENSURE(t.count == 1 && t.data[0].i == 3 && t.data[0].y == 2.5);
    pl_array_free(&t);
    return 0;
}

static int failures_seen;
static const char *failed_expr;
static void recording_handler(const char *file, int line, const char *expr, void *ctx) {
    (void)file, (void)line;
    failures_seen += *(int *)ctx;
    failed_expr = expr;
}

static int assert_handler_replaceable(void) {
    ENSURE(pl_asserts_enabled() == PL_ASSERTS_ON); /* engine and test built alike */
    int weight = 1;
    pl_set_assert_handler(recording_handler, &weight);
    int calls = 0;
    PL_ASSERT(1 + 1 == 2);
    ENSURE(PL_CHECK(++calls > 0)); /* the checked expression is evaluated in every build */
    ENSURE(!PL_CHECK(calls == 7));
    PL_ASSERT(calls == 2);
    pl_set_assert_handler(NULL, NULL);
    ENSURE(calls == 1);
    if (PL_ASSERTS_ON) {
        ENSURE(failures_seen == 2);
        ENSURE(strcmp(failed_expr, "calls == 2") == 0);
    } else {
        ENSURE(failures_seen == 0);
    }
    fprintf(stderr, "assertions are %s in this build\n", PL_ASSERTS_ON ? "on" : "off");
    return 0;
}

int main(void) {
    RUN(counters_follow_blocks);
    RUN(zero_sizes_and_overflow);
    RUN(replaceable_backend);
    RUN(array_grows_and_reuses);
    RUN(assert_handler_replaceable);
    return pl_test_report();
}
