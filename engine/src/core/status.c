#include "porelab/core.h"

const char *pl_status_name(pl_status s) {
    switch (s) {
    case PL_OK: return "ok";
    case PL_ERR_ARG: return "bad argument";
    case PL_ERR_STATE: return "invalid state";
    case PL_ERR_UNSTABLE: return "unstable";
    case PL_ERR_NOT_BUILT: return "not built";
    case PL_ERR_NUMERIC: return "numerical failure";
    case PL_ERR_IO: return "input/output error";
    case PL_ERR_NOMEM: return "out of memory";
    case PL_ERR_UNKNOWN: return "unknown name";
    }
    return "unknown status";
}
