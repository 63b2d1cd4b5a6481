/* Narrow phase: evaluates every neighbour pair with the law of its shape pair. Serial: each
 * evaluation is added to its bodies at once, in pair order. With the world's task hook
 * (parallel.c) the evaluations run in parallel into per-pair slots and are then added per body,
 * again in pair order, so that the sums, and the state, are bit-identical. */
#include "dem/contact_disc.h"
#include "dem/contact_polygon.h"
#include "dem/parallel.h"

/* The sums over polygon pairs (energies, the worst overlap) in pair order. */
static inline __attribute__((always_inline)) void account_poly(pl_world *w, const pl_pair *p,
                                                                const pl_contact_out *o, double e_elastic,
                                                                double *e_poly) {
    *e_poly += e_elastic;
    if (o->add.flags & PL_OUT_EFRIC) w->e_friction += o->e_friction;
    if (o->add.flags & PL_OUT_POLY) {
        w->e_damped += o->e_damped;
        if (o->ratio > w->worst_overlap_ratio) {
            w->worst_overlap_ratio = o->ratio;
            w->worst_a = p->a;
            w->worst_b = p->b;
        }
    }
}

static pl_disc_ctx make_ctx(pl_world *w) {
    return (pl_disc_ctx){w->pos, w->vel, w->omega, w->radius, w->force, w->torque, w->tally, w->def.track_energy,
                         0, 0, 0, -1, -1};
}

static void finish(pl_world *w, const pl_disc_ctx *c, double e_poly) {
    w->e_shear_prev = w->e_shear;
    w->e_shear = c->e_shear;
    w->e_elastic = c->e_normal + c->e_shear + e_poly;
    if (c->worst_ratio > w->worst_overlap_ratio) {
        w->worst_overlap_ratio = c->worst_ratio;
        w->worst_a = c->worst_a;
        w->worst_b = c->worst_b;
    }
}

/* Task of the threaded loop: evaluates pairs [begin, end) into their slots (flag 0: nothing
   to add; the slot itself is then left as it was). */
typedef struct eval_task {
    pl_world *w;
    pl_disc_ctx c;
    pl_contact_add *out;
    pl_contact_sum *sum;
    uint16_t *flag;
    double dt;
} eval_task;

static void eval_range(void *ctx, int begin, int end) {
    const eval_task *t = ctx;
    pl_disc_ctx c = t->c; /* only read when not applying */
    const pl_world *w = t->w;
    const pl_pair_params *params = w->pair_params;
    for (int k = begin; k < end; k++) {
        pl_pair *p = &w->pairs[k];
        const pl_pair_params *pp = &params[p->params];
        switch (p->kind) {
        case PL_PAIR_DISC_DISC:
        case PL_PAIR_DISC_SEGMENT: {
            pl_contact_out o;
            o.es = o.en = o.ratio = 0; /* set by the law (PL_OUT_LAW); zero for a release or no contact */
            if (p->kind == PL_PAIR_DISC_DISC) pl__contact_disc_disc(&c, p, pp, t->dt, &o, 0);
            else pl__contact_disc_segment(&c, w, p, pp, t->dt, &o, 0);
            t->flag[k] = (uint16_t)o.add.flags;
            if (o.add.flags) {
                t->out[k] = o.add;
                t->sum[k] = o.add.flags & PL_OUT_LAW ? (pl_contact_sum){o.es, o.en, 0, o.ratio} : (pl_contact_sum){0, 0, 0, 0};
            }
            break;
        }
        case PL_PAIR_POLY_DISC:
        case PL_PAIR_POLY_POLY:
        case PL_PAIR_POLY_SEGMENT: {
            pl_contact_out o;
            pl__contact_polygon(w, p, pp, t->dt, &o);
            o.add.flags |= PL_OUT_POLYKIND;
            t->flag[k] = (uint16_t)o.add.flags;
            t->out[k] = o.add;
            const uint32_t f = o.add.flags;
            t->sum[k] = (pl_contact_sum){f & PL_OUT_POLY ? o.e_damped : 0, f & PL_OUT_EFRIC ? o.e_friction : 0,
                                         p->touching ? p->elastic : 0, f & PL_OUT_POLY ? o.ratio : 0};
            break;
        }
        default: t->flag[k] = 0; break;
        }
    }
}

static void compute_serial(pl_world *w, double dt);

static void compute_threaded(pl_world *w, double dt) {
    uint16_t *flag;
    pl_contact_sum *sum;
    pl_contact_add *out = pl__parallel_slots(w, &flag, &sum);
    if (!out) { /* out of memory for the slots: the serial loop gives the same result */
        compute_serial(w, dt);
        return;
    }
    eval_task t = {w, make_ctx(w), out, sum, flag, dt};
    w->def.parallel_for(w->def.parallel_user, w->pair_n, eval_range, &t);
    pl__parallel_gather(w, out, flag);
    /* the sums over pairs, in pair order as in the serial loop */
    pl_disc_ctx *c = &t.c;
    double e_poly = 0;
    w->worst_overlap_ratio = 0;
    for (int k = 0; k < w->pair_n; k++) {
        const uint32_t f = flag[k];
        if (!f) continue;
        const pl_contact_sum *o = &sum[k];
        if (f & PL_OUT_POLYKIND) {
            e_poly += o->z;
            if (f & PL_OUT_EFRIC) w->e_friction += o->y;
            if (f & PL_OUT_POLY) {
                w->e_damped += o->x;
                if (o->ratio > w->worst_overlap_ratio) {
                    w->worst_overlap_ratio = o->ratio;
                    w->worst_a = w->pairs[k].a;
                    w->worst_b = w->pairs[k].b;
                }
            }
        } else if (f & PL_OUT_LAW) {
            c->e_shear += o->x;
            c->e_normal += o->y;
            if (o->ratio > c->worst_ratio) {
                c->worst_ratio = o->ratio;
                c->worst_a = w->pairs[k].a;
                c->worst_b = w->pairs[k].b;
            }
        }
    }
    finish(w, c, e_poly);
}

static void compute_serial(pl_world *w, double dt) {
    pl_disc_ctx c = make_ctx(w);
    const pl_pair_params *params = w->pair_params;
    double e_poly = 0;
    w->worst_overlap_ratio = 0;
    for (int k = 0; k < w->pair_n; k++) {
        pl_pair *p = &w->pairs[k];
        const pl_pair_params *pp = &params[p->params];
        /* one out per case, so that the disc ones stay in registers */
        switch (p->kind) {
        case PL_PAIR_DISC_DISC: {
            pl_contact_out o;
            pl__contact_disc_disc(&c, p, pp, dt, &o, 1);
            break;
        }
        case PL_PAIR_DISC_SEGMENT: {
            pl_contact_out o;
            pl__contact_disc_segment(&c, w, p, pp, dt, &o, 1);
            break;
        }
        case PL_PAIR_POLY_DISC:
        case PL_PAIR_POLY_POLY:
        case PL_PAIR_POLY_SEGMENT: {
            pl_contact_out o;
            pl__contact_polygon(w, p, pp, dt, &o);
            if (o.add.flags) pl__apply(&c, &o, p->a, p->b);
            account_poly(w, p, &o, p->touching ? p->elastic : 0, &e_poly);
            break;
        }
        default: break;
        }
    }
    finish(w, &c, e_poly);
}

void pl__compute_contact_forces(pl_world *w, double dt) {
    if (w->def.parallel_for) compute_threaded(w, dt);
    else compute_serial(w, dt);
}
