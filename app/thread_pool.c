/* Worker pool for the world's task hook. One job at a time: the caller publishes it by bumping
 * a generation counter, every worker runs its range, the last one to finish wakes the caller.
 * Waits spin briefly (a step of a few thousand grains takes some hundred microseconds, less
 * than a sleep and wake-up costs) and then sleep on a condition variable, so idle workers take
 * no core on a shared machine. The ranges depend only on n and the thread count; the engine's
 * results do not depend on them at all (parallel.c). */
#include "thread_pool.h"
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SPINS 2000

typedef struct worker_arg {
    struct pl_thread_pool *p;
    int index;
} worker_arg;

struct pl_thread_pool {
    int n; /* threads including the caller */
    worker_arg arg[PL_MAX_THREADS];
    pthread_t th[PL_MAX_THREADS];
    pthread_mutex_t lock;
    pthread_cond_t wake, done;
    atomic_uint gen;
    atomic_int pending;
    atomic_int quit;
    /* the current job */
    pl_task_fn task;
    void *ctx;
    int count;
};


static inline void relax(void) {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

static void run_range(pl_thread_pool *p, int t) {
    const long long n = p->count;
    const int b = (int)(n * t / p->n), e = (int)(n * (t + 1) / p->n);
    if (e > b) p->task(p->ctx, b, e);
}

static void *worker(void *arg) {
    worker_arg *a = arg;
    pl_thread_pool *p = a->p;
    unsigned seen = 0;
    for (;;) {
        int i = 0;
        while (atomic_load_explicit(&p->gen, memory_order_acquire) == seen && !atomic_load(&p->quit) && i < SPINS) {
            relax();
            i++;
        }
        if (atomic_load_explicit(&p->gen, memory_order_acquire) == seen && !atomic_load(&p->quit)) {
            pthread_mutex_lock(&p->lock);
            while (atomic_load(&p->gen) == seen && !atomic_load(&p->quit)) pthread_cond_wait(&p->wake, &p->lock);
            pthread_mutex_unlock(&p->lock);
        }
        if (atomic_load(&p->quit)) break;
        seen = atomic_load_explicit(&p->gen, memory_order_acquire);
        run_range(p, a->index);
        if (atomic_fetch_sub_explicit(&p->pending, 1, memory_order_acq_rel) == 1) {
            pthread_mutex_lock(&p->lock);
            pthread_cond_signal(&p->done);
            pthread_mutex_unlock(&p->lock);
        }
    }
    return NULL;
}

pl_thread_pool *pl_thread_pool_create(int n) {
    if (n < 1 || n > PL_MAX_THREADS) return NULL;
    pl_thread_pool *p = calloc(1, sizeof *p);
    if (!p) return NULL;
    p->n = n;
    pthread_mutex_init(&p->lock, NULL);
    pthread_cond_init(&p->wake, NULL);
    pthread_cond_init(&p->done, NULL);
    atomic_init(&p->gen, 0);
    atomic_init(&p->pending, 0);
    atomic_init(&p->quit, 0);
    for (int t = 1; t < n; t++) {
        p->arg[t] = (worker_arg){p, t};
        if (pthread_create(&p->th[t], NULL, worker, &p->arg[t]) != 0) {
            p->n = t; /* stop the ones started */
            pl_thread_pool_destroy(&p);
            return NULL;
        }
    }
    return p;
}

void pl_thread_pool_destroy(pl_thread_pool **pp) {
    if (!pp || !*pp) return;
    pl_thread_pool *p = *pp;
    pthread_mutex_lock(&p->lock);
    atomic_store(&p->quit, 1);
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->lock);
    for (int t = 1; t < p->n; t++) pthread_join(p->th[t], NULL);
    pthread_mutex_destroy(&p->lock);
    pthread_cond_destroy(&p->wake);
    pthread_cond_destroy(&p->done);
    free(p);
    *pp = NULL;
}

void pl_thread_pool_parallel_for(void *user, int n, pl_task_fn task, void *ctx) {
    pl_thread_pool *p = user;
    if (p->n == 1 || n < 2) {
        if (n > 0) task(ctx, 0, n);
        return;
    }
    p->task = task;
    p->ctx = ctx;
    p->count = n;
    atomic_store(&p->pending, p->n - 1);
    pthread_mutex_lock(&p->lock);
    atomic_fetch_add_explicit(&p->gen, 1, memory_order_release);
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->lock);
    run_range(p, 0);
    for (int i = 0; i < SPINS && atomic_load_explicit(&p->pending, memory_order_acquire) > 0; i++) relax();
    if (atomic_load_explicit(&p->pending, memory_order_acquire) > 0) {
        pthread_mutex_lock(&p->lock);
        while (atomic_load(&p->pending) > 0) pthread_cond_wait(&p->done, &p->lock);
        pthread_mutex_unlock(&p->lock);
    }
}

int pl_cli_threads(const char *command, const char *value, int *n) {
    *n = 0;
    if (!value) return 0;
    char *end;
    const long v = strtol(value, &end, 10);
    if (end == value || *end || v < 1 || v > PL_MAX_THREADS) {
        fprintf(stderr, "porelab %s: --threads must be a whole number of threads in [1, %d] (got '%s')\n", command,
                PL_MAX_THREADS, value);
        return -1;
    }
    *n = (int)v;
    return 0;
}
