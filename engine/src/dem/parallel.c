/* Threaded contact loop. The pair evaluations of a step are independent (each writes only its
 * own pair's history), so they run in parallel into per-pair slots (contact_dispatch.c). The
 * slots are then added to the bodies by a second parallel pass over bodies: each body walks
 * its own list of pairs, sorted by pair index, and adds their contributions in that order, the
 * order of the serial loop. Every body's sums are therefore the same floating-point operations
 * in the same order as without threads, and the state is bit-identical for any thread count
 * and any split of the ranges (tests/cli/threads.cmake). */
#include "dem/parallel.h"
#include "core/alloc.h"
#include <string.h>

struct pl_par {
    pl_contact_add *out; /* per pair: what it adds to its bodies (valid where flag != 0) */
    pl_contact_sum *sum; /* per pair: its terms of the sums over pairs (valid where flag != 0) */
    uint16_t *flag; /* per pair: the slot's flags (0: nothing to add), dense for the passes */
    int out_cap, sum_cap, flag_cap;
    int *start;   /* n + 1: body i's pairs are item[start[i] .. start[i+1]) */
    int *item;    /* 2 pair_n: pair index * 2 + end (1: the body is b, 0: a), ascending */
    int start_cap, item_cap;
    int64_t rebuilds; /* the pair list the lists were built for */
    int n, pair_n;
    const pl_pair *pairs;
};

void pl_world_set_parallel_for(pl_world *w, pl_parallel_for_fn fn, void *user) {
    w->def.parallel_for = fn;
    w->def.parallel_user = user;
}

void pl__parallel_free(pl_world *w) {
    if (!w->par) return;
    pl_free(w->par->out);
    pl_free(w->par->sum);
    pl_free(w->par->flag);
    pl_free(w->par->start);
    pl_free(w->par->item);
    pl_free(w->par);
    w->par = NULL;
}

static int grow(void **p, int *cap, int need, size_t elem) {
    if (need <= *cap) return 1;
    const int c = need + need / 2 + 16;
    void *q = pl_realloc(*p, (size_t)c * elem);
    if (!q) return 0;
    *p = q;
    *cap = c;
    return 1;
}

pl_contact_add *pl__parallel_slots(pl_world *w, uint16_t **flag, pl_contact_sum **sum) {
    if (!w->par) {
        w->par = pl_malloc(sizeof *w->par);
        if (!w->par) return NULL;
        memset(w->par, 0, sizeof *w->par);
        w->par->rebuilds = -1;
    }
    struct pl_par *q = w->par;
    if (!grow((void **)&q->out, &q->out_cap, w->pair_n, sizeof *q->out) ||
        !grow((void **)&q->flag, &q->flag_cap, w->pair_n, sizeof *q->flag) ||
        !grow((void **)&q->sum, &q->sum_cap, w->pair_n, sizeof *q->sum))
        return NULL;
    *flag = q->flag;
    *sum = q->sum;
    if (q->rebuilds == w->rebuilds && q->n == w->n && q->pair_n == w->pair_n && q->pairs == w->pairs) return q->out;
    /* counting sort of the pair ends by body; filling in pair order keeps each list ascending */
    if (!grow((void **)&q->start, &q->start_cap, w->n + 1, sizeof *q->start) ||
        !grow((void **)&q->item, &q->item_cap, 2 * w->pair_n, sizeof *q->item))
        return NULL;
    int *start = q->start, *item = q->item;
    memset(start, 0, (size_t)(w->n + 1) * sizeof *start);
    for (int k = 0; k < w->pair_n; k++) {
        start[w->pairs[k].a + 1]++;
        start[w->pairs[k].b + 1]++;
    }
    for (int i = 0; i < w->n; i++) start[i + 1] += start[i];
    for (int k = 0; k < w->pair_n; k++) {
        item[start[w->pairs[k].a]++] = 2 * k;
        item[start[w->pairs[k].b]++] = 2 * k + 1;
    }
    for (int i = w->n; i > 0; i--) start[i] = start[i - 1]; /* the fill advanced each start by its count */
    start[0] = 0;
    q->rebuilds = w->rebuilds;
    q->n = w->n;
    q->pair_n = w->pair_n;
    q->pairs = w->pairs;
    return q->out;
}

typedef struct gather_task {
    pl_world *w;
    const pl_contact_add *out;
    const uint16_t *flag;
} gather_task;

static void gather_range(void *ctx, int begin, int end) {
    const gather_task *t = ctx;
    pl_world *w = t->w;
    const int *start = w->par->start, *item = w->par->item;
    const int track = w->def.track_energy;
    for (int i = begin; i < end; i++)
        for (int j = start[i]; j < start[i + 1]; j++) {
            const int k = item[j] >> 1;
            if (t->flag[k]) pl__apply_end(w->force, w->torque, w->tally, track, &t->out[k], i, item[j] & 1);
        }
}

void pl__parallel_gather(pl_world *w, const pl_contact_add *out, const uint16_t *flag) {
    gather_task t = {w, out, flag};
    w->def.parallel_for(w->def.parallel_user, w->n, gather_range, &t);
}
