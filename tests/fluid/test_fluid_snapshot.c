/* Snapshots of worlds with a pore fluid (issue 7, docs/fluid.md §10): step N, snapshot, step M
 * -> state hash H1 (grains, contacts and the fluid: heads, permeabilities, solid areas,
 * consolidation reference and source, reused forces, update phase); restore, step M -> H2 = H1
 * bit for bit; and again after stepping the world elsewhere in between (other step counts, so
 * the fluid update's phase differs; other boundary conditions; other flags). Worlds:
 *   quicksand-like: upward seepage through a disc bed carrying a polygon block, FLUID_PERM 1,
 *     FLUID_CONSOLIDATION 1, FLUID_SOLVE_TIMESTEPS 3, heads raised at run time (as the scene's
 *     hook does: clear_fluid_bcs + add_fluid_bc);
 *   liquefaction-like: discs on a shaking floor between shaking polygon slabs, low
 *     permeability, compressible fluid, FLUID_FORCE_REUSE 1, FLUID_SOLVE_TIMESTEPS 2;
 *   transient: constant permeability (the factor is kept for the whole run, so the restored run
 *     refactorizes what the first run reused: the refactorization must be bit-identical),
 *     backward Euler, Crank-Nicolson and explicit, FIRST_STEP_STATIC 0; and per-element
 *     conductivities from the scene (FLUID_PERM 2).
 * Also: a snapshot of a fresh world (mesh not built yet), a snapshot taken with boundary
 * conditions changed but not yet applied, a mesh changed after the snapshot, and a snapshot
 * from before the first fluid quad. And queries (what a frame draws, what a hook asks) leave the
 * state alone: the same hash with and without them. */
#include "harness.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define W 0.06
#define H 0.10

static void set_flags(pl_world *w, const char *const *names, const double *vals, int n) {
    for (int k = 0; k < n; k++)
        if (pl_world_set_flag(w, names[k], vals[k]) != PL_OK) fprintf(stderr, "%s\n", pl_world_last_error(w));
}

static int add_box(pl_world *w, int wall, pl_vec2 c, double hw, double hh, pl_motion_type motion) {
    pl_vec2 v[4] = {{c.x - hw, c.y - hh}, {c.x + hw, c.y - hh}, {c.x + hw, c.y + hh}, {c.x - hw, c.y + hh}};
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_POLYGON;
    b.motion = motion;
    b.material = wall;
    b.vertices = v;
    b.vertex_count = 4;
    return pl_world_add_body(w, &b);
}

static void add_discs(pl_world *w, int mat, int n, double x0, double y0) {
    for (int k = 0; k < n; k++) {
        pl_body_def d = pl_default_body_def();
        d.shape = PL_SHAPE_DISC;
        d.material = mat;
        d.radius = (k % 2) ? 0.0026 : 0.0020;
        int row = k / 11, col = k % 11;
        d.position = (pl_vec2){x0 + col * 0.0050 + (row % 2) * 0.0008, y0 + row * 0.0058};
        pl_world_add_body(w, &d);
    }
}

static int materials(pl_world *w, int *wall) {
    pl_material_def md = pl_default_material_def();
    md.name = "sand";
    md.density = 2650;
    md.kn = 2e5;
    md.friction = 0.3;
    md.restitution = 0.3;
    int sand = pl_world_add_material(w, &md);
    md.name = "wall";
    md.friction = 0.2;
    *wall = pl_world_add_material(w, &md);
    return sand;
}

static void segment(pl_world *w, int mat, pl_vec2 a, pl_vec2 b, pl_motion_type motion) {
    pl_body_def s = pl_default_body_def();
    s.shape = PL_SHAPE_SEGMENT;
    s.motion = motion;
    s.material = mat;
    s.a = a;
    s.b = b;
    pl_world_add_body(w, &s);
}

static void fluid_box(pl_world *w, double x0, double x1, int nx, int ny) {
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){x0, 0};
    q.corners[1] = (pl_vec2){x1, 0};
    q.corners[2] = (pl_vec2){x1, H};
    q.corners[3] = (pl_vec2){x0, H};
    q.ndivx = nx;
    q.ndivy = ny;
    pl_world_add_fluid_quad(w, &q);
}

