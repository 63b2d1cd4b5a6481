/* A small pool of worker threads implementing the world's task hook (porelab/world.h,
 * pl_parallel_for_fn) for `porelab run --threads N`. */
#ifndef PL_APP_THREAD_POOL_H
#define PL_APP_THREAD_POOL_H
#include "porelab/world.h"

typedef struct pl_thread_pool pl_thread_pool;

#define PL_MAX_THREADS 64

/* n threads in all: the caller's and n - 1 workers (1 <= n <= PL_MAX_THREADS). NULL when the
 * threads cannot be started. */
pl_thread_pool *pl_thread_pool_create(int n);
void pl_thread_pool_destroy(pl_thread_pool **pool);
/* The task hook: splits [0, n) into one contiguous range per thread, runs them and returns
 * when all are done. user: the pool. */
void pl_thread_pool_parallel_for(void *user, int n, pl_task_fn task, void *ctx);

/* --threads N of a command: 0 when absent (serial, no hook), else N; prints the error and
 * returns -1 when N is not a whole number in [1, PL_MAX_THREADS]. */
int pl_cli_threads(const char *command, const char *value, int *n);
#endif
