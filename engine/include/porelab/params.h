/// Parameter tables: one row per numeric field of a def struct (world, Darcy, hydrostatic, ...).
///
/// A table drives everything that reads or checks a def: validation with the field's range
/// (pl_param_check), the historical MIMES flags (flag name per row), the Lua readers (one field
/// name per row) and the generated flag documentation (`porelab flags`). C and Lua therefore
/// cannot disagree about a range.
#ifndef PORELAB_PARAMS_H
#define PORELAB_PARAMS_H

#include "porelab/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Storage type of a field in its def struct.
typedef enum pl_param_type {
    PL_PARAM_DOUBLE = 0, ///< double
    PL_PARAM_INT = 1,    ///< int; the value must be an integer
    PL_PARAM_BOOL = 2    ///< int holding 0 or 1
} pl_param_type;

/// One field of a def struct.
typedef struct pl_param {
    const char *name;    ///< field name in Lua tables (e.g. "solve_every")
    const char *flag;    ///< MIMES flag name (e.g. "FLUID_SOLVE_TIMESTEPS"), or NULL
    size_t offset;       ///< offsetof(def struct, field)
    pl_param_type type;
    const char *unit;    ///< "m/s", "1", "0/1", "steps", ...
    double min, max;     ///< valid closed range (always finite)
    double def;          ///< default value
    const char *doc;     ///< one line for users
} pl_param;

/// Checks v against row p (finite, in [min, max], integer for INT/BOOL). Returns PL_OK, or
/// PL_ERR_ARG with "<name> must be in [min, max] unit (got v)" written into msg.
pl_status pl_param_check(const pl_param *p, double v, char *msg, size_t len);
/// Writes v into the def at p's offset (no check).
void pl_param_write(const pl_param *p, void *def, double v);
/// Reads the field at p's offset as a double.
double pl_param_read(const pl_param *p, const void *def);
/// Fills a def with the defaults of its table.
void pl_params_defaults(const pl_param *table, int n, void *def);
/// Checks every field of a def; the first bad one gives PL_ERR_ARG and a message prefixed by
/// `what` ("world", "darcy", ...).
pl_status pl_params_check_all(const pl_param *table, int n, const void *def, const char *what, char *msg,
                              size_t len);
/// Row named `name` (Lua field name) or NULL.
const pl_param *pl_param_find(const pl_param *table, int n, const char *name);

#ifdef __cplusplus
}
#endif
#endif
