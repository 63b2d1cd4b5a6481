/* Hydrostatic water in a world (porelab/hydrostatic.h), against Archimedes and against the Darcy
 * model on the same scene. The tank of scenes/lab/buoyancy.lua: 0.40 m wide, water 0.30 m deep,
 * rho_f = 1000 kg/m^3, g = 9.81, Rayleigh damping alpha = 16 1/s, dt = 2e-4 s.
 * References:
 * - a floating block (rho_b < rho_f, upright, wide enough to be stable) settles at the draft
 *   d = (rho_b / rho_f) H: wood 0.07 x 0.04 (600: d = 0.024 m), ice 0.06 x 0.05 (920: 0.046 m),
 *   within 1e-6 of d (measured: 5e-12); a disc r = 0.025 m of density 300 floats with the submerged
 *   segment of central angle theta, theta - sin theta = 2 pi 0.3, draft r (1 - cos(theta / 2));
 * - the same scene with the Darcy model (16 x 12 quad, head 0 on the top line, FLUID_STORAGE 0,
 *   FLUID_SOLVE_TIMESTEPS 20, as the classroom scene did) gives the same drafts within 1e-9 relative (measured 2e-14; both
 *   models are exact here: P1 elements carry the linear hydrostatic pressure exactly and the
 *   Darcy outline integral is exact for straight edges and for discs);
 * - moving level: a block dropped into a narrow tank (0.10 m wide) raises the level by exactly
 *   its submerged area / width (1e-9), and that area is rho_b A / rho_f (1e-3);
 * - a pebble (rho 2650, r = 0.012) resting on the floor under water presses on it with its
 *   buoyant weight (rho_b - rho_f) g pi r^2 (1e-3);
 * - linear drag: a pebble sinking through water with drag beta (no other damping) reaches the
 *   terminal velocity (rho_b - rho_f) g / beta, whatever its size (1e-5);
 * - argument checks; snapshot and restore give the same state hash; the model's state image
 *   (save, load into a new instance) gives the same model hash, a truncated or damaged image is
 *   refused with a message. */
#include "harness.h"
#include "porelab/fluid.h"
#include "porelab/hydrostatic.h"
#include "porelab/world.h"
#include "world/image_internal.h"
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define TANK_W 0.40
#define WATER_H 0.30
#define DT 2e-4

enum { HYDRO = 0, DARCY = 1 };

static pl_world *tank(int model, double width, int moving) {
    pl_world_def wd = pl_default_world_def();
    wd.rayleigh_alpha = 16;
    wd.dt = DT;
    pl_world *w = pl_world_create(&wd);
    pl_material_def md = pl_default_material_def();
    md.name = "tank";
    md.density = 2500;
    md.kn = 2e5;
    md.friction = 0.4;
    md.restitution = 0.2;
    pl_world_add_material(w, &md);
    const pl_vec2 seg[3][2] = {{{-0.02, 0}, {width + 0.02, 0}}, {{0, 0}, {0, 0.42}}, {{width, 0}, {width, 0.42}}};
    for (int k = 0; k < 3; k++) {
        pl_body_def b = pl_default_body_def();
        b.shape = PL_SHAPE_SEGMENT;
        b.motion = PL_MOTION_FIXED;
        b.material = 0;
        b.a = seg[k][0];
        b.b = seg[k][1];
        pl_world_add_body(w, &b);
    }
    if (model == HYDRO) {
        pl_hydrostatic_def h = pl_default_hydrostatic_def();
        h.x_min = 0;
        h.x_max = width;
        h.bottom = 0;
        h.level = WATER_H;
        h.density = 1000;
        h.moving_level = moving;
        if (pl_world_attach_hydrostatic(w, &h) != PL_OK) fprintf(stderr, "%s\n", pl_world_last_error(w));
    } else {
        pl_fluid_quad_def q = pl_default_fluid_quad_def();
        q.corners[0] = (pl_vec2){0, 0};
        q.corners[1] = (pl_vec2){width, 0};
        q.corners[2] = (pl_vec2){width, WATER_H};
        q.corners[3] = (pl_vec2){0, WATER_H};
        q.ndivx = 16;
        q.ndivy = 12;
        pl_world_add_fluid_quad(w, &q);
        pl_world_add_fluid_bc(w, (pl_vec2){0, WATER_H}, (pl_vec2){width, WATER_H}, 0);
        const char *names[] = {"FLUIDS_ON", "FLUID_DENSITY", "FLUID_STORAGE", "FLUID_SOLVE_TIMESTEPS"};
        const double vals[] = {1, 1000, 0, 20};
        for (int k = 0; k < 4; k++)
            if (pl_world_set_flag(w, names[k], vals[k]) != PL_OK) fprintf(stderr, "%s\n", pl_world_last_error(w));
    }
    return w;
}

