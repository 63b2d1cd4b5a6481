#include "options.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const pl_opt_spec help_spec = {"--help", "-h", NULL, "show this help"};

/* Limits of the sandbox, offered by every command that loads a scene (those with --trust). */
static const pl_opt_spec sandbox_specs[] = {
    {"--max-cpu", NULL, "SECONDS",
     "CPU time the scene's code may take in one go (main chunk, one hook call); default 300 "
     "in the sandbox, none with --trust"},
    {"--max-memory", NULL, "MB",
     "memory the scene's Lua data may take; default 1024 in the sandbox, none with --trust"},
    {NULL, NULL, NULL, NULL}};

static int own_count(const pl_command_help *cmd)
{
    int n = 0;
    while (cmd->specs[n].name) n++;
    return n;
}

static int has_trust(const pl_command_help *cmd)
{
    for (int i = 0; cmd->specs[i].name; i++)
        if (strcmp(cmd->specs[i].name, "--trust") == 0) return 1;
    return 0;
}

/* The command's own options, then (for commands with --trust) the sandbox limits. */
static const pl_opt_spec *spec_at(const pl_command_help *cmd, int i)
{
    int n = own_count(cmd);
    if (i < n) return &cmd->specs[i];
    if (!has_trust(cmd)) return NULL;
    return sandbox_specs[i - n].name ? &sandbox_specs[i - n] : NULL;
}

static void list_valid(FILE *f, const pl_command_help *cmd)
{
    fprintf(f, "valid options:");
    for (int i = 0; spec_at(cmd, i); i++) fprintf(f, " %s", spec_at(cmd, i)->name);
    fprintf(f, " --help\n");
}

void pl_opts_print_help(FILE *f, const pl_command_help *cmd)
{
    fprintf(f, "usage: porelab %s %s\n\n%s\n\noptions:\n", cmd->command, cmd->usage,
            cmd->summary);
    for (int i = 0;; i++) {
        const pl_opt_spec *s = spec_at(cmd, i) ? spec_at(cmd, i) : &help_spec;
        char left[64];
        snprintf(left, sizeof left, "%s%s%s%s%s", s->alias ? s->alias : "",
                 s->alias ? ", " : "", s->name, s->arg ? " " : "", s->arg ? s->arg : "");
        fprintf(f, "  %-24s %s\n", left, s->help);
        if (s == &help_spec) break;
    }
}

static int find_spec(const pl_command_help *cmd, const char *arg)
{
    for (int i = 0; spec_at(cmd, i); i++)
        if (strcmp(arg, spec_at(cmd, i)->name) == 0 ||
            (spec_at(cmd, i)->alias && strcmp(arg, spec_at(cmd, i)->alias) == 0))
            return i;
    return -1;
}

int pl_opts_parse(pl_opts *o, const pl_command_help *cmd, int argc, char **argv,
                  int max_positional)
{
    memset(o, 0, sizeof *o);
    o->cmd = cmd;
    o->argc = argc;
    o->argv = argv;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            pl_opts_print_help(stdout, cmd);
            return PL_EXIT_OK;
        }
        if (a[0] != '-' || a[1] == '\0') {
            if (o->npositional >= max_positional) {
                fprintf(stderr, "porelab %s: unexpected argument '%s' (usage: porelab %s %s)\n",
                        cmd->command, a, cmd->command, cmd->usage);
                return PL_EXIT_USAGE;
            }
            o->positional[o->npositional++] = a;
            continue;
        }
        int k = find_spec(cmd, a);
        if (k < 0) {
            fprintf(stderr, "porelab %s: unknown option '%s'; ", cmd->command, a);
            list_valid(stderr, cmd);
            return PL_EXIT_USAGE;
        }
        if (spec_at(cmd, k)->arg) {
            if (i + 1 >= argc) {
                fprintf(stderr, "porelab %s: %s needs a value (%s)\n", cmd->command, a,
                        spec_at(cmd, k)->arg);
                return PL_EXIT_USAGE;
            }
            o->value[k] = argv[++i];
        } else {
            o->value[k] = "";
        }
    }
    return -1;
}

const char *pl_opts_get(const pl_opts *o, const char *name)
{
    int k = find_spec(o->cmd, name);
    return k < 0 ? NULL : o->value[k];
}

int pl_opts_has(const pl_opts *o, const char *name) { return pl_opts_get(o, name) != NULL; }

int pl_opts_all(const pl_opts *o, const char *name, const char **out, int cap)
{
    int k = find_spec(o->cmd, name), n = 0;
    if (k < 0 || !spec_at(o->cmd, k)->arg) return 0;
    for (int i = 0; i + 1 < o->argc; i++) {
        if (find_spec(o->cmd, o->argv[i]) != k) continue;
        if (n < cap) out[n] = o->argv[i + 1];
        n++;
        i++;
    }
    return n;
}

static int bad_value(const pl_opts *o, const char *name, const char *want, const char *got)
{
    fprintf(stderr, "porelab %s: %s must be %s (got '%s')\n", o->cmd->command, name, want, got);
    return -1;
}

int pl_opts_double(const pl_opts *o, const char *name, double min, int inclusive,
                   double *out)
{
    const char *s = pl_opts_get(o, name);
    if (!s) return 0;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end || errno || !isfinite(v) || !(inclusive ? v >= min : v > min)) {
        char want[64];
        snprintf(want, sizeof want, "a number %s %g", inclusive ? ">=" : ">", min);
        return bad_value(o, name, want, s);
    }
    *out = v;
    return 0;
}

int pl_opts_count(const pl_opts *o, const char *name, long long min, long long *out)
{
    const char *s = pl_opts_get(o, name);
    if (!s) return 0;
    char *end;
    errno = 0;
    long long v = strtoll(s, &end, 10);
    if (end == s || *end || errno || v < min) {
        char want[64];
        snprintf(want, sizeof want, "an integer >= %lld", min);
        return bad_value(o, name, want, s);
    }
    *out = v;
    return 0;
}

int pl_opts_size(const pl_opts *o, const char *name, int *w, int *h)
{
    const char *s = pl_opts_get(o, name);
    if (!s) return 0;
    int a, b;
    char x, extra;
    if (sscanf(s, "%d%c%d%c", &a, &x, &b, &extra) != 3 || (x != 'x' && x != 'X') || a < 16 ||
        b < 16 || a > 16384 || b > 16384)
        return bad_value(o, name, "WIDTHxHEIGHT in pixels, each in 16..16384", s);
    *w = a;
    *h = b;
    return 0;
}
