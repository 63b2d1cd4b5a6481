/* State images (restart files, issue 12): pl_world_save_state / pl_world_load_state.
 *   - a dry world and two fluid worlds (upward seepage with FLUID_CONSOLIDATION 1 and
 *     FLUID_FORCE_REUSE 1, and a transient pool): step k, save; step N - k -> H. A fresh world
 *     built the same way loads the bytes: its hash is the hash at step k (and not the fresh
 *     world's), and N - k steps on give H bit for bit;
 *   - in one process: save -> load gives what snapshot -> restore gives;
 *   - saving twice gives the same bytes;
 *   - a truncated file, a flipped bit anywhere, another format version, another layout hash
 *     and another world are refused with PL_ERR_IO / PL_ERR_STATE and a message, and the world
 *     is left as it was (same hash, still steps). */
#include "harness.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define W 0.06
#define H 0.10

static int materials(pl_world *w, int *wall) {
    pl_material_def md = pl_default_material_def();
    md.name = "sand";
    md.density = 2650;
    md.kn = 2e5;
    md.friction = 0.3;
    md.restitution = 0.3;
    md.rolling = 0.05;
    int sand = pl_world_add_material(w, &md);
    md.name = "wall";
    md.friction = 0.2;
    md.rolling = 0;
    *wall = pl_world_add_material(w, &md);
    return sand;
}

static void segment(pl_world *w, int mat, pl_vec2 a, pl_vec2 b) {
    pl_body_def s = pl_default_body_def();
    s.shape = PL_SHAPE_SEGMENT;
    s.motion = PL_MOTION_FIXED;
    s.material = mat;
    s.a = a;
    s.b = b;
    pl_world_add_body(w, &s);
}

static void box(pl_world *w, int mat, pl_vec2 c, double hw, double hh) {
    pl_vec2 v[4] = {{c.x - hw, c.y - hh}, {c.x + hw, c.y - hh}, {c.x + hw, c.y + hh}, {c.x - hw, c.y + hh}};
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_POLYGON;
    b.material = mat;
    b.vertices = v;
    b.vertex_count = 4;
    pl_world_add_body(w, &b);
}

static pl_world *grains(int ndisc) {
    pl_world_def wd = pl_default_world_def();
    wd.rayleigh_alpha = 20;
    pl_world *w = pl_world_create(&wd);
    int wall, sand = materials(w, &wall);
    segment(w, wall, (pl_vec2){-0.01, 0}, (pl_vec2){W + 0.01, 0});
    segment(w, wall, (pl_vec2){0, 0}, (pl_vec2){0, 0.2});
    segment(w, wall, (pl_vec2){W, 0}, (pl_vec2){W, 0.2});
    for (int k = 0; k < ndisc; k++) {
        pl_body_def d = pl_default_body_def();
        d.shape = PL_SHAPE_DISC;
        d.material = sand;
        d.radius = (k % 2) ? 0.0026 : 0.0020;
        int row = k / 11, col = k % 11;
        d.position = (pl_vec2){0.0027 + col * 0.0050 + (row % 2) * 0.0008, 0.004 + row * 0.0058};
        pl_world_add_body(w, &d);
    }
    box(w, wall, (pl_vec2){0.02, 0.06}, 0.008, 0.005);
    return w;
}

static pl_world *dry(void) { return grains(55); }

static void fluid_box(pl_world *w, int nx, int ny) {
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){W, 0};
    q.corners[2] = (pl_vec2){W, H};
    q.corners[3] = (pl_vec2){0, H};
    q.ndivx = nx;
    q.ndivy = ny;
    pl_world_add_fluid_quad(w, &q);
}

static void flags(pl_world *w, const char *const *names, const double *vals, int n) {
    for (int k = 0; k < n; k++)
        if (pl_world_set_flag(w, names[k], vals[k]) != PL_OK) fprintf(stderr, "%s\n", pl_world_last_error(w));
}

static pl_world *seepage(void) {
    pl_world *w = grains(66);
    fluid_box(w, 6, 10);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){W, 0}, H + 0.01);
    pl_world_add_fluid_bc(w, (pl_vec2){0, H}, (pl_vec2){W, H}, 0);
    const char *names[] = {"FLUIDS_ON", "FIRST_STEP_STATIC", "FLUID_PERM", "FLUID_PERM_LOW", "FLUID_PERM_HIGH",
                           "FLUID_STORAGE", "FLUID_CONSOLIDATION", "FLUID_BULK_MODULUS", "FLUID_SOLVE_TIMESTEPS",
                           "FLUID_FORCE_REUSE"};
    const double vals[] = {1, 1, 1, 1e-3, 1.0, 0, 1, 2.2e6, 3, 1};
    flags(w, names, vals, 10);
    return w;
}

