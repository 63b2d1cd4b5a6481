/* Benchmark of the boundary-element Stokes model (not a test; docs/stokes.md "Cost"):
 *   1. error against CPU time for several element counts per particle
 *      - seed 003 §4.4.1, the fixed cylinder in Poiseuille flow (k = 0.2): T/(μU) against the
 *        finest run of the set (every boundary refined in proportion);
 *      - seed 003 §5.1, the disc between walls: its resistance K from one solve against Faxén's
 *        series (Happel & Brenner 7-5.9; 16.533 μ at k = 0.2);
 *   2. cost per coupled grain step with 3, 20, 50, 100 and 400 discs (16 elements each) in a
 *      fixed box, the dense LU's growth with the boundary nodes and the process's peak memory;
 *   3. the §5.1 disc falling between walls with the hydrostatic and the Darcy models beside the
 *      boundary elements (and the Darcy model started from zero pressure instead of its static
 *      field): fall velocity after 0.03 s and CPU per step.
 *     bench_stokes [OUT_DIR] [--docs FILE] [--max-discs N]
 *       CSV OUT_DIR/bench_stokes.csv; with the app's charts (porelab_render) OUT_DIR/stokes_error_cpu.png;
 *       --docs: the tables between FILE's "<!-- generated: bench_stokes NAME begin" and
 *       "<!-- generated: bench_stokes NAME end -->" lines are rewritten (docs/stokes.md, Cost);
 *       --max-discs: leave out the step-cost cases with more discs (400 needs about 10 GB and
 *       tens of minutes). Set OPENBLAS_NUM_THREADS=1 for CPU times of one core.
 *     bench_stokes OUT_DIR --chart-from CSV
 *       only the chart, from the cylinder and disc rows of a bench_stokes.csv. */
#include "stokes/stokes_cases.h"
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#if BENCH_CHART
#include "bench/bench_chart.h"
#endif

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

static double peak_gb(void) {
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1048576.0; /* kB -> GB */
}

static double load_average(void) {
    double l = -1;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &l) != 1) l = -1;
        fclose(f);
    }
    return l;
}

/* Markdown blocks for --docs, one per table */
#define NBLOCK 4
static const char *const block_name[NBLOCK] = {"elements", "cylinder", "step-cost", "rungs"};
static char block[NBLOCK][4096];

static void md(int b, const char *fmt, ...) {
    const size_t n = strlen(block[b]);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(block[b] + n, sizeof block[b] - n, fmt, ap);
    va_end(ap);
}

/* Rewrites the lines between each block's begin and end markers in FILE; fails when a
   marker is missing. */
static int write_docs(const char *file) {
    FILE *f = fopen(file, "rb");
    if (!f) {
        fprintf(stderr, "bench_stokes: --docs: cannot read %s\n", file);
        return 1;
    }
    fseek(f, 0, SEEK_END);
    const long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = malloc((size_t)len + 1);
    if (!text || fread(text, 1, (size_t)len, f) != (size_t)len) {
        fclose(f);
        free(text);
        fprintf(stderr, "bench_stokes: --docs: cannot read %s\n", file);
        return 1;
    }
    fclose(f);
    text[len] = 0;
    for (int b = 0; b < NBLOCK; b++) {
        char begin[128], end[128];
        snprintf(begin, sizeof begin, "<!-- generated: bench_stokes %s begin", block_name[b]);
        snprintf(end, sizeof end, "<!-- generated: bench_stokes %s end -->", block_name[b]);
        char *p = strstr(text, begin), *q = p ? strstr(p, end) : NULL;
        char *eol = p ? strchr(p, '\n') : NULL;
        if (!p || !q || !eol || eol > q) {
            fprintf(stderr, "bench_stokes: --docs: %s has no block '%s ... -->' followed by '%s'\n", file, begin, end);
            free(text);
            return 1;
        }
        const size_t head = (size_t)(eol + 1 - text), nb = strlen(block[b]), tail = strlen(q);
        char *t = malloc(head + nb + tail + 1);
        if (!t) {
            free(text);
            return 1;
        }
        memcpy(t, text, head);
        memcpy(t + head, block[b], nb);
        memcpy(t + head + nb, q, tail + 1);
        free(text);
        text = t;
    }
    f = fopen(file, "wb");
    if (!f || fputs(text, f) < 0) {
        fprintf(stderr, "bench_stokes: --docs: cannot write %s\n", file);
        if (f) fclose(f);
        free(text);
        return 1;
    }
    fclose(f);
    free(text);
    printf("wrote the tables into %s\n", file);
    return 0;
}

