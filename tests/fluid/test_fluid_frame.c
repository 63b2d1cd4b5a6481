/* Darcy's law in an accelerating frame (pl_world_fluid_set_frame; docs/soil.md §2): the pore
 * water shares the acceleration a of a shaking body, q = -D (grad h + a/g).
 *
 * 1. Vertical shaking of a water column (no grains) under a head line p = 0 at its top: the
 *    exact solution is hydrostatic in the effective gravity, p = rho_f (g + a_y) depth (linear,
 *    so the P1 field must reproduce it to round-off): checked at several depths and times
 *    against the shaking law's closed-form acceleration, and p = rho_f g depth without the frame.
 * 2. Horizontal shaking of a tall column (height 5 widths): below the surface layer the water
 *    is accelerated by the walls, dp/dx = -rho_f a_x (the surface modes decay as
 *    exp(-pi depth / width): 2e-5 at 3.5 widths). A fixed disc there receives the horizontal
 *    buoyancy rho_f a_x pi r^2 and no drag (no flow). Tolerance 1% (discretisation). The Darcy
 *    flux reported there (element field: drawn, written to VTK) is relative to the table: below 1%
 *    of k a_x / g (measured 2e-5; the raw -k dh/dx would be k a_x / g).
 * 3. A body without a known acceleration (a servo wall) is refused with a message. */
#include "harness.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include <math.h>
#include <string.h>

#define RHO 1000.0
#define G 9.81

static pl_world *column(double width, double height, int nx, int ny, pl_vec2 amp, double freq, int *table) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, -G};
    wd.dt = 1e-4;
    pl_world *w = pl_world_create(&wd);
    pl_material_def md = pl_default_material_def();
    md.name = "m";
    md.density = 2650;
    md.kn = 1e6;
    const int m = pl_world_add_material(w, &md);
    pl_body_def s = pl_default_body_def();
    s.shape = PL_SHAPE_SEGMENT;
    s.motion = PL_MOTION_FIXED;
    s.material = m;
    s.a = (pl_vec2){-1, -1};
    s.b = (pl_vec2){1, -1};
    *table = pl_world_add_body(w, &s);
    if (*table < 0) fprintf(stderr, "  %s\n", pl_world_last_error(w));
    if (pl_world_set_sinusoid(w, *table, amp, freq, 0.0, 10.0) != PL_OK) fprintf(stderr, "  %s\n", pl_world_last_error(w));
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){width, 0};
    q.corners[2] = (pl_vec2){width, height};
    q.corners[3] = (pl_vec2){0, height};
    q.ndivx = nx;
    q.ndivy = ny;
    pl_world_add_fluid_quad(w, &q);
    pl_world_add_fluid_bc(w, (pl_vec2){0, height}, (pl_vec2){width, height}, 0);
    const char *names[] = {"FLUIDS_ON", "FIRST_STEP_STATIC", "FLUID_PERM", "FLUID_PERM_HIGH", "FLUID_METHOD"};
    const double vals[] = {1, 1, 0, 1e-3, 3};
    for (int k = 0; k < 5; k++) pl_world_set_flag(w, names[k], vals[k]);
    return w;
}

/* closed-form acceleration of A sin(2 pi f t) */
static double acc(double A, double f, double t) { return -A * 4 * M_PI * M_PI * f * f * sin(2 * M_PI * f * t); }

static int vertical_shaking(void) {
    const double H = 0.2, A = 0.004, F = 5;
    int table;
    pl_world *w = column(0.1, H, 4, 8, (pl_vec2){0, A}, F, &table);
    ENSURE(pl_world_fluid_set_frame(w, table) == PL_OK);
    double worst = 0;
    for (int k = 0; k < 4; k++) {
        ENSURE(pl_world_step(w, 130) == PL_OK);
        const double t = pl_world_time(w), ay = acc(A, F, t);
        double p = 0, ref = 0;
        for (int j = 1; j <= 4; j++) {
            const double d = H * j / 5;
            pl_world_prepare(w); /* queries read only: build first */
            pl_world_fluid_pressure_at(w, (pl_vec2){0.037, H - d}, &p, NULL);
            ref = RHO * (G + ay) * d;
            const double e = fabs(p - ref) / (RHO * G * d);
            if (e > worst) worst = e;
        }
        fprintf(stderr, "  t = %.4f s: a_y = %+.3f m/s^2, p at depth %.2f m = %.4f Pa (rho (g + a_y) d = %.4f Pa)\n", t,
                ay, 0.8 * H, p, ref);
    }
    fprintf(stderr, "  vertical shaking: worst |p - rho (g + a_y) d| / (rho g d) = %.2e\n", worst);
    pl_validation("fluid.frame", "water in a shaking table's frame (u–p)",
                  "vertical: p = ρ_f (g + a_y) d; horizontal, deep: ∂p/∂x = −ρ_f a_x, disc force ρ_f a_x πr²",
                  "1e-10; 1 %", "vertical %.0e", worst);
    ENSURE(worst < 1e-10);
    /* without the frame: hydrostatic in g */
    ENSURE(pl_world_fluid_set_frame(w, -1) == PL_OK);
    ENSURE(pl_world_step(w, 1) == PL_OK);
    double p;
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_pressure_at(w, (pl_vec2){0.05, H / 2}, &p, NULL);
    ENSURE_NEAR(p, RHO * G * H / 2, 1e-9 * RHO * G * H);
    pl_world_destroy(&w);
    return 0;
}

