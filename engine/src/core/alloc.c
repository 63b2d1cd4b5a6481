/* The engine's allocator: a 16-byte header before every block holds its size (for the byte
 * counter and for backends that want the size back) and a magic that catches a foreign or
 * double free in builds with assertions. Counters are atomic so worlds on different threads
 * can share them; the backend itself is set once, before use. */
#include "core/alloc.h"
#include "core/assert.h"
#include <stdalign.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define PL_ALLOC_MAGIC 0x706c616cu /* "plal" */
#define PL_FREED_MAGIC 0x64656164u /* "dead" */

typedef struct pl_block_header {
    size_t size;     /* bytes asked for, header excluded */
    uint32_t magic;
    uint32_t spare;
} pl_block_header;

/* 16 bytes keep the 16-byte alignment of the backend's blocks for the caller's block. */
#define PL_HEADER 16
_Static_assert(sizeof(pl_block_header) <= PL_HEADER, "allocation header must fit 16 bytes");

static atomic_size_t live_bytes;
static atomic_uint_fast64_t alloc_count;

static void *default_alloc(size_t size, void *ctx) {
    (void)ctx;
    return malloc(size);
}
static void default_free(void *ptr, size_t size, void *ctx) {
    (void)size, (void)ctx;
    free(ptr);
}

static pl_alloc_fn backend_alloc = default_alloc;
static pl_free_fn backend_free = default_free;
static void *backend_ctx = NULL;

pl_status pl_set_allocator(pl_alloc_fn alloc_fn, pl_free_fn free_fn, void *ctx) {
    if ((alloc_fn == NULL) != (free_fn == NULL)) return PL_ERR_STATE;
    if (atomic_load(&live_bytes) != 0) return PL_ERR_STATE;
    backend_alloc = alloc_fn ? alloc_fn : default_alloc;
    backend_free = free_fn ? free_fn : default_free;
    backend_ctx = alloc_fn ? ctx : NULL;
    return PL_OK;
}

size_t pl_alloc_bytes(void) {
    return atomic_load_explicit(&live_bytes, memory_order_relaxed);
}

uint64_t pl_alloc_count(void) {
    return (uint64_t)atomic_load_explicit(&alloc_count, memory_order_relaxed);
}

static pl_block_header *header_of(void *ptr) {
    pl_block_header *h = (pl_block_header *)(void *)((char *)ptr - PL_HEADER);
    PL_ASSERT(h->magic == PL_ALLOC_MAGIC); /* not a pl_ block, or freed twice */
    return h;
}

static void *finish(pl_block_header *h, size_t size) {
    h->size = size;
    h->magic = PL_ALLOC_MAGIC;
    h->spare = 0;
    atomic_fetch_add_explicit(&live_bytes, size, memory_order_relaxed);
    atomic_fetch_add_explicit(&alloc_count, 1, memory_order_relaxed);
    return (char *)h + PL_HEADER;
}

void *pl_malloc(size_t size) {
    if (size > SIZE_MAX - PL_HEADER) return NULL;
    pl_block_header *h = backend_alloc(size + PL_HEADER, backend_ctx);
    if (!h) return NULL;
    PL_ASSERT(((uintptr_t)h & 15u) == 0); /* the backend must return 16-byte aligned blocks */
    return finish(h, size);
}

void *pl_calloc(size_t count, size_t size) {
    if (size != 0 && count > (SIZE_MAX - PL_HEADER) / size) return NULL;
    void *p = pl_malloc(count * size);
    if (p) memset(p, 0, count * size);
    return p;
}

void pl_free(void *ptr) {
    if (!ptr) return;
    pl_block_header *h = header_of(ptr);
    const size_t size = h->size;
    h->magic = PL_FREED_MAGIC;
    atomic_fetch_sub_explicit(&live_bytes, size, memory_order_relaxed);
    backend_free(h, size + PL_HEADER, backend_ctx);
}

void *pl_realloc(void *ptr, size_t size) {
    if (!ptr) return pl_malloc(size);
    pl_block_header *h = header_of(ptr);
    const size_t old = h->size;
    if (size == old) return ptr;
    if (size > SIZE_MAX - PL_HEADER) return NULL;
    pl_block_header *n;
    if (backend_alloc == default_alloc) {
        n = realloc(h, size + PL_HEADER); /* on failure the old block stays valid and counted */
        if (!n) return NULL;
    } else {
        n = backend_alloc(size + PL_HEADER, backend_ctx);
        if (!n) return NULL;
        memcpy((char *)n + PL_HEADER, ptr, old < size ? old : size);
        h->magic = PL_FREED_MAGIC;
        backend_free(h, old + PL_HEADER, backend_ctx);
    }
    PL_ASSERT(((uintptr_t)n & 15u) == 0);
    atomic_fetch_sub_explicit(&live_bytes, old, memory_order_relaxed);
    return finish(n, size);
}