/* Quicksand-like: heads H + dh at the floor, 0 at the top. */
static void quicksand_bcs(pl_world *w, double dh) {
    pl_world_clear_fluid_bcs(w);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){W, 0}, H + dh);
    pl_world_add_fluid_bc(w, (pl_vec2){0, H}, (pl_vec2){W, H}, 0);
}

static pl_world *quicksand(void) {
    pl_world_def wd = pl_default_world_def();
    wd.rayleigh_alpha = 20;
    pl_world *w = pl_world_create(&wd);
    int wall, sand = materials(w, &wall);
    segment(w, wall, (pl_vec2){-0.01, 0}, (pl_vec2){W + 0.01, 0}, PL_MOTION_FIXED);
    segment(w, wall, (pl_vec2){0, 0}, (pl_vec2){0, 0.2}, PL_MOTION_FIXED);
    segment(w, wall, (pl_vec2){W, 0}, (pl_vec2){W, 0.2}, PL_MOTION_FIXED);
    add_discs(w, sand, 66, 0.0027, 0.004);
    add_box(w, wall, (pl_vec2){0.02, 0.05}, 0.008, 0.005, PL_MOTION_DYNAMIC); /* the block */
    fluid_box(w, 0, W, 6, 10);
    quicksand_bcs(w, 0);
    const char *names[] = {"FLUIDS_ON", "FIRST_STEP_STATIC", "FLUID_PERM", "FLUID_PERM_LOW", "FLUID_PERM_HIGH",
                           "FLUID_STORAGE", "FLUID_CONSOLIDATION", "FLUID_BULK_MODULUS", "FLUID_SOLVE_TIMESTEPS"};
    const double vals[] = {1, 1, 1, 1e-3, 1.0, 0, 1, 2.2e9, 3};
    set_flags(w, names, vals, 9);
    return w;
}

static int g_lag = 0; /* FLUID_POROSITY_TIMESTEPS of the liquefaction-like world */

static pl_world *liquefaction(void) {
    pl_world_def wd = pl_default_world_def();
    wd.rayleigh_alpha = 5;
    pl_world *w = pl_world_create(&wd);
    int wall, sand = materials(w, &wall);
    segment(w, wall, (pl_vec2){-0.03, 0}, (pl_vec2){W + 0.03, 0}, PL_MOTION_PRESCRIBED);
    int l = add_box(w, wall, (pl_vec2){-0.01, 0.1}, 0.01, 0.1, PL_MOTION_PRESCRIBED);
    int r = add_box(w, wall, (pl_vec2){W + 0.01, 0.1}, 0.01, 0.1, PL_MOTION_PRESCRIBED);
    for (int b = 0; b < 3; b++)
        pl_world_set_sinusoid(w, b == 0 ? 0 : (b == 1 ? l : r), (pl_vec2){0.0015, 0}, 8.0, 0.0, 100.0);
    add_discs(w, sand, 77, 0.0027, 0.004);
    fluid_box(w, -0.004, W + 0.004, 7, 6);
    pl_world_add_fluid_bc(w, (pl_vec2){-0.004, H}, (pl_vec2){W + 0.004, H}, 0);
    const char *names[] = {"FLUIDS_ON", "FIRST_STEP_STATIC", "FLUID_PERM", "FLUID_PERM_LOW", "FLUID_PERM_HIGH",
                           "FLUID_STORAGE", "FLUID_CONSOLIDATION", "FLUID_BULK_MODULUS", "FLUID_SOLVE_TIMESTEPS",
                           "FLUID_FORCE_REUSE"};
    const double vals[] = {1, 1, 1, 1e-4, 0.5, 0, 1, 3e5, 2, 1};
    set_flags(w, names, vals, 10);
    if (g_lag) { /* solve every step, pieces cut every g_lag steps */
        pl_world_set_flag(w, "FLUID_SOLVE_TIMESTEPS", 1);
        pl_world_set_flag(w, "FLUID_POROSITY_TIMESTEPS", g_lag);
    }
    return w;
}

static int g_method = 0, g_perm2 = 0;

/* FLUID_PERM 2: per-element conductivities from the scene, 1e-3 m/s x scale x a pattern */
static void set_user_perm(pl_world *w, double scale) {
    pl_world_prepare(w); /* queries read only: build first */
    int ne = pl_world_fluid_triangle_count(w);
    double *k = malloc(sizeof(double) * (size_t)ne);
    for (int e = 0; e < ne; e++) k[e] = 1e-3 * scale * (1.0 + 0.5 * sin(0.7 * e));
    if (pl_world_fluid_set_element_permeability(w, k, ne) != PL_OK) fprintf(stderr, "%s\n", pl_world_last_error(w));
    free(k);
}

