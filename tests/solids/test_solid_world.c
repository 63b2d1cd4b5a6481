/* The solid model in a world (porelab/solid.h) with discs:
 * - the world's automatic step includes the solid's critical step (dt = dt_safety x dt_crit),
 *   and a fixed step beyond it stops the run with a message naming the critical step;
 * - a disc resting on an elastic block: the contact force on the block equals the disc's weight
 *   m g (1 %), and the penetration r - d equals m g / k_n (2 %) (spring law, seed 002 eq. 106);
 * - a disc dropped on a stiff block bounces with the restitution of the linear spring-dashpot,
 *   e = exp(-zeta pi / sqrt(1 - zeta^2)), zeta = c_n / (2 sqrt(m k_n)) (3 %);
 * - coupled energy: without damping, the disc's kinetic energy before impact equals, after
 *   rebound, the disc's kinetic energy plus the solid's kinetic and elastic energy (1 %);
 * - determinism: a snapshot/restore and a save/load resume reproduce the state hash bit for bit. */
#include "harness.h"
#include "porelab/solid.h"
#include "porelab/bonds.h"
#include "porelab/world.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double build_friction = 0; /* solid's friction coefficient in build() */
static int build_prescribed = 0;  /* 1: the disc follows its initial velocity */

typedef struct scene {
    pl_world *w;
    int disc;
    double mass, r;
} scene;

/* Block [0,1] x [0,0.2] fixed at the bottom, a disc of radius r above its middle. */
static int build(scene *sc, double gy, double young, double cn, double dt_fixed, double disc_y, double vy,
                 double solid_damping) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, gy};
    wd.dt = dt_fixed;
    wd.dt_safety = 0.5;
    sc->w = pl_world_create(&wd);
    pl_material_def md = pl_default_material_def();
    md.name = "sand";
    md.density = 2000;
    md.kn = 1e7;
    const int mat = pl_world_add_material(sc->w, &md);
    pl_body_def bd = pl_default_body_def();
    bd.shape = PL_SHAPE_DISC;
    bd.motion = build_prescribed ? PL_MOTION_PRESCRIBED : PL_MOTION_DYNAMIC;
    bd.material = mat;
    sc->r = 0.05;
    bd.radius = sc->r;
    bd.position = (pl_vec2){0.5, disc_y};
    bd.velocity = (pl_vec2){0, vy};
    sc->disc = pl_world_add_body(sc->w, &bd);
    if (mat < 0 || sc->disc < 0) {
        fprintf(stderr, "%s\n", pl_world_last_error(sc->w));
        return 1;
    }
    pl_body_info bi;
    pl_world_body_info(sc->w, sc->disc, &bi);
    sc->mass = bi.mass;
    pl_solid_def sd = pl_default_solid_def();
    sd.young = young;
    sd.poisson = 0.3;
    sd.density = 2000;
    sd.contact_stiffness = 1e6;
    sd.contact_damping = cn;
    sd.damping = solid_damping;
    sd.friction = build_friction;
    if (pl_world_attach_solid(sc->w, &sd) != PL_OK) {
        fprintf(stderr, "%s\n", pl_world_last_error(sc->w));
        return 1;
    }
    if (pl_world_solid_rectangle(sc->w, 0, 0, 1, 0.2, 20, 4) < 0) {
        fprintf(stderr, "%s\n", pl_world_last_error(sc->w));
        return 1;
    }
    if (pl_world_solid_fix(sc->w, -1, -1e-9, 2, 1e-9, 3) < 0) {
        fprintf(stderr, "%s\n", pl_world_last_error(sc->w));
        return 1;
    }
    return 0;
}

static int test_world_step_includes_solid(void) {
    scene sc;
    ENSURE(build(&sc, 0, 1e9, 0, 0, 0.5, 0, 0) == 0);
    const pl_dt_report r = pl_world_dt_report(sc.w);
    int e;
    const double crit = pl_world_solid_critical_dt(sc.w, &e);
    fprintf(stderr, "world step %.4g s, critical %.4g s (%s), solid element bound %.4g s\n", r.dt, r.dt_critical,
            r.limit_kind, crit);
    ENSURE(strcmp(r.limit_kind, "solid") == 0);
    ENSURE(r.dt_critical <= crit);
    ENSURE_REL(r.dt, 0.5 * r.dt_critical, 1e-12);
    pl_world_destroy(&sc.w);
    /* a fixed step past the solid's limit: the run stops with the message */
    ENSURE(build(&sc, 0, 1e9, 0, 2 * crit, 0.5, 0, 0) == 0);
    ENSURE(pl_world_step(sc.w, 10) == PL_ERR_UNSTABLE);
    fprintf(stderr, "fixed step past the limit: %s\n", pl_world_last_error(sc.w));
    ENSURE(strstr(pl_world_last_error(sc.w), "critical step") != NULL);
    pl_world_destroy(&sc.w);
    return 0;
}

