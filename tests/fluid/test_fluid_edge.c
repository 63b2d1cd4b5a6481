/* Buoyancy of grains pressed into a wall at the fluid mesh's edge (issue 13 item 6;
 * docs/fluid.md §6.1). Still water 0 <= y <= 0.1 m over 0 <= x <= 0.2 m (head line: pressure
 * head 0 on the top edge, no flow elsewhere: p = rho_f g (0.1 - y)), rho_f = 1000 kg/m^3,
 * g = 9.81. The floor (a segment wall) lies on the mesh's bottom edge y = 0 and the left wall on
 * its left edge x = 0, so a grain resting on them overlaps them and part of it lies beyond the
 * mesh.
 *
 * Reference: Archimedes for the whole grain, F = rho_f g A (0, 1), A the grain's full area, and
 * no horizontal force. The overlap is the soft contact's stand-in for a point contact (it shrinks
 * as 1/k_n); the water surrounds a real grain up to that point, so the grain displaces its whole
 * area whatever k_n. With A_above (the area above the floor) the floor would carry more than the
 * buoyant weight, by an amount that depends on the contact stiffness; with the mesh reaching below
 * the floor the code already gives rho_f g A exactly (the last case checks it), and two
 * overlapping grains inside the mesh each feel rho_f g A too.
 *
 * Every case is run three ways: with the grains' pieces cut for the drag (exact areas), in the
 * thesis's force mode (drag off, uniform permeability, no consolidation: no pieces are cut at all)
 * and with the pixel porosity method (FLUID_POROSITY_METHOD = 1); the edge is found from the mesh
 * in all three, so the force is the same. Before that, the thesis mode and the pixel method
 * still cut the outline at the mesh boundary: every case but the control failed there (floor disc
 * F_y / rho_f g A = -0.876 / 0.541 / 0.867 at k_n = 1e5 / 1e6 / 1e7).
 * Cases, each at k_n = 1e5, 1e6, 1e7 N/m: a disc (r = 2.5 mm, rho_s = 2650) and polygons (a
 * 5 mm square resting flat, a hexagon resting on a vertex) on the floor; a disc and a square of
 * the water's density pushed into the left wall at mid-depth by a horizontal load of 0.3 N; a
 * disc pushed into the bottom-left corner; and a disc and a square on the floor in upward seepage
 * (i = 0.5, head line on the floor, drag off, uniform conductivity): rho_f g A (1 + i). Each is settled (damped) to rest, then fixed and
 * stepped once (so that its pieces are cut where it is): the disc force then takes the Gauss form
 * on the pieces; moved by 1e-12 m, it takes the outline integral; both are checked to 1e-6 of
 * rho_f g A, as is the polygon's outline integral (the only form for polygons, printed twice) and its
 * moment (zero about the centroid).
 * The printed "old" column is the force with the mesh edge treated as dry, computed here from the
 * overlap (rho_f g A_above minus the boundary pressure times the chord, over rho_f g A); the floor
 * load is checked to 1e-3: k_n x overlap = (rho_s - rho_f) g A. */
#include "harness.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include <stdlib.h>
#include <string.h>

#define PI 3.141592653589793
#define RHO 1000.0
#define G 9.81
#define H 0.1
#define R 0.0025

enum { DISC, SQUARE, HEXAGON };

/* upward seepage: extra total head under the floor (0: still water); the drag is off then, so
   that the force is the pressure's, rho_f g A (1 + i) with i = DH / H */
static double DH = 0;

/* how the fluid sees the grains: pieces cut for the drag (exact areas), the thesis's force mode
   (drag off, uniform permeability, no consolidation: no pieces cut at all), or pixel areas */
enum { MODE_DRAG, MODE_THESIS, MODE_PIXEL };
static int MODE = MODE_DRAG;
/* worst relative force error and moment over every case (the validation row) */
static double WORST_F = 0, WORST_M = 0;
static const char *MODE_NAME[] = {"exact pieces", "thesis force mode", "pixel porosity"};

typedef struct {
    pl_world *w;
    int body;
    double area;
} setup;

