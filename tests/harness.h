/// Minimal test harness: a test is a function returning 0 (pass) or 1 (fail).
/// ENSURE(cond) and ENSURE_NEAR(value, expected, tolerance) print file:line and the
/// measured numbers on failure. RUN(test) runs one and counts; main returns pl_test_report().
#ifndef PL_TEST_HARNESS_H
#define PL_TEST_HARNESS_H
#include <math.h>
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

static inline int pl_test_report(void) {
    fprintf(stderr, "%d of %d tests passed\n", pl_test_run_ - pl_test_failed_, pl_test_run_);
    return pl_test_failed_ ? 1 : 0;
}
#endif