static int add_block(pl_world *w, const char *name, double rho, pl_vec2 c, double L, double H) {
    pl_material_def md = pl_default_material_def();
    md.name = name;
    md.density = rho;
    md.kn = 2e5;
    md.friction = 0.4;
    md.restitution = 0.2;
    const int m = pl_world_add_material(w, &md);
    const pl_vec2 v[4] = {{c.x - L / 2, c.y - H / 2}, {c.x + L / 2, c.y - H / 2}, {c.x + L / 2, c.y + H / 2},
                          {c.x - L / 2, c.y + H / 2}};
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_POLYGON;
    b.material = m;
    b.vertices = v;
    b.vertex_count = 4;
    return pl_world_add_body(w, &b);
}

static int run(pl_world *w, double T) {
    pl_status st = pl_world_step(w, (int)(T / DT + 0.5));
    if (st != PL_OK) fprintf(stderr, "step: %s\n", pl_world_last_error(w));
    return st == PL_OK ? 0 : 1;
}

/* the two blocks of the classroom scene; drafts from the water line (level at the end) */
static double drafts[2][3];

static int floating_blocks(int model) {
    pl_world *w = tank(model, TANK_W, 0);
    const double H[2] = {0.04, 0.05}, L[2] = {0.07, 0.06}, rho[2] = {600, 920};
    int b[2];
    b[0] = add_block(w, "wood", rho[0], (pl_vec2){0.10, WATER_H + 0.005}, L[0], H[0]);
    b[1] = add_block(w, "ice", rho[1], (pl_vec2){0.28, WATER_H + 0.005}, L[1], H[1]);
    ENSURE(b[0] >= 0 && b[1] >= 0);
    pl_material_def md = pl_default_material_def();
    md.name = "cork";
    md.density = 300;
    md.kn = 2e5;
    md.restitution = 0.2;
    pl_body_def bd = pl_default_body_def();
    bd.shape = PL_SHAPE_DISC;
    bd.material = pl_world_add_material(w, &md);
    bd.radius = 0.025;
    bd.position = (pl_vec2){0.19, WATER_H + 0.01};
    const int disc = pl_world_add_body(w, &bd);
    ENSURE(run(w, 3.0) == 0);
    const char *names[2] = {"hydrostatic", "Darcy"};
    for (int k = 0; k < 2; k++) {
        pl_body_info bi;
        pl_world_body_info(w, b[k], &bi);
        /* lowest point of the (nearly upright) block */
        pl_vec2 v[4];
        pl_world_body_vertices(w, b[k], v, 4);
        double ylo = v[0].y;
        for (int j = 1; j < 4; j++) ylo = fmin(ylo, v[j].y);
        const double d = WATER_H - ylo, dref = rho[k] / 1000 * H[k];
        drafts[model][k] = d;
        fprintf(stderr, "  %-11s %s block: draft %.6f m (Archimedes %.6f, error %.2e relative), angle %.1e rad\n",
                names[model], k ? "ice " : "wood", d, dref, fabs(d - dref) / dref, bi.angle);
        ENSURE_REL(d, dref, 1e-6);
    }
    double th = 2;
    for (int k = 0; k < 60; k++) th -= (th - sin(th) - 2 * PI * 0.3) / (1 - cos(th));
    const double dref = 0.025 * (1 - cos(th / 2));
    pl_body_info bi;
    pl_world_body_info(w, disc, &bi);
    const double d = WATER_H - (bi.position.y - 0.025);
    drafts[model][2] = d;
    fprintf(stderr, "  %-11s disc r 0.025, rho 300: draft %.6f m (theta - sin theta = 0.6 pi: %.6f, error %.2e relative)\n",
            names[model], d, dref, fabs(d - dref) / dref);
    ENSURE_REL(d, dref, 1e-6);
    pl_world_destroy(&w);
    return 0;
}

