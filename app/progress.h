/* Progress bar on a terminal (stderr): simulated time, steps per second, ETA. Silent when
 * stderr is not a terminal or --quiet was given. */
#ifndef PL_APP_PROGRESS_H
#define PL_APP_PROGRESS_H

typedef struct pl_progress {
    int enabled;
    double wall_start;  /* s, monotonic clock */
    double last_draw;   /* s */
    long long total;    /* steps */
} pl_progress;

/* Monotonic wall-clock seconds (for display and timing only, never for physics). */
double pl_wall_seconds(void);

void pl_progress_start(pl_progress *p, long long total_steps, int quiet);
/* Redraws at most ~10 times per second. */
void pl_progress_update(pl_progress *p, long long done, double t_sim, double t_end);
/* Clears the bar. */
void pl_progress_finish(pl_progress *p);

#endif
