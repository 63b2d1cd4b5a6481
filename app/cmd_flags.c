/* porelab flags: the MIMES flag table from the engine (pl_flag_at), as text or Markdown. */
#include "commands.h"
#include "options.h"
#include "porelab/world.h"

#include <stdio.h>

static const pl_opt_spec flags_specs[] = {
    {"--markdown", NULL, NULL, "print a Markdown table (used in docs/scene-reference.md)"},
    {NULL, NULL, NULL, NULL}};

static const pl_command_help flags_help = {
    "flags", "[--markdown]",
    "Lists every flag a scene may set with world{flags = {...}} or world:set_flag(name, v):\n"
    "its unit, valid range, whether its feature is built, and what it does.",
    flags_specs};

int pl_cmd_flags(int argc, char **argv)
{
    pl_opts o;
    int rc = pl_opts_parse(&o, &flags_help, argc, argv, 0);
    if (rc >= 0) return rc;
    int md = pl_opts_has(&o, "--markdown");
    if (md)
        printf("| Flag | Unit | Range | Built | Meaning |\n|---|---|---|---|---|\n");
    for (int i = 0; i < pl_flag_count(); i++) {
        const pl_flag_info *f = pl_flag_at(i);
        if (md)
            printf("| `%s` | %s | %g .. %g | %s | %s |\n", f->name, f->unit, f->min, f->max,
                   f->built ? "yes" : "not yet", f->description);
        else
            printf("%-22s %-8s %g..%g%s\n    %s\n", f->name, f->unit, f->min, f->max,
                   f->built ? "" : "  (recognised, not built yet)", f->description);
    }
    return PL_EXIT_OK;
}
