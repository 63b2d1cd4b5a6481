/* Static Darcy solutions (seed 000 §3.7-3.10) and pressure forces (§3.11):
 * - dam flow (§4.1, Appendix C.1): inflow through the head-40 line equals the outflow through
 *   the head-0 line (relative 1e-8), heads within the prescribed range (maximum principle),
 *   flow converging under mesh refinement, independent of gravity (total head), and the
 *   static solve skipped when nothing changed;
 * - still water (Appendix C.2 box): hydrostatic pressure and zero Darcy velocity exactly;
 * - Archimedes: a fully immersed polygon and disc feel rho_f g A upward (relative 1e-10) and
 *   no moment about the centroid; partly immersed ones feel rho_f g A_wet through the centroid
 *   of the wetted part (exact, §3.11.4 and Fig. 3-11). */
#include "harness.h"
#include "stdio_writer.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include <stdlib.h>
#include <string.h>

static pl_world *new_world(double gy) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, gy};
    pl_world *w = pl_world_create(&wd);
    pl_world_set_flag(w, "GRAVITY_Y", gy);
    return w;
}

static int add_quad(pl_world *w, double x0, double y0, double x1, double y1, int nx, int ny) {
    pl_fluid_quad_def d = pl_default_fluid_quad_def();
    d.corners[0] = (pl_vec2){x0, y0};
    d.corners[1] = (pl_vec2){x1, y0};
    d.corners[2] = (pl_vec2){x1, y1};
    d.corners[3] = (pl_vec2){x0, y1};
    d.ndivx = nx;
    d.ndivy = ny;
    return pl_world_add_fluid_quad(w, &d);
}

static int dam(int refine, double gy, double *q_in, double *q_out, double *hmin, double *hmax) {
    pl_world *w = new_world(gy);
    int r = refine;
    if (add_quad(w, 50, 50, 250, 300, 4 * r, 4 * r) < 0 || add_quad(w, 250, 50, 350, 100, 4 * r, 4 * r) < 0 ||
        add_quad(w, 350, 50, 480, 300, 4 * r, 4 * r) < 0) {
        fprintf(stderr, "%s\n", pl_world_last_error(w));
        return 1;
    }
    int l0 = pl_world_add_fluid_bc(w, (pl_vec2){50, 300}, (pl_vec2){250, 300}, 40);
    int l1 = pl_world_add_fluid_bc(w, (pl_vec2){350, 300}, (pl_vec2){480, 300}, 0);
    pl_world_set_flag(w, "FLUID_PERM", 0);
    pl_world_set_flag(w, "FLUID_PERM_HIGH", 5.0);
    pl_world_set_flag(w, "FLUID_DENSITY", 0.1);
    if (pl_world_fluid_solve_static(w) != PL_OK) {
        fprintf(stderr, "%s\n", pl_world_last_error(w));
        return 1;
    }
    *q_in = pl_world_fluid_line_inflow(w, l0);
    *q_out = -pl_world_fluid_line_inflow(w, l1);
    /* total heads relative to the outlet's (300 with gravity: h = psi + y; 0 without) */
    pl_world_prepare(w); /* queries read only: build first */
    int nn = pl_world_fluid_node_count(w);
    double *h = malloc(sizeof(double) * nn);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_node_field(w, PL_FLUID_HEAD, h, nn);
    const double h_out = gy != 0 ? 300 : 0;
    *hmin = 1e300;
    *hmax = -1e300;
    for (int i = 0; i < nn; i++) {
        *hmin = fmin(*hmin, h[i] - h_out);
        *hmax = fmax(*hmax, h[i] - h_out);
    }
    if (refine == 1 && gy != 0) {
        /* a second solve with nothing changed is skipped: no new factorization */
        pl_fluid_stats s0, s1;
        pl_world_fluid_stats(w, &s0);
        pl_world_fluid_solve_static(w);
        pl_world_fluid_stats(w, &s1);
        if (s1.factorizations != s0.factorizations || s1.skipped != s0.skipped + 1) {
            fprintf(stderr, "repeat solve not skipped (%ld/%ld factorizations, %ld/%ld skipped)\n", s0.factorizations,
                    s1.factorizations, s0.skipped, s1.skipped);
            return 1;
        }
    }
    free(h);
    pl_world_destroy(&w);
    return 0;
}

