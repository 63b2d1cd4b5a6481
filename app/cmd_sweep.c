/* porelab sweep SCENE.lua: expands a grid of parameter values (and a seed list, or a Latin
 * hypercube) into one `porelab run` command per job, written as DIR/jobs.txt (one shell line
 * per job: GNU parallel reads it, a Slurm array task picks its line), DIR/jobs.tsv (what each
 * job is), and on request a Slurm array script and a Snakemake rule file; --run runs the jobs
 * not done yet through GNU parallel. Each job writes DIR/job_NNNN/manifest.json; a job whose
 * manifest holds a finished run with the same inputs is skipped (porelab run --skip-done), so
 * a sweep can be re-run after an interruption and only the missing jobs run. */
#include "cli_common.h"
#include "commands.h"
#include "manifest.h"
#include "progress.h"
#include "porelab/shapes.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define MAX_AXES 16
#define MAX_VALUES 1000
#define MAX_SEEDS 100000
#define MAX_JOBS 100000

static const pl_opt_spec sweep_specs[] = {
    {"--grid", NULL, "NAME=LIST", "values of one declared parameter: 'amp=0.25,0.35,0.5' or 'amp=0.2:0.6:5' "
     "(5 values from 0.2 to 0.6); repeat for more parameters (all combinations)"},
    {"--seeds", NULL, "LIST", "run seeds, e.g. 1..6 or 1,3,7 (default: 0, the scene's own seeds)"},
    {"--lhs", NULL, "N", "also N Latin-hypercube points over the --range parameters (or all declared ones)"},
    {"--range", NULL, "NAME=LO:HI", "range of a parameter for --lhs (repeatable; default its declared range)"},
    {"--lhs-seed", NULL, "S", "seed of the Latin hypercube (default 1)"},
    {"--out", NULL, "DIR", "sweep folder (default out/<scene-name>-sweep/)"},
    {"--jobs", "-j", "N", "jobs at once with --run (default: the number of cores)"},
    {"--run", NULL, NULL, "run the jobs not done yet through GNU parallel (Debian package parallel)"},
    {"--slurm", NULL, NULL, "also write DIR/sweep.slurm, a Slurm job-array script (sbatch DIR/sweep.slurm)"},
    {"--snakemake", NULL, NULL, "also write DIR/Snakefile (snakemake -s DIR/Snakefile --cores N)"},
    {"--until", NULL, "T", "simulated end time of every run, s (passed to porelab run)"},
    {"--steps", NULL, "N", "steps of every run (passed to porelab run)"},
    {"--frames", NULL, NULL, "let every run write its frame images (default: --no-frames)"},
    {"--trust", NULL, NULL, "lift the sandbox (the scene and every run; only for scenes you trust)"},
    {"--traceback", NULL, NULL, "print the Lua traceback with errors"},
    {NULL, NULL, NULL, NULL}};

static const pl_command_help sweep_help = {
    "sweep", "SCENE.lua [--grid NAME=LIST ...] [--seeds LIST] [--lhs N] [options]",
    "Expands parameter values (the scene's declared params, checked against their ranges) and\n"
    "run seeds into jobs: DIR/jobs.txt holds one 'porelab run' command per line, DIR/jobs.tsv\n"
    "what each job is. --run runs the jobs not done yet through GNU parallel; --slurm writes a\n"
    "Slurm array script (SLURM_ARRAY_TASK_ID picks the line of jobs.txt) and --snakemake a\n"
    "Snakefile. Every job writes DIR/job_NNNN/manifest.json; a job whose manifest holds a\n"
    "finished run with the same inputs is skipped, so re-running resumes an interrupted sweep.\n"
    "Then: porelab collect DIR --chart RESULT:PARAM (docs/scaling.md).",
    sweep_specs};

typedef struct axis {
    char name[48];
    int n;
    double *v;
    int idx; /* into the declared parameters */
} axis;