static int test_disc_rests(void) {
    scene sc;
    const double g = 9.81;
    ENSURE(build(&sc, -g, 1e8, 200, 0, 0.2 + 0.05, 0, 200) == 0);
    ENSURE(pl_world_step(sc.w, 40000) == PL_OK);
    const pl_vec2 F = pl_world_solid_contact_force(sc.w);
    pl_body_info bi;
    pl_world_body_info(sc.w, sc.disc, &bi);
    pl_vec2 u;
    pl_world_solid_displacement(sc.w, (pl_vec2){0.5, 0.2}, &u);
    const double pen = sc.r - (bi.position.y - (0.2 + u.y));
    const double W = sc.mass * g;
    fprintf(stderr, "disc at rest: contact force %.6g N/m (weight %.6g), penetration %.6g m (m g / k_n = %.6g), top "
                    "node moved %.3g m\n",
            -F.y, W, pen, W / 1e6, u.y);
    pl_validation("solids.rest", "disc resting on an elastic block: contact force, penetration",
                  "m g; m g / k_n (eq. 106)", "1 %; 2 %", "F %.5g vs %.5g N/m, delta %.4g vs %.4g m", -F.y, W, pen,
                  W / 1e6);
    ENSURE_REL(-F.y, W, 0.01);
    ENSURE_REL(pen, W / 1e6, 0.02);
    pl_world_destroy(&sc.w);
    return 0;
}

/* A disc bonded to the block's top and pulled off by a suddenly applied upward load m g (gravity
   pointing up): the bond is a linear spring, so the tension peaks at 2 m g (step load on an
   undamped spring, closed form); the brittle law breaks it when the tension passes R_n. With
   R_n = 1.9 m g it breaks, with R_n = 2.1 m g it holds (the 5 % margins cover the block's own
   compliance and the step's sampling of the peak). */
static int pull_off(double rn_over_w, int *broke, double *nmax) {
    scene sc;
    const double g = 9.81;
    ENSURE(build(&sc, g, 1e10, 0, 0, 0.2 + 0.05, 0, 0) == 0);
    pl_bond_def bd = pl_default_bond_def();
    bd.kn = 1e6;
    bd.rn = rn_over_w * sc.mass * g;
    bd.rt = 1e9;
    const int made = pl_world_solid_bond(sc.w, &bd, 1e-6);
    if (made != 1) fprintf(stderr, "solid_bond: %d (%s)\n", made, pl_world_last_error(sc.w));
    ENSURE(made == 1);
    *nmax = 0;
    for (int k = 0; k < 400; k++) {
        ENSURE(pl_world_step(sc.w, 10) == PL_OK);
        pl_bond_info bi;
        ENSURE(pl_world_solid_bonds(sc.w, &bi, 1) == 1);
        if (bi.state == PL_BOND_INTACT && bi.n > *nmax) *nmax = bi.n;
    }
    int intact;
    pl_world_solid_bond_count(sc.w, &intact);
    *broke = intact == 0;
    *nmax /= sc.mass * g;
    pl_world_destroy(&sc.w);
    return 0;
}

static int test_bond_pull_off(void) {
    int b1, b2;
    double n1, n2;
    ENSURE(pull_off(1.9, &b1, &n1) == 0);
    ENSURE(pull_off(2.1, &b2, &n2) == 0);
    fprintf(stderr, "bonded disc under a step load m g: R_n = 1.9 m g %s (largest tension %.4f m g), R_n = 2.1 m g "
                    "%s (largest tension %.4f m g)\n",
            b1 ? "broke" : "held", n1, b2 ? "broke" : "held", n2);
    pl_validation("solids.bond_pull_off", "disc bonded to an element edge, step load m g: peak tension, break",
                  "2 m g (step load on a linear spring); breaks iff R_n < 2 m g", "2 %",
                  "peak %.4f m g; R_n 1.9 m g %s, 2.1 m g %s", n2, b1 ? "broke" : "held", b2 ? "broke" : "held");
    ENSURE(b1 && !b2);
    ENSURE_REL(n2, 2.0, 0.02);
    return 0;
}