static pl_world *pool(void) {
    pl_world *w = grains(22);
    fluid_box(w, 6, 8);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){0, H}, 0.02);
    pl_world_add_fluid_bc(w, (pl_vec2){W, 0}, (pl_vec2){W, H}, -0.01);
    pl_world_add_fluid_flux(w, (pl_vec2){0, 0}, (pl_vec2){W, 0}, 1e-4);
    const char *names[] = {"FLUIDS_ON", "FIRST_STEP_STATIC", "FLUID_PERM", "FLUID_PERM_HIGH", "FLUID_STORAGE",
                           "FLUID_SOLVE_TIMESTEPS", "FLUID_METHOD"};
    const double vals[] = {1, 0, 0, 1e-3, 2.0, 4, 1};
    flags(w, names, vals, 7);
    return w;
}

static int step(pl_world *w, int n) {
    pl_status st = pl_world_step(w, n);
    if (st != PL_OK) fprintf(stderr, "step: %s\n", pl_world_last_error(w));
    return st == PL_OK;
}

/* step k, save, step N - k: H; fresh world, load, step N - k: H */
static int restart(pl_world *(*build)(void), int k, int n) {
    pl_world *a = build();
    const uint64_t h0 = pl_world_state_hash(a);
    ENSURE(step(a, k));
    const uint64_t hk = pl_world_state_hash(a);
    void *bytes = NULL;
    size_t len = 0;
    ENSURE(pl_world_save_state(a, &bytes, &len) == PL_OK);
    void *again = NULL;
    size_t len2 = 0;
    ENSURE(pl_world_save_state(a, &again, &len2) == PL_OK);
    ENSURE(len2 == len && memcmp(bytes, again, len) == 0); /* the same state gives the same bytes */
    pl_state_free(again);
    ENSURE(step(a, n - k));
    const uint64_t hn = pl_world_state_hash(a);
    ENSURE(step(a, 1));
    const uint64_t hn1 = pl_world_state_hash(a);
    pl_world_destroy(&a);

    pl_world *b = build();
    pl_status st = pl_world_load_state(b, bytes, len);
    if (st != PL_OK) fprintf(stderr, "load: %s\n", pl_world_last_error(b));
    ENSURE(st == PL_OK);
    ENSURE(pl_world_state_hash(b) == hk);
    ENSURE(k == 0 || hk != h0);
    ENSURE(pl_world_step_count(b) == k);
    ENSURE(step(b, n - k));
    fprintf(stderr, "  k = %d, N = %d: %zu bytes, hash %016llx (uninterrupted %016llx)\n", k, n, len,
            (unsigned long long)pl_world_state_hash(b), (unsigned long long)hn);
    ENSURE(pl_world_state_hash(b) == hn);
    ENSURE(hn != hn1);
    pl_world_destroy(&b);
    pl_state_free(bytes);
    return 0;
}

static int restart_dry(void) { return restart(dry, 300, 700); }
static int restart_seepage(void) { return restart(seepage, 101, 260); }
static int restart_pool(void) { return restart(pool, 37, 150); }
/* before the fluid's first update (mesh not built yet) */
static int restart_seepage_fresh(void) { return restart(seepage, 0, 40); }

/* save -> load in one world equals snapshot -> restore */
static int same_as_snapshot(void) {
    pl_world *w = seepage();
    ENSURE(step(w, 120));
    pl_snapshot *s = pl_world_snapshot(w);
    ENSURE(s);
    void *bytes = NULL;
    size_t len = 0;
    ENSURE(pl_world_save_state(w, &bytes, &len) == PL_OK);
    ENSURE(step(w, 50));
    const uint64_t h = pl_world_state_hash(w);
    ENSURE(pl_world_restore(w, s) == PL_OK);
    ENSURE(step(w, 50));
    const uint64_t hr = pl_world_state_hash(w);
    ENSURE(step(w, 31));
    ENSURE(pl_world_load_state(w, bytes, len) == PL_OK);
    ENSURE(step(w, 50));
    const uint64_t hf = pl_world_state_hash(w);
    ENSURE(hr == h);
    ENSURE(hf == h);
    pl_snapshot_destroy(&s);
    pl_state_free(bytes);
    pl_world_destroy(&w);
    return 0;
}