static void fmt_num(char *b, size_t n, double v)
{
    snprintf(b, n, "%.15g", v);
    if (strtod(b, NULL) != v) snprintf(b, n, "%.17g", v);
}

/* 'text' quoted for sh */
static void put_quoted(FILE *f, const char *s)
{
    fputc('\'', f);
    for (; *s; s++) {
        if (*s == '\'') fputs("'\\''", f);
        else fputc(*s, f);
    }
    fputc('\'', f);
}

/* "text" as a Python string literal */
static void put_pystr(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\') fputc('\\', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

static int bad(const char *fmt, const char *a, const char *b)
{
    fprintf(stderr, "porelab sweep: ");
    fprintf(stderr, fmt, a, b);
    fputc('\n', stderr);
    return -1;
}

static int parse_number(const char *s, size_t len, double *out)
{
    char buf[64];
    if (len == 0 || len >= sizeof buf) return -1;
    memcpy(buf, s, len);
    buf[len] = '\0';
    char *end;
    double v = strtod(buf, &end);
    if (end == buf || *end || !isfinite(v)) return -1;
    *out = v;
    return 0;
}

/* "name=a,b,c" or "name=lo:hi:count" */
static int parse_grid(const char *arg, axis *a)
{
    const char *eq = strchr(arg, '=');
    if (!eq || eq == arg || (size_t)(eq - arg) >= sizeof a->name)
        return bad("--grid must be NAME=V1,V2,... or NAME=LO:HI:COUNT (got '%s')%s", arg, "");
    memcpy(a->name, arg, (size_t)(eq - arg));
    a->name[eq - arg] = '\0';
    const char *list = eq + 1;
    a->v = calloc(MAX_VALUES, sizeof *a->v);
    a->n = 0;
    if (!a->v) return bad("out of memory%s%s", "", "");
    if (strchr(list, ':')) {
        double lo, hi, cnt;
        const char *c1 = strchr(list, ':'), *c2 = c1 ? strchr(c1 + 1, ':') : NULL;
        if (!c2 || parse_number(list, (size_t)(c1 - list), &lo) || parse_number(c1 + 1, (size_t)(c2 - c1 - 1), &hi) ||
            parse_number(c2 + 1, strlen(c2 + 1), &cnt) || cnt < 1 || cnt > MAX_VALUES || cnt != floor(cnt) ||
            (cnt == 1 && lo != hi))
            return bad("--grid %s: LO:HI:COUNT needs two numbers and a count in 1..1000 (got '%s')", a->name, list);
        for (int i = 0; i < (int)cnt; i++) a->v[a->n++] = cnt == 1 ? lo : lo + (hi - lo) * i / (cnt - 1);
        return 0;
    }
    for (const char *p = list;;) {
        const char *c = strchr(p, ',');
        size_t len = c ? (size_t)(c - p) : strlen(p);
        if (a->n >= MAX_VALUES) return bad("--grid %s: at most 1000 values%s", a->name, "");
        if (parse_number(p, len, &a->v[a->n]) != 0)
            return bad("--grid %s: '%s' is not a list of numbers (NAME=V1,V2,...)", a->name, list);
        a->n++;
        if (!c) break;
        p = c + 1;
    }
    return 0;
}

/* "1..6", "1,3,5", "0..2,10" */
static int parse_seeds(const char *s, long long *out, int *n)
{
    *n = 0;
    for (const char *p = s;;) {
        const char *c = strchr(p, ',');
        size_t len = c ? (size_t)(c - p) : strlen(p);
        char buf[64];
        if (len == 0 || len >= sizeof buf) return bad("--seeds must be a list like 1..6 or 1,3,7 (got '%s')%s", s, "");
        memcpy(buf, p, len);
        buf[len] = '\0';
        char *end;
        long long a = strtoll(buf, &end, 10), b = a;
        if (end == buf) return bad("--seeds must be a list like 1..6 or 1,3,7 (got '%s')%s", s, "");
        if (strncmp(end, "..", 2) == 0) {
            char *e2;
            b = strtoll(end + 2, &e2, 10);
            if (e2 == end + 2 || *e2) return bad("--seeds must be a list like 1..6 or 1,3,7 (got '%s')%s", s, "");
        } else if (*end) {
            return bad("--seeds must be a list like 1..6 or 1,3,7 (got '%s')%s", s, "");
        }
        if (a < 0 || b < a || b > 9007199254740991LL)
            return bad("--seeds: each range A..B needs 0 <= A <= B <= 2^53-1 (got '%s')%s", s, "");
        for (long long k = a; k <= b; k++) {
            if (*n >= MAX_SEEDS) return bad("--seeds: at most 100000 seeds (got '%s')%s", s, "");
            out[(*n)++] = k;
        }
        if (!c) break;
        p = c + 1;
    }
    return 0;
}

static int self_exe(char *out, size_t n)
{
    ssize_t k = readlink("/proc/self/exe", out, n - 1);
    if (k <= 0) return -1;
    out[k] = '\0';
    return 0;
}

static FILE *open_out(const char *dir, const char *name, char *path, size_t n)
{
    snprintf(path, n, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    if (!f) fprintf(stderr, "porelab sweep: cannot write %s: %s\n", path, strerror(errno));
    return f;
}

static int close_out(FILE *f, const char *path)
{
    if (ferror(f) | (fclose(f) != 0)) {
        fprintf(stderr, "porelab sweep: cannot write %s\n", path);
        return -1;
    }
    return 0;
}

/* Runs GNU parallel on the pending jobs; returns its exit status (the number of failed jobs,
 * up to 100) or -1 when it cannot be started. */
static int run_parallel(const char *pending, const char *joblog, long long jobs)
{
    char j[32];
    snprintf(j, sizeof j, "%lld", jobs);
    pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        char *args[] = {"parallel", "--will-cite", "--jobs", j, "--joblog", (char *)joblog, "--arg-file",
                        (char *)pending, NULL};
        execvp("parallel", args);
        fprintf(stderr, "porelab sweep: cannot start GNU parallel (%s): install the Debian package 'parallel', or "
                        "run the lines of jobs.txt another way (sweep.slurm, Snakefile, or: bash jobs.txt)\n",
                strerror(errno));
        _exit(127);
    }
    int st;
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR) return -1;
    if (!WIFEXITED(st)) return -1;
    return WEXITSTATUS(st) == 127 ? -1 : WEXITSTATUS(st);
}