static int test_dam_flow(void) {
    double qi[3], qo[3], lo, hi;
    int refs[3] = {1, 2, 4};
    for (int k = 0; k < 3; k++) {
        ENSURE(dam(refs[k], -9.81, &qi[k], &qo[k], &lo, &hi) == 0);
        fprintf(stderr, "  dam x%d: inflow %.12g outflow %.12g (relative difference %.2e), total head range [%.6g, %.6g] + 300\n",
                refs[k], qi[k], qo[k], fabs(qi[k] - qo[k]) / qi[k], lo, hi);
        pl_validation("fluid.dam_flow", "dam flow (§4.1): inflow = outflow", "mass conservation", "1e-8 relative",
                      "%.1e (refinement %d)", fabs(qi[k] - qo[k]) / qi[k], refs[k]);
        ENSURE(qi[k] > 0);
        ENSURE_REL(qo[k], qi[k], 1e-8);
        ENSURE(lo >= -1e-9 && hi <= 40 + 1e-9);
    }
    /* flow converges under refinement (P1 flux error falls with h) */
    double d1 = fabs(qi[0] - qi[1]), d2 = fabs(qi[1] - qi[2]);
    fprintf(stderr, "  dam flow changes under refinement: %.4g then %.4g (ratio %.2f)\n", d1, d2, d1 / d2);
    ENSURE(d2 < d1);
    /* total head: gravity does not change the flow (both lines at the same elevation) */
    double q0, qo0;
    ENSURE(dam(1, 0.0, &q0, &qo0, &lo, &hi) == 0);
    ENSURE_REL(q0, qi[0], 1e-10);
    return 0;
}

/* Box of seed 000 Appendix C.2: 100..300 x 100..300 (mesh may extend above the water). */
static pl_world *still_water(double top, int nx, int ny, double rho) {
    pl_world *w = new_world(-9.81);
    add_quad(w, 100, 100, 300, top, nx, ny);
    pl_world_add_fluid_bc(w, (pl_vec2){100, 100}, (pl_vec2){300, 100}, 200);   /* pressure head at the floor */
    pl_world_add_fluid_bc(w, (pl_vec2){100, top}, (pl_vec2){300, top}, 300 - top); /* water level y = 300 */
    pl_world_set_flag(w, "FLUID_DENSITY", rho);
    pl_world_set_flag(w, "FLUID_PERM", 0);
    pl_material_def md = pl_default_material_def();
    md.name = "grain";
    md.density = 1;
    md.kn = 1e5;
    pl_world_add_material(w, &md);
    return w;
}

static int test_hydrostatic(void) {
    pl_world *w = still_water(300, 4, 4, 1.0);
    ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
    pl_world_prepare(w); /* queries read only: build first */
    int nn = pl_world_fluid_node_count(w), ne = pl_world_fluid_triangle_count(w);
    double *h = malloc(sizeof(double) * (nn > ne ? nn : ne));
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_node_field(w, PL_FLUID_HEAD, h, nn);
    for (int i = 0; i < nn; i++) ENSURE_NEAR(h[i], 300, 1e-10);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_element_field(w, PL_FLUID_VELOCITY_Y, h, ne);
    for (int e = 0; e < ne; e++) ENSURE_NEAR(h[e], 0, 1e-10);
    for (int k = 0; k < 20; k++) {
        pl_vec2 p = {100 + 200 * ((k * 37) % 101) / 101.0, 100 + 200 * ((k * 53) % 97) / 97.0};
        double pr;
        pl_world_prepare(w); /* queries read only: build first */
        ENSURE(pl_world_fluid_pressure_at(w, p, &pr, NULL) == 1);
        ENSURE_NEAR(pr, 9.81 * (300 - p.y), 1e-9 * 9.81 * 200);
    }
    double pr;
    pl_world_prepare(w); /* queries read only: build first */
    ENSURE(pl_world_fluid_pressure_at(w, (pl_vec2){50, 50}, &pr, NULL) == 0);
    pl_validation("fluid.hydrostatic", "still water", "hydrostatic, zero Darcy velocity", "1e-10",
                  "head 300 at every node, v = 0 in every element, p = ρ g (300 − y) at 20 points");
    ENSURE(pr == 0);
    free(h);
    pl_world_destroy(&w);
    return 0;
}

