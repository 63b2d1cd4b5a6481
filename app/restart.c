/* Restart files of `porelab run` (restart.h). */
#include "restart.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MAX_SAVE_AT 256

struct pl_restart {
    char dir[4096];
    double dt, t_start;
    long long total;
    long long every;             /* steps between --save-every saves (0: none) */
    double every_t;              /* its T, s */
    long long next_every_k;      /* next multiple of every_t */
    long long at[MAX_SAVE_AT];   /* --save-at steps (from the run's start), sorted */
    int nat, at_next;
    long long resumed;           /* steps done when resumed (-1: not resumed) */
    long long last_saved;        /* step of the last file written (-1: none) */
    char err[1024];
};

static long long steps_for(double duration, double dt)
{
    return (long long)ceil(duration / dt - 1e-9); /* as run_plan.c */
}

static int cmp_ll(const void *a, const void *b)
{
    long long x = *(const long long *)a, y = *(const long long *)b;
    return x < y ? -1 : x > y;
}

void *pl_restart_read_file(const char *path, size_t *len, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "cannot open %s: %s", path, strerror(errno));
        return NULL;
    }
    size_t cap = 1 << 16, n = 0;
    unsigned char *buf = malloc(cap);
    while (buf) {
        if (n == cap) {
            unsigned char *p = cap > ((size_t)1 << 40) ? NULL : realloc(buf, cap * 2);
            if (!p) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = p;
            cap *= 2;
        }
        size_t got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (got == 0) break;
    }
    int bad = ferror(f);
    fclose(f);
    if (!buf || bad) {
        free(buf);
        snprintf(err, errlen, bad ? "cannot read %s" : "out of memory reading %s", path);
        return NULL;
    }
    *len = n;
    return buf;
}

int pl_restart_write_file(const char *path, const void *bytes, size_t len, char *err, size_t errlen)
{
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        snprintf(err, errlen, "cannot write %s: %s", tmp, strerror(errno));
        return -1;
    }
    int ok = fwrite(bytes, 1, len, f) == len;
    ok = fflush(f) == 0 && ok;
    ok = fsync(fileno(f)) == 0 && ok;
    ok = fclose(f) == 0 && ok;
    if (!ok || rename(tmp, path) != 0) {
        snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
        remove(tmp);
        return -1;
    }
    return 0;
}

/* "0.5,1,end" -> steps from the run's start. 0 or -1 after printing. */
static int parse_at(pl_restart *r, const char *list)
{
    const char *s = list;
    while (*s) {
        const char *e = strchr(s, ',');
        size_t n = e ? (size_t)(e - s) : strlen(s);
        char item[64];
        if (n == 0 || n >= sizeof item) goto bad;
        memcpy(item, s, n);
        item[n] = '\0';
        long long step;
        if (strcmp(item, "end") == 0) {
            step = r->total;
        } else {
            char *end;
            errno = 0;
            double t = strtod(item, &end);
            if (end == item || *end || errno || !isfinite(t)) goto bad;
            if (t < r->t_start - 1e-12) {
                fprintf(stderr, "porelab run: --save-at %g is before the run's start, t = %g s\n", t, r->t_start);
                return -1;
            }
            step = steps_for(t - r->t_start, r->dt);
            if (step < 0) step = 0;
        }
        if (r->nat == MAX_SAVE_AT) {
            fprintf(stderr, "porelab run: --save-at: at most %d times\n", MAX_SAVE_AT);
            return -1;
        }
        r->at[r->nat++] = step;
        s += n;
        if (*s == ',') s++;
    }
    qsort(r->at, (size_t)r->nat, sizeof *r->at, cmp_ll);
    return 0;
bad:
    fprintf(stderr, "porelab run: --save-at must be a comma list of times in s or 'end' (got '%s')\n", list);
    return -1;
}

int pl_restart_open(pl_restart **rp, const pl_opts *o, const pl_run_plan *p, pl_world *w, const char *out_dir,
                    long long start_step)
{
    *rp = NULL;
    const char *every = pl_opts_get(o, "--save-every"), *at = pl_opts_get(o, "--save-at"),
               *resume = pl_opts_get(o, "--resume");
    if (!every && !at && !resume) return 0;
    pl_restart *r = calloc(1, sizeof *r);
    if (!r) return PL_EXIT_FAIL;
    snprintf(r->dir, sizeof r->dir, "%s", out_dir);
    r->dt = p->dt;
    r->t_start = p->t_start;
    r->total = p->total_steps;
    r->resumed = -1;
    r->last_saved = -1;
    if (every) {
        double t = 0;
        if (pl_opts_double(o, "--save-every", 0, 0, &t) != 0) {
            free(r);
            return PL_EXIT_USAGE;
        }
        r->every_t = t;
        r->every = 1;
        r->next_every_k = 1;
    }
    if (at && parse_at(r, at) != 0) {
        free(r);
        return PL_EXIT_USAGE;
    }
    if (resume && pl_opts_get(o, "--renderer") && strcmp(pl_opts_get(o, "--renderer"), "gl") == 0) {
        fprintf(stderr, "porelab run: --resume draws its frames with the cairo renderer only (drop --renderer gl)\n");
        free(r);
        return PL_EXIT_USAGE;
    }
    if (resume) {
        char err[1024];
        size_t len = 0;
        void *bytes = pl_restart_read_file(resume, &len, err, sizeof err);
        if (!bytes) {
            fprintf(stderr, "porelab run: --resume: %s\n", err);
            free(r);
            return PL_EXIT_FAIL;
        }
        pl_status st = pl_world_load_state(w, bytes, len);
        free(bytes);
        if (st != PL_OK) {
            fprintf(stderr, "porelab run: --resume %s: %s\n", resume, pl_world_last_error(w));
            free(r);
            return PL_EXIT_FAIL;
        }
        r->resumed = (long long)pl_world_step_count(w) - start_step;
        if (r->resumed < 0) {
            fprintf(stderr, "porelab run: --resume %s: the file is at step %lld, before the scene's start (step %lld)\n",
                    resume, (long long)pl_world_step_count(w), start_step);
            free(r);
            return PL_EXIT_FAIL;
        }
        r->last_saved = r->resumed; /* the file we came from */
        fprintf(stderr, "porelab: resumed from %s at t = %.9g s (step %lld of %lld)\n", resume, pl_world_time(w),
                r->resumed, r->total);
    }
    *rp = r;
    return 0;
}