/* A disc pressed into the block by delta and driven along its top at v: F_n = k_n delta,
   F_t = mu F_n tanh(v / v_e); over a time T the friction work is W = F_t v T, the heat the
   solid receives alpha W / 2 (half to each side, the grains' law) and its Archard wear
   k F_n v T / H (closed forms; 1 %: the block's deflection changes delta by k_n / E ~ 1e-4). */
static int test_heat_wear(void) {
    scene sc;
    build_friction = 0.5;
    build_prescribed = 1;
    const double delta = 1e-4, v = 0.1, alpha = 0.8, kw = 1e-3, H = 1e8;
    const int bad = build(&sc, 0, 1e10, 0, 0, 0.2 + 0.05 - delta, 0, 0);
    build_friction = 0;
    build_prescribed = 0;
    ENSURE(bad == 0);
    pl_world_set_body_velocity(sc.w, sc.disc, (pl_vec2){v, 0}, 0);
    pl_thermal_def th = pl_default_thermal_def();
    th.heat_capacity = 500;
    th.wear = kw;
    th.hardness = H;
    ENSURE(pl_world_solid_thermal(sc.w, &th, alpha, 293.15) == PL_OK);
    const double t0 = pl_world_time(sc.w);
    ENSURE(pl_world_step(sc.w, 2000) == PL_OK);
    const double T = pl_world_time(sc.w) - t0;
    double q, wv, tmax;
    ENSURE(pl_world_solid_thermal_totals(sc.w, &q, &wv, &tmax) == PL_OK);
    const double Fn = 1e6 * delta, Ft = 0.5 * Fn * tanh(v / 1e-3);
    const double qx = 0.5 * alpha * Ft * v * T, wx = kw * Fn * v * T / H;
    fprintf(stderr, "sliding disc over %.4g s: solid heat %.6g J/m (alpha W/2 = %.6g), wear %.6g m^2/m (k F_n s / H = "
                    "%.6g), hottest node %.5g K\n",
            T, q, qx, wv, wx, tmax);
    pl_validation("solids.heat_wear", "disc sliding on an element edge: heat and Archard wear of the element side",
                  "alpha mu F_n v T / 2; k F_n v T / H", "1 %", "heat %.5g vs %.5g J/m, wear %.5g vs %.5g m^2/m", q, qx,
                  wv, wx);
    ENSURE_REL(q, qx, 0.01);
    ENSURE_REL(wv, wx, 0.01);
    pl_world_destroy(&sc.w);
    return 0;
}

/* Steps until the grain has touched the block and left it moving up (at most 200000 steps);
   bi gets the grain's state at that step. Returns 0, or 1 with the world's message. */
static int step_until_rebound(pl_world *w, int disc, pl_body_info *bi) {
    int touched = 0;
    for (int k = 0; k < 200000; k++) {
        if (pl_world_step(w, 1) != PL_OK) {
            fprintf(stderr, "%s\n", pl_world_last_error(w));
            return 1;
        }
        pl_world_body_info(w, disc, bi);
        const pl_vec2 F = pl_world_solid_contact_force(w);
        if (F.y != 0) touched = 1;
        if (touched && F.y == 0 && bi->velocity.y > 0) return 0;
    }
    return 0;
}

/* Drop at v0 onto the block; returns the rebound speed ratio and the energy terms. */
static int bounce(double cn, double young, double *e, double *ke0, double *eend, double *zeta) {
    scene sc;
    const double v0 = 1.0;
    if (build(&sc, 0, young, cn, 0, 0.2 + 0.05 + 0.002, -v0, 0)) return 1;
    *zeta = cn / (2 * sqrt(sc.mass * 1e6));
    *ke0 = 0.5 * sc.mass * v0 * v0;
    pl_body_info bi;
    if (step_until_rebound(sc.w, sc.disc, &bi)) return 1;
    *e = bi.velocity.y / v0;
    pl_solid_energy se;
    pl_world_solid_energy(sc.w, &se);
    *eend = 0.5 * sc.mass * (bi.velocity.x * bi.velocity.x + bi.velocity.y * bi.velocity.y) + se.kinetic + se.elastic;
    pl_world_destroy(&sc.w);
    return 0;
}

