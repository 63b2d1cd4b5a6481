/* One pair evaluation's additions to its two bodies (contact laws, parallel.c). */
#ifndef PL_CONTACT_OUT_H
#define PL_CONTACT_OUT_H
#include "dem/world_internal.h"

/* What one pair evaluation adds to its two bodies, kept apart from the adding so that the same
   evaluation can be applied at once (serial loop) or stored in the pair's slot and gathered per
   body later (threaded loop, parallel.c) with the same additions in the same order per body:
   the results are bit-identical either way. Values are what is added to b (the force, its
   dashpot and spring parts, the rolling moment; a gets them negated: x - y = x + (-y) exactly)
   or, per end, the torque and tally moments added. A flag says which additions happen; an
   addition of 0 is not the same as none (-0 + 0 = +0). */
enum {
    PL_OUT_F = 1,       /* force: +F on b, -F on a */
    PL_OUT_FD = 2,      /* tally dfx, dfy: +Fd on b, -Fd on a */
    PL_OUT_FS = 4,      /* tally sfx, sfy (+Fs on b, -Fs on a) and sm (sma, smb) */
    PL_OUT_ROLL = 8,    /* rolling moment: torque and tally sm +mr on b, -mr on a, before the rest */
    PL_OUT_TQA = 16,    /* torque[a] += tqa */
    PL_OUT_TQB = 32,    /* torque[b] += tqb */
    PL_OUT_DMA = 64,    /* tally[a].dm += dma */
    PL_OUT_DMB = 128,   /* tally[b].dm += dmb */
    PL_OUT_LAW = 256,   /* a disc law evaluation: es, en and ratio are set */
    PL_OUT_POLY = 512,  /* a polygon evaluation: e_damped, ratio set (and e_friction with EFRIC) */
    PL_OUT_EFRIC = 1024, /* polygon sliding: e_friction set */
    PL_OUT_POLYKIND = 2048 /* a polygon pair (threaded loop): e_elastic set, touching or not */
};
typedef struct pl_contact_add { /* what is added to the bodies (the threaded loop's slot) */
    uint32_t flags;
    float pad;
    double fx, fy, mr, tqa, tqb;               /* enough without the energy tallies */
    double dfx, dfy, sfx, sfy, dma, dmb, sma, smb; /* the tallies */
} pl_contact_add;
typedef struct pl_contact_out {
    pl_contact_add add;
    double es, en, ratio;     /* disc law: spring energies, overlap / smaller radius */
    double e_damped, e_friction; /* polygons: dissipation of this evaluation */
    double e_elastic;         /* polygons: the pair's stored energy (0 when apart) */
} pl_contact_out;
/* The sums over pairs of the threaded loop, kept apart from the slots so that their serial pass
   reads a dense array: es, en, ratio (discs) or e_damped, e_friction, e_elastic, ratio (polygons). */
typedef struct pl_contact_sum {
    double x, y, z, ratio;
} pl_contact_sum;

/* Adds an evaluation to body b (end 1) or a (end 0), in the order of the original loop. */
static inline __attribute__((always_inline)) void pl__apply_end(pl_vec2 *restrict force, double *restrict torque,
                                                                 pl_tally *restrict tally, int track,
                                                                 const pl_contact_add *o, int i, int end) {
    const uint32_t f = o->flags;
    if (end) {
        if (f & PL_OUT_ROLL) torque[i] += o->mr;
        if (f & PL_OUT_F) force[i].x += o->fx, force[i].y += o->fy;
        if (f & PL_OUT_TQB) torque[i] += o->tqb;
        if (track) {
            pl_tally *t = &tally[i];
            if (f & PL_OUT_ROLL) t->sm += o->mr;
            if (f & PL_OUT_FD) t->dfx += o->dfx, t->dfy += o->dfy;
            if (f & PL_OUT_FS) t->sfx += o->sfx, t->sfy += o->sfy;
            if (f & PL_OUT_DMB) t->dm += o->dmb;
            if (f & PL_OUT_FS) t->sm += o->smb;
        }
    } else {
        if (f & PL_OUT_ROLL) torque[i] -= o->mr;
        if (f & PL_OUT_F) force[i].x -= o->fx, force[i].y -= o->fy;
        if (f & PL_OUT_TQA) torque[i] += o->tqa;
        if (track) {
            pl_tally *t = &tally[i];
            if (f & PL_OUT_ROLL) t->sm -= o->mr;
            if (f & PL_OUT_FD) t->dfx -= o->dfx, t->dfy -= o->dfy;
            if (f & PL_OUT_FS) t->sfx -= o->sfx, t->sfy -= o->sfy;
            if (f & PL_OUT_DMA) t->dm += o->dma;
            if (f & PL_OUT_FS) t->sm += o->sma;
        }
    }
}

#endif