/* Transient pool with a few discs: constant permeability, storage, heads on both sides. */
static pl_world *transient(void) {
    pl_world_def wd = pl_default_world_def();
    pl_world *w = pl_world_create(&wd);
    int wall, sand = materials(w, &wall);
    segment(w, wall, (pl_vec2){-0.01, 0}, (pl_vec2){W + 0.01, 0}, PL_MOTION_FIXED);
    segment(w, wall, (pl_vec2){0, 0}, (pl_vec2){0, 0.2}, PL_MOTION_FIXED);
    segment(w, wall, (pl_vec2){W, 0}, (pl_vec2){W, 0.2}, PL_MOTION_FIXED);
    add_discs(w, sand, 22, 0.0027, 0.004);
    fluid_box(w, 0, W, 6, 8);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){0, H}, 0.02);
    pl_world_add_fluid_bc(w, (pl_vec2){W, 0}, (pl_vec2){W, H}, -0.01);
    pl_world_add_fluid_flux(w, (pl_vec2){0, 0}, (pl_vec2){W, 0}, 1e-4);
    const char *names[] = {"FLUIDS_ON", "FIRST_STEP_STATIC", "FLUID_PERM", "FLUID_PERM_HIGH", "FLUID_STORAGE",
                           "FLUID_SOLVE_TIMESTEPS", "FLUID_METHOD"};
    const double vals[] = {1, 0, g_perm2 ? 2 : 0, 1e-3, 2.0, 4, g_method};
    set_flags(w, names, vals, 7);
    if (g_perm2) set_user_perm(w, 1.0);
    return w;
}

/* The stepping after the snapshot: as a scene hook would, raise the heads halfway. */
typedef struct plan {
    pl_world *(*build)(void);
    int n, m;           /* steps before the snapshot and after it */
    int bc_at;          /* step (after the snapshot) where the heads change; < 0 none */
} plan;

static int change_bcs(pl_world *w, const plan *p, double dh) {
    if (p->build == quicksand) quicksand_bcs(w, dh);
    else {
        pl_world_clear_fluid_bcs(w);
        pl_world_add_fluid_bc(w, (pl_vec2){-0.004, H}, (pl_vec2){W + 0.004, H}, dh);
        if (p->build == transient) pl_world_add_fluid_bc(w, (pl_vec2){W, 0}, (pl_vec2){W, H}, -dh);
    }
    return 0;
}

static int step_m(pl_world *w, const plan *p) {
    if (p->bc_at < 0) return pl_world_step(w, p->m) == PL_OK;
    if (pl_world_step(w, p->bc_at) != PL_OK) return 0;
    change_bcs(w, p, 0.004);
    return pl_world_step(w, p->m - p->bc_at) == PL_OK;
}

