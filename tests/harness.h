/// Minimal test harness: a test is a function returning 0 (pass) or 1 (fail).
/// ENSURE(cond) and ENSURE_NEAR(value, expected, tolerance) print file:line and the
/// measured numbers on failure. RUN(test) runs one and counts; main returns pl_test_report().
/// pl_validation(...) prints a row of docs/validation.md (below).
#ifndef PL_TEST_HARNESS_H
#define PL_TEST_HARNESS_H
#include <math.h>
#include <stdarg.h>
#include <stdio.h>

static int pl_test_failed_ = 0, pl_test_run_ = 0;

#define ENSURE(cond)                                                                     \
    do {                                                                                 \
        if (!(cond)) {                                                                   \
            fprintf(stderr, "%s:%d: ENSURE failed: %s\n", __FILE__, __LINE__, #cond);    \
            return 1;                                                                    \
        }                                                                                \
    } while (0)

#define ENSURE_NEAR(value, expected, tol)                                                \
    do {                                                                                 \
        double v_ = (value), e_ = (expected), t_ = (tol);                                \
        if (!(fabs(v_ - e_) <= t_)) {                                                    \
            fprintf(stderr, "%s:%d: %s = %.10g, expected %.10g +- %.3g (off by %.3g)\n", \
                    __FILE__, __LINE__, #value, v_, e_, t_, fabs(v_ - e_));              \
            return 1;                                                                    \
        }                                                                                \
    } while (0)

/// Relative tolerance: |value - expected| <= rel * |expected|.
#define ENSURE_REL(value, expected, rel) ENSURE_NEAR(value, expected, (rel) * fabs((double)(expected)))

#define RUN(test)                                                                        \
    do {                                                                                 \
        pl_test_run_++;                                                                  \
        int r_ = test();                                                                 \
        fprintf(stderr, "%-48s %s\n", #test, r_ ? "FAIL" : "ok");                        \
        pl_test_failed_ += r_ ? 1 : 0;                                                   \
    } while (0)


/// One row, or one part of a row, of the validation table in docs/validation.md, printed on
/// stdout as the machine-readable line
///     VALIDATION|<id>|<check>|<reference>|<tolerance>|<measured>
/// <id> is "<table>.<name>" (table: grains, polygon, fluid, soil) and names the row; the other
/// fields are the table's columns. tests/validation/validation_doc.cmake (ctest label
/// validation-doc) runs the tests, collects these lines and writes the tables: one row per id,
/// in the order of the tests and of the lines; the check, reference and tolerance of the id's
/// first line; the measured parts of all its lines joined by "; "; the tests that printed it.
/// The measured column is printf-formatted from the test's own numbers, so the table cannot
/// drift from what the build measures. A '|' or a newline in a field is written as &#124; or a
/// space (the line's separator stays unambiguous). Lua scenes print the same line with print().
static inline void pl_validation_field_(const char *s) {
    for (; *s; s++) {
        if (*s == '|') fputs("&#124;", stdout);
        else if (*s == '\n' || *s == '\r') fputc(' ', stdout);
        else fputc(*s, stdout);
    }
}
#if defined(__GNUC__)
__attribute__((format(printf, 5, 6)))
#endif
static inline void pl_validation(const char *id, const char *check, const char *reference,
                                 const char *tolerance, const char *measured_fmt, ...) {
    char measured[2048];
    va_list ap;
    va_start(ap, measured_fmt);
    vsnprintf(measured, sizeof measured, measured_fmt, ap);
    va_end(ap);
    const char *fields[] = {id, check, reference, tolerance, measured};
    fputs("VALIDATION", stdout);
    for (int i = 0; i < 5; i++) {
        fputc('|', stdout);
        pl_validation_field_(fields[i]);
    }
    fputc('\n', stdout);
    fflush(stdout);
}

static inline int pl_test_report(void) {
    fprintf(stderr, "%d of %d tests passed\n", pl_test_run_ - pl_test_failed_, pl_test_run_);
    return pl_test_failed_ ? 1 : 0;
}
#endif