static setup make(int shape, double kn, double rho_s, pl_vec2 c, pl_vec2 load, double mesh_bottom) {
    setup s = {0};
    pl_world_def wd = pl_default_world_def();
    wd.rayleigh_alpha = 30;
    wd.local_damping = 0.3;
    pl_world *w = pl_world_create(&wd);
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, mesh_bottom};
    q.corners[1] = (pl_vec2){0.2, mesh_bottom};
    q.corners[2] = (pl_vec2){0.2, H};
    q.corners[3] = (pl_vec2){0, H};
    q.ndivx = 8;
    q.ndivy = 4;
    pl_world_add_fluid_quad(w, &q);
    pl_world_add_fluid_bc(w, (pl_vec2){0, H}, (pl_vec2){0.2, H}, 0.0);
    if (DH != 0) pl_world_add_fluid_bc(w, (pl_vec2){0, mesh_bottom}, (pl_vec2){0.2, mesh_bottom}, H - mesh_bottom + DH);
    /* with seepage: drag off, and in the modes that cut pieces the permeability "from porosity"
       with equal low and high values (uniform, so the gradient is uniform) */
    const char *names[] = {"FLUIDS_ON", "FIRST_STEP_STATIC", "FLUID_PERM", "FLUID_DENSITY", "FLUID_SOLVE_TIMESTEPS",
                           "FLUID_DRAG", "FLUID_PERM_LOW", "FLUID_PERM_HIGH", "FLUID_POROSITY_METHOD"};
    const int thesis = MODE == MODE_THESIS;
    const double vals[] = {1, 1, DH != 0 && !thesis ? 1 : 0, RHO, 1, DH != 0 || thesis ? 0 : 1, 1e-3, 1e-3,
                           MODE == MODE_PIXEL ? 1 : 0};
    for (int k = 0; k < 9; k++)
        if (pl_world_set_flag(w, names[k], vals[k]) != PL_OK) fprintf(stderr, "%s\n", pl_world_last_error(w));
    pl_material_def md = pl_default_material_def();
    md.name = "grain";
    md.density = rho_s;
    md.kn = kn;
    md.friction = 0.3;
    int mat = pl_world_add_material(w, &md);
    pl_body_def fl = pl_default_body_def();
    fl.shape = PL_SHAPE_SEGMENT;
    fl.motion = PL_MOTION_FIXED;
    fl.material = mat;
    fl.a = (pl_vec2){-0.1, 0};
    fl.b = (pl_vec2){0.3, 0};
    pl_world_add_body(w, &fl);
    fl.a = (pl_vec2){0, 0};
    fl.b = (pl_vec2){0, 0.2};
    pl_world_add_body(w, &fl);
    pl_body_def bd = pl_default_body_def();
    bd.material = mat;
    pl_vec2 v[6];
    if (shape == DISC) {
        bd.shape = PL_SHAPE_DISC;
        bd.position = c;
        bd.radius = R;
        s.area = PI * R * R;
    } else if (shape == SQUARE) {
        const double h = R; /* 5 mm square */
        v[0] = (pl_vec2){c.x - h, c.y - h};
        v[1] = (pl_vec2){c.x + h, c.y - h};
        v[2] = (pl_vec2){c.x + h, c.y + h};
        v[3] = (pl_vec2){c.x - h, c.y + h};
        bd.shape = PL_SHAPE_POLYGON;
        bd.vertices = v;
        bd.vertex_count = 4;
        s.area = 4 * h * h;
    } else {
        for (int k = 0; k < 6; k++) /* vertex down: k = 0 at -90 degrees */
            v[k] = (pl_vec2){c.x + R * cos(-PI / 2 + k * PI / 3), c.y + R * sin(-PI / 2 + k * PI / 3)};
        bd.shape = PL_SHAPE_POLYGON;
        bd.vertices = v;
        bd.vertex_count = 6;
        s.area = 1.5 * sqrt(3.0) * R * R;
    }
    s.body = pl_world_add_body(w, &bd);
    if (load.x != 0 || load.y != 0) pl_world_set_body_load(w, s.body, load, 0);
    s.w = w;
    return s;
}

/* Settles the grain, fixes it, cuts its pieces where it is; returns the overlaps with the floor
   and the left wall (m) through *dy, *dx. */