static int check_plan(const char *name, const plan *p) {
    pl_world *w = p->build();
    ENSURE(w);
    if (p->n > 0) ENSURE(pl_world_step(w, p->n) == PL_OK);
    uint64_t h0 = pl_world_state_hash(w);
    pl_snapshot *s = pl_world_snapshot(w);
    if (!s) fprintf(stderr, "%s\n", pl_world_last_error(w));
    ENSURE(s);
    ENSURE(step_m(w, p));
    uint64_t h1 = pl_world_state_hash(w);
    pl_fluid_stats st1;
    pl_world_fluid_stats(w, &st1);
    /* restore and step the same way */
    ENSURE(pl_world_restore(w, s) == PL_OK);
    ENSURE(pl_world_state_hash(w) == h0);
    ENSURE(step_m(w, p));
    uint64_t h2 = pl_world_state_hash(w);
    /* elsewhere first: another number of steps (another fluid phase), other heads, other
       flags and permeabilities, a query; then restore */
    ENSURE(pl_world_restore(w, s) == PL_OK);
    ENSURE(pl_world_step(w, 7) == PL_OK);
    change_bcs(w, p, -0.003);
    pl_world_set_flag(w, "FLUID_SOLVE_TIMESTEPS", 5);
    pl_world_set_flag(w, "FLUID_PERM_HIGH", 2.5e-3);
    if (g_perm2) set_user_perm(w, 3.0);
    ENSURE(pl_world_step(w, 11) == PL_OK);
    double pr, hd;
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_pressure_at(w, (pl_vec2){0.5 * W, 0.5 * H}, &pr, &hd);
    ENSURE(pl_world_restore(w, s) == PL_OK);
    ENSURE(pl_world_state_hash(w) == h0);
    ENSURE(step_m(w, p));
    uint64_t h3 = pl_world_state_hash(w);
    /* elsewhere with the same boundary conditions and phase but other conductivities (the
       world's factor is then of another matrix with the same coefficients) */
    ENSURE(pl_world_restore(w, s) == PL_OK);
    pl_world_set_flag(w, "FLUID_PERM_HIGH", 2.5e-3);
    if (g_perm2) set_user_perm(w, 3.0);
    ENSURE(pl_world_step(w, 12) == PL_OK);
    ENSURE(pl_world_restore(w, s) == PL_OK);
    ENSURE(step_m(w, p));
    uint64_t h4 = pl_world_state_hash(w);
    fprintf(stderr, "  %-34s N %4d M %4d: snapshot %7zu bytes, %ld fluid updates, %ld factorizations; "
                    "hashes %016llx %016llx %016llx %016llx\n",
            name, p->n, p->m, pl_snapshot_bytes(s), st1.updates, st1.factorizations, (unsigned long long)h1,
            (unsigned long long)h2, (unsigned long long)h3, (unsigned long long)h4);
    pl_validation("fluid.snapshot", "queries never change the run; snapshots restore the fluid",
                  "same state hash with and without queries, after restore", "exact", "%s: %s", name,
                  h1 == h2 && h1 == h3 && h1 == h4 ? "identical" : "DIFFERENT");
    ENSURE(h1 != h0);
    ENSURE(h1 == h2);
    ENSURE(h1 == h3);
    ENSURE(h1 == h4);
    pl_snapshot_destroy(&s);
    pl_world_destroy(&w);
    return 0;
}

static int quicksand_restores(void) {
    plan a = {quicksand, 301, 400, 150};
    plan b = {quicksand, 302, 200, -1};
    return check_plan("quicksand-like", &a) || check_plan("quicksand-like, other phase", &b);
}

static int liquefaction_restores(void) {
    plan a = {liquefaction, 400, 301, -1};
    plan b = {liquefaction, 401, 300, 101};
    return check_plan("liquefaction-like", &a) || check_plan("liquefaction-like, heads changed", &b);
}

static int lagged_pieces_restore(void) {
    plan a = {liquefaction, 403, 301, -1};
    plan b = {liquefaction, 405, 300, 101};
    g_lag = 7;
    int r = check_plan("liquefaction-like, pieces every 7", &a) || check_plan("same, other phase, heads", &b);
    g_lag = 0;
    return r;
}

static int transient_restores(void) {
    const char *names[] = {"transient backward Euler", "transient Crank-Nicolson", "transient explicit"};
    for (g_method = 0; g_method < 3; g_method++) {
        plan a = {transient, 203, 250, 97};
        if (check_plan(names[g_method], &a)) return 1;
    }
    g_method = 0;
    g_perm2 = 1; /* per-element conductivities from the scene (changed elsewhere) */
    plan b = {transient, 150, 200, -1};
    int r = check_plan("transient, FLUID_PERM 2", &b);
    g_perm2 = 0;
    return r;
}

/* Steps n from the snapshot s, restores it and steps n again: the same state hash. */
static int replays_same(pl_world *w, const pl_snapshot *s, int n) {
    ENSURE(pl_world_step(w, n) == PL_OK);
    const uint64_t h1 = pl_world_state_hash(w);
    ENSURE(pl_world_restore(w, s) == PL_OK);
    ENSURE(pl_world_step(w, n) == PL_OK);
    ENSURE(pl_world_state_hash(w) == h1);
    return 0;
}

/* A snapshot of the world as built (mesh not made yet), and one after a query at t = 0 (the
   static field computed ahead of the first step). */
static int fresh_world_restores(void) {
    plan a = {quicksand, 0, 120, 50};
    if (check_plan("fresh world", &a)) return 1;
    pl_world *w = quicksand();
    pl_world_prepare(w); /* queries read only: build first */
    ENSURE(pl_world_fluid_node_count(w) > 0); /* query: static solve before the first step */
    pl_snapshot *s = pl_world_snapshot(w);
    ENSURE(s);
    if (replays_same(w, s, 100)) return 1;
    pl_snapshot_destroy(&s);
    pl_world_destroy(&w);
    return 0;
}