static int add_poly(pl_world *w, const pl_vec2 *v, int n) {
    pl_body_def bd = pl_default_body_def();
    bd.shape = PL_SHAPE_POLYGON;
    bd.motion = PL_MOTION_FIXED;
    bd.material = 0;
    bd.vertices = v;
    bd.vertex_count = n;
    return pl_world_add_body(w, &bd);
}

static int add_disc(pl_world *w, pl_vec2 c, double r) {
    pl_body_def bd = pl_default_body_def();
    bd.shape = PL_SHAPE_DISC;
    bd.motion = PL_MOTION_FIXED;
    bd.material = 0;
    bd.position = c;
    bd.radius = r;
    return pl_world_add_body(w, &bd);
}

static double poly_area(const pl_vec2 *v, int n, pl_vec2 *c) {
    double a = 0, cx = 0, cy = 0;
    for (int k = 0; k < n; k++) {
        pl_vec2 p = v[k], q = v[(k + 1) % n];
        double cr = p.x * q.y - q.x * p.y;
        a += cr;
        cx += (p.x + q.x) * cr;
        cy += (p.y + q.y) * cr;
    }
    if (c) *c = (pl_vec2){cx / (3 * a), cy / (3 * a)};
    return 0.5 * a;
}

static int test_archimedes(void) {
    const double rho = 1000, g = 9.81;
    pl_world *w = still_water(300, 5, 7, rho);
    pl_world_set_flag(w, "FLUID_DRAG", 1);
    /* an irregular convex hexagon, not aligned with the mesh */
    pl_vec2 hex[6];
    for (int k = 0; k < 6; k++) {
        double a = 0.3 + k * 2 * 3.141592653589793 / 6 + 0.1 * (k % 2);
        double r = 31 + 7 * (k % 3);
        hex[k] = (pl_vec2){173.3 + r * cos(a), 191.7 + r * sin(a)};
    }
    int b = add_poly(w, hex, 6);
    ENSURE(b >= 0);
    int d = add_disc(w, (pl_vec2){241.3, 158.9}, 23.7);
    ENSURE(d >= 0);
    ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
    pl_vec2 c;
    double A = poly_area(hex, 6, &c);
    pl_vec2 F;
    double M;
    pl_world_prepare(w); /* queries read only: build first */
    ENSURE(pl_world_fluid_body_force(w, b, &F, &M) == PL_OK);
    fprintf(stderr, "  hexagon: F = (%.3e, %.15g), rho g A = %.15g, M = %.3e\n", F.x, F.y, rho * g * A, M);
    pl_validation("fluid.archimedes", "Archimedes, bodies fully immersed", "ρ_f g A up, no moment", "1e-10",
                  "hexagon %.0e", fabs(F.y - rho * g * A) / (rho * g * A));
    ENSURE_REL(F.y, rho * g * A, 1e-10);
    ENSURE_NEAR(F.x, 0, 1e-10 * rho * g * A);
    ENSURE_NEAR(M, 0, 1e-10 * rho * g * A * 40);
    pl_world_prepare(w); /* queries read only: build first */
    ENSURE(pl_world_fluid_body_force(w, d, &F, &M) == PL_OK);
    double Ad = 3.141592653589793 * 23.7 * 23.7;
    fprintf(stderr, "  disc: F = (%.3e, %.15g), rho g pi r^2 = %.15g\n", F.x, F.y, rho * g * Ad);
    pl_validation("fluid.archimedes", "", "", "", "disc %.0e", fabs(F.y - rho * g * Ad) / (rho * g * Ad));
    ENSURE_REL(F.y, rho * g * Ad, 1e-10);
    ENSURE_NEAR(F.x, 0, 1e-10 * rho * g * Ad);
    pl_world_destroy(&w);
    /* a large disc and polygon over a fine mesh (thousands of elements under each) */
    w = still_water(300, 60, 60, rho);
    d = add_disc(w, (pl_vec2){190.3, 180.1}, 61.3);
    pl_vec2 oct[8];
    for (int k = 0; k < 8; k++) oct[k] = (pl_vec2){200 + 70 * cos(0.2 + k * 0.785398), 210 + 70 * sin(0.2 + k * 0.785398)};
    b = add_poly(w, oct, 8);
    ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
    pl_world_prepare(w); /* queries read only: build first */
    ENSURE(pl_world_fluid_body_force(w, d, &F, &M) == PL_OK);
    Ad = 3.141592653589793 * 61.3 * 61.3;
    fprintf(stderr, "  large disc on a 60 x 60 mesh: F_y = %.15g, rho g pi r^2 = %.15g\n", F.y, rho * g * Ad);
    pl_validation("fluid.archimedes", "", "", "", "large disc on a 60 × 60 mesh %.0e", fabs(F.y - rho * g * Ad) / (rho * g * Ad));
    ENSURE_REL(F.y, rho * g * Ad, 1e-10);
    pl_world_prepare(w); /* queries read only: build first */
    ENSURE(pl_world_fluid_body_force(w, b, &F, &M) == PL_OK);
    A = poly_area(oct, 8, &c);
    ENSURE_REL(F.y, rho * g * A, 1e-10);
    ENSURE_NEAR(M, 0, 1e-10 * rho * g * A * 70);
    pl_world_destroy(&w);
    return 0;
}

