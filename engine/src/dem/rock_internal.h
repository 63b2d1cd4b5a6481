/* Bond, heat and wear records of the grain store (porelab/bonds.h) and the bond law kernel on
 * plain structs (testable without a world: tests/rock). Included by dem/world_internal.h. */
#ifndef PL_ROCK_INTERNAL_H
#define PL_ROCK_INTERNAL_H
#include "porelab/bonds.h"
#include <stdint.h>

/* One bond. The law's state: plastic displacements (up_*) and accumulated plastic opening or
   slip (kap_*) for the plastic law; the largest opening or slip reached (kap_*) and the damage
   (om_*) for the damage law. */
typedef struct pl_bond {
    int32_t a, b;          /* discs, a < b */
    int32_t law;           /* index into world->bond_laws */
    int32_t state;         /* pl_bond_state */
    double d0;             /* rest distance of the centres, m */
    double ut, rot;        /* tangential slip (m) and relative rotation (rad) since creation */
    double up_n, up_t;     /* plastic opening and slip, m */
    double kap_n, kap_t;   /* plastic: accumulated |plastic increment|; damage: largest |u| reached */
    double om_n, om_t;     /* damage 0..1 */
    double n, s, m;        /* last tension (N), shear (N), moment (N m) */
    double un;             /* last opening, m */
    double elastic;        /* stored energy, J */
    double dissipated;     /* released so far, J */
    int64_t broken_step;   /* -1 while intact */
    double broken_time;
} pl_bond;

typedef struct pl_bond_law {
    int32_t ma, mb;        /* material pair (ma <= mb) */
    pl_bond_def def;       /* checked, kt resolved */
} pl_bond_law;

typedef struct pl_thermal {
    int32_t set;           /* 1 when the scene gave the material's properties */
    pl_thermal_def def;
} pl_thermal;

/* What the law gives for one evaluation. */
typedef struct pl_bond_eval {
    double n, s, m;        /* tension, shear, moment */
    double elastic;        /* stored energy after the evaluation, J */
    double released;       /* energy released in this evaluation (softening, damage, breaking), J */
    int broke;             /* pl_bond_state of the break, 0 when still intact */
} pl_bond_eval;

/* Evaluates law L for opening un, slip ut and rotation rot (total, since creation) of a bond of
   half width hw (m, min(r_a, r_b): the beam criterion's R), updating
   the law's history in b (up_*, kap_*, om_*) and b->n, s, m, un, elastic, dissipated. Does not
   change b->state: the caller breaks the bond when e->broke != 0 (seed 002 §3, docs/rock.md). */
void pl__bond_law(const pl_bond_def *L, pl_bond *b, double un, double ut, double rot, double hw, pl_bond_eval *e);

/* Hardness at temperature T (seed 002 §4.2, docs/rock.md): H_0 max(h_min, 1 - beta (T - t_ref)). */
static inline double pl__hardness(const pl_thermal_def *d, double T) {
    double f = 1 - d->softening * (T - d->t_ref);
    if (f < d->h_min) f = d->h_min;
    return d->hardness * f;
}
#endif