/* Heads changed just before the snapshot (applied at the next step, or by a query); the mesh
   changed after the snapshot (a second quad: the restore must remesh back). */
static int dirty_inputs_restore(void) {
    pl_world *w = quicksand();
    ENSURE(pl_world_step(w, 200) == PL_OK);
    quicksand_bcs(w, 0.006);
    pl_snapshot *s = pl_world_snapshot(w);
    ENSURE(s);
    if (replays_same(w, s, 100)) return 1;
    const uint64_t h1 = pl_world_state_hash(w); /* 100 steps after the snapshot */
    /* a second fluid quad above the first: another mesh */
    ENSURE(pl_world_restore(w, s) == PL_OK);
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, H};
    q.corners[1] = (pl_vec2){W, H};
    q.corners[2] = (pl_vec2){W, 1.5 * H};
    q.corners[3] = (pl_vec2){0, 1.5 * H};
    q.ndivx = 6;
    q.ndivy = 5;
    ENSURE(pl_world_add_fluid_quad(w, &q) >= 0);
    ENSURE(pl_world_step(w, 30) == PL_OK);
    pl_world_prepare(w); /* queries read only: build first */
    int nn2 = pl_world_fluid_node_count(w);
    ENSURE(pl_world_restore(w, s) == PL_OK);
    ENSURE(pl_world_fluid_quad_count(w) == 1);
    ENSURE(pl_world_step(w, 100) == PL_OK);
    ENSURE(pl_world_state_hash(w) == h1);
    pl_world_prepare(w); /* queries read only: build first */
    ENSURE(pl_world_fluid_node_count(w) < nn2);
    pl_snapshot_destroy(&s);
    /* heads changed and applied by a query before the snapshot: the next step still restarts
       the fluid after the restore */
    quicksand_bcs(w, 0.009);
    double pr, hd;
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_pressure_at(w, (pl_vec2){0.5 * W, 0.5 * H}, &pr, &hd);
    s = pl_world_snapshot(w);
    ENSURE(s);
    if (replays_same(w, s, 60)) return 1;
    pl_snapshot_destroy(&s);
    pl_world_destroy(&w);
    return 0;
}

/* A snapshot from before the first fluid quad: restoring it removes the model. */
static int snapshot_before_fluid(void) {
    pl_world_def wd = pl_default_world_def();
    pl_world *w = pl_world_create(&wd);
    int wall, sand = materials(w, &wall);
    segment(w, wall, (pl_vec2){-0.01, 0}, (pl_vec2){W + 0.01, 0}, PL_MOTION_FIXED);
    add_discs(w, sand, 22, 0.0027, 0.004);
    ENSURE(pl_world_step(w, 50) == PL_OK);
    pl_snapshot *s = pl_world_snapshot(w);
    ENSURE(s);
    ENSURE(pl_world_step(w, 100) == PL_OK);
    uint64_t h1 = pl_world_state_hash(w);
    ENSURE(pl_world_restore(w, s) == PL_OK);
    fluid_box(w, 0, W, 4, 4);
    pl_world_add_fluid_bc(w, (pl_vec2){0, H}, (pl_vec2){W, H}, 0);
    pl_world_set_flag(w, "FLUIDS_ON", 1);
    ENSURE(pl_world_step(w, 60) == PL_OK);
    pl_snapshot *s2 = pl_world_snapshot(w); /* with the fluid */
    ENSURE(s2);
    ENSURE(pl_world_step(w, 40) == PL_OK);
    uint64_t h2 = pl_world_state_hash(w);
    ENSURE(pl_world_restore(w, s) == PL_OK);
    pl_world_set_flag(w, "FLUIDS_ON", 0);
    ENSURE(pl_world_fluid_quad_count(w) == 0);
    ENSURE(pl_world_step(w, 100) == PL_OK);
    ENSURE(pl_world_state_hash(w) == h1);
    ENSURE(pl_world_restore(w, s2) == PL_OK); /* the model comes back */
    ENSURE(pl_world_fluid_quad_count(w) == 1);
    ENSURE(pl_world_step(w, 40) == PL_OK);
    ENSURE(pl_world_state_hash(w) == h2);
    pl_snapshot_destroy(&s);
    pl_snapshot_destroy(&s2);
    pl_world_destroy(&w);
    return 0;
}