/* Clip polygon to y <= level (independent of the engine's clipping). */
static int clip_below(const pl_vec2 *v, int n, double level, pl_vec2 *out) {
    int m = 0;
    for (int k = 0; k < n; k++) {
        pl_vec2 p = v[k], q = v[(k + 1) % n];
        int pin = p.y <= level, qin = q.y <= level;
        if (pin) out[m++] = p;
        if (pin != qin) {
            double t = (level - p.y) / (q.y - p.y);
            out[m++] = (pl_vec2){p.x + t * (q.x - p.x), level};
        }
    }
    return m;
}

static int test_partial_submersion(void) {
    const double rho = 1000, g = 9.81;
    /* mesh up to y = 340 with the water table at y = 300 inside elements (7 divisions): the
       region above is dry (p < 0 clamped to 0) */
    pl_world *w = still_water(340, 6, 7, rho);
    pl_vec2 sq[4];
    double ang = 0.5;
    for (int k = 0; k < 4; k++) {
        double a = ang + k * 3.141592653589793 / 2;
        sq[k] = (pl_vec2){180 + 28 * cos(a), 297 + 28 * sin(a)};
    }
    int b = add_poly(w, sq, 4);
    double yc = 300 + 0.3 * 20;
    int d = add_disc(w, (pl_vec2){250, yc}, 20);
    ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
    pl_vec2 wet[8], cw, c;
    int nw = clip_below(sq, 4, 300, wet);
    double Aw = poly_area(wet, nw, &cw);
    poly_area(sq, 4, &c);
    pl_vec2 F;
    double M;
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_body_force(w, b, &F, &M);
    fprintf(stderr, "  tilted square: F = (%.3e, %.12g) expected (0, %.12g); M = %.10g expected %.10g\n", F.x, F.y,
            rho * g * Aw, M, (cw.x - c.x) * rho * g * Aw);
    ENSURE_REL(F.y, rho * g * Aw, 1e-9);
    ENSURE_NEAR(F.x, 0, 1e-9 * rho * g * Aw);
    ENSURE_REL(M, (cw.x - c.x) * rho * g * Aw, 1e-8);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_body_force(w, d, &F, &M);
    double dd = yc - 300, r = 20;
    double Aseg = r * r * acos(dd / r) - dd * sqrt(r * r - dd * dd);
    fprintf(stderr, "  disc, centre 0.3 r above the water: F_y = %.12g expected %.12g\n", F.y, rho * g * Aseg);
    ENSURE_REL(F.y, rho * g * Aseg, 1e-9);
    ENSURE_NEAR(F.x, 0, 1e-9 * rho * g * Aseg);
    /* a small disc inside one element, crossing the water table (single-element path) */
    pl_world_destroy(&w);
    w = still_water(340, 6, 7, rho);
    double rs = 2, ys = 300.6;
    int ds = add_disc(w, (pl_vec2){118.0, ys}, rs);
    pl_vec2 dry = {0, 0};
    int dd2 = add_disc(w, (pl_vec2){150.0, 320.0}, rs); /* fully above the water */
    int dw = add_disc(w, (pl_vec2){118.0, 200.3}, rs);  /* fully below, inside one element */
    ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_body_force(w, ds, &F, &M);
    dd = ys - 300;
    Aseg = rs * rs * acos(dd / rs) - dd * sqrt(rs * rs - dd * dd);
    fprintf(stderr, "  small disc across the water table: F_y = %.12g expected %.12g\n", F.y, rho * g * Aseg);
    ENSURE_REL(F.y, rho * g * Aseg, 1e-9);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_body_force(w, dd2, &dry, &M);
    /* dry: no pressure; only the drag of the round-off head gradient (1e-15) may remain */
    ENSURE_NEAR(hypot(dry.x, dry.y), 0, 1e-10 * rho * g * 3.141592653589793 * rs * rs);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_body_force(w, dw, &F, &M);
    ENSURE_REL(F.y, rho * g * 3.141592653589793 * rs * rs, 1e-10);
    pl_world_destroy(&w);
    return 0;
}

