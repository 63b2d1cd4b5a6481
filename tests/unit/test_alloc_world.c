/* The core allocator on whole worlds: a world with discs, polygons and a Darcy fluid leaves
 * no byte behind after stepping, snapshot/restore and destroy; and a settled packing steps
 * 1000 times without one allocation (dry, and with the Darcy fluid solving every step;
 * CHOLMOD's own workspace is CHOLMOD's and not counted). */
#include "../physics/common.h"
#include "porelab/alloc.h"
#include "porelab/assert.h"
#include "world/world_layer.h"
#include "porelab/fluid.h"
#include "harness.h"
#include <stdint.h>

static int add_box(pl_world *w, int mat, double x, double y, double hw, double hh) {
    const pl_vec2 v[4] = {{x - hw, y - hh}, {x + hw, y - hh}, {x + hw, y + hh}, {x - hw, y + hh}};
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_POLYGON;
    b.material = mat;
    b.vertices = v;
    b.vertex_count = 4;
    return pl_world_add_body(w, &b);
}

/* ~200 bidisperse discs (and optionally 10 boxes) above a floor in a 0.6 m wide box. */
static pl_world *packing(int ndisc, int nbox, double local_damping) {
    pl_world_def wd = pl_default_world_def();
    wd.local_damping = local_damping;
    pl_world *w = pl_world_create(&wd);
    if (!w) return NULL;
    const int m = add_material(w, "grain", 2500, 1e7, -1, 0.5, 20, -1);
    add_wall(w, m, 0, 0, 0.6, 0);
    add_wall(w, m, 0, 0, 0, 1.2);
    add_wall(w, m, 0.6, 0, 0.6, 1.2);
    uint64_t s = 7;
    for (int i = 0; i < ndisc; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        add_disc(w, m, 0.02 + 0.028 * (i % 20), 0.02 + 0.028 * (i / 20), (s >> 20) % 2 ? 0.012 : 0.009);
    }
    for (int i = 0; i < nbox; i++) add_box(w, m, 0.04 + 0.055 * i, 0.06 + 0.028 * (ndisc / 20), 0.02, 0.01);
    return w;
}

static int add_darcy(pl_world *w) {
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){0.6, 0};
    q.corners[2] = (pl_vec2){0.6, 0.4};
    q.corners[3] = (pl_vec2){0, 0.4};
    q.ndivx = 12;
    q.ndivy = 8;
    if (pl_world_add_fluid_quad(w, &q) < 0) return 0;
    if (pl_world_add_fluid_bc(w, (pl_vec2){0, 0.4}, (pl_vec2){0.6, 0.4}, 0.0) < 0) return 0;
    return pl_world_set_flag(w, "FLUIDS_ON", 1) == PL_OK;
}

static int byte_count_zero_after_destroy(void) {
    const size_t b0 = pl_alloc_bytes();
    const uint64_t n0 = pl_alloc_count();
    pl_world *w = packing(100, 10, 0);
    ENSURE(w && add_darcy(w));
    ENSURE(pl_world_step(w, 200) == PL_OK);
    ENSURE(pl_world_fluid_node_count(w) > 0);
    pl_snapshot *snap = pl_world_snapshot(w);
    ENSURE(snap);
    const uint64_t h = pl_world_state_hash(w);
    ENSURE(pl_world_step(w, 50) == PL_OK);
    ENSURE(pl_world_restore(w, snap) == PL_OK);
    ENSURE(pl_world_state_hash(w) == h);
    ENSURE(pl_world_step(w, 50) == PL_OK);
    const size_t live = pl_alloc_bytes() - b0;
    pl_snapshot_destroy(&snap);
    pl_world_destroy(&w);
    fprintf(stderr, "  %llu allocations, %zu bytes live before destroy, %zu after\n",
            (unsigned long long)(pl_alloc_count() - n0), live, pl_alloc_bytes() - b0);
    ENSURE(live > 0);
    ENSURE(pl_alloc_bytes() == b0);
    return 0;
}

/* Settle (local damping), then count the allocations of 1000 further steps. */
static int no_allocation_in_settled_steps(int darcy, int settle_steps) {
    pl_world *w = packing(200, 0, 0.3);
    ENSURE(w);
    uint64_t n = pl_alloc_count();
    ENSURE(pl_world_step(w, 1) == PL_OK);
    const uint64_t first = pl_alloc_count() - n;
    const int settle = (int)(1.5 / pl_world_dt(w));
    n = pl_alloc_count();
    ENSURE(pl_world_step(w, settle) == PL_OK);
    const uint64_t settling = pl_alloc_count() - n;
    uint64_t fluid_first = 0;
    if (darcy) { /* water in the settled bed: mesh, analysis and the first solves, then settle again */
        ENSURE(add_darcy(w));
        n = pl_alloc_count();
        ENSURE(pl_world_step(w, settle_steps) == PL_OK);
        fluid_first = pl_alloc_count() - n;
    }
    pl_fluid_stats st0 = {0}, st1 = {0};
    if (darcy) ENSURE(pl_world_fluid_stats(w, &st0) == PL_OK);
    n = pl_alloc_count();
    for (int k = 0; k < 1000; k++) ENSURE(pl_world_step(w, 1) == PL_OK);
    const uint64_t hot = pl_alloc_count() - n;
    if (darcy) ENSURE(pl_world_fluid_stats(w, &st1) == PL_OK);
    fprintf(stderr, "  %s: first step %llu allocations, %d settling steps %llu, %d steps with water %llu, "
                    "then 1000 steps %llu (%ld fluid updates, %ld solves; kinetic energy %.3g J, %d contacts)\n",
            darcy ? "Darcy" : "dry", (unsigned long long)first, settle, (unsigned long long)settling,
            darcy ? settle_steps : 0, (unsigned long long)fluid_first, (unsigned long long)hot,
            st1.updates - st0.updates, st1.solves - st0.solves, pl_world_energy(w).kinetic,
            pl_world_contact_count(w));
    ENSURE(hot == 0);
    if (darcy) ENSURE(st1.solves - st0.solves > 0); /* the fluid did work in the counted steps */
    pl_world_destroy(&w);
    return 0;
}

static int no_allocation_in_1000_settled_steps(void) { return no_allocation_in_settled_steps(0, 0); }
static int no_allocation_in_1000_darcy_steps(void) { return no_allocation_in_settled_steps(1, 2000); }

/* A programmer error inside the engine reaches the assertion handler in builds with asserts,
   and is the same silent no-op as before in Release. */
static int seen;
static void count_failure(const char *file, int line, const char *expr, void *ctx) {
    (void)ctx;
    seen++;
    fprintf(stderr, "  handler called: %s:%d: %s\n", file, line, expr);
}
static int engine_assert_reaches_handler(void) {
    pl_set_assert_handler(count_failure, NULL);
    const void *cls = pl__model_class_at(pl__model_class_count());
    pl_set_assert_handler(NULL, NULL);
    ENSURE(cls == NULL);
    ENSURE(seen == (pl_asserts_enabled() ? 1 : 0));
    return 0;
}

int main(void) {
    RUN(engine_assert_reaches_handler);
    RUN(byte_count_zero_after_destroy);
    RUN(no_allocation_in_1000_settled_steps);
    RUN(no_allocation_in_1000_darcy_steps);
    return pl_test_report();
}