int pl_cmd_sweep(int argc, char **argv)
{
    pl_opts o;
    int rc = pl_opts_parse(&o, &sweep_help, argc, argv, 1);
    if (rc >= 0) return rc;
    if (pl_cli_require_scene(&o) != 0) return PL_EXIT_USAGE;
    const char *scene = o.positional[0];
    char dir[PATH_MAX], stem[256], cwd[PATH_MAX];
    pl_path_stem(scene, stem, sizeof stem);
    if (pl_opts_has(&o, "--out")) snprintf(dir, sizeof dir, "%s", pl_opts_get(&o, "--out"));
    else snprintf(dir, sizeof dir, "out/%s-sweep", stem);
    size_t dl = strlen(dir);
    while (dl > 1 && dir[dl - 1] == '/') dir[--dl] = '\0';
    if (dir[0] != '/' && getcwd(cwd, sizeof cwd)) {
        char rel[PATH_MAX];
        snprintf(rel, sizeof rel, "%s", dir);
        pl_path_join(dir, sizeof dir, cwd, rel);
    }
    long long jobs_at_once = sysconf(_SC_NPROCESSORS_ONLN) > 0 ? sysconf(_SC_NPROCESSORS_ONLN) : 1, lhs = 0,
              lhs_seed = 1;
    if (pl_opts_count(&o, "--jobs", 1, &jobs_at_once) || pl_opts_count(&o, "--lhs", 1, &lhs) ||
        pl_opts_count(&o, "--lhs-seed", 0, &lhs_seed))
        return PL_EXIT_USAGE;
    if (lhs > MAX_JOBS) return bad("--lhs: at most 100000 points (got %s)%s", pl_opts_get(&o, "--lhs"), ""), PL_EXIT_USAGE;
    double tmp;
    if (pl_opts_double(&o, "--until", 0, 0, &tmp)) return PL_EXIT_USAGE;
    long long tsteps;
    if (pl_opts_count(&o, "--steps", 1, &tsteps)) return PL_EXIT_USAGE;

    /* the grid, checked against what the scene declares */
    axis ax[MAX_AXES];
    memset(ax, 0, sizeof ax);
    const char *grid[MAX_AXES + 1], *ranges[MAX_AXES + 1];
    int ngrid = pl_opts_all(&o, "--grid", grid, MAX_AXES + 1), nrange = pl_opts_all(&o, "--range", ranges, MAX_AXES + 1);
    if (ngrid > MAX_AXES || nrange > MAX_AXES) return bad("at most 16 --grid and 16 --range options%s%s", "", ""), PL_EXIT_USAGE;
    int nax = 0;
    rc = PL_EXIT_USAGE;
    long long *seeds = calloc(MAX_SEEDS, sizeof *seeds);
    int nseeds = 1;
    double *pts = NULL;
    pl_scene *s = NULL;
    if (!seeds) goto done;
    if (pl_opts_has(&o, "--seeds") && parse_seeds(pl_opts_get(&o, "--seeds"), seeds, &nseeds) != 0) goto done;
    for (int i = 0; i < ngrid; i++, nax++) {
        if (parse_grid(grid[i], &ax[nax]) != 0) goto done;
        for (int k = 0; k < nax; k++)
            if (strcmp(ax[k].name, ax[nax].name) == 0) {
                bad("--grid %s given twice%s", ax[nax].name, "");
                nax++;
                goto done;
            }
    }
    if (pl_path_mkdirs(dir) != 0) {
        fprintf(stderr, "porelab sweep: cannot create %s: %s\n", dir, strerror(errno));
        rc = PL_EXIT_FAIL;
        goto done;
    }
    s = pl_cli_load_scene(&o, dir); /* builds it once: the declared parameters and their ranges */
    if (!s) {
        rc = PL_EXIT_FAIL;
        goto done;
    }
    pl_scene_param decl[2 * PL_SCENE_MAX_PARAMS];
    int ndecl = pl_scene_declared_params(s, decl, NULL, 2 * PL_SCENE_MAX_PARAMS);
    char list[2048] = "";
    for (int i = 0, k = 0; i < ndecl; i++)
        k += snprintf(list + k, sizeof list - (size_t)k, "%s%s in [%g, %g]%s%s", i ? ", " : "", decl[i].name,
                      decl[i].min, decl[i].max, decl[i].unit[0] ? " " : "", decl[i].unit);
    for (int a = 0; a < nax; a++) {
        ax[a].idx = -1;
        for (int i = 0; i < ndecl; i++)
            if (strcmp(decl[i].name, ax[a].name) == 0) ax[a].idx = i;
        if (ax[a].idx < 0) {
            fprintf(stderr, "porelab sweep: --grid %s: %s declares no parameter '%s'; %s%s\n", ax[a].name, scene,
                    ax[a].name, ndecl ? "its parameters: " : "it declares none (porelab.params{...}, "
                                                             "docs/scene-reference.md)", list);
            goto done;
        }
        const pl_scene_param *p = &decl[ax[a].idx];
        for (int k = 0; k < ax[a].n; k++)
            if (!(ax[a].v[k] >= p->min && ax[a].v[k] <= p->max)) {
                fprintf(stderr, "porelab sweep: --grid %s: %g is outside the declared range [%g, %g]%s%s\n", p->name,
                        ax[a].v[k], p->min, p->max, p->unit[0] ? " " : "", p->unit);
                goto done;
            }
    }
    /* the Latin hypercube: N points, each parameter's range cut into N strata, one point per
     * stratum in each parameter, strata paired by independent random permutations */
    int lhs_dim[MAX_AXES], nlhs = 0;
    double lhs_lo[MAX_AXES], lhs_hi[MAX_AXES];
    if (lhs > 0) {
        for (int r = 0; r < nrange; r++) {
            const char *eq = strchr(ranges[r], '='), *c = eq ? strchr(eq, ':') : NULL;
            char name[48];
            double lo, hi;
            if (!eq || !c || (size_t)(eq - ranges[r]) >= sizeof name || parse_number(eq + 1, (size_t)(c - eq - 1), &lo) ||
                parse_number(c + 1, strlen(c + 1), &hi) || !(hi > lo)) {
                bad("--range must be NAME=LO:HI with LO < HI (got '%s')%s", ranges[r], "");
                goto done;
            }
            memcpy(name, ranges[r], (size_t)(eq - ranges[r]));
            name[eq - ranges[r]] = '\0';
            int idx = -1;
            for (int i = 0; i < ndecl; i++)
                if (strcmp(decl[i].name, name) == 0) idx = i;
            if (idx < 0 || lo < decl[idx].min || hi > decl[idx].max) {
                fprintf(stderr, "porelab sweep: --range %s: %s\n", ranges[r],
                        idx < 0 ? "the scene declares no such parameter" : "outside the declared range");
                if (ndecl) fprintf(stderr, "porelab sweep: its parameters: %s\n", list);
                goto done;
            }
            lhs_dim[nlhs] = idx, lhs_lo[nlhs] = lo, lhs_hi[nlhs++] = hi;
        }
        if (nrange == 0)
            for (int i = 0; i < ndecl && nlhs < MAX_AXES; i++) {
                int on_grid = 0;
                for (int a = 0; a < nax; a++) on_grid |= ax[a].idx == i;
                if (!on_grid) lhs_dim[nlhs] = i, lhs_lo[nlhs] = decl[i].min, lhs_hi[nlhs++] = decl[i].max;
            }
        for (int d = 0; d < nlhs; d++)
            for (int a = 0; a < nax; a++)
                if (ax[a].idx == lhs_dim[d]) {
                    fprintf(stderr, "porelab sweep: %s is both on the grid and in the Latin hypercube\n", ax[a].name);
                    goto done;
                }
        if (nlhs == 0) {
            fprintf(stderr, "porelab sweep: --lhs: no parameter to sample (the scene declares %s)\n",
                    ndecl ? "only grid parameters" : "none");
            goto done;
        }
        pts = calloc((size_t)lhs * (size_t)nlhs, sizeof *pts);
        int *perm = calloc((size_t)lhs, sizeof *perm);
        if (!pts || !perm) {
            free(perm);
            rc = PL_EXIT_FAIL;
            goto done;
        }
        pl_rng rng;
        pl_rng_seed(&rng, (uint64_t)lhs_seed);
        for (int d = 0; d < nlhs; d++) {
            for (int i = 0; i < lhs; i++) perm[i] = i;
            for (int i = (int)lhs - 1; i > 0; i--) {
                int j = (int)(pl_rng_next(&rng) % (uint64_t)(i + 1));
                int t = perm[i];
                perm[i] = perm[j];
                perm[j] = t;
            }
            for (int i = 0; i < lhs; i++)
                pts[i * nlhs + d] = lhs_lo[d] + (lhs_hi[d] - lhs_lo[d]) * (perm[i] + pl_rng_uniform(&rng)) / (double)lhs;
        }
        free(perm);
    }
    long long ncomb = 1;
    for (int a = 0; a < nax; a++) ncomb *= ax[a].n;
    long long npoints = ncomb * (lhs > 0 ? lhs : 1), njobs = npoints * nseeds;
    if (njobs > MAX_JOBS) {
        fprintf(stderr, "porelab sweep: %lld jobs (grid %lld x Latin hypercube %lld x seeds %d): at most %d\n", njobs,
                ncomb, lhs > 0 ? lhs : 1, nseeds, MAX_JOBS);
        goto done;
    }

    /* the job files */
    rc = PL_EXIT_FAIL;
    char exe[PATH_MAX], scene_abs[PATH_MAX], pj[PATH_MAX + 32], pt[PATH_MAX + 32], pp[PATH_MAX + 32];
    if (self_exe(exe, sizeof exe) != 0) snprintf(exe, sizeof exe, "porelab");
    if (!realpath(scene, scene_abs)) snprintf(scene_abs, sizeof scene_abs, "%s", scene);
    FILE *fj = open_out(dir, "jobs.txt", pj, sizeof pj);
    FILE *ft = fj ? open_out(dir, "jobs.tsv", pt, sizeof pt) : NULL;
    FILE *fp = ft ? open_out(dir, "pending.txt", pp, sizeof pp) : NULL;
    if (!fp) {
        if (fj) fclose(fj);
        if (ft) fclose(ft);
        goto done;
    }
    fprintf(ft, "job\tdir");
    for (int a = 0; a < nax; a++) fprintf(ft, "\t%s", ax[a].name);
    for (int d = 0; d < nlhs; d++) fprintf(ft, "\t%s", decl[lhs_dim[d]].name);
    fprintf(ft, "\tseed\tstatus\n");
    int width = njobs < 10000 ? 4 : 6, ndone = 0;
    const char *until = pl_opts_get(&o, "--until"), *steps = pl_opts_get(&o, "--steps");
    for (long long j = 0; j < njobs; j++) {
        long long seed_i = j % nseeds, point = j / nseeds, comb = point / (lhs > 0 ? lhs : 1),
                  lp = point % (lhs > 0 ? lhs : 1);
        char jdir[PATH_MAX + 64], num[40];
        snprintf(jdir, sizeof jdir, "%s/job_%0*lld", dir, width, j + 1);
        /* the command; the inputs key the same as the job's porelab run computes */
        pl_manifest m;
        memset(&m, 0, sizeof m);
        m.seed = seeds[seed_i];
        m.until = until;
        m.steps = steps;
        char line[8192];
        FILE *fl = fmemopen(line, sizeof line, "w");
        if (!fl) goto close_all;
        fprintf(fl, "mkdir -p ");
        put_quoted(fl, jdir);
        fprintf(fl, " && ");
        put_quoted(fl, exe);
        fprintf(fl, " run ");
        put_quoted(fl, scene_abs);
        fprintf(fl, " --out ");
        put_quoted(fl, jdir);
        long long c = comb;
        fprintf(ft, "%lld\t%s", j + 1, jdir);
        for (int a = 0; a < nax; a++) { /* the first axis varies slowest */
            long long stride = 1;
            for (int b = a + 1; b < nax; b++) stride *= ax[b].n;
            double v = ax[a].v[(c / stride) % ax[a].n];
            fmt_num(num, sizeof num, v);
            fprintf(fl, " --param %s=%s", ax[a].name, num);
            fprintf(ft, "\t%s", num);
            snprintf(m.over_name[m.nover], sizeof m.over_name[0], "%.47s", ax[a].name);
            m.over_value[m.nover++] = v;
        }
        for (int d = 0; d < nlhs; d++) {
            double v = pts[lp * nlhs + d];
            fmt_num(num, sizeof num, v);
            strtod(num, NULL);
            v = strtod(num, NULL); /* the run gets the printed value */
            fprintf(fl, " --param %s=%s", decl[lhs_dim[d]].name, num);
            fprintf(ft, "\t%s", num);
            snprintf(m.over_name[m.nover], sizeof m.over_name[0], "%.47s", decl[lhs_dim[d]].name);
            m.over_value[m.nover++] = v;
        }
        fprintf(fl, " --seed %lld", seeds[seed_i]);
        if (until) fprintf(fl, " --until %s", until);
        if (steps) fprintf(fl, " --steps %s", steps);
        if (!pl_opts_has(&o, "--frames")) fprintf(fl, " --no-frames");
        if (pl_opts_has(&o, "--trust")) fprintf(fl, " --trust");
        fprintf(fl, " --quiet --skip-done > ");
        char log[PATH_MAX + 80];
        snprintf(log, sizeof log, "%s/run.log", jdir);
        put_quoted(fl, log);
        fprintf(fl, " 2>&1");
        int over = fclose(fl) != 0 || strlen(line) + 1 >= sizeof line;
        if (over) {
            fprintf(stderr, "porelab sweep: the command of job %lld is too long\n", j + 1);
            goto close_all;
        }
        char err[256];
        pl_manifest_prepare(&m, scene, err, sizeof err);
        int done_already = pl_manifest_done(jdir, m.inputs);
        ndone += done_already;
        fprintf(fj, "%s\n", line);
        if (!done_already) fprintf(fp, "%s\n", line);
        fprintf(ft, "\t%lld\t%s\n", seeds[seed_i], done_already ? "done" : "pending");
    }
    if (close_out(fj, pj) | close_out(ft, pt) | close_out(fp, pp)) goto done;
    fj = ft = fp = NULL;
    printf("porelab sweep: %lld jobs (", njobs);
    for (int a = 0; a < nax; a++) printf("%s%s %d values", a ? " x " : "", ax[a].name, ax[a].n);
    if (lhs > 0) printf("%sLatin hypercube %lld points over %d parameters", nax ? " x " : "", lhs, nlhs);
    printf("%s%d seed%s) in %s/: %d done, %lld to run\n", nax || lhs ? " x " : "", nseeds, nseeds == 1 ? "" : "s",
           dir, ndone, njobs - ndone);
    printf("  %-12s%s (one 'porelab run' per line), jobs.tsv, pending.txt\n", "jobs", pj);

    if (pl_opts_has(&o, "--slurm")) {
        char path[PATH_MAX + 32];
        FILE *f = open_out(dir, "sweep.slurm", path, sizeof path);
        if (!f) goto done;
        fprintf(f, "#!/bin/bash\n"
                   "# porelab sweep of %s: %lld jobs, one per array task (task N runs line N of jobs.txt).\n"
                   "# Submit: sbatch %s   (add e.g. --time=1:00:00 --partition=... as your cluster needs)\n"
                   "# Try one task here: SLURM_ARRAY_TASK_ID=1 bash %s\n"
                   "# Jobs already done (same inputs) return at once, so resubmitting finishes the rest.\n"
                   "#SBATCH --job-name=porelab-%s\n#SBATCH --array=1-%lld\n#SBATCH --ntasks=1\n"
                   "#SBATCH --cpus-per-task=1\n#SBATCH --output=%s/slurm-%%A_%%a.out\n"
                   "set -euo pipefail\n"
                   ": \"${SLURM_ARRAY_TASK_ID:?set by sbatch --array (or by hand: SLURM_ARRAY_TASK_ID=1 bash $0)}\"\n"
                   "jobs=",
                scene_abs, njobs, path, path, stem, njobs, dir);
        put_quoted(f, pj);
        fprintf(f, "\nline=$(sed -n \"${SLURM_ARRAY_TASK_ID}p\" \"$jobs\")\n"
                   "if [ -z \"$line\" ]; then\n"
                   "  echo \"porelab sweep: no job ${SLURM_ARRAY_TASK_ID} in $jobs (1..%lld)\" >&2\n  exit 2\nfi\n"
                   "exec bash -c \"$line\"\n", njobs);
        if (close_out(f, path)) goto done;
        chmod(path, 0755);
        printf("  %-12s%s (sbatch it; SLURM_ARRAY_TASK_ID picks the line)\n", "slurm", path);
    }
    if (pl_opts_has(&o, "--snakemake")) {
        char path[PATH_MAX + 32];
        FILE *f = open_out(dir, "Snakefile", path, sizeof path);
        if (!f) goto done;
        fprintf(f, "# porelab sweep of %s: %lld jobs. Run: snakemake -s %s --cores N\n"
                   "# (on a cluster, with a Slurm executor or profile: snakemake -s %s --jobs N ...).\n"
                   "# A job's target is its manifest; snakemake runs only the missing ones.\n"
                   "JOBS = [line.rstrip(\"\\n\") for line in open(",
                scene_abs, njobs, path, path);
        put_pystr(f, pj);
        fprintf(f, ")]\nIDS = [\"%%0%dd\" %% (i + 1) for i in range(len(JOBS))]\nOUT = ", width);
        put_pystr(f, dir);
        fprintf(f, "\n\nrule all:\n    input: expand(OUT + \"/job_{id}/manifest.json\", id=IDS)\n\n"
                   "rule run:\n    output: OUT + \"/job_{id}/manifest.json\"\n"
                   "    params: cmd=lambda wc: JOBS[int(wc.id) - 1]\n    shell: \"{params.cmd}\"\n");
        if (close_out(f, path)) goto done;
        printf("  %-12s%s (snakemake -s %s --cores N)\n", "snakemake", path, path);
    }
    if (pl_opts_has(&o, "--run")) {
        char joblog[PATH_MAX + 32];
        snprintf(joblog, sizeof joblog, "%s/parallel.log", dir);
        double t0 = pl_wall_seconds();
        long long todo = njobs - ndone;
        int failed = todo > 0 ? run_parallel(pp, joblog, jobs_at_once) : 0;
        double wall = pl_wall_seconds() - t0;
        if (failed < 0) {
            fprintf(stderr, "porelab sweep: GNU parallel could not be run (see above)\n");
            goto done;
        }
        if (failed > 101) {
            /* GNU parallel: 1-100 failed jobs, 101 more than 100, 255 (and others) an error of its own or a
               signal; the jobs that finished keep their manifests */
            fprintf(stderr, "porelab sweep: GNU parallel stopped after %.1f s (exit status %d: interrupted, or an "
                            "error of its own; log %s); finished jobs are kept, re-running the sweep resumes\n",
                    wall, failed, joblog);
            goto done;
        }
        printf("  %-12s%lld job%s through GNU parallel --jobs %lld in %.1f s (%.1f jobs/hour); log %s\n", "ran",
               todo, todo == 1 ? "" : "s", jobs_at_once, wall, wall > 0 ? 3600.0 * (double)todo / wall : 0, joblog);
        if (failed > 0) {
            printf("  %-12s%s%d job%s failed (exit status in their manifest.json and run.log); re-running the sweep "
                   "runs them again\n", "failed", failed == 101 ? "more than " : "", failed == 101 ? 100 : failed,
                   failed == 1 ? "" : "s");
            goto done;
        }
        printf("  %-12sporelab collect %s\n", "next", dir);
    } else {
        printf("  %-12sporelab sweep ... --run (GNU parallel), or: parallel --jobs N < %s\n", "run", pp);
    }
    rc = PL_EXIT_OK;
    goto done;
close_all:
    if (fj) fclose(fj);
    if (ft) fclose(ft);
    if (fp) fclose(fp);
done:
    pl_scene_destroy(&s);
    for (int a = 0; a < nax; a++) free(ax[a].v);
    free(pts);
    free(seeds);
    return rc;
}