/* Prescribed inflow (eq. 3.14) on the floor of a 2 x 1 box, head 0 on the top: everything
   that enters leaves through the top (q W), and the head difference is q L / K (1D Darcy).
   With anisotropy D_y / D_x = 3 the same flux needs a third of the head difference. */
static int test_flux_and_anisotropy(void) {
    for (int k = 0; k < 2; k++) {
        double aniso = k ? 3.0 : 1.0;
        pl_world *w = new_world(0);
        pl_fluid_quad_def d = pl_default_fluid_quad_def();
        d.corners[0] = (pl_vec2){0, 0};
        d.corners[1] = (pl_vec2){2, 0};
        d.corners[2] = (pl_vec2){2, 1};
        d.corners[3] = (pl_vec2){0, 1};
        d.ndivx = 6;
        d.ndivy = 5;
        d.anisotropy = aniso;
        ENSURE(pl_world_add_fluid_quad(w, &d) >= 0);
        ENSURE(pl_world_add_fluid_flux(w, (pl_vec2){0, 0}, (pl_vec2){2, 0}, 0.01) >= 0);
        int top = pl_world_add_fluid_bc(w, (pl_vec2){0, 1}, (pl_vec2){2, 1}, 0);
        pl_world_set_flag(w, "FLUID_PERM", 0);
        pl_world_set_flag(w, "FLUID_PERM_HIGH", 0.5);
        ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
        pl_world_prepare(w); /* queries read only: build first */
        double out = -pl_world_fluid_line_inflow(w, top);
        double h0;
        pl_world_prepare(w); /* queries read only: build first */
        pl_world_fluid_pressure_at(w, (pl_vec2){1, 0}, NULL, &h0);
        fprintf(stderr, "  inflow 0.01 m/s x 2 m: outflow %.15g m^2/s; floor head %.12g (expected %.12g), D_y/D_x = %g\n", out,
                h0, 0.01 * 1 / (0.5 * aniso), aniso);
        pl_validation("fluid.flux_line", "flux line", "inflow leaves through the head line; floor head q L / D_y",
                      "1e-10", "D_y/D_x = %g: outflow %.1e, floor head %.1e", aniso, fabs(out - 0.02) / 0.02,
                      fabs(h0 - 0.01 / (0.5 * aniso)) / (0.01 / (0.5 * aniso)));
        ENSURE_REL(out, 0.02, 1e-10);
        ENSURE_REL(h0, 0.01 / (0.5 * aniso), 1e-10);
        pl_world_prepare(w); /* queries read only: build first */
        int ne = pl_world_fluid_triangle_count(w);
        double *vy = malloc(sizeof(double) * ne);
        pl_world_prepare(w); /* queries read only: build first */
        pl_world_fluid_copy_element_field(w, PL_FLUID_VELOCITY_Y, vy, ne);
        for (int e = 0; e < ne; e++) ENSURE_REL(vy[e], 0.01, 1e-9); /* Darcy velocity = inflow */
        free(vy);
        pl_world_destroy(&w);
    }
    return 0;
}

/* FLUID_PERM 2: per-element conductivities from the scene. Two layers in series along x
   (K1 = 2 for x < 0.5, K2 = 0.5 beyond), heads 1 and 0 at the ends of a unit square:
   flow q = dh / (L1 / K1 + L2 / K2) = 1 / (0.25 + 1) = 0.8 m^2/s per m of width. */