void pl_restart_frames(const pl_restart *r, const pl_run_plan *p, long long *k, int *draw_first, int *first)
{
    *k = 1, *draw_first = 1, *first = 0;
    if (!r || r->resumed <= 0) return;
    /* the first frame at or after the resumed step */
    long long j = p->every > 0 ? r->resumed / p->every : (long long)floor((double)r->resumed * p->dt * p->fps);
    while (j > 0 && pl_run_plan_frame_step(p, j) >= r->resumed) j--;
    while (pl_run_plan_frame_step(p, j) < r->resumed) j++;
    *draw_first = pl_run_plan_frame_step(p, j) == r->resumed;
    *k = *draw_first ? j + 1 : j;
    *first = (int)j;
}

static long long next_every(const pl_restart *r)
{
    return r->every ? steps_for((double)r->next_every_k * r->every_t, r->dt) : -1;
}

long long pl_restart_clip(const pl_restart *r, long long target, long long done)
{
    if (!r) return target;
    long long e = next_every(r);
    if (e > done && e < target) target = e;
    for (int i = r->at_next; i < r->nat; i++)
        if (r->at[i] > done && r->at[i] < target) {
            target = r->at[i];
            break;
        }
    return target;
}

static int save(pl_restart *r, const pl_world *w)
{
    void *bytes = NULL;
    size_t len = 0;
    if (pl_world_save_state(w, &bytes, &len) != PL_OK) {
        snprintf(r->err, sizeof r->err, "restart file: %s", pl_world_last_error(w));
        return -1;
    }
    char path[4200], err[900];
    snprintf(path, sizeof path, "%s/state_%.6f.plstate", r->dir, pl_world_time(w));
    int rc = pl_restart_write_file(path, bytes, len, err, sizeof err);
    pl_state_free(bytes);
    if (rc != 0) {
        snprintf(r->err, sizeof r->err, "restart file: %s", err);
        return -1;
    }
    return 0;
}

int pl_restart_after_steps(pl_restart *r, const pl_world *w, long long done)
{
    if (!r) return 0;
    int due = 0;
    while (r->every && next_every(r) <= done) {
        due |= next_every(r) <= done;
        r->next_every_k++;
    }
    while (r->at_next < r->nat && r->at[r->at_next] <= done) {
        due = 1;
        r->at_next++;
    }
    if (!due || done == r->last_saved) return 0; /* the file we resumed from is not written again */
    r->last_saved = done;
    return save(r, w);
}

const char *pl_restart_error(const pl_restart *r) { return r ? r->err : ""; }

void pl_restart_close(pl_restart **r)
{
    free(*r);
    *r = NULL;
}

void pl_restart_frame_at(const pl_run_plan *p, long long done, long long *index, long long *step)
{
    long long j = p->every > 0 ? done / p->every : (long long)floor((double)done * p->dt * p->fps);
    while (j > 0 && pl_run_plan_frame_step(p, j) >= done) j--;
    while (pl_run_plan_frame_step(p, j) < done) j++;
    *index = j;
    *step = pl_run_plan_frame_step(p, j);
}

#include <dirent.h>

int pl_restart_load_nearest(const char *dir, pl_world *w, long long start_step, long long target, int *loaded,
                            char *used, size_t n)
{
    *loaded = 0;
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "porelab still: --from-state: cannot open %s: %s\n", dir, strerror(errno));
        return -1;
    }
    char best[4200] = "";
    long long best_step = -1;
    struct dirent *e;
    while ((e = readdir(d))) {
        const size_t len = strlen(e->d_name);
        if (len < 8 || strcmp(e->d_name + len - 8, ".plstate") != 0) continue;
        char path[4200], err[512];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        FILE *f = fopen(path, "rb");
        if (!f) continue;
        unsigned char head[72];
        const size_t got = fread(head, 1, sizeof head, f);
        fclose(f);
        pl_state_info info;
        if (pl_state_info_of(head, got, &info, err, sizeof err) != PL_OK) continue; /* not ours, or another build */
        const long long s = (long long)info.step - start_step;
        if (s >= 0 && s <= target && s > best_step && info.bodies == pl_world_body_count(w)) {
            best_step = s;
            snprintf(best, sizeof best, "%s", path);
        }
    }
    closedir(d);
    if (best_step < 0) return 0;
    char err[1024];
    size_t len = 0;
    void *bytes = pl_restart_read_file(best, &len, err, sizeof err);
    if (!bytes) {
        fprintf(stderr, "porelab still: --from-state: %s\n", err);
        return -1;
    }
    pl_status st = pl_world_load_state(w, bytes, len);
    free(bytes);
    if (st != PL_OK) {
        fprintf(stderr, "porelab still: --from-state %s: %s\n", best, pl_world_last_error(w));
        return -1;
    }
    *loaded = 1;
    snprintf(used, n, "%s", best);
    return 0;
}