/* Everything a renderer or a scene hook may query, as a frame does. */
static void query_all(pl_world *w) {
    pl_world_prepare(w); /* queries read only: build first */
    int nn = pl_world_fluid_node_count(w), ne = pl_world_fluid_triangle_count(w);
    double *v = malloc(sizeof(double) * (size_t)(nn > ne ? nn : ne) + 1);
    pl_vec2 *xy = malloc(sizeof(pl_vec2) * (size_t)nn + 1);
    int *tri = malloc(sizeof(int) * 3 * (size_t)ne + 1);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_nodes(w, xy, nn);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_triangles(w, tri, ne);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_node_field(w, PL_FLUID_EXCESS_PRESSURE, v, nn);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_element_field(w, PL_FLUID_POROSITY, v, ne);
    double p, h;
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_pressure_at(w, (pl_vec2){0.5 * W, 0.5 * H}, &p, &h);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_line_inflow(w, 0);
    pl_vec2 F;
    double M;
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_body_force(w, pl_world_body_count(w) - 1, &F, &M);
    free(v);
    free(xy);
    free(tri);
}

/* Queries never change what the world does next: the same run with queries at t = 0, every
   few steps, and right after the heads were changed (before the step that applies them)
   gives the same state hash as without them. */
static int queries_leave_state_alone(void) {
    pl_world *(*builds[])(void) = {quicksand, liquefaction, transient, liquefaction};
    const char *names[] = {"quicksand-like", "liquefaction-like", "transient", "same, pieces every 7"};
    for (int b = 0; b < 4; b++) {
        uint64_t hash[2];
        g_lag = b == 3 ? 7 : 0; /* the first query's static solve must not shift the cuts */
        for (int q = 0; q < 2; q++) {
            pl_world *w = builds[b]();
            plan p = {builds[b], 0, 0, 0};
            for (int k = 0; k < 30; k++) {
                if (q) query_all(w);
                if (k == 12) {
                    change_bcs(w, &p, 0.005);
                    if (q) query_all(w);
                }
                ENSURE(pl_world_step(w, 7) == PL_OK);
            }
            hash[q] = pl_world_state_hash(w);
            pl_world_destroy(&w);
        }
        fprintf(stderr, "  %-18s without queries %016llx, with %016llx\n", names[b], (unsigned long long)hash[0],
                (unsigned long long)hash[1]);
        pl_validation("fluid.snapshot", "", "", "", "queries in %s: %s", names[b],
                      hash[0] == hash[1] ? "identical" : "DIFFERENT");
        ENSURE(hash[0] == hash[1]);
    }
    g_lag = 0;
    /* a query between changed heads and a solve, an advance or new heads set by the scene */
    const char *calls[] = {"solve_static", "advance", "set_pressure_head"};
    for (int c = 0; c < 3; c++) {
        uint64_t hash[2];
        for (int q = 0; q < 2; q++) {
            pl_world *w = transient();
            plan p = {transient, 0, 0, 0};
            ENSURE(pl_world_step(w, 50) == PL_OK);
            change_bcs(w, &p, 0.006);
            if (q) query_all(w);
            if (c == 0) ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
            if (c == 1) ENSURE(pl_world_fluid_advance(w, 1e-4) == PL_OK);
            if (c == 2) ENSURE(pl_world_fluid_set_pressure_head(w, 0.001) == PL_OK);
            ENSURE(pl_world_step(w, 30) == PL_OK);
            hash[q] = pl_world_state_hash(w);
            pl_world_destroy(&w);
        }
        fprintf(stderr, "  heads, query, %-17s: without the query %016llx, with %016llx\n", calls[c],
                (unsigned long long)hash[0], (unsigned long long)hash[1]);
        ENSURE(hash[0] == hash[1]);
    }
    return 0;
}

int main(void) {
    RUN(quicksand_restores);
    RUN(liquefaction_restores);
    RUN(lagged_pieces_restore);
    RUN(transient_restores);
    RUN(fresh_world_restores);
    RUN(dirty_inputs_restore);
    RUN(snapshot_before_fluid);
    RUN(queries_leave_state_alone);
    return pl_test_report();
}
