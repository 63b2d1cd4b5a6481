/// The engine's allocator: every byte the engine allocates goes through it (CHOLMOD's own
/// workspace excepted, which CHOLMOD allocates itself). It counts live bytes and allocations
/// so a test can prove that a destroyed world leaves nothing behind and that a settled step
/// allocates nothing. The backend is replaceable (an arena, a tracking allocator, a host's
/// allocator); the default is the C library's malloc/free.
#ifndef PORELAB_ALLOC_H
#define PORELAB_ALLOC_H

#include "porelab/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Backend allocation: return `size` bytes aligned to at least 16 bytes, or NULL.
/// `size` is never 0 (the engine adds its own 16-byte header to every request).
typedef void *(*pl_alloc_fn)(size_t size, void *ctx);

/// Backend release of a block returned by the matching pl_alloc_fn; `size` is the size that
/// was asked for. Never called with NULL.
typedef void (*pl_free_fn)(void *ptr, size_t size, void *ctx);

/// Replace the backend (both functions, or both NULL for the default malloc/free); `ctx` is
/// passed to every call. Only while no engine block is live: returns PL_ERR_STATE (and
/// changes nothing) when pl_alloc_bytes() is not 0 or when exactly one function is NULL.
/// Not thread-safe: call it before any thread uses the engine.
pl_status pl_set_allocator(pl_alloc_fn alloc_fn, pl_free_fn free_fn, void *ctx);

/// Bytes currently allocated by the engine (sum of the sizes asked for, headers excluded),
/// process-wide, all worlds together. 0 when nothing is live.
size_t pl_alloc_bytes(void);

/// Allocations made so far, process-wide: every successful pl_malloc/pl_calloc, and every
/// pl_realloc that changed a block's size. Never decreases; the difference across a call
/// is the number of allocations the call made (0 for a settled step).
uint64_t pl_alloc_count(void);

#ifdef __cplusplus
}
#endif
#endif