static int test_user_permeability(void) {
    pl_world *w = new_world(0);
    pl_fluid_quad_def d = pl_default_fluid_quad_def();
    d.ndivx = 8;
    d.ndivy = 3;
    ENSURE(pl_world_add_fluid_quad(w, &d) >= 0);
    int left = pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){0, 1}, 1);
    pl_world_add_fluid_bc(w, (pl_vec2){1, 0}, (pl_vec2){1, 1}, 0);
    pl_world_set_flag(w, "FLUID_PERM", 2);
    pl_world_prepare(w); /* queries read only: build first */
    int nn = pl_world_fluid_node_count(w), ne = pl_world_fluid_triangle_count(w);
    pl_vec2 *xy = malloc(sizeof(pl_vec2) * nn);
    int *t = malloc(sizeof(int) * 3 * ne);
    double *k = malloc(sizeof(double) * ne);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_nodes(w, xy, nn);
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_copy_triangles(w, t, ne);
    for (int e = 0; e < ne; e++) k[e] = (xy[t[3 * e]].x + xy[t[3 * e + 1]].x + xy[t[3 * e + 2]].x) / 3 < 0.5 ? 2.0 : 0.5;
    ENSURE(pl_world_fluid_solve_static(w) != PL_OK); /* values not given yet: refused */
    ENSURE(pl_world_fluid_set_element_permeability(w, k, ne) == PL_OK);
    ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
    pl_world_prepare(w); /* queries read only: build first */
    double q = pl_world_fluid_line_inflow(w, left), hm;
    pl_world_prepare(w); /* queries read only: build first */
    pl_world_fluid_pressure_at(w, (pl_vec2){0.5, 0.5}, NULL, &hm);
    fprintf(stderr, "  layers in series: flow %.15g (expected 0.8), head at the interface %.12g (expected 1 - q L1 / K1 = 0.8)\n", q, hm);
    ENSURE_REL(q, 0.8, 1e-10);
    ENSURE_REL(hm, 0.8, 1e-10);
    free(xy);
    free(t);
    free(k);
    pl_world_destroy(&w);
    return 0;
}

/* Output files: VTK (.vtu) with the expected counts, MATLAB geometry (one row per node). */
static int test_output_files(void) {
    pl_world *w = still_water(300, 3, 2, 1000);
    ENSURE(pl_world_fluid_solve_static(w) == PL_OK);
    pl_world_prepare(w); /* queries read only: build first */
    int nn = pl_world_fluid_node_count(w), ne = pl_world_fluid_triangle_count(w);
    /* the engine opens no files: without a writer from the host, output is refused */
    ENSURE(pl_world_fluid_write_vtu(w, "fluid_test.vtu") == PL_ERR_IO);
    ENSURE(strstr(pl_world_last_error(w), "no file writer") != NULL);
    FILE *none = fopen("fluid_test.vtu", "r");
    ENSURE(none == NULL);
    pl_world_set_file_writer(w, &pl_test_stdio_writer);
    ENSURE(pl_world_fluid_write_vtu(w, "fluid_test.vtu") == PL_OK);
    FILE *f = fopen("fluid_test.vtu", "r");
    ENSURE(f);
    char line[256], want[128];
    snprintf(want, sizeof want, "<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">", nn, ne);
    int found = 0, arrays = 0;
    while (fgets(line, sizeof line, f)) {
        if (strstr(line, want)) found = 1;
        if (strstr(line, "<DataArray")) arrays++;
    }
    fclose(f);
    ENSURE(found);
    ENSURE(arrays == 1 + 3 + 4 + 1 + 5); /* points, cells (3), node fields, velocity, element fields */
    ENSURE(pl_world_fluid_write_geometry(w, "fluid_test.flu") == PL_OK);
    f = fopen("fluid_test.flu", "r");
    ENSURE(f);
    int rows = 0;
    while (fgets(line, sizeof line, f)) rows += line[0] != '%';
    fclose(f);
    ENSURE(rows == nn);
    const char *files[1] = {"fluid_test.vtu"};
    double times[1] = {0};
    ENSURE(pl_world_fluid_write_pvd(w, "fluid_test.pvd", files, times, 1) == PL_OK);
    remove("fluid_test.vtu");
    remove("fluid_test.flu");
    remove("fluid_test.flu.tri");
    remove("fluid_test.pvd");
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(test_dam_flow);
    RUN(test_flux_and_anisotropy);
    RUN(test_user_permeability);
    RUN(test_output_files);
    RUN(test_hydrostatic);
    RUN(test_archimedes);
    RUN(test_partial_submersion);
    return pl_test_report();
}
