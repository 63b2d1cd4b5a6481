/* Command-line options: each command lists its options in a table; anything else is an
 * error that lists the valid ones. */
#ifndef PL_APP_OPTIONS_H
#define PL_APP_OPTIONS_H

#include <stdio.h>

/* Exit codes of the program. */
enum { PL_EXIT_OK = 0, PL_EXIT_FAIL = 1, PL_EXIT_USAGE = 2 };

#define PL_MAX_OPTIONS 32

typedef struct pl_opt_spec {
    const char *name;  /* "--out" */
    const char *alias; /* "-o" or NULL */
    const char *arg;   /* argument name ("DIR") or NULL for a switch */
    const char *help;
} pl_opt_spec;

typedef struct pl_command_help {
    const char *command; /* "run" */
    const char *usage;   /* "SCENE.lua [options]" */
    const char *summary; /* one paragraph */
    const pl_opt_spec *specs; /* terminated by {NULL} */
} pl_command_help;

typedef struct pl_opts {
    const pl_command_help *cmd;
    const char *value[PL_MAX_OPTIONS]; /* argument (or "" for a switch) when present */
    const char *positional[4];
    int npositional;
    int argc;     /* the arguments parsed (for options given more than once) */
    char **argv;
} pl_opts;

/* Parses argv (after the command name). Returns -1 on success; otherwise the exit code to
 * return (help printed: PL_EXIT_OK; usage error printed: PL_EXIT_USAGE). */
int pl_opts_parse(pl_opts *o, const pl_command_help *cmd, int argc, char **argv,
                  int max_positional);
void pl_opts_print_help(FILE *f, const pl_command_help *cmd);

/* Value of an option, or NULL when absent. */
const char *pl_opts_get(const pl_opts *o, const char *name);
int pl_opts_has(const pl_opts *o, const char *name);
/* Every value of an option given more than once (--param a=1 --param b=2), in order; returns
 * the count (at most cap are stored). */
int pl_opts_all(const pl_opts *o, const char *name, const char **out, int cap);

/* Converts an option's argument; prints "porelab CMD: --name must be ... (got 'x')" and
 * returns -1 when it is not a number in the range. Absent options leave *out unchanged and
 * return 0. */
int pl_opts_double(const pl_opts *o, const char *name, double min, int inclusive,
                   double *out);
int pl_opts_count(const pl_opts *o, const char *name, long long min, long long *out);
/* "WxH" with 16 <= W, H <= 16384. */
int pl_opts_size(const pl_opts *o, const char *name, int *w, int *h);

#endif