static int settle(setup *s, int shape, double *dx, double *dy) {
    if (pl_world_step(s->w, 1) != PL_OK) {
        fprintf(stderr, "step: %s\n", pl_world_last_error(s->w));
        return 1;
    }
    double dt = pl_world_dt(s->w);
    int n = (int)(0.25 / dt);
    if (pl_world_step(s->w, n) != PL_OK) {
        fprintf(stderr, "step: %s\n", pl_world_last_error(s->w));
        return 1;
    }
    pl_world_set_flag(s->w, "DT", dt); /* no dynamic body left to size the step */
    pl_world_set_body_motion(s->w, s->body, PL_MOTION_FIXED);
    if (pl_world_step(s->w, 1) != PL_OK) {
        fprintf(stderr, "step: %s\n", pl_world_last_error(s->w));
        return 1;
    }
    pl_vec2 v[8];
    double lo_x = INFINITY, lo_y = INFINITY;
    pl_body_info bi;
    pl_world_body_info(s->w, s->body, &bi);
    if (shape == DISC) {
        lo_x = bi.position.x - R;
        lo_y = bi.position.y - R;
    } else {
        int nv = pl_world_body_vertices(s->w, s->body, v, 8);
        for (int k = 0; k < nv; k++) {
            lo_x = fmin(lo_x, v[k].x);
            lo_y = fmin(lo_y, v[k].y);
        }
    }
    *dx = -lo_x;
    *dy = -lo_y;
    return 0;
}

/* Fluid force (and moment) on the grain now, and after a 1e-12 m shift (outline integral for a
   disc, whose pieces are then stale). */
static int check(setup *s, int shape, const char *what, double kn, double dx, double dy, double old) {
    const double ref = RHO * G * s->area * (1 + DH / H);
    pl_vec2 F = {0, 0};
    double M = 0;
    if (pl_world_fluid_body_force(s->w, s->body, &F, &M) != PL_OK) {
        fprintf(stderr, "fluid_body_force: %s\n", pl_world_last_error(s->w));
        return 1;
    }
    pl_body_info bi;
    pl_world_body_info(s->w, s->body, &bi);
    pl_world_set_body_position(s->w, s->body, (pl_vec2){bi.position.x + 1e-12, bi.position.y}, bi.angle);
    pl_vec2 F2 = {0, 0};
    double M2 = 0;
    if (pl_world_fluid_body_force(s->w, s->body, &F2, &M2) != PL_OK) {
        fprintf(stderr, "fluid_body_force: %s\n", pl_world_last_error(s->w));
        return 1;
    }
    fprintf(stderr,
            "  %-28s %-17s kn %.0e: overlap floor %.3e wall %.3e m; F/F_ref - (0, 1) = (%+.1e, %+.1e) %s, (%+.1e, %+.1e) "
            "outline; moment %+.1e N m; old (edge dry) %.3f\n",
            what, MODE_NAME[MODE], kn, dy > 0 ? dy : 0, dx > 0 ? dx : 0, F.x / ref, F.y / ref - 1,
            shape == DISC && MODE == MODE_DRAG ? "pieces" : "outline", F2.x / ref, F2.y / ref - 1,
            shape == DISC ? 0.0 : M2, old);
    WORST_F = fmax(WORST_F, fmax(fmax(fabs(F.y / ref - 1), fabs(F.x / ref)), fmax(fabs(F2.y / ref - 1), fabs(F2.x / ref))));
    if (shape != DISC) WORST_M = fmax(WORST_M, fabs(M2));
    ENSURE(dx > 0 || dy > 0); /* it does reach beyond the mesh */
    ENSURE_NEAR(F.y / ref, 1, 1e-6);
    ENSURE_NEAR(F.x / ref, 0, 1e-6);
    ENSURE_NEAR(F2.y / ref, 1, 1e-6);
    ENSURE_NEAR(F2.x / ref, 0, 1e-6);
    if (shape != DISC) ENSURE(fabs(M2) <= 1e-6 * ref * R);
    return 0;
}

/* Force of the old outline integral (p = 0 beyond the mesh) on a disc pressed into the floor by
   dy: rho g A_above - p_floor x chord, over rho g A. */
static double old_floor_disc(double dy) {
    if (!(dy > 0)) return 1;
    double a = R - dy, half = sqrt(R * R - a * a);
    double seg = R * R * acos(a / R) - a * half;
    return (PI * R * R - seg - H * 2 * half) / (PI * R * R);
}

