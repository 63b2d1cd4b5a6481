/* PL_ASSERT(cond): a check of a programmer error (an index the engine computed itself, an
 * invariant between two of its own arrays), never of user input, which gets a status code
 * and a message instead. On in Debug and RelWithDebInfo builds (CMake defines PL_ASSERTS
 * there, and in any build with -DPL_ASSERTS=ON), and when NDEBUG is not defined; off in
 * Release. A failure calls the handler set by pl_set_assert_handler (porelab/assert.h);
 * the default prints file, line and expression and aborts.
 *
 * PL_CHECK(cond) is for the places that today return silently on a programmer error: it is
 * an expression with the value of cond (always evaluated, in every build) that also reports
 * a false cond through the handler when assertions are on:
 *     if (!PL_CHECK(b >= 0 && b < w->nbodies)) return;   */
#ifndef PL_CORE_ASSERT_H
#define PL_CORE_ASSERT_H

#include "porelab/assert.h"

void pl__assert_fail(const char *file, int line, const char *expr);

#if defined(PL_ASSERTS) || !defined(NDEBUG)
#define PL_ASSERTS_ON 1
#define PL_ASSERT(cond) ((cond) ? (void)0 : pl__assert_fail(__FILE__, __LINE__, #cond))
#define PL_CHECK(cond) ((cond) ? 1 : (pl__assert_fail(__FILE__, __LINE__, #cond), 0))
#else
#define PL_ASSERTS_ON 0
#define PL_ASSERT(cond) ((void)0)
#define PL_CHECK(cond) ((cond) ? 1 : 0)
#endif

#endif
