/* Placeholder until the fluid module lands: no fluid model can be attached yet, so
 * w->fluid is always NULL and these are never reached with a model. */
#include "fluid/fluid_hook.h"

pl_status pl__fluid_step(pl_world *w, double dt) {
    (void)dt;
    if (w->fluid) return pl__error(w, PL_ERR_NOT_BUILT, "fluid model not built yet");
    return PL_OK;
}

void pl__fluid_free(struct pl_fluid *f) { (void)f; }