static int horizontal_shaking(void) {
    const double Wd = 0.1, H = 0.5, A = 0.004, F = 5, r = 0.01;
    int table;
    pl_world *w = column(Wd, H, 10, 50, (pl_vec2){A, 0}, F, &table);
    /* a fixed disc deep in the column */
    pl_material_def md = pl_world_material(w, 0);
    (void)md;
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_DISC;
    b.position = (pl_vec2){0.05, 0.12};
    b.radius = r;
    b.material = 0;
    b.motion = PL_MOTION_FIXED;
    const int disc = pl_world_add_body(w, &b);
    ENSURE(disc >= 0);
    ENSURE(pl_world_fluid_set_frame(w, table) == PL_OK);
    double worst_g = 0, worst_f = 0;
    for (int k = 0; k < 3; k++) {
        ENSURE(pl_world_step(w, 170) == PL_OK);
        const double t = pl_world_time(w), ax = acc(A, F, t);
        double p1, p2;
        pl_world_prepare(w); /* queries read only: build first */
        pl_world_fluid_pressure_at(w, (pl_vec2){0.02, 0.12}, &p1, NULL);
        pl_world_prepare(w); /* queries read only: build first */
        pl_world_fluid_pressure_at(w, (pl_vec2){0.08, 0.12}, &p2, NULL);
        const double dpdx = (p2 - p1) / 0.06;
        pl_vec2 Fd;
        double M;
        pl_world_prepare(w); /* queries read only: build first */
        ENSURE(pl_world_fluid_body_force(w, disc, &Fd, &M) == PL_OK);
        const double Fref = RHO * ax * M_PI * r * r;
        fprintf(stderr, "  t = %.4f s: a_x = %+.3f m/s^2: dp/dx = %+.3f Pa/m (-rho a_x = %+.3f); disc F_x = %+.5f N/m "
                        "(rho a_x pi r^2 = %+.5f), F_y = %.5f (rho g pi r^2 = %.5f)\n",
                t, ax, dpdx, -RHO * ax, Fd.x, Fref, Fd.y, RHO * G * M_PI * r * r);
        ENSURE(fabs(ax) > 1);
        const double eg = fabs(dpdx + RHO * ax) / (RHO * fabs(ax)), ef = fabs(Fd.x - Fref) / fabs(Fref);
        if (eg > worst_g) worst_g = eg;
        if (ef > worst_f) worst_f = ef;
        ENSURE_NEAR(Fd.y, RHO * G * M_PI * r * r, 1e-2 * RHO * G * M_PI * r * r);
        /* the Darcy flux reported (element field, drawn and written to VTK) is relative to the
           table: the water deep in the column moves with it, so q_x ~ 0 there, while the raw
           -k dh/dx is k a_x / g */
        pl_world_prepare(w); /* queries read only: build first */
        const int nt = pl_world_fluid_triangle_count(w), nn = pl_world_fluid_node_count(w);
        static double vx[4000];
        static int tri[12000];
        static pl_vec2 xy[4000];
        ENSURE(nt <= 4000 && nn <= 4000);
        pl_world_prepare(w); /* queries read only: build first */
        ENSURE(pl_world_fluid_copy_element_field(w, PL_FLUID_VELOCITY_X, vx, nt) == nt);
        pl_world_prepare(w); /* queries read only: build first */
        ENSURE(pl_world_fluid_copy_triangles(w, tri, nt) == nt);
        pl_world_prepare(w); /* queries read only: build first */
        ENSURE(pl_world_fluid_copy_nodes(w, xy, nn) == nn);
        double qmax = 0;
        for (int e = 0; e < nt; e++) {
            const double yc = (xy[tri[3 * e]].y + xy[tri[3 * e + 1]].y + xy[tri[3 * e + 2]].y) / 3;
            if (yc < H - 3.5 * Wd && fabs(vx[e]) > qmax) qmax = fabs(vx[e]);
        }
        fprintf(stderr, "  deep in the column: |q_x| <= %.3e m/s (k a_x / g = %.3e m/s)\n", qmax, 1e-3 * fabs(ax) / G);
        ENSURE(qmax < 1e-2 * 1e-3 * fabs(ax) / G);
    }
    fprintf(stderr, "  horizontal shaking: worst relative error of dp/dx %.2e, of the disc's horizontal force %.2e\n",
            worst_g, worst_f);
    pl_validation("fluid.frame", "", "", "", "horizontal %.0e, disc force %.0e", worst_g, worst_f);
    ENSURE(worst_g < 1e-2);
    ENSURE(worst_f < 1e-2);
    pl_world_destroy(&w);
    return 0;
}

static int refuses_unknown_acceleration(void) {
    int table;
    pl_world *w = column(0.1, 0.1, 2, 2, (pl_vec2){0.001, 0}, 5, &table);
    ENSURE(pl_world_set_servo(w, table, (pl_vec2){0, 1}, 10, 0.1, 0.01) == PL_OK);
    ENSURE(pl_world_fluid_set_frame(w, table) != PL_OK);
    fprintf(stderr, "  %s\n", pl_world_last_error(w));
    ENSURE(strstr(pl_world_last_error(w), "known acceleration") != NULL);
    ENSURE(pl_world_fluid_set_frame(w, 99) != PL_OK);
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(vertical_shaking);
    RUN(horizontal_shaking);
    RUN(refuses_unknown_acceleration);
    return pl_test_report();
}