#define NCYL 4
#define NDISC 5

/* The chart: the §4.4.1 cylinder against its finest run, the §5.1 disc against Faxén's series */
static void chart(const char *dir, const double c1[], const double e1[], int n1, const double c2[], const double e2[],
                  int n2) {
#if BENCH_CHART
    char path[512];
    snprintf(path, sizeof path, "%s/stokes_error_cpu.png", dir);
    const char *const names[2] = {"cylinder in Poiseuille flow between plates (against the finest mesh)",
                                  "disc settling between walls (against Faxén's series)"};
    const double *const x[2] = {c1, c2}, *const y[2] = {e1, e2};
    const int n[2] = {n1, n2};
    bench_error_cpu_chart(path, "Boundary-element Stokes: drag error against CPU time", "CPU time per solve (s)",
                          "relative error of the drag", 4, 2, names, x, y, n);
#else
    (void)dir, (void)c1, (void)e1, (void)n1, (void)c2, (void)e2, (void)n2;
#endif
}

/* --chart-from CSV: the chart again from the rows a full run wrote (bench_stokes.csv), so it
   matches the tables of docs/stokes.md without the hour-long run */
static int chart_from_csv(const char *csv, const char *dir) {
    FILE *f = fopen(csv, "r");
    if (!f) {
        fprintf(stderr, "bench_stokes: --chart-from: cannot read %s\n", csv);
        return 1;
    }
    double c1[NCYL], e1[NCYL], c2[NDISC], e2[NDISC];
    int n1 = 0, n2 = 0, line = 0;
    char buf[512];
    while (fgets(buf, sizeof buf, f)) {
        line++;
        char name[64];
        int el, unk;
        double cpu_s, value, err;
        if (sscanf(buf, "%63[^,],%d,%d,%lf,%lf,%lf", name, &el, &unk, &cpu_s, &value, &err) != 6) continue;
        if (!strcmp(name, "cylinder_4.4.1") && n1 < NCYL) c1[n1] = cpu_s, e1[n1++] = err;
        else if (!strcmp(name, "disc_5.1") && n2 < NDISC) c2[n2] = cpu_s, e2[n2++] = err;
    }
    fclose(f);
    if (n1 != NCYL || n2 != NDISC) {
        fprintf(stderr, "bench_stokes: --chart-from: %s has %d cylinder_4.4.1 rows (need %d) and %d disc_5.1 rows (need %d) in %d lines\n",
                csv, n1, NCYL, n2, NDISC, line);
        return 1;
    }
    chart(dir, c1, e1, n1, c2, e2, n2);
    return 0;
}

