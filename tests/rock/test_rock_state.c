/* Determinism, rewind and restart across bond breaking; the energy balance with fracture.
 * A bonded hexagonal block of discs (a few bonds weaker than the rest) is pulled apart by its
 * top row: bonds break in the run. The state hash must be the same for two runs, for a run
 * rewound with a snapshot taken before the first break, and for a run saved to a state image
 * before the break and loaded into a freshly built world; it must change when a bond breaks. */
#include "harness.h"
#include "porelab/bonds.h"
#include "porelab/world.h"
#include <stdlib.h>
#include <string.h>

#define NX 8
#define NY 6
#define RAD 1e-3

static pl_world *block(int heat) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, 0};
    pl_world *w = pl_world_create(&wd);
    pl_material_def m = pl_default_material_def();
    m.name = "rock";
    m.density = 2600;
    m.kn = 1e7;
    m.restitution = 0.5;
    const int mat = pl_world_add_material(w, &m);
    pl_bond_def L = pl_default_bond_def();
    L.law = PL_BOND_DAMAGE;
    L.kn = 1e7;
    L.rn = 20;
    L.rt = 20;
    L.kr = 1e-2;
    pl_world_set_bond_law(w, mat, mat, &L);
    const double d = 2 * RAD, h = d * sqrt(3) / 2;
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            pl_body_def b = pl_default_body_def();
            b.material = mat;
            b.radius = RAD * (1 + 0.002 * ((i * 7 + j * 3) % 5)); /* slightly polydisperse: some pairs overlap, bonded in parallel with their contacts */
            b.position = (pl_vec2){i * d + (j % 2) * 0.5 * d, j * h};
            if (j == 0) b.motion = PL_MOTION_FIXED;
            const int k = pl_world_add_body(w, &b);
            if (j == NY - 1) pl_world_prescribe_velocity(w, k, (pl_vec2){0.02, 0.2}, 0);
        }
    pl_world_bond_touching(w, 0.1 * RAD);
    if (heat) {
        pl_thermal_def t = pl_default_thermal_def();
        t.conductivity = 3;
        pl_world_set_thermal(w, mat, &t);
        pl_world_enable_heat(w, 1, 300);
        pl_world_set_body_temperature(w, 0, 400, 1);
    }
    return w;
}

static int first_break_step(pl_world *w, int max) {
    for (int s = 0; s < max; s++) {
        const int64_t before = pl_world_step_count(w);
        if (pl_world_step(w, 1) != PL_OK) return -2;
        if (pl_world_broken_bonds(w, before, NULL, 0) > 0) return (int)before;
    }
    return -1;
}

static int determinism_and_restart(void) {
    for (int heat = 0; heat <= 1; heat++) {
        pl_world *w = block(heat);
        const int total = pl_world_bond_total(w);
        ENSURE(total > 100);
        const int s0 = first_break_step(w, 20000);
        ENSURE(s0 > 10);
        pl_world_destroy(&w);
        /* reference: to s0 - 10, snapshot and state image, then on to s0 + 400 */
        w = block(heat);
        ENSURE(pl_world_step(w, s0 - 10) == PL_OK);
        pl_snapshot *snap = pl_world_snapshot(w);
        void *bytes = NULL;
        size_t len = 0;
        ENSURE(pl_world_save_state(w, &bytes, &len) == PL_OK);
        const uint64_t h_before = pl_world_state_hash(w);
        ENSURE(pl_world_step(w, 410) == PL_OK);
        const int broken = total - pl_world_bond_count(w);
        ENSURE(broken > 0);
        const uint64_t ref = pl_world_state_hash(w);
        /* a second run */
        pl_world *w2 = block(heat);
        ENSURE(pl_world_step(w2, s0 + 400) == PL_OK);
        ENSURE(pl_world_state_hash(w2) == ref);
        pl_world_destroy(&w2);
        /* rewind */
        ENSURE(pl_world_restore(w, snap) == PL_OK);
        ENSURE(pl_world_state_hash(w) == h_before);
        ENSURE(pl_world_bond_count(w) == total);
        ENSURE(pl_world_step(w, 410) == PL_OK);
        ENSURE(pl_world_state_hash(w) == ref);
        /* restart into a new world built by the same set-up */
        pl_world *w3 = block(heat);
        ENSURE(pl_world_load_state(w3, bytes, len) == PL_OK);
        ENSURE(pl_world_state_hash(w3) == h_before);
        ENSURE(pl_world_step(w3, 410) == PL_OK);
        ENSURE(pl_world_state_hash(w3) == ref);
        ENSURE(pl_world_bond_count(w3) == total - broken);
        /* the hash sees the bonds: a world whose bond broke differs from one whose did not */
        pl_world *w4 = block(heat);
        ENSURE(pl_world_step(w4, s0) == PL_OK);
        const uint64_t h_intact = pl_world_state_hash(w4);
        ENSURE(pl_world_step(w4, 1) == PL_OK);
        ENSURE(pl_world_state_hash(w4) != h_intact);
        const pl_energy e = pl_world_energy(w3);
        const double moved = fabs(e.kinetic) + fabs(e.elastic) + fabs(e.damped) + fabs(e.fracture) + fabs(e.external);
        fprintf(stderr, "  heat %d: first break at step %d, %d of %d bonds broken by step %d; energy: elastic %.4g, "
                "fracture %.4g, damped %.4g, external %.4g J, balance %.3g J (%.3g %%)\n",
                heat, s0, broken, total, s0 + 400, e.elastic, e.fracture, e.damped, e.external, e.balance,
                100 * fabs(e.balance) / moved);
        /* the balance closes with the fracture energy in it (explicit scheme: a small fraction) */
        ENSURE(e.fracture > 0);
        ENSURE(fabs(e.balance) < 0.01 * moved);
        pl_world_destroy(&w4);
        pl_world_destroy(&w3);
        pl_snapshot_destroy(&snap);
        pl_state_free(bytes);
        pl_world_destroy(&w);
    }
    return 0;
}

int main(void) {
    RUN(determinism_and_restart);
    return pl_test_report();
}
