/* porelab: a 2D lab where grains and the water in their pores move together. */
#define _GNU_SOURCE /* RTLD_DEFAULT */
#include "commands.h"
#include "options.h"
#include "porelab/core.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const struct {
    const char *name;
    int (*fn)(int, char **);
    const char *summary;
} commands[] = {
    {"run", pl_cmd_run, "run a scene and write PNG frames (and a video)"},
    {"view", pl_cmd_view, "open a scene in the live lab window (play, pause, rewind, poke)"},
    {"still", pl_cmd_still, "draw one figure of a scene at a time T (PNG, SVG or PDF)"},
    {"info", pl_cmd_info, "describe a scene: bodies, materials, contact law, time step, flags"},
    {"flags", pl_cmd_flags, "list the MIMES flags with units, ranges and whether they are built"},
    {"compare", pl_cmd_compare, "run benchmark problems with every method: error against CPU time"},
    {"sweep", pl_cmd_sweep, "expand parameters and seeds into jobs (GNU parallel, Slurm array, Snakemake)"},
    {"collect", pl_cmd_collect, "gather the manifests of runs into one CSV and chart a result"},
    {"export-lammps", pl_cmd_export_lammps, "write a dry disc scene as a LAMMPS input (GRANULAR package)"},
    {"import-lammps", pl_cmd_import_lammps, "read LAMMPS dumps back: frames, VTK, contact diagnostics"},
};
#define NCOMMANDS ((int)(sizeof commands / sizeof commands[0]))

static void usage(FILE *f)
{
    fprintf(f, "usage: porelab COMMAND [options]   (porelab COMMAND --help for details)\n\n"
               "commands:\n");
    for (int i = 0; i < NCOMMANDS; i++)
        fprintf(f, "  %-14s %s\n", commands[i].name, commands[i].summary);
    fprintf(f, "\nother options:\n  --version  print the version\n  --help     show this help\n"
               "\nexample: porelab run scenes/demo.lua   (frames go to out/demo/)\n");
}

/* The libraries' own threads (OpenBLAS under LAPACK and UMFPACK, OpenMP under CHOLMOD and gmsh)
 * run on one thread unless the user sets OPENBLAS_NUM_THREADS or OMP_NUM_THREADS. Their results
 * may depend on their thread count, which would break "same scene and build, same state"; and
 * on porelab's small factorisations their spinning workers cost more CPU than they save (the
 * Navier-Stokes granular step, 50 steps: 3.4 s wall and 5.1 s CPU with them, 2.9 s and 2.9 s
 * without). porelab's own --threads is separate and deterministic. The setters are looked up
 * at run time so that a build against another BLAS still links. */
static void libraries_on_one_thread(void)
{
    if (getenv("OPENBLAS_NUM_THREADS") || getenv("OMP_NUM_THREADS")) return;
    void (*set)(int);
    *(void **)&set = dlsym(RTLD_DEFAULT, "openblas_set_num_threads");
    if (set) set(1);
    *(void **)&set = dlsym(RTLD_DEFAULT, "omp_set_num_threads");
    if (set) set(1);
}

int main(int argc, char **argv)
{
    libraries_on_one_thread();
    if (argc < 2) {
        usage(stderr);
        return PL_EXIT_USAGE;
    }
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
        usage(stdout);
        return PL_EXIT_OK;
    }
    if (strcmp(cmd, "--version") == 0) {
        printf("porelab %s\n", PL_VERSION_STRING);
        return PL_EXIT_OK;
    }
    for (int i = 0; i < NCOMMANDS; i++)
        if (strcmp(cmd, commands[i].name) == 0) return commands[i].fn(argc - 2, argv + 2);
    fprintf(stderr, "porelab: unknown command '%s'; valid commands:", cmd);
    for (int i = 0; i < NCOMMANDS; i++) fprintf(stderr, " %s", commands[i].name);
    fprintf(stderr, " (and --help, --version)\n");
    return PL_EXIT_USAGE;
}
