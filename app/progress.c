#define _POSIX_C_SOURCE 200809L
#include "progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

double pl_wall_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void pl_progress_start(pl_progress *p, long long total_steps, int quiet)
{
    p->enabled = !quiet && isatty(STDERR_FILENO);
    p->wall_start = pl_wall_seconds();
    p->last_draw = 0;
    p->total = total_steps;
}

static void format_duration(char *buf, size_t n, double s)
{
    if (s < 0 || s > 1e7) {
        snprintf(buf, n, "--:--");
        return;
    }
    long t = (long)(s + 0.5);
    if (t >= 3600)
        snprintf(buf, n, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
    else
        snprintf(buf, n, "%ld:%02ld", t / 60, t % 60);
}

void pl_progress_update(pl_progress *p, long long done, double t_sim, double t_end)
{
    if (!p->enabled) return;
    double now = pl_wall_seconds();
    if (now - p->last_draw < 0.1 && done < p->total) return;
    p->last_draw = now;
    double elapsed = now - p->wall_start;
    double rate = elapsed > 0 ? (double)done / elapsed : 0;
    double frac = p->total > 0 ? (double)done / (double)p->total : 1;
    char eta[32];
    format_duration(eta, sizeof eta, rate > 0 ? (double)(p->total - done) / rate : -1);
    enum { WIDTH = 28 };
    char bar[WIDTH + 1];
    int filled = (int)(frac * WIDTH);
    for (int i = 0; i < WIDTH; i++) bar[i] = i < filled ? '#' : '.';
    bar[WIDTH] = '\0';
    fprintf(stderr, "\r[%s] %3.0f%%  t = %.4g / %.4g s  %.0f steps/s  ETA %s   ", bar,
            100 * frac, t_sim, t_end, rate, eta);
    fflush(stderr);
}

void pl_progress_finish(pl_progress *p)
{
    if (!p->enabled) return;
    fprintf(stderr, "\r%100s\r", "");
    fflush(stderr);
}