static int test_floating_block_hydrostatic(void) { return floating_blocks(HYDRO); }
static int test_floating_block_darcy(void) {
    if (floating_blocks(DARCY)) return 1;
    const char *what[3] = {"wood", "ice ", "disc"};
    for (int k = 0; k < 3; k++)
        fprintf(stderr, "  %s: Darcy - hydrostatic draft %+.3e m (%.2e relative)\n", what[k],
                drafts[DARCY][k] - drafts[HYDRO][k], fabs(drafts[DARCY][k] - drafts[HYDRO][k]) / drafts[HYDRO][k]);
    for (int k = 0; k < 3; k++) ENSURE_REL(drafts[DARCY][k], drafts[HYDRO][k], 1e-9);
    return 0;
}

static int test_moving_level(void) {
    const double width = 0.10, L = 0.06, H = 0.05, rho = 600;
    pl_world *w = tank(HYDRO, width, 1);
    const double L0 = pl_world_hydrostatic_level(w);
    const int b = add_block(w, "wood", rho, (pl_vec2){0.05, WATER_H + 0.06}, L, H); /* above the water */
    ENSURE(run(w, 4.0) == 0);
    const double L1 = pl_world_hydrostatic_level(w);
    pl_vec2 v[4];
    pl_world_body_vertices(w, b, v, 4);
    double ylo = v[0].y;
    for (int j = 1; j < 4; j++) ylo = fmin(ylo, v[j].y);
    pl_body_info bi;
    pl_world_body_info(w, b, &bi);
    const double a_sub = (L1 - ylo) * L; /* upright block */
    fprintf(stderr,
            "  moving level: %.6f -> %.9f m, rise x width %.9e m^2, submerged area %.9e m^2 (rho_b A / rho_f "
            "%.9e), angle %.1e\n",
            L0, L1, (L1 - L0) * width, a_sub, rho * L * H / 1000, bi.angle);
    ENSURE(fabs(bi.angle) < 1e-6);
    ENSURE_REL((L1 - L0) * width, a_sub, 1e-9);
    ENSURE_REL(a_sub, rho * L * H / 1000, 1e-3);
    /* the field the renderer draws (pl_world_field_sample, the model interface's field): the
       water body on linear triangles, p = rho_f g (level - y) exactly at every node */
    int nt = 0;
    const int nn = pl_world_field_sample(w, PL_FLUID_PRESSURE, NULL, NULL, NULL, 0, 0, &nt);
    ENSURE(nn >= 3 && nt >= 1);
    pl_vec2 xy[16];
    int32_t tri[48];
    double val[16];
    ENSURE(nn <= 16 && nt <= 16);
    ENSURE(pl_world_field_sample(w, PL_FLUID_PRESSURE, xy, tri, val, 16, 16, &nt) == nn);
    double area = 0;
    for (int i = 0; i < nn; i++) ENSURE_NEAR(val[i], 1000 * 9.81 * (L1 - xy[i].y), 1e-9 * 1000 * 9.81);
    for (int t = 0; t < nt; t++) {
        const pl_vec2 a = xy[tri[3 * t]], b2 = xy[tri[3 * t + 1]], c = xy[tri[3 * t + 2]];
        area += 0.5 * ((b2.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b2.y - a.y));
    }
    fprintf(stderr, "  drawn field: %d nodes, %d triangles, area %.9e m^2 (water body %.9e)\n", nn, nt, area,
            width * L1);
    ENSURE_REL(area, width * L1, 1e-12); /* the tank's bottom is at y = 0 */
    pl_world_destroy(&w);
    return 0;
}

