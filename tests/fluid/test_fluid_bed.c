/* Quick condition of a granular bed under upward seepage (DESIGN §3): with the interphase drag
 * the fluid carries the whole seepage force -grad p_excess on the skeleton, so the bed lifts
 * (its floor reaction vanishes) at the critical hydraulic gradient
 *     i_c = (1 - n) (G_s - 1)          (Terzaghi; e.g. Das, Principles of Geotechnical Eng.)
 * with n the bed's measured porosity and G_s = rho_s / rho_f. A disc bed (72 discs, 2.0 and
 * 2.6 mm, rho_s = 2650 kg/m^3) settles in a box with frictionless walls in still water; the
 * head at the floor is then raised step by step; i is measured from the computed heads across
 * the bed. Lift is the first level where the floor reaction falls below 3% of the buoyant
 * weight or the bed's top rises by a quarter of the small grain radius (heave; once the bed
 * moves its grains bounce on the floor and the instantaneous reaction stays noisy).
 * The test fails when i at lift is not within 10% of i_c, and also checks that without
 * the drag (FLUID_DRAG 0, the thesis's force model) the bed does not lift at 1.1 i_c. */
#include "harness.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include <stdlib.h>
#include <string.h>

#define PI 3.141592653589793
#define W 0.06
#define H 0.10

static int floor_body;

static pl_world *bed(int ndisc, int drag, double *solid_area, double *rho_s) {
    pl_world_def wd = pl_default_world_def();
    pl_world *w = pl_world_create(&wd);
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){W, 0};
    q.corners[2] = (pl_vec2){W, H};
    q.corners[3] = (pl_vec2){0, H};
    q.ndivx = 6;
    q.ndivy = 10;
    pl_world_add_fluid_quad(w, &q);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){W, 0}, H);
    pl_world_add_fluid_bc(w, (pl_vec2){0, H}, (pl_vec2){W, H}, 0);
    const char *names[] = {"FLUIDS_ON", "FIRST_STEP_STATIC", "FLUID_PERM", "FLUID_DENSITY", "FLUID_SOLVE_TIMESTEPS",
                           "FLUID_STORAGE", "FLUID_PERM_LOW", "FLUID_PERM_HIGH", "RAYLEIGH_FACTOR", "FLUID_DRAG"};
    const double vals[] = {1, 1, 1, 1000, 10, 0, 1e-3, 1.0, 30, drag};
    for (int k = 0; k < 10; k++)
        if (pl_world_set_flag(w, names[k], vals[k]) != PL_OK) fprintf(stderr, "%s\n", pl_world_last_error(w));
    *rho_s = 2650;
    pl_material_def md = pl_default_material_def();
    md.name = "sand";
    md.density = *rho_s;
    md.kn = 2e5;
    md.friction = 0.3;
    md.restitution = 0.3;
    int sand = pl_world_add_material(w, &md);
    md.name = "wall";
    md.friction = 0;
    int wall = pl_world_add_material(w, &md);
    pl_body_def s = pl_default_body_def();
    s.shape = PL_SHAPE_SEGMENT;
    s.motion = PL_MOTION_FIXED;
    s.material = wall;
    s.a = (pl_vec2){-0.01, 0};
    s.b = (pl_vec2){W + 0.01, 0};
    floor_body = pl_world_add_body(w, &s);
    s.a = (pl_vec2){0, 0};
    s.b = (pl_vec2){0, 2 * H};
    pl_world_add_body(w, &s);
    s.a = (pl_vec2){W, 0};
    s.b = (pl_vec2){W, 2 * H};
    pl_world_add_body(w, &s);
    *solid_area = 0;
    for (int k = 0; k < ndisc; k++) {
        pl_body_def d = pl_default_body_def();
        d.shape = PL_SHAPE_DISC;
        d.material = sand;
        d.radius = (k % 2) ? 0.0026 : 0.0020;
        int row = k / 12, col = k % 12;
        d.position = (pl_vec2){0.0027 + col * 0.0048 + (row % 2) * 0.0008, 0.004 + row * 0.0058};
        if (pl_world_add_body(w, &d) < 0) fprintf(stderr, "%s\n", pl_world_last_error(w));
        *solid_area += PI * d.radius * d.radius;
    }
    return w;
}

static double bed_top(pl_world *w) {
    double top = 0;
    for (int i = 0; i < pl_world_body_count(w); i++) {
        pl_body_info bi;
        pl_world_body_info(w, i, &bi);
        if (bi.shape == PL_SHAPE_DISC) top = fmax(top, bi.position.y + bi.radius);
    }
    return top;
}

