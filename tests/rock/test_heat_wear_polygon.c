/* Frictional heat, Archard wear and conduction on polygon contacts (seed 002 §4 with the
 * polygon area law of seed 004; docs/rock.md "Heat" and "Wear"), against the same closed forms
 * as the disc tests (test_heat_wear):
 *  - sliding: a square block, guided vertically and loaded by F, lies on a wall that slides
 *    under it at v; once the block has settled (global damping on its vertical motion) the
 *    normal force is F and the Coulomb force mu F, so each body receives alpha mu F v / 2 per
 *    second, and the block's Archard wear grows at k F v / H;
 *  - conduction: a block pressed onto a fixed block held at its temperature (a
 *    reservoir) cools as exp(-H t / C), H = k_th w / d with w the contact width (the face)
 *    and d the centre distance. */
#include "harness.h"
#include "porelab/bonds.h"
#include "porelab/world.h"
#include <math.h>
#include <string.h>

#define DT 1e-6
#define W 4e-3 /* block width, m */
#define HB 2e-3 /* block height, m */

static int add_block(pl_world *w, int mat, double x, double y, pl_motion_type mo) {
    const pl_vec2 v[4] = {{x - W / 2, y - HB / 2}, {x + W / 2, y - HB / 2}, {x + W / 2, y + HB / 2}, {x - W / 2, y + HB / 2}};
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_POLYGON;
    b.material = mat;
    b.vertices = v;
    b.vertex_count = 4;
    b.motion = mo;
    if (mo == PL_MOTION_DYNAMIC) b.guide = (pl_vec2){0, 1};
    return pl_world_add_body(w, &b);
}

static pl_world *world(int *mat) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, 0};
    wd.dt = DT;
    wd.global_c = 100; /* N s/m: about critical for the block's vertical motion */
    pl_world *w = pl_world_create(&wd);
    pl_material_def m = pl_default_material_def();
    m.name = "tool";
    m.density = 7800;
    m.kn = 1e7;
    m.friction = 0.4;
    *mat = pl_world_add_material(w, &m);
    return w;
}

static int polygon_sliding(void) {
    int mat;
    pl_world *w = world(&mat);
    const double F = 10, v = 0.05, alpha = 0.8, k = 1e-3, H0 = 1e9;
    pl_body_def s = pl_default_body_def();
    s.shape = PL_SHAPE_SEGMENT;
    s.material = mat;
    s.a = (pl_vec2){-1, 0};
    s.b = (pl_vec2){1, 0};
    s.motion = PL_MOTION_FIXED;
    const int wall = pl_world_add_body(w, &s);
    const int blk = add_block(w, mat, 0, HB / 2, PL_MOTION_DYNAMIC);
    ENSURE(wall >= 0 && blk >= 0);
    pl_world_set_body_load(w, blk, (pl_vec2){0, -F}, 0);
    ENSURE(pl_world_step(w, 30000) == PL_OK); /* settle on the fixed wall */
    pl_world_prescribe_velocity(w, wall, (pl_vec2){v, 0}, 0);
    pl_thermal_def t = pl_default_thermal_def();
    t.heat_capacity = 460;
    t.wear = k;
    t.hardness = H0;
    ENSURE(pl_world_set_thermal(w, mat, &t) == PL_OK);
    ENSURE(pl_world_enable_heat(w, alpha, 300) == PL_OK);
    ENSURE(pl_world_enable_wear(w, 1) == PL_OK);
    ENSURE(pl_world_step(w, 200) == PL_OK); /* the shear spring builds up to mu F */
    const double h0 = pl_world_body_heat(w, blk), hw0 = pl_world_body_heat(w, wall);
    const double v0 = pl_world_body_wear(w, blk), vw0 = pl_world_body_wear(w, wall);
    const int n = 5000;
    ENSURE(pl_world_step(w, n) == PL_OK);
    const double q = 0.5 * alpha * 0.4 * F * v * n * DT, dv = k * F * v * n * DT / H0;
    const double hb = pl_world_body_heat(w, blk) - h0, hw = pl_world_body_heat(w, wall) - hw0;
    const double wb = pl_world_body_wear(w, blk) - v0, ww = pl_world_body_wear(w, wall) - vw0;
    fprintf(stderr, "  polygon sliding: heat to the block %.10g J, to the wall %.10g J (alpha mu F v t / 2 = %.10g J); "
                    "wear %.10g m^2 (k F s / H = %.10g m^2)\n", hb, hw, q, wb, dv);
    ENSURE_REL(hb, q, 1e-6);
    ENSURE_REL(hw, q, 1e-6);
    ENSURE_REL(wb, dv, 1e-6);
    ENSURE_REL(ww, dv, 1e-6);
    pl_world_destroy(&w);
    return 0;
}

static int polygon_conduction(void) {
    int mat;
    pl_world *w = world(&mat);
    const double F = 10, kth = 5, c = 460;
    const int base = add_block(w, mat, 0, -HB / 2, PL_MOTION_FIXED);
    const int blk = add_block(w, mat, 0, HB / 2, PL_MOTION_DYNAMIC);
    pl_world_set_body_load(w, blk, (pl_vec2){0, -F}, 0);
    ENSURE(pl_world_step(w, 30000) == PL_OK);
    pl_thermal_def t = pl_default_thermal_def();
    t.heat_capacity = c;
    t.conductivity = kth;
    ENSURE(pl_world_set_thermal(w, mat, &t) == PL_OK);
    ENSURE(pl_world_enable_heat(w, 1, 300) == PL_OK);
    ENSURE(pl_world_set_body_temperature(w, blk, 400, 0) == PL_OK);
    ENSURE(pl_world_set_body_temperature(w, base, 300, 1) == PL_OK); /* a reservoir */
    pl_body_info a, b;
    pl_world_body_info(w, base, &a);
    pl_world_body_info(w, blk, &b);
    const double d = b.position.y - a.position.y;
    const double H = kth * W / d, C = b.mass * c, lambda = H / C;
    const int n = 20000;
    ENSURE(pl_world_step(w, n) == PL_OK);
    const double T = pl_world_body_temperature(w, blk), T_base = pl_world_body_temperature(w, base);
    /* explicit Euler: (1 - lambda dt)^n, the closed form of the scheme; exp(-lambda t) to O(lambda dt) */
    const double euler = 300 + 100 * pow(1 - lambda * DT, n), exact = 300 + 100 * exp(-lambda * n * DT);
    fprintf(stderr, "  polygon conduction: T = %.10g K after %g s (exp(-H t/C): %.10g K, H = k w/d = %.6g W/K), base %.6g K\n",
            T, n * DT, exact, H, T_base);
    ENSURE(T_base == 300);
    ENSURE_REL(T - 300, euler - 300, 1e-6);
    ENSURE_REL(T - 300, exact - 300, 1e-3);
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(polygon_sliding);
    RUN(polygon_conduction);
    return pl_test_report();
}