static int test_sunk_pebble_contact_force(void) {
    pl_world *w = tank(HYDRO, TANK_W, 0);
    pl_material_def md = pl_default_material_def();
    md.name = "pebble";
    md.density = 2650;
    md.kn = 2e5;
    md.friction = 0.4;
    md.restitution = 0.2;
    const int m = pl_world_add_material(w, &md);
    const double r = 0.012;
    pl_body_def bd = pl_default_body_def();
    bd.shape = PL_SHAPE_DISC;
    bd.material = m;
    bd.radius = r;
    bd.position = (pl_vec2){0.2, 0.1};
    const int b = pl_world_add_body(w, &bd);
    ENSURE(run(w, 2.0) == 0);
    pl_contact_info c[8];
    const int nc = pl_world_copy_contacts(w, c, 8);
    double fn = 0;
    for (int k = 0; k < nc; k++)
        if (c[k].a == b || c[k].b == b) fn += c[k].fn;
    const double ref = (2650 - 1000) * 9.81 * PI * r * r;
    fprintf(stderr, "  sunk pebble: contact force %.6f N (buoyant weight (rho_b - rho_f) g A = %.6f N), %d contact(s)\n",
            fn, ref, nc);
    ENSURE_REL(fn, ref, 1e-3);
    pl_world_destroy(&w);
    return 0;
}

static int test_drag_terminal_velocity(void) {
    pl_world_def wd = pl_default_world_def();
    wd.dt = DT;
    pl_world *w = pl_world_create(&wd);
    pl_hydrostatic_def h = pl_default_hydrostatic_def();
    h.x_max = 1;
    h.level = 1;
    h.drag = 2e5;
    ENSURE(pl_world_attach_hydrostatic(w, &h) == PL_OK);
    pl_material_def md = pl_default_material_def();
    md.name = "pebble";
    md.density = 2650;
    md.kn = 2e5;
    const int m = pl_world_add_material(w, &md);
    const double radii[2] = {0.012, 0.03};
    int b[2];
    for (int k = 0; k < 2; k++) {
        pl_body_def bd = pl_default_body_def();
        bd.shape = PL_SHAPE_DISC;
        bd.material = m;
        bd.radius = radii[k];
        bd.position = (pl_vec2){0.25 + 0.5 * k, 0.8};
        b[k] = pl_world_add_body(w, &bd);
    }
    ENSURE(run(w, 0.2) == 0); /* 15 time constants rho_b / beta = 0.013 s */
    const double vt = -(2650 - 1000) * 9.81 / 2e5;
    for (int k = 0; k < 2; k++) {
        pl_body_info bi;
        pl_world_body_info(w, b[k], &bi);
        fprintf(stderr, "  drag 2e5 N s/m^3, r = %.3f m: sinking at %.7f m/s (terminal (rho_b - rho_f) g / beta = %.7f)\n",
                radii[k], bi.velocity.y, vt);
        ENSURE_REL(bi.velocity.y, vt, 1e-5);
        ENSURE(fabs(bi.velocity.x) < 1e-12 && fabs(bi.omega) < 1e-12);
    }
    pl_world_destroy(&w);
    return 0;
}