/* Mean total head along a horizontal line. */
static double head_at(pl_world *w, double y) {
    double s = 0;
    int n = 0;
    for (int k = 0; k < 25; k++) {
        double h;
        pl_world_prepare(w); /* queries read only: build first */
        if (pl_world_fluid_pressure_at(w, (pl_vec2){W * (k + 0.5) / 25, y}, NULL, &h)) { s += h; n++; }
    }
    return s / n;
}

static void set_excess_head(pl_world *w, double dh) {
    pl_world_clear_fluid_bcs(w);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){W, 0}, H + dh);
    pl_world_add_fluid_bc(w, (pl_vec2){0, H}, (pl_vec2){W, H}, 0);
}

/* Ramps the excess head; returns the gradient at which the floor reaction first falls below
   3% of the buoyant weight (or -1). */
static double ramp(pl_world *w, double solid, double rho_s, double i_stop, double *i_c_out, double *n_out) {
    double top = bed_top(w);
    double n = 1 - solid / (W * top);
    double i_c = (1 - n) * (rho_s / 1000 - 1);
    double Wb = (rho_s - 1000) * 9.81 * solid;
    *i_c_out = i_c;
    *n_out = n;
    double prev_i = 0, prev_r = 1;
    for (double f = 0.5; f <= i_stop; f += 0.02) {
        double dh = f * i_c * top;
        set_excess_head(w, dh);
        if (pl_world_step(w, 300) != PL_OK) {
            fprintf(stderr, "%s\n", pl_world_last_error(w));
            return -2;
        }
        double i = (head_at(w, 1e-9) - head_at(w, top)) / top;
        pl_body_info fl;
        pl_world_body_info(w, floor_body, &fl);
        double r = fabs(fl.force.y) / Wb;
        double heave = bed_top(w) - top;
        if (r < 0.03) {
            /* interpolate the zero crossing between the last two levels */
            double il = prev_i + (i - prev_i) * prev_r / (prev_r - r);
            fprintf(stderr, "  floor reaction %.3f W' at i = %.4f (previous %.3f W' at %.4f): lift at i = %.4f\n", r, i,
                    prev_r, prev_i, il);
            return il;
        }
        if (heave > 0.25 * 0.0020) {
            /* the bed has started to expand (a quarter of the small grain radius): once lifting,
               grains bounce on the floor and its instantaneous reaction no longer falls to zero */
            fprintf(stderr, "  bed top rose %.2f mm at i = %.4f (floor reaction %.3f W'): lift at i = %.4f\n", 1e3 * heave,
                    i, r, i);
            return i;
        }
        if (getenv("PL_TRACE")) fprintf(stderr, "  f %.2f i %.4f r %.3f top %.5f\n", f, i, r, bed_top(w));
        prev_i = i;
        prev_r = r;
    }
    fprintf(stderr, "  no lift up to i = %.4f (floor reaction %.3f W')\n", prev_i, prev_r);
    return -1;
}

static int test_lift_at_critical_gradient(void) {
    double solid, rho_s;
    pl_world *w = bed(72, 1, &solid, &rho_s);
    if (pl_world_step(w, 6000) != PL_OK) {
        fprintf(stderr, "%s\n", pl_world_last_error(w));
        return 1;
    }
    double i_c, n;
    double il = ramp(w, solid, rho_s, 1.4, &i_c, &n);
    fprintf(stderr, "  bed: porosity n = %.4f (areal, measured), G_s = %.3f, i_c = (1 - n)(G_s - 1) = %.4f; lift at %.4f "
                    "(%.1f%% off)\n",
            n, rho_s / 1000, i_c, il, 100 * (il - i_c) / i_c);
    pl_validation("fluid.bed_lift", "bed under upward seepage", "lifts at i_c = (1 − n)(G_s − 1)", "10 %",
                  "%+.1f %% (n measured %.3f)", 100 * (il - i_c) / i_c, n);
    ENSURE(il > 0);
    ENSURE_NEAR(il, i_c, 0.10 * i_c);
    pl_world_destroy(&w);
    return 0;
}

static int test_no_drag_no_lift(void) {
    /* the thesis's outline pressure alone carries only (1 - n) of the seepage force */
    double solid, rho_s;
    pl_world *w = bed(72, 0, &solid, &rho_s);
    if (pl_world_step(w, 6000) != PL_OK) {
        fprintf(stderr, "%s\n", pl_world_last_error(w));
        return 1;
    }
    double i_c, n;
    double il = ramp(w, solid, rho_s, 1.1, &i_c, &n);
    pl_validation("fluid.bed_no_drag", "same without the interphase drag", "does not lift at 1.1 i_c", "—", "%s",
                  il == -1 ? "no lift" : "LIFTS");
    ENSURE(il == -1);
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(test_lift_at_critical_gradient);
    RUN(test_no_drag_no_lift);
    return pl_test_report();
}
