/* Flags with the MIMES names (seed 000 Appendix B.2 and the Appendix C scripts): the world
 * layer's compatibility table. Each flag has a unit, a valid range and a default; flags of
 * features that are not built yet are recognised and refused (unless set to their default "off"
 * value). The grain engine's flags are rows of this file; a model's flags are the rows of its
 * parameter table that carry a MIMES name (fluid/darcy/darcy_params.c), gathered here once, in
 * the order of the model registry (world/models.c). The flag values are the one storage of a
 * model's flag-backed def (pl__world_flag_values). */
#include "core/alloc.h"
#include "core/assert.h"
#include "dem/world_internal.h"
#include "world/world_layer.h"
#include <threads.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct flag_row {
    pl_flag_info info;
    double def;
    int integral; /* 1: whole numbers only */
} flag_row;

/* Rows of the grain engine and run control, then (after DEM_ROWS) the rows nobody builds. */

/* The order is the index into w->flag_values. */
static const flag_row BASE[] = {
    /* run control */
    {{"TIMESTEPS", "steps", "number of time steps a declarative run takes (when the command line gives none)", 0, 1e12, 1}, 0, 1},
    {{"PRINT_INT", "steps", "steps between output frames (when the command line gives neither --fps nor --every)", 1, 1e12, 1}, 0, 1},
    {{"MAX_DT_CR", "s", "cap on the time step (the automatic step is min(safety x critical, MAX_DT_CR)); 0 = no cap", 0, 1e6, 1}, 0, 0},
    {{"DT", "s", "fixed time step; 0 = automatic (DT_SAFETY x critical step)", 0, 1e6, 1}, 0, 0},
    {{"DT_SAFETY", "1", "fraction of the critical time step used by the automatic step", 1e-6, 1, 1}, 0.1, 0},
    /* body forces and damping */
    {{"GRAVITY_X", "m/s^2", "gravity, x component", -1e6, 1e6, 1}, 0, 0},
    {{"GRAVITY_Y", "m/s^2", "gravity, y component", -1e6, 1e6, 1}, -9.81, 0},
    {{"RAYLEIGH_FACTOR", "1/s", "mass-proportional damping alpha of the Rege scheme (Klosek 1997 eq. 2.5)", 0, 1e9, 1}, 0, 0},
    {{"GLOBAL_DAMPING", "N s/m", "translational global damping C (Tan 1990 eq. 2.21)", 0, 1e30, 1}, 0, 0},
    {{"GLOBAL_DAMPING_ROT", "N m s", "rotational global damping C* (Tan 1990 eq. 2.22)", 0, 1e30, 1}, 0, 0},
    {{"LOCAL_DAMPING", "1", "non-viscous damping ratio proportional to the resultant force (Oñate & Rojek 2004 eqs. 24-29)", 0, 1, 1}, 0, 0},
    {{"ENERGY_TRACKING", "0/1", "1: exact tallies of the energy dissipated by dashpots and friction; 0: off, for speed", 0, 1, 1}, 1, 1},
    /* MIMES output flags that porelab replaces with VTK/PNG output */
    {{"EXODUSFLAG", "0/1", "EXODUS output of MIMES: not built (porelab writes VTK .vtu/.pvd and PNG instead)", 0, 1, 0}, 0, 1},
    {{"EXODUSOUTPUTSTEP", "steps", "EXODUS output interval of MIMES: not built (use PRINT_INT)", 0, 1e12, 0}, 0, 1},
};
#define NBASE ((int)(sizeof BASE / sizeof BASE[0]))
#define DEM_ROWS 12 /* BASE rows before the not-built MIMES output flags */
#define MAX_FLAGS 128

/* The whole table, gathered once: BASE[0..DEM_ROWS), each registered model's flag rows, then
   the rest of BASE. Never changes after that. */
static flag_row FLAGS[MAX_FLAGS];
static int NFLAGS;
static int g_block_start[PL_MAX_MODEL_CLASSES]; /* first flag of each class (-1: none) */
static once_flag g_once = ONCE_FLAG_INIT;

static void gather(void) {
    int n = 0;
    for (int i = 0; i < DEM_ROWS; i++) FLAGS[n++] = BASE[i];
    for (int c = 0; c < pl__model_class_count(); c++) {
        const pl_model_class *cls = pl__model_class_at(c);
        g_block_start[c] = -1;
        for (int k = 0; k < cls->nparams && n < MAX_FLAGS; k++) {
            const pl_param *p = &cls->params[k];
            if (!p->flag) continue;
            if (g_block_start[c] < 0) g_block_start[c] = n;
            FLAGS[n++] = (flag_row){{p->flag, p->unit, p->doc, p->min, p->max, 1}, p->def, p->type != PL_PARAM_DOUBLE};
        }
    }
    for (int i = DEM_ROWS; i < NBASE && n < MAX_FLAGS; i++) FLAGS[n++] = BASE[i];
    NFLAGS = n;
}

static void ensure_table(void) { call_once(&g_once, gather); }

int pl_flag_count(void) {
    ensure_table();
    return NFLAGS;
}

const pl_flag_info *pl_flag_at(int i) {
    ensure_table();
    if (i < 0 || i >= NFLAGS) return NULL;
    return &FLAGS[i].info;
}

static int find_flag(const char *name) {
    ensure_table();
    for (int i = 0; i < NFLAGS; i++)
        if (strcmp(FLAGS[i].info.name, name) == 0) return i;
    return -1;
}

