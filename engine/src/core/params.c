/* Parameter tables (porelab/params.h): checks, typed reads and writes at an offset. */
#include "porelab/params.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

pl_status pl_param_check(const pl_param *p, double v, char *msg, size_t len) {
    const int integral = p->type != PL_PARAM_DOUBLE;
    if (!isfinite(v) || v < p->min || v > p->max || (integral && v != floor(v))) {
        if (msg && len)
            snprintf(msg, len, "%s must be %s in [%g, %g] %s (got %g)", p->name, integral ? "an integer" : "a number",
                     p->min, p->max, p->unit, v);
        return PL_ERR_ARG;
    }
    return PL_OK;
}

void pl_param_write(const pl_param *p, void *def, double v) {
    char *at = (char *)def + p->offset;
    if (p->type == PL_PARAM_DOUBLE) memcpy(at, &v, sizeof v);
    else {
        int i = p->type == PL_PARAM_BOOL ? (v != 0) : (int)v;
        memcpy(at, &i, sizeof i);
    }
}

double pl_param_read(const pl_param *p, const void *def) {
    const char *at = (const char *)def + p->offset;
    if (p->type == PL_PARAM_DOUBLE) {
        double v;
        memcpy(&v, at, sizeof v);
        return v;
    }
    int i;
    memcpy(&i, at, sizeof i);
    return i;
}

void pl_params_defaults(const pl_param *table, int n, void *def) {
    for (int k = 0; k < n; k++) pl_param_write(&table[k], def, table[k].def);
}

pl_status pl_params_check_all(const pl_param *table, int n, const void *def, const char *what, char *msg,
                              size_t len) {
    for (int k = 0; k < n; k++) {
        char one[256];
        if (pl_param_check(&table[k], pl_param_read(&table[k], def), one, sizeof one) != PL_OK) {
            if (msg && len) snprintf(msg, len, "%s: %s", what, one);
            return PL_ERR_ARG;
        }
    }
    return PL_OK;
}

const pl_param *pl_param_find(const pl_param *table, int n, const char *name) {
    for (int k = 0; name && k < n; k++)
        if (strcmp(table[k].name, name) == 0) return &table[k];
    return NULL;
}
