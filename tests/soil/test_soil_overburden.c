/* Geostatic overburden of a region (pl_soil_region.overburden; docs/soil.md §3, used for r_u in
 * the liquefaction scene): the submerged weight per unit width of the dynamic bodies whose
 * centroids lie in the region's column above each level, averaged over the region's height:
 *
 *   overburden = (1 / (W H)) sum_i w_i clamp((y_i - lo.y) / H, 0, 1),
 *   w_i = (m_i - rho_f A_i) g below the water (pore pressure > 0 at the centroid), m_i g above.
 *
 * Checked to round-off on hand-placed discs: two under water at different depths inside the
 * region, one under water above the region (counts whole), one above the water (no buoyancy),
 * one outside the column and one below the region (not counted), and a fixed disc (not counted).
 * Without gravity along -y the overburden is 0 (it is defined for gravity along -y only). */
#include "harness.h"
#include "porelab/fluid.h"
#include "porelab/soil.h"
#include "porelab/world.h"
#include <math.h>

#define G 9.81
#define RHO_S 2650.0
#define RHO_F 1000.0

static int disc(pl_world *w, int mat, double x, double y, double r, int fixed) {
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_DISC;
    b.material = mat;
    b.position = (pl_vec2){x, y};
    b.radius = r;
    b.motion = fixed ? PL_MOTION_FIXED : PL_MOTION_DYNAMIC;
    return pl_world_add_body(w, &b);
}

static pl_world *make(double gx, double gy) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){gx, gy};
    pl_world *w = pl_world_create(&wd);
    pl_material_def md = pl_default_material_def();
    md.name = "sand";
    md.density = RHO_S;
    md.kn = 1e6;
    const int m = pl_world_add_material(w, &md);
    const double r = 0.004;
    disc(w, m, 0.030, 0.030, r, 0); /* in the region, under water */
    disc(w, m, 0.060, 0.065, r, 0); /* in the region, under water */
    disc(w, m, 0.045, 0.090, r, 0); /* above the region, under water: whole */
    disc(w, m, 0.050, 0.130, r, 0); /* above the water (mesh top 0.1): no buoyancy */
    disc(w, m, 0.150, 0.050, r, 0); /* outside the column */
    disc(w, m, 0.050, 0.010, r, 0); /* below the region */
    disc(w, m, 0.020, 0.050, r, 1); /* fixed: not soil */
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){0.1, 0};
    q.corners[2] = (pl_vec2){0.1, 0.1};
    q.corners[3] = (pl_vec2){0, 0.1};
    q.ndivx = 5;
    q.ndivy = 5;
    pl_world_add_fluid_quad(w, &q);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0.1}, (pl_vec2){0.1, 0.1}, 0);
    pl_world_set_flag(w, "FLUIDS_ON", 1);
    pl_world_set_flag(w, "FLUID_PERM", 0);
    return w;
}

static int overburden_exact(void) {
    pl_world *w = make(0, -G);
    ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
    const pl_vec2 lo = {0, 0.02}, hi = {0.1, 0.08};
    pl_soil_region r;
    ENSURE(pl_world_soil_region(w, lo, hi, &r) == PL_OK);
    const double A = M_PI * 0.004 * 0.004, wet = (RHO_S - RHO_F) * A * G, dry = RHO_S * A * G;
    const double H = 0.06, W = 0.1;
    const double ref = (wet * (0.030 - 0.02) / H + wet * (0.065 - 0.02) / H + wet + dry) / W;
    fprintf(stderr, "  overburden %.6f Pa, reference %.6f Pa (submerged %.4f N/m, dry %.4f N/m per disc)\n", r.overburden,
            ref, wet, dry);
    pl_validation("soil.overburden", "overburden of a region (submerged and dry grains)", "Σ weights above / width",
                  "1e-12", "%.1e", fabs(r.overburden - ref) / ref);
    ENSURE_NEAR(r.overburden, ref, 1e-12 * ref);
    pl_world_destroy(&w);
    /* gravity not along -y: not defined, 0 */
    w = make(-1, -G);
    ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
    ENSURE(pl_world_soil_region(w, lo, hi, &r) == PL_OK);
    ENSURE(r.overburden == 0);
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(overburden_exact);
    return pl_test_report();
}