int pl__flag_block_start(const pl_model_class *cls) {
    ensure_table();
    for (int c = 0; c < pl__model_class_count(); c++)
        if (pl__model_class_at(c) == cls) return g_block_start[c];
    PL_ASSERT(0 && "model class missing from the class list (world/models.c)");
    return -1;
}

const double *pl__world_flag_values(const pl_world *w, const pl_model_class *cls) {
    const int at = pl__flag_block_start(cls);
    return at < 0 ? NULL : w->flag_values + at;
}

pl_status pl__world_set_flag_values(pl_world *w, const pl_model_class *cls, const double *v, const char *what) {
    const int at = pl__flag_block_start(cls);
    if (at < 0) return pl__error(w, PL_ERR_STATE, "%s: the model has no flag-backed parameters", what);
    int j = 0;
    for (int k = 0; k < cls->nparams; k++) {
        const pl_param *p = &cls->params[k];
        if (!p->flag) continue;
        char msg[512];
        if (pl_param_check(p, v[j], msg, sizeof msg) != PL_OK) return pl__error(w, PL_ERR_ARG, "%s: %s", what, msg);
        j++;
    }
    memcpy(w->flag_values + at, v, (size_t)j * sizeof *v);
    return PL_OK;
}

void pl__flags_init(pl_world *w) {
    ensure_table();
    w->flag_values = pl_malloc((size_t)NFLAGS * sizeof *w->flag_values);
    if (!w->flag_values) return;
    for (int i = 0; i < NFLAGS; i++) w->flag_values[i] = FLAGS[i].def;
    /* flags mirrored by the world definition */
    w->flag_values[find_flag("GRAVITY_X")] = w->def.gravity.x;
    w->flag_values[find_flag("GRAVITY_Y")] = w->def.gravity.y;
    w->flag_values[find_flag("MAX_DT_CR")] = w->def.max_dt;
    w->flag_values[find_flag("DT")] = w->def.dt;
    w->flag_values[find_flag("DT_SAFETY")] = w->def.dt_safety;
    w->flag_values[find_flag("RAYLEIGH_FACTOR")] = w->def.rayleigh_alpha;
    w->flag_values[find_flag("GLOBAL_DAMPING")] = w->def.global_c;
    w->flag_values[find_flag("GLOBAL_DAMPING_ROT")] = w->def.global_c_rot;
    w->flag_values[find_flag("LOCAL_DAMPING")] = w->def.local_damping;
    w->flag_values[find_flag("ENERGY_TRACKING")] = w->def.track_energy;
}

static void list_flags(char *buf, size_t len) {
    size_t off = 0;
    for (int i = 0; i < NFLAGS && off < len; i++)
        off += (size_t)snprintf(buf + off, len - off, "%s%s", i ? ", " : "", FLAGS[i].info.name);
}

pl_status pl_world_set_flag(pl_world *w, const char *name, double v) {
    const int i = name ? find_flag(name) : -1;
    if (i < 0) {
        char list[1024];
        list_flags(list, sizeof list);
        return pl__error(w, PL_ERR_UNKNOWN, "unknown flag '%s'; valid flags: %s", name ? name : "(null)", list);
    }
    const pl_flag_info *f = pl_flag_at(i);
    if (!isfinite(v) || v < f->min || v > f->max)
        return pl__error(w, PL_ERR_ARG, "flag %s must be in [%g, %g] %s (got %g)", f->name, f->min, f->max, f->unit, v);
    if (FLAGS[i].integral && v != floor(v)) {
        return pl__error(w, PL_ERR_ARG, "flag %s takes whole numbers in [%g, %g] %s (got %g)", f->name, f->min, f->max,
                         f->unit, v);
    }
    if (!f->built && v != FLAGS[i].def)
        return pl__error(w, PL_ERR_NOT_BUILT,
                         "flag %s is recognised but its feature is not built in this version of porelab (%s); "
                         "remove the line or leave it at %g",
                         f->name, f->description, FLAGS[i].def);
    w->flag_values[i] = v;
    if (!strcmp(name, "GRAVITY_X")) w->def.gravity.x = v;
    else if (!strcmp(name, "GRAVITY_Y")) w->def.gravity.y = v;
    else if (!strcmp(name, "MAX_DT_CR")) w->def.max_dt = v;
    else if (!strcmp(name, "DT")) w->def.dt = v;
    else if (!strcmp(name, "DT_SAFETY")) w->def.dt_safety = v;
    else if (!strcmp(name, "RAYLEIGH_FACTOR")) w->def.rayleigh_alpha = v;
    else if (!strcmp(name, "GLOBAL_DAMPING")) w->def.global_c = v;
    else if (!strcmp(name, "GLOBAL_DAMPING_ROT")) w->def.global_c_rot = v;
    else if (!strcmp(name, "LOCAL_DAMPING")) w->def.local_damping = v;
    else if (!strcmp(name, "ENERGY_TRACKING")) w->def.track_energy = v != 0;
    w->dt = 0; /* recompute the step with the new settings */
    w->energy_initialised = 0;
    return PL_OK;
}

pl_status pl_world_get_flag(const pl_world *w, const char *name, double *v) {
    const int i = name ? find_flag(name) : -1;
    if (i < 0) {
        char list[1024];
        list_flags(list, sizeof list);
        return pl__error(w, PL_ERR_UNKNOWN, "unknown flag '%s'; valid flags: %s", name ? name : "(null)",
                         list);
    }
    *v = w->flag_values[i];
    return PL_OK;
}
