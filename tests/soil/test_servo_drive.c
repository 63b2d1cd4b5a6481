/* The servo extras of engine/src/dem/servo_drive.c used by the simple-shear scene
 * (docs/soil.md §5.4): a servo body (a polygon lid) pressing on a disc that rests on a floor,
 * with a drive velocity across the servo direction.
 * 1. The lid moves across at exactly the drive velocity (its component along the servo direction
 *    is removed) and the servo still holds the target force within 1%.
 * 2. A drive on a body that is not a servo is refused with PL_ERR_STATE.
 * 3. with_fluid and no fluid model: the same motion as without (the fluid term is skipped). */
#include "harness.h"
#include "porelab/world.h"
#include <math.h>
#include <stdio.h>

typedef struct rig { pl_world *w; int lid, disc; } rig;

static rig make(void) {
    rig r;
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, 0};
    wd.dt = 2e-6;
    r.w = pl_world_create(&wd);
    pl_material_def md = pl_default_material_def();
    md.name = "m";
    md.density = 2000;
    md.kn = 1e7;
    md.friction = 0; /* the disc must not be dragged along */
    md.restitution = 0.5;
    int m = pl_world_add_material(r.w, &md);
    pl_body_def s = pl_default_body_def();
    s.shape = PL_SHAPE_SEGMENT;
    s.motion = PL_MOTION_FIXED;
    s.material = m;
    s.a = (pl_vec2){-1, 0};
    s.b = (pl_vec2){1, 0};
    pl_world_add_body(r.w, &s);
    pl_body_def d = pl_default_body_def();
    d.shape = PL_SHAPE_DISC;
    d.material = m;
    d.radius = 0.01;
    d.position = (pl_vec2){0, 0.01};
    r.disc = pl_world_add_body(r.w, &d);
    pl_vec2 v[4] = {{-0.05, 0.0201}, {0.05, 0.0201}, {0.05, 0.0301}, {-0.05, 0.0301}};
    pl_body_def p = pl_default_body_def();
    p.shape = PL_SHAPE_POLYGON;
    p.material = m;
    p.vertices = v;
    p.vertex_count = 4;
    p.motion = PL_MOTION_FIXED;
    r.lid = pl_world_add_body(r.w, &p);
    return r;
}

static int run_drive(int with_fluid, double *vx, double *fy) {
    rig r = make();
    const double F = 200; /* N/m */
    ENSURE(pl_world_set_servo(r.w, r.lid, (pl_vec2){0, -1}, F, 0.05, 0.05) == PL_OK);
    ENSURE(pl_world_set_servo_drive(r.w, r.lid, (pl_vec2){0.02, 0.5}, with_fluid) == PL_OK);
    pl_body_info a, b;
    ENSURE(pl_world_step(r.w, 20000) == PL_OK); /* 0.04 s: the servo settles */
    pl_world_body_info(r.w, r.lid, &a);
    ENSURE(pl_world_step(r.w, 5000) == PL_OK);
    pl_world_body_info(r.w, r.lid, &b);
    *vx = (b.position.x - a.position.x) / (5000 * 2e-6);
    *fy = b.force.y;
    fprintf(stderr, "  with_fluid %d: lid vx = %.6f m/s (drive 0.02), contact force %.2f N/m (target %.0f)\n", with_fluid, *vx,
            *fy, F);
    ENSURE_NEAR(*vx, 0.02, 1e-9);
    ENSURE_NEAR(*fy, F, 0.01 * F);
    pl_world_destroy(&r.w);
    return 0;
}

static int drive_across_servo(void) {
    double vx, fy;
    ENSURE(run_drive(0, &vx, &fy) == 0);
    return 0;
}

static int drive_needs_servo(void) {
    rig r = make();
    ENSURE(pl_world_set_servo_drive(r.w, r.lid, (pl_vec2){0.02, 0}, 0) == PL_ERR_STATE);
    fprintf(stderr, "  refused: %s\n", pl_world_last_error(r.w));
    pl_world_destroy(&r.w);
    return 0;
}

static int fluid_flag_without_fluid(void) {
    double vx0, fy0, vx1, fy1;
    ENSURE(run_drive(0, &vx0, &fy0) == 0);
    ENSURE(run_drive(1, &vx1, &fy1) == 0);
    ENSURE(vx0 == vx1 && fy0 == fy1);
    return 0;
}

int main(void) {
    RUN(drive_across_servo);
    RUN(drive_needs_servo);
    RUN(fluid_flag_without_fluid);
    return pl_test_report();
}
