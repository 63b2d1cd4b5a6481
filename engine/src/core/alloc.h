/* The engine's allocation calls (public side: porelab/alloc.h). Every engine allocation goes
 * through these so the byte and allocation counters see it. They behave like their C library
 * namesakes with two differences that make a mechanical replacement safe:
 *   - pl_malloc(0), pl_calloc(0, n) and pl_realloc(p, 0) return a valid, unique block of
 *     size 0 (never NULL except when out of memory), so "NULL means out of memory" holds;
 *   - pl_calloc and the size arithmetic refuse to overflow (NULL).
 * A block from here must be released by pl_free, never by free(), and vice versa: memory
 * from strdup, CHOLMOD or another library is not a pl_ block. Debug and RelWithDebInfo
 * builds check this with PL_ASSERT (a header magic). */
#ifndef PL_CORE_ALLOC_H
#define PL_CORE_ALLOC_H

#include "porelab/alloc.h"
#include <stddef.h>

void *pl_malloc(size_t size);
void *pl_calloc(size_t count, size_t size);
void *pl_realloc(void *ptr, size_t size);
void pl_free(void *ptr);

/* Free and set the lvalue to NULL (the argument is evaluated twice: no side effects). */
#define pl_free_null(p)                                                                       \
    do {                                                                                      \
        pl_free(p);                                                                           \
        (p) = NULL;                                                                           \
    } while (0)

#endif
