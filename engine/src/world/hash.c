/* The state hash (determinism tests): the grain store, then every attached model. */
#include "world/world_layer.h"

uint64_t pl_world_state_hash(const pl_world *w) {
    /* the grain store: positions, velocities, contact history */
    uint64_t h = PL_HASH_SEED;
    h = pl_hash_bytes(h, &w->time, sizeof w->time);
    h = pl_hash_bytes(h, &w->step, sizeof w->step);
    h = pl_hash_bytes(h, w->pos, (size_t)w->n * sizeof *w->pos);
    h = pl_hash_bytes(h, w->vel, (size_t)w->n * sizeof *w->vel);
    h = pl_hash_bytes(h, w->angle, (size_t)w->n * sizeof *w->angle);
    h = pl_hash_bytes(h, w->omega, (size_t)w->n * sizeof *w->omega);
    for (int k = 0; k < w->pair_n; k++) {
        const pl_pair *p = &w->pairs[k];
        if (!p->touching) continue;
        h = pl_hash_bytes(h, &p->a, sizeof p->a);
        h = pl_hash_bytes(h, &p->b, sizeof p->b);
        h = pl_hash_bytes(h, &p->fs, sizeof p->fs);
        if (p->mr != 0) h = pl_hash_bytes(h, &p->mr, sizeof p->mr); /* rolling: no change without it */
        h = pl_hash_bytes(h, &p->area_prev, sizeof p->area_prev);
    }
    /* bonds, temperatures and wear (porelab/bonds.h): only when used, so that worlds without
       them keep their hashes */
    if (w->bond_n) {
        h = pl_hash_bytes(h, w->bonds, (size_t)w->bond_n * sizeof *w->bonds);
        h = pl_hash_bytes(h, &w->e_fracture, sizeof w->e_fracture);
    }
    if (w->heat_on) {
        h = pl_hash_bytes(h, w->temperature, (size_t)w->n * sizeof *w->temperature);
        h = pl_hash_bytes(h, w->heat, (size_t)w->n * sizeof *w->heat);
    }
    if (w->wear_on) {
        h = pl_hash_bytes(h, w->wear, (size_t)w->n * sizeof *w->wear);
        h = pl_hash_bytes(h, w->removed, (size_t)w->n);
    }
    return pl__models_hash(w, h); /* every attached model, in attachment order */
}