int main(int argc, char **argv) {
    const char *dir = ".", *docs = NULL, *chart_csv = NULL;
    int max_discs = 400;
    for (int a = 1; a < argc; a++) {
        if (!strcmp(argv[a], "--chart-from") && a + 1 < argc) {
            chart_csv = argv[++a];
        } else if (!strcmp(argv[a], "--docs") && a + 1 < argc) {
            docs = argv[++a];
        } else if (!strcmp(argv[a], "--max-discs") && a + 1 < argc) {
            char *e;
            const long v = strtol(argv[++a], &e, 10);
            if (*e || v < 3 || v > 400) {
                fprintf(stderr, "bench_stokes: --max-discs must be an integer in [3, 400] (got '%s')\n", argv[a]);
                return 2;
            }
            max_discs = (int)v;
        } else if (argv[a][0] != '-') {
            dir = argv[a];
        } else {
            fprintf(stderr, "usage: bench_stokes [OUT_DIR] [--docs FILE] [--max-discs N] [--chart-from CSV]\n");
            return 2;
        }
    }
    if (chart_csv) return chart_from_csv(chart_csv, dir);
    setvbuf(stdout, NULL, _IOLBF, 0);
    const double load0 = load_average();
    char path[512];
    snprintf(path, sizeof path, "%s/bench_stokes.csv", dir);
    FILE *csv = fopen(path, "w");
    if (!csv) {
        fprintf(stderr, "bench_stokes: cannot write %s\n", path);
        return 1;
    }
    fprintf(csv, "case,elements_per_particle,unknowns,cpu_s,value,rel_error\n");
    pl_sb_rules R;
    if (pl_sb_rules_init(&R) != PL_OK) return 1;

    /* 1a. §4.4.1 cylinder: walls 5, ends 2.5, disc 64/(2π) elements per unit length at s = 1 */
    const double sc[NCYL] = {0.25, 0.5, 1, 2}, sref = 3;
    double c1[NCYL], e1[NCYL], T1[NCYL];
    pl_sb_solver s;
    memset(&s, 0, sizeof s);
    const double Tref = sc_cylinder(&R, &s, 0.2, 15, (int)(150 * sref), (int)(25 * sref), (int)(64 * sref), 0, NULL);
    printf("4.4.1 cylinder, k = 0.2: reference (disc %d elements, walls %d) T/(mu U) = %.5f (Tan 24.20)\n",
           (int)(64 * sref), (int)(150 * sref), Tref);
    printf("  disc elements  unknowns  CPU per solve (s)  T/(mu U)   error vs finest\n");
    md(1, "| §4.4.1 cylinder: elements on the disc | unknowns | CPU per solve | T/(μU) | error vs the finest (%d elements: %.3f) |\n"
          "|---|---|---|---|---|\n", (int)(64 * sref), Tref);
    for (int i = 0; i < NCYL; i++) {
        pl_sb_solver_free(&s);
        memset(&s, 0, sizeof s);
        const double t0 = cpu();
        T1[i] = sc_cylinder(&R, &s, 0.2, 15, (int)(150 * sc[i]), (int)(25 * sc[i]), (int)(64 * sc[i]), 0, NULL);
        c1[i] = cpu() - t0;
        e1[i] = fabs(T1[i] / Tref - 1);
        printf("  %13d  %8d  %17.3f  %9.5f  %.2e\n", (int)(64 * sc[i]), s.n, c1[i], T1[i], e1[i]);
        fprintf(csv, "cylinder_4.4.1,%d,%d,%.6g,%.8g,%.6g\n", (int)(64 * sc[i]), s.n, c1[i], T1[i], e1[i]);
        md(1, "| %d | %d | %.3g s | %.3f | %.1e |\n", (int)(64 * sc[i]), s.n, c1[i], T1[i], e1[i]);
    }
    pl_sb_solver_free(&s);

    /* 1b. §5.1 disc: resistance from one world solve against Faxén */
    const int nd[NDISC] = {8, 16, 32, 64, 128};
    double c2[NDISC], e2[NDISC];
    const double Kf = 50 * sc_faxen(0.2);
    printf("5.1 disc between walls (r = 0.5 cm, 2b = 5 cm, 40 cm high, mu = 50 P): Faxen K = %.3f g/(cm s)\n", Kf);
    printf("  disc elements  unknowns  CPU per solve (s)  K/mu      error vs Faxen\n");
    md(0, "| §5.1 disc: elements per disc | unknowns | CPU per solve | K/μ | K error vs Faxén (%.3f) |\n"
          "|---|---|---|---|---|\n", Kf / 50);
    for (int i = 0; i < NDISC; i++) {
        pl_world *w = sc_world_box(-2.5, 2.5, -20, 20, -980, 5e-4, 2.0, pl_default_material_def().friction);
        const int d = sc_world_disc(w, (pl_vec2){0, 0}, 0.5);
        pl_stokes_def sd = pl_default_stokes_def();
        sd.viscosity = 50;
        sd.density = 1;
        sd.disc_elements = nd[i];
        sd.wall_elements = 4;
        sd.element_length = 8.0 / nd[i];
        pl_world_attach_stokes(w, &sd);
        const double t0 = cpu();
        if (pl_world_stokes_solve(w) != PL_OK) {
            fprintf(stderr, "solve: %s\n", pl_world_last_error(w));
            return 1;
        }
        c2[i] = cpu() - t0;
        pl_stokes_body_result r;
        pl_world_stokes_body(w, d, &r);
        e2[i] = fabs(r.k_trans / Kf - 1);
        printf("  %13d  %8d  %17.3f  %8.4f  %.2e\n", nd[i], pl_world_stokes_unknowns(w), c2[i], r.k_trans / 50, e2[i]);
        fprintf(csv, "disc_5.1,%d,%d,%.6g,%.8g,%.6g\n", nd[i], pl_world_stokes_unknowns(w), c2[i], r.k_trans / 50, e2[i]);
        md(0, "| %d | %d | %.3g s | %.3f | %.1e |\n", nd[i], pl_world_stokes_unknowns(w), c2[i], r.k_trans / 50, e2[i]);
        pl_world_destroy(&w);
    }
    chart(dir, c1, e1, NCYL, c2, e2, NDISC);

    /* 2. cost per coupled step: N discs r = 1 cm, 16 elements each, solid fraction about 0.2,
       placed on a jittered lattice (clearance at least 0.4 r). Up to 100 discs a first step
       factorises the container's block and the next steps are timed; the 400-disc step is
       timed from the start (the container's block, about a tenth of the unknowns, costs about
       a thousandth of the whole LU), since one step takes tens of minutes. */
#define NSTEP 5
    const int NN[NSTEP] = {3, 20, 50, 100, 400};
    double lnN[NSTEP], lnT[NSTEP];
    int nq = 0;
    printf("cost per coupled step (16 elements per disc, fixed box, water):\n"
           "  discs  unknowns  CPU per step (s)  dense matrix (GB)  peak memory (GB)\n");
    md(2, "| discs | unknowns | CPU per step | dense matrix | peak memory of the process so far |\n|---|---|---|---|---|\n");
    for (int q = 0; q < NSTEP && NN[q] <= max_discs; q++, nq++) {
        const int N = NN[q];
        const double r = 0.01, side = sqrt(N * M_PI * r * r / 0.2);
        const int nx = (int)ceil(sqrt((double)N));
        const double pitch = side / nx;
        pl_world *w = sc_world_box(0, side, 0, side, 0, 1e-4, 2650, pl_default_material_def().friction);
        srand(7);
        for (int k = 0; k < N; k++) {
            const double jx = (rand() / (double)RAND_MAX - 0.5) * (pitch - 2.4 * r);
            const double jy = (rand() / (double)RAND_MAX - 0.5) * (pitch - 2.4 * r);
            sc_world_disc(w, (pl_vec2){(k % nx + 0.5) * pitch + jx, (k / nx + 0.5) * pitch + jy}, r);
        }
        pl_stokes_def sd = pl_default_stokes_def();
        sd.disc_elements = 16;
        sd.wall_elements = 4;
        sd.element_length = 2 * M_PI * r / 16;
        sd.check_stability = 1;
        pl_world_attach_stokes(w, &sd);
        if (N < 400 && pl_world_step(w, 1) != PL_OK) { /* first step: the container's factor */
            fprintf(stderr, "step: %s\n", pl_world_last_error(w));
            return 1;
        }
        const int steps = N >= 400 ? 1 : N >= 50 ? 1 : 3;
        const double t0 = cpu();
        if (pl_world_step(w, steps) != PL_OK) {
            fprintf(stderr, "step: %s\n", pl_world_last_error(w));
            return 1;
        }
        const double t = (cpu() - t0) / steps;
        const int n = pl_world_stokes_unknowns(w);
        const double gb = (double)n * n * 8 / 1e9, peak = peak_gb();
        lnN[q] = log((double)n);
        lnT[q] = log(t);
        printf("  %5d  %8d  %16.3f  %17.2f  %16.2f\n", N, n, t, gb, peak);
        fprintf(csv, "step_cost,%d,%d,%.6g,%d,\n", 16, n, t, N);
        md(2, "| %d | %d | %.3g s%s | %.2g GB | %.2g GB |\n", N, n, t, N >= 400 ? " (the first step, with the container's factor)" : "", gb, peak);
        pl_world_destroy(&w);
    }
    if (nq >= 2) {
        const double p = (lnT[nq - 1] - lnT[nq - 2]) / (lnN[nq - 1] - lnN[nq - 2]);
        printf("  growth between %d and %d discs: CPU ~ unknowns^%.2f\n", NN[nq - 2], NN[nq - 1], p);
        md(2, "\nBetween %d and %d discs the CPU time per step grows as unknowns^%.2f (the dense LU: 3).\n", NN[nq - 2],
           NN[nq - 1], p);
    }

    /* 3. the §5.1 disc with the other fluid rungs: fall velocity after 0.03 s; the last case is
       the Darcy model started from zero pressure (the set-up error test_stokes_rungs guards) */
    const double vterm = (2.0 - 1.0) * 980 * M_PI * 0.25 / (50 * sc_faxen(0.2)); /* W' / K */
    const double vfree = 980 * (1 - 1 / 2.0) * 0.03;
    printf("5.1 disc falling between walls, 60 steps of 0.5 ms (exact terminal velocity %.4f cm/s, Faxen;\n"
           "buoyancy alone: %.2f cm/s after 0.03 s):\n"
           "  model           v after 0.03 s (cm/s)  CPU per step (s)\n",
           vterm, vfree);
    md(3, "| model | fall velocity after 0.03 s | CPU per step | what it gets wrong |\n|---|---|---|---|\n");
    for (int m = 0; m < 4; m++) {
        static const char *const names[4] = {"stokes (BEM)", "hydrostatic", "darcy", "darcy, zero start"};
        static const char *const rows[4] = {
            "Stokes (boundary elements)", "hydrostatic (`w:water`, no drag)",
            "Darcy (1 cm cells, Kozeny–Carman permeability, started from the static field)",
            "Darcy as above, started from zero pressure (`first_step_static = 0`, the default)"};
        const char *name = names[m];
        int d;
        pl_status st;
        pl_world *w = sc_disc_rung((sc_rung)(m < 3 ? m : SC_RUNG_DARCY), &d, &st);
        if (st == PL_OK && m == 3) st = pl_world_set_flag(w, "FIRST_STEP_STATIC", 0);
        if (st == PL_OK) {
            const double t0 = cpu();
            st = pl_world_step(w, 60);
            const double t = (cpu() - t0) / 60;
            pl_body_info bi;
            pl_world_body_info(w, d, &bi);
            const double v = -bi.velocity.y;
            printf("  %-17s %19.4f  %16.2e\n", name, v, t);
            fprintf(csv, "rung_%s,,,%.6g,%.8g,\n", name, t, v);
            char wrong[400];
            if (m == 0)
                snprintf(wrong, sizeof wrong, "%+.1f %% against the exact %.4f cm/s (discretisation)", 100 * (v / vterm - 1),
                         vterm);
            else if (m == 1)
                snprintf(wrong, sizeof wrong, "buoyancy only: the disc falls freely at (1 − ρ_l/ρ_s) g, %.2f cm/s at 0.03 s",
                         vfree);
            else if (m == 2)
                snprintf(wrong, sizeof wrong, "the same as hydrostatic (relative difference %.1e): without consolidation a single moving "
                         "grain drives no flow, so nothing but buoyancy acts on it", v / vfree - 1);
            else
                snprintf(wrong, sizeof wrong, "the water column first drains downwards through the grain and drags it "
                         "faster than free fall (%.2f cm/s): a set-up error, not a defect of the model's grain forces",
                         980 * 0.03);
            md(3, "| %s | %.4f cm/s | %.2g s | %s |\n", rows[m], v, t, wrong);
        }
        if (st != PL_OK) printf("  %-17s refused: %s\n", name, pl_world_last_error(w));
        pl_world_destroy(&w);
    }
    const double load1 = load_average();
    printf("load average (1 min) at the start %.1f, at the end %.1f\n", load0, load1);
    md(2, "Measured on a loaded machine: 1-minute load average %.1f at the start of the benchmark and %.1f at its end, on 2 cores.\n",
       load0, load1);
    fclose(csv);
    printf("wrote %s\n", path);
    return docs ? write_docs(docs) : 0;
}