/* loads a bad image: the expected status, a message containing `what`, and w unchanged */
static int refused(pl_world *w, const void *bytes, size_t len, pl_status want, const char *what) {
    const uint64_t h = pl_world_state_hash(w);
    pl_status st = pl_world_load_state(w, bytes, len);
    if (st != want || !strstr(pl_world_last_error(w), what)) {
        fprintf(stderr, "  len %zu: status %d (want %d), message: %s (want '%s')\n", len, st, want,
                pl_world_last_error(w), what);
        return 1;
    }
    ENSURE(pl_world_state_hash(w) == h);
    return 0;
}

static int damaged_files(void) {
    pl_world *w = seepage();
    ENSURE(step(w, 60));
    void *bytes = NULL;
    size_t len = 0;
    ENSURE(pl_world_save_state(w, &bytes, &len) == PL_OK);
    pl_world *v = seepage(); /* the victim: loads must fail and leave it alone */
    ENSURE(step(v, 10));
    unsigned char *b = malloc(len);
    /* truncated: at every length up to the header's end, then at many points after */
    for (size_t cut = 0; cut < len; cut += cut < 80 ? 1 : 1 + len / 97) {
        ENSURE(refused(v, bytes, cut, PL_ERR_IO, "truncated") == 0);
    }
    ENSURE(refused(v, bytes, 40, PL_ERR_IO, "truncated") == 0);
    ENSURE(refused(v, bytes, len - 1, PL_ERR_IO, "truncated") == 0);
    /* one flipped bit: in the header, the grains section, the fluid section (and the last byte) */
    int flips = 0;
    for (size_t at = 0; at < len; at += at < 80 ? 3 : 1 + len / 61) {
        memcpy(b, bytes, len);
        b[at] ^= (unsigned char)(1u << (at % 8));
        pl_status st = pl_world_load_state(v, b, len);
        if (st != PL_ERR_IO && st != PL_ERR_STATE) fprintf(stderr, "  bit flip at byte %zu: status %d\n", at, st);
        ENSURE(st == PL_ERR_IO || st == PL_ERR_STATE);
        flips++;
    }
    memcpy(b, bytes, len);
    b[len - 1] ^= 0x10;
    ENSURE(refused(v, b, len, PL_ERR_IO, "fails its checksum") == 0);
    memcpy(b, bytes, len);
    b[200] ^= 0x01;
    ENSURE(refused(v, b, len, PL_ERR_IO, "section 'grains' fails its checksum") == 0);
    memcpy(b, bytes, len);
    b[30] ^= 0x04;
    ENSURE(refused(v, b, len, PL_ERR_IO, "header fails its checksum") == 0);
    memcpy(b, bytes, len);
    b[0] = 'X';
    ENSURE(refused(v, b, len, PL_ERR_IO, "not a porelab state file") == 0);
    /* another format version */
    memcpy(b, bytes, len);
    const uint32_t ver = 2;
    memcpy(b + 8, &ver, 4);
    ENSURE(refused(v, b, len, PL_ERR_STATE, "format version 2") == 0);
    /* another layout (header checksum made right again) */
    memcpy(b, bytes, len);
    b[16] ^= 0xff;
    const uint64_t sum = pl_hash_bytes(PL_HASH_SEED, b, 64);
    memcpy(b + 64, &sum, 8);
    ENSURE(refused(v, b, len, PL_ERR_STATE, "another state layout") == 0);
    /* header info */
    pl_state_info info;
    char err[256];
    ENSURE(pl_state_info_of(bytes, len, &info, err, sizeof err) == PL_OK);
    ENSURE(info.step == 60 && info.models == 1 && info.version == 1);
    ENSURE(pl_state_info_of(bytes, 20, &info, err, sizeof err) == PL_ERR_IO && strstr(err, "truncated"));
    /* another world */
    pl_world *other = grains(54);
    ENSURE(refused(other, bytes, len, PL_ERR_STATE, "this one has") == 0);
    pl_world_destroy(&other);
    /* and the victim still steps as its twin does */
    pl_world *twin = seepage();
    ENSURE(step(twin, 10) && step(twin, 30) && step(v, 30));
    ENSURE(pl_world_state_hash(twin) == pl_world_state_hash(v));
    /* a good load still works after all that */
    ENSURE(pl_world_load_state(v, bytes, len) == PL_OK);
    ENSURE(pl_world_step_count(v) == 60);
    fprintf(stderr, "  %zu bytes, %d flipped bits refused\n", len, flips);
    pl_world_destroy(&twin);
    pl_world_destroy(&v);
    pl_world_destroy(&w);
    free(b);
    pl_state_free(bytes);
    return 0;
}

int main(void) {
    RUN(restart_dry);
    RUN(restart_seepage);
    RUN(restart_pool);
    RUN(restart_seepage_fresh);
    RUN(same_as_snapshot);
    RUN(damaged_files);
    return pl_test_report();
}
