/// The engine's assertion handler. Assertions (PL_ASSERT inside the engine) check programmer
/// errors only, never user input: bad input is refused with a status code and a message.
/// They are compiled into Debug and RelWithDebInfo builds (and into Release when PL_ASSERTS
/// is defined, cmake -DPL_ASSERTS=ON); a Release build has none.
#ifndef PORELAB_ASSERT_H
#define PORELAB_ASSERT_H

#ifdef __cplusplus
extern "C" {
#endif

/// Called when an assertion fails: source file, line and the expression as written.
/// The default handler prints "file:line: assertion failed: expr" to stderr and aborts.
/// A replacement may log and abort, longjmp out (tests), or return: the engine then carries
/// on past the failed check, which is only safe where the check guards a silent no-op.
typedef void (*pl_assert_fn)(const char *file, int line, const char *expr, void *ctx);

/// Replace the handler (NULL restores the default); `ctx` is passed to every call.
/// Returns the previous handler. Not thread-safe: set it before threads use the engine.
pl_assert_fn pl_set_assert_handler(pl_assert_fn handler, void *ctx);

/// 1 when this build of the engine checks its assertions, 0 when they are compiled out.
int pl_asserts_enabled(void);

#ifdef __cplusplus
}
#endif
#endif