static int test_bounce(void) {
    double e, ke0, eend, zeta;
    ENSURE(bounce(1000, 1e11, &e, &ke0, &eend, &zeta) == 0);
    const double eref = exp(-zeta * M_PI / sqrt(1 - zeta * zeta));
    fprintf(stderr, "bounce: e = %.4f (spring-dashpot %.4f, zeta %.3f)\n", e, eref, zeta);
    pl_validation("solids.bounce", "disc dropped on a stiff block: restitution",
                  "exp(-zeta pi / sqrt(1 - zeta^2)), zeta = c_n / (2 sqrt(m k_n))", "3 %", "e = %.4f vs %.4f", e,
                  eref);
    ENSURE_REL(e, eref, 0.03);
    ENSURE(bounce(0, 1e8, &e, &ke0, &eend, &zeta) == 0);
    fprintf(stderr, "coupled energy: disc KE before %.6g J/m, after: disc KE + solid KE + elastic = %.6g J/m (disc "
                    "rebound %.3f)\n",
            ke0, eend, e);
    pl_validation("solids.energy", "disc on a soft elastic block, no damping: energy after rebound",
                  "disc kinetic energy before impact", "1 %", "%.5g vs %.5g J/m (%.2f %%)", eend, ke0,
                  100 * (eend - ke0) / ke0);
    ENSURE_REL(eend, ke0, 0.01);
    return 0;
}

/* A square grain (side 0.1 m, density 2000) above the middle of the block, flat face down. */
static int build_square(scene *sc, double gy, double young, double cn, double bottom, double vy, double solid_damping) {
    if (build(sc, gy, young, cn, 0, 0.6, 0, solid_damping)) return 1;
    /* the scene's disc moved aside, away from the block and the square (free fall) */
    pl_world_set_body_position(sc->w, sc->disc, (pl_vec2){3, 0.6}, 0);
    pl_material_def md = pl_default_material_def();
    md.name = "rock";
    md.density = 2000;
    md.kn = 1e7;
    const int mat = pl_world_add_material(sc->w, &md);
    const double h = 0.05;
    const pl_vec2 v[4] = {{0.5 - h, bottom}, {0.5 + h, bottom}, {0.5 + h, bottom + 2 * h}, {0.5 - h, bottom + 2 * h}};
    pl_body_def bd = pl_default_body_def();
    bd.shape = PL_SHAPE_POLYGON;
    bd.motion = PL_MOTION_DYNAMIC;
    bd.material = mat;
    bd.vertices = v;
    bd.vertex_count = 4;
    bd.velocity = (pl_vec2){0, vy};
    sc->disc = pl_world_add_body(sc->w, &bd);
    if (mat < 0 || sc->disc < 0) {
        fprintf(stderr, "%s\n", pl_world_last_error(sc->w));
        return 1;
    }
    pl_body_info bi;
    pl_world_body_info(sc->w, sc->disc, &bi);
    sc->mass = bi.mass;
    return 0;
}

/* Polygon grains against the element edges: a square resting flat on the block carries its
   weight on its two lower vertices (force m g, each vertex in by m g / (2 k_n)); dropped flat,
   it rebounds with the restitution of two spring-dashpots in parallel,
   e = exp(-zeta pi / sqrt(1 - zeta^2)), zeta = 2 c_n / (2 sqrt(2 k_n m)). The disc of the
   scene is moved aside (it falls freely beside the block). */