static int test_checks_and_snapshot(void) {
    pl_world_def wd = pl_default_world_def();
    pl_world *w = pl_world_create(&wd);
    pl_hydrostatic_def h = pl_default_hydrostatic_def();
    h.x_max = -1;
    ENSURE(pl_world_attach_hydrostatic(w, &h) == PL_ERR_ARG);
    fprintf(stderr, "  x_max <= x_min: %s\n", pl_world_last_error(w));
    ENSURE(strstr(pl_world_last_error(w), "x_max"));
    h = pl_default_hydrostatic_def();
    h.level = -0.1;
    ENSURE(pl_world_attach_hydrostatic(w, &h) == PL_ERR_ARG);
    fprintf(stderr, "  level below the bottom: %s\n", pl_world_last_error(w));
    h = pl_default_hydrostatic_def();
    h.density = -5;
    ENSURE(pl_world_attach_hydrostatic(w, &h) == PL_ERR_ARG);
    fprintf(stderr, "  density: %s\n", pl_world_last_error(w));
    ENSURE(strstr(pl_world_last_error(w), "density must be"));
    h = pl_default_hydrostatic_def();
    h.moving_level = 2;
    ENSURE(pl_world_attach_hydrostatic(w, &h) == PL_ERR_ARG);
    ENSURE(!pl_world_has_hydrostatic(w));
    h = pl_default_hydrostatic_def();
    ENSURE(pl_world_attach_hydrostatic(w, &h) == PL_OK);
    ENSURE(pl_world_attach_hydrostatic(w, &h) == PL_ERR_STATE);
    fprintf(stderr, "  second attach: %s\n", pl_world_last_error(w));
    ENSURE_NEAR(pl_world_hydrostatic_pressure(w, (pl_vec2){0.5, 0.1}), 1000 * 9.81 * 0.4, 1e-9);
    ENSURE(pl_world_hydrostatic_pressure(w, (pl_vec2){0.5, 0.6}) == 0);
    ENSURE(pl_world_hydrostatic_pressure(w, (pl_vec2){1.5, 0.1}) == 0);
    pl_world_destroy(&w);
    /* snapshot / restore / hash over a moving-level run */
    w = tank(HYDRO, 0.1, 1);
    add_block(w, "wood", 600, (pl_vec2){0.05, WATER_H + 0.03}, 0.06, 0.05);
    ENSURE(run(w, 0.1) == 0);
    pl_snapshot *s = pl_world_snapshot(w);
    ENSURE(s != NULL);
    ENSURE(run(w, 0.1) == 0);
    const uint64_t h1 = pl_world_state_hash(w);
    const double lv1 = pl_world_hydrostatic_level(w);
    ENSURE(pl_world_restore(w, s) == PL_OK);
    ENSURE(run(w, 0.1) == 0);
    ENSURE(pl_world_state_hash(w) == h1);
    ENSURE(pl_world_hydrostatic_level(w) == lv1);
    /* redefine: a denser water lifts the block */
    pl_hydrostatic_def cur;
    ENSURE(pl_world_hydrostatic_def(w, &cur) == PL_OK);
    cur.density = 2000;
    ENSURE(pl_world_hydrostatic_redefine(w, &cur) == PL_OK);
    ENSURE(pl_world_state_hash(w) != h1);
    pl_snapshot_destroy(&s);
    pl_world_destroy(&w);
    return 0;
}

static int test_image_round_trip(void) {
    pl_world *w = tank(HYDRO, 0.1, 1);
    add_block(w, "wood", 600, (pl_vec2){0.05, WATER_H + 0.03}, 0.06, 0.05);
    ENSURE(run(w, 0.2) == 0);
    const pl_model_class *cls = &pl_hydrostatic_class;
    void *self = pl__world_model(w, cls);
    ENSURE(self != NULL);
    pl_image img = {0};
    ENSURE(cls->save(self, &img) == PL_OK);
    void *copy = cls->create();
    ENSURE(copy != NULL);
    ENSURE(cls->load(copy, w, &img) == PL_OK);
    ENSURE(cls->hash(copy, 1) == cls->hash(self, 1));
    fprintf(stderr, "  image: %zu bytes, loaded copy has the same hash\n", img.len);
    /* truncated */
    img.pos = 0;
    img.len -= 2;
    ENSURE(cls->load(copy, w, &img) == PL_ERR_IO);
    /* damaged: the density (5th double) made negative */
    img.len += 2;
    img.pos = 0;
    img.failed = 0;
    double rho;
    memcpy(&rho, img.data + 4 * sizeof(double), sizeof rho);
    rho = -rho;
    memcpy(img.data + 4 * sizeof(double), &rho, sizeof rho);
    ENSURE(cls->load(copy, w, &img) == PL_ERR_IO);
    fprintf(stderr, "  damaged image: %s\n", pl_world_last_error(w));
    ENSURE(strstr(pl_world_last_error(w), "damaged"));
    cls->destroy(copy);
    pl__image_free(&img);
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(test_image_round_trip);
    RUN(test_checks_and_snapshot);
    RUN(test_floating_block_hydrostatic);
    RUN(test_floating_block_darcy);
    RUN(test_moving_level);
    RUN(test_sunk_pebble_contact_force);
    RUN(test_drag_terminal_velocity);
    return pl_test_report();
}
