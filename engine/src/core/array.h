/* A typed growable array on the engine's allocator.
 *
 *     PL_ARRAY(pl_vec2) pts = {0};            // data NULL, count 0, capacity 0
 *     if (pl_array_push(&pts, v) != PL_OK) ...  // PL_ERR_NOMEM, the array unchanged
 *     if (pl_array_reserve(&pts, n) != PL_OK) ...
 *     pl_array_clear(&pts);                   // count 0, the buffer kept (reuse per step)
 *     pl_array_free(&pts);
 *
 * Capacity grows by doubling (at least 8 elements), so a buffer reused step after step stops
 * allocating once it has reached its working size. Every size computation is checked for
 * overflow and fails with PL_ERR_NOMEM. The macros evaluate their array argument more than
 * once: pass a plain pointer expression. */
#ifndef PL_CORE_ARRAY_H
#define PL_CORE_ARRAY_H

#include "core/alloc.h"
#include "porelab/core.h"
#include <stdint.h>
#include <string.h>

#define PL_ARRAY(T)                                                                           \
    struct {                                                                                  \
        T *data;                                                                              \
        size_t count, capacity;                                                               \
    }

/* Make room for `need` elements of `elem` bytes. `data_field` points to the array's typed
 * data pointer (read and written through memcpy, so no T** is punned to void**). */
static inline pl_status pl__array_reserve(void *data_field, size_t *capacity, size_t need,
                                          size_t elem) {
    if (need <= *capacity) return PL_OK;
    if (elem == 0 || need > SIZE_MAX / elem) return PL_ERR_NOMEM;
    size_t cap = *capacity < 8 ? 8 : *capacity;
    while (cap < need) cap = cap > SIZE_MAX / 2 ? need : cap * 2;
    if (cap > SIZE_MAX / elem) cap = need;
    void *old;
    memcpy(&old, data_field, sizeof old);
    void *grown = pl_realloc(old, cap * elem);
    if (!grown) return PL_ERR_NOMEM;
    memcpy(data_field, &grown, sizeof grown);
    *capacity = cap;
    return PL_OK;
}

#define pl_array_reserve(a, n)                                                                \
    pl__array_reserve(&(a)->data, &(a)->capacity, (n), sizeof *(a)->data)

/* Append v (an expression of the element type); PL_OK or PL_ERR_NOMEM. */
#define pl_array_push(a, v)                                                                   \
    (((a)->count < (a)->capacity ||                                                           \
      ((a)->count < SIZE_MAX && pl_array_reserve((a), (a)->count + 1) == PL_OK))              \
         ? ((a)->data[(a)->count++] = (v), PL_OK)                                             \
         : PL_ERR_NOMEM)

/* Set the count to n (new elements uninitialised); PL_OK or PL_ERR_NOMEM. */
#define pl_array_resize(a, n)                                                                 \
    (pl_array_reserve((a), (n)) == PL_OK ? ((a)->count = (n), PL_OK) : PL_ERR_NOMEM)

#define pl_array_clear(a) ((void)((a)->count = 0))

#define pl_array_free(a)                                                                      \
    do {                                                                                      \
        pl_free((a)->data);                                                                   \
        (a)->data = NULL;                                                                     \
        (a)->count = (a)->capacity = 0;                                                       \
    } while (0)

#endif