static int test_polygon_rest_bounce(void) {
    scene sc;
    const double g = 9.81, kn = 1e6;
    ENSURE(build_square(&sc, -g, 1e8, 2000, 0.2, 0, 200) == 0);
    ENSURE(pl_world_step(sc.w, 40000) == PL_OK);
    pl_body_info bi;
    pl_world_body_info(sc.w, sc.disc, &bi);
    pl_vec2 u;
    pl_world_solid_displacement(sc.w, (pl_vec2){0.45, 0.2}, &u);
    const pl_vec2 F = pl_world_solid_contact_force(sc.w);
    const double W = sc.mass * g;
    const double pen = (0.2 + u.y) - (bi.position.y - 0.05);
    fprintf(stderr, "square at rest: contact force %.6g N/m (weight %.6g), vertex penetration %.6g m (m g / (2 k_n) "
                    "= %.6g), angle %.2g rad\n",
            -F.y, W, pen, W / (2 * kn), bi.angle);
    pl_validation("solids.polygon_rest", "square grain resting flat on an elastic block: contact force, penetration",
                  "m g; m g / (2 k_n) (two vertices)", "1 %; 3 %", "F %.5g vs %.5g N/m, delta %.4g vs %.4g m", -F.y,
                  W, pen, W / (2 * kn));
    ENSURE_REL(-F.y, W, 0.01);
    ENSURE_REL(pen, W / (2 * kn), 0.03);
    ENSURE(fabs(bi.angle) < 1e-3);
    pl_world_destroy(&sc.w);
    /* bounce, no gravity: a stiff block so that the grain's springs dominate */
    const double cn = 300, v0 = 1.0;
    ENSURE(build_square(&sc, 0, 1e11, cn, 0.2 + 0.002, -v0, 0) == 0);
    if (step_until_rebound(sc.w, sc.disc, &bi)) return 1;
    const double zeta = 2 * cn / (2 * sqrt(2 * kn * sc.mass));
    const double eref = exp(-zeta * M_PI / sqrt(1 - zeta * zeta)), e = bi.velocity.y / v0;
    fprintf(stderr, "square bounce: e = %.4f (two spring-dashpots %.4f, zeta %.3f), spin after %.2g rad/s\n", e, eref,
            zeta, bi.omega);
    pl_validation("solids.polygon_bounce", "square grain dropped flat on a block: restitution",
                  "exp(-zeta pi / sqrt(1 - zeta^2)), zeta = c_n / sqrt(2 k_n m)", "5 %", "e = %.4f vs %.4f", e, eref);
    ENSURE_REL(e, eref, 0.05);
    ENSURE(fabs(bi.omega) < 1e-2); /* the alternating-diagonal mesh is not exactly symmetric */
    pl_world_destroy(&sc.w);
    return 0;
}

static int test_hash_resume(void) {
    scene a;
    ENSURE(build(&a, 0, 1e8, 100, 0, 0.26, -0.5, 0) == 0);
    if (pl_world_step(a.w, 3000) != PL_OK) {
        fprintf(stderr, "%s\n", pl_world_last_error(a.w));
        return 1;
    }
    pl_snapshot *snap = pl_world_snapshot(a.w);
    void *bytes = NULL;
    size_t len = 0;
    ENSURE(snap && pl_world_save_state(a.w, &bytes, &len) == PL_OK);
    if (pl_world_step(a.w, 3000) != PL_OK) {
        fprintf(stderr, "%s\n", pl_world_last_error(a.w));
        return 1;
    }
    const uint64_t h_ref = pl_world_state_hash(a.w);
    ENSURE(pl_world_restore(a.w, snap) == PL_OK);
    ENSURE(pl_world_step(a.w, 3000) == PL_OK);
    const uint64_t h_restore = pl_world_state_hash(a.w);
    scene b;
    ENSURE(build(&b, 0, 1e8, 100, 0, 0.26, -0.5, 0) == 0);
    ENSURE(pl_world_load_state(b.w, bytes, len) == PL_OK);
    ENSURE(pl_world_step(b.w, 3000) == PL_OK);
    const uint64_t h_load = pl_world_state_hash(b.w);
    /* and the solid is in the hash: a nudge of a solid parameter-free state changes it */
    scene c;
    ENSURE(build(&c, 0, 1e8, 100, 0, 0.26, -0.5, 0) == 0);
    ENSURE(pl_world_step(c.w, 6000) == PL_OK);
    const uint64_t h_fresh = pl_world_state_hash(c.w);
    fprintf(stderr, "hash: reference %016llx, restore %016llx, load %016llx, fresh run %016llx\n",
            (unsigned long long)h_ref, (unsigned long long)h_restore, (unsigned long long)h_load,
            (unsigned long long)h_fresh);
    ENSURE(h_ref == h_restore && h_ref == h_load && h_ref == h_fresh);
    pl_snapshot_destroy(&snap);
    pl_state_free(bytes);
    pl_world_destroy(&a.w);
    pl_world_destroy(&b.w);
    pl_world_destroy(&c.w);
    return 0;
}

int main(void) {
    RUN(test_world_step_includes_solid);
    RUN(test_disc_rests);
    RUN(test_bond_pull_off);
    RUN(test_heat_wear);
    RUN(test_bounce);
    RUN(test_polygon_rest_bounce);
    RUN(test_hash_resume);
    return pl_test_report();
}
