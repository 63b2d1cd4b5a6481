/* The engine's one timer: seconds of a monotonic wall clock, for the cost that models report
 * (`porelab info`, pl_model_class.cost). Never used for anything that changes results. */
#ifndef PL_CORE_CLOCK_H
#define PL_CORE_CLOCK_H

#include <time.h>

static inline double pl_clock_seconds(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#endif