static int case_floor(int shape, const char *what) {
    const double kns[3] = {1e5, 1e6, 1e7};
    int bad = 0;
    for (int k = 0; k < 3; k++) {
        setup s = make(shape, kns[k], 2650, (pl_vec2){0.1, R}, (pl_vec2){0, 0}, 0); /* touching the floor */
        double dx, dy;
        if (settle(&s, shape, &dx, &dy)) return 1;
        bad |= check(&s, shape, what, kns[k], dx, dy, shape == DISC && DH == 0 ? old_floor_disc(dy) : NAN);
        if (shape == DISC && DH == 0) {
            /* the floor carries the grain's submerged weight (linear contact: k_n x overlap) */
            double ratio = kns[k] * dy / ((2650 - RHO) * G * s.area);
            fprintf(stderr, "    floor load / submerged weight (rho_s - rho_f) g A = %.6f\n", ratio);
            if (!(fabs(ratio - 1) <= 1e-3)) {
                fprintf(stderr, "%s:%d: floor load off the submerged weight\n", __FILE__, __LINE__);
                bad = 1;
            }
        }
        pl_world_destroy(&s.w);
    }
    return bad; /* all three stiffnesses are run (and printed) even when one fails */
}

static int test_disc_on_floor(void) { return case_floor(DISC, "disc on the floor"); }
static int test_square_on_floor(void) { return case_floor(SQUARE, "square on the floor"); }
static int test_hexagon_on_floor(void) { return case_floor(HEXAGON, "hexagon (vertex) on the floor"); }

static int case_wall(int shape, const char *what, int corner) {
    const double kns[3] = {1e5, 1e6, 1e7};
    int bad = 0;
    for (int k = 0; k < 3; k++) {
        pl_vec2 c = corner ? (pl_vec2){R, R} : (pl_vec2){R, 0.05};
        setup s = make(shape, kns[k], corner ? 2650 : RHO, c, (pl_vec2){-0.3, 0}, 0);
        double dx, dy;
        if (settle(&s, shape, &dx, &dy)) return 1;
        bad |= check(&s, shape, what, kns[k], dx, dy, NAN);
        pl_world_destroy(&s.w);
    }
    return bad;
}

static int test_disc_into_side_wall(void) { return case_wall(DISC, "disc into the side wall", 0); }
static int test_square_into_side_wall(void) { return case_wall(SQUARE, "square into the side wall", 0); }
static int test_disc_into_corner(void) { return case_wall(DISC, "disc into the corner", 1); }
static int test_square_into_corner(void) { return case_wall(SQUARE, "square into the corner", 1); }

/* Control: the mesh reaching 1 cm below the floor (the grain wholly inside it). */
static int test_mesh_below_floor(void) {
    setup s = make(DISC, 1e5, 2650, (pl_vec2){0.1, R}, (pl_vec2){0, 0}, -0.01);
    double dx, dy;
    if (settle(&s, DISC, &dx, &dy)) return 1;
    int bad = check(&s, DISC, "disc, mesh below the floor", 1e5, dx, dy, 1);
    pl_world_destroy(&s.w);
    return bad;
}

/* Upward seepage through the mesh (head line on the floor: i = 0.5, uniform gradient): the
   field beyond the floor is the boundary element's, extended; the pressure force is
   -A grad p = rho_f g A (1 + i) for the whole area. */
static int test_seepage_on_floor(void) {
    DH = 0.5 * H;
    int bad = case_floor(DISC, "disc on the floor, i = 0.5") | case_floor(SQUARE, "square on the floor, i = 0.5");
    DH = 0;
    return bad;
}

int main(void) {
    for (MODE = MODE_DRAG; MODE <= MODE_PIXEL; MODE++) {
        fprintf(stderr, "-- %s\n", MODE_NAME[MODE]);
        RUN(test_disc_on_floor);
        RUN(test_square_on_floor);
        RUN(test_hexagon_on_floor);
        RUN(test_disc_into_side_wall);
        RUN(test_square_into_side_wall);
        RUN(test_disc_into_corner);
        RUN(test_square_into_corner);
        RUN(test_mesh_below_floor);
        RUN(test_seepage_on_floor);
    }
    pl_validation("fluid.edge",
                  "grains pressed into a floor, side wall and corner at the mesh's edge (discs, squares, hexagon; "
                  "k_n = 10⁵–10⁷ N/m; pieces, thesis force mode, pixel porosity; also in seepage i = 0.5)",
                  "ρ_f g A (1 + i) for the whole area, no moment", "1e-6 of ρ_f g A",
                  "worst %.1e of ρ_f g A; moments ≤ %.0e N m", WORST_F, WORST_M);
    return pl_test_report();
}
