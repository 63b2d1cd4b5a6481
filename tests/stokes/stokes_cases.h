/* Shared set-ups of the boundary-element Stokes tests and benchmark (seed 003 §4.4): a channel
 * box with inlet/outlet profiles and a disc or rectangle inside, solved with the kernels of
 * fluid/stokes_bem/stokes_internal.h (no world); and the §5.1 disc between walls as a world
 * with one of the fluid rungs (Stokes, hydrostatic, Darcy), the benchmark's "other rungs"
 * comparison and its regression test (test_stokes_rungs). */
#ifndef PL_TEST_STOKES_CASES_H
#define PL_TEST_STOKES_CASES_H
#include "fluid/stokes_bem/stokes_internal.h"
#include "porelab/darcy.h"
#include "porelab/fluid.h"
#include "porelab/hydrostatic.h"
#include "porelab/stokes.h"
#include "porelab/world.h"
#include <math.h>
#include <string.h>

/* Box [-hx, hx] x [-hy, hy] counter-clockwise as curve 0 (fixed): sides bottom, right, top,
   left with nx elements on the long sides and ny on the short ones. */
static inline void sc_box(pl_sb_bnd *b, double hx, double hy, int nx, int ny) {
    pl_sb_bnd_curve(b, (pl_vec2){0, 0}, 0);
    pl_sb_bnd_line(b, (pl_vec2){-hx, -hy}, (pl_vec2){hx, -hy}, nx);
    pl_sb_bnd_line(b, (pl_vec2){hx, -hy}, (pl_vec2){hx, hy}, ny);
    pl_sb_bnd_line(b, (pl_vec2){hx, hy}, (pl_vec2){-hx, hy}, nx);
    pl_sb_bnd_line(b, (pl_vec2){-hx, hy}, (pl_vec2){-hx, -hy}, ny);
    b->nfixed = 1;
}

/* Container velocities: Poiseuille u = 1.5 U (1 - (y/hy)^2) at inlet/outlet, walls at rest
   (profile = 0), or everything moving at U (profile = 1). */
static inline void sc_box_velocity(pl_sb_bnd *b, double hy, double U, int profile) {
    for (int e = b->curve_start[0]; e < b->curve_start[1]; e++)
        for (int m = 0; m < 2; m++) {
            const pl_vec2 x = pl_sb_node_pos(b->a[e], b->b[e], m);
            const int side = fabs(b->a[e].x - b->b[e].x) < 1e-12; /* inlet / outlet */
            double u = 0;
            if (profile == 0) u = side ? 1.5 * U * (1 - (x.y / hy) * (x.y / hy)) : 0;
            else u = U;
            b->u[4 * e + 2 * m] = u;
            b->u[4 * e + 2 * m + 1] = 0;
            b->kind[4 * e + 2 * m] = b->kind[4 * e + 2 * m + 1] = PL_SB_VEL;
        }
}

/* Rectangle [-lx, lx] x [-ly, ly] clockwise (a particle), n elements per unit... per side. */
static inline void sc_rect(pl_sb_bnd *b, pl_vec2 c, double lx, double ly, int nx, int ny) {
    pl_sb_bnd_curve(b, c, 1);
    pl_sb_bnd_line(b, (pl_vec2){c.x - lx, c.y - ly}, (pl_vec2){c.x - lx, c.y + ly}, ny);
    pl_sb_bnd_line(b, (pl_vec2){c.x - lx, c.y + ly}, (pl_vec2){c.x + lx, c.y + ly}, nx);
    pl_sb_bnd_line(b, (pl_vec2){c.x + lx, c.y + ly}, (pl_vec2){c.x + lx, c.y - ly}, ny);
    pl_sb_bnd_line(b, (pl_vec2){c.x + lx, c.y - ly}, (pl_vec2){c.x - lx, c.y - ly}, nx);
}

/* §4.4.1 / §4.4.2 / Faxén: cylinder of radius 1 at the centre of a channel of half-width
   1/k and half-length hx; profile 0: Poiseuille past the fixed cylinder; 1: walls and ends at
   U (= the cylinder translating at -U through fluid at rest, in the walls' frame). Returns the
   drag F_x/(μ U) on the cylinder; *fy gets F_y/(μU). */
static inline double sc_cylinder(const pl_sb_rules *r, pl_sb_solver *s, double k, double hx, int nwall, int nend,
                                 int ndisc, int profile, double *fy) {
    pl_sb_bnd b;
    memset(&b, 0, sizeof b);
    const double hy = 1 / k, mu = 1, U = 1;
    sc_box(&b, hx, hy, nwall, nend);
    sc_box_velocity(&b, hy, U, profile);
    pl_sb_bnd_disc(&b, (pl_vec2){0, 0}, 1, ndisc, 1, 0);
    pl_sb_bnd_rigid(&b, 1, (pl_vec2){0, 0}, 0);
    double F = NAN;
    if (pl_sb_solve(s, &b, r, mu, NULL) == PL_OK) {
        pl_vec2 f;
        double M;
        pl_sb_curve_load(&b, b.t, b.curve_start[1], b.curve_start[2], (pl_vec2){0, 0}, &f, &M);
        F = f.x / (mu * U);
        if (fy) *fy = f.y / (mu * U);
    }
    pl_sb_bnd_free(&b);
    return F;
}

/* Faxén's series for a cylinder translating midway between plates, fluid at rest at infinity
   (Happel & Brenner 1965, eq. 7-5.9): F/(μU) = 4π / (ln(1/k) - 0.9157 + 1.7244 k^2 - 1.7302 k^4
   + 2.4056 k^6 - 4.5913 k^8). */
static inline double sc_faxen(double k) {
    const double k2 = k * k;
    return 4 * M_PI / (log(1 / k) - 0.9157 + 1.7244 * k2 - 1.7302 * k2 * k2 + 2.4056 * k2 * k2 * k2 -
                       4.5913 * k2 * k2 * k2 * k2);
}
/* Takaisi's approximation (seed 003 eq. 5.1): K/μ = π (8 - 4k^2) / (2 ln(1/k) + 3.4486 k^2 - 1.8312). */
static inline double sc_takaisi(double k) {
    return M_PI * (8 - 4 * k * k) / (2 * log(1 / k) + 3.4486 * k * k - 1.8312);
}

/* A world with a closed box [x0, x1] x [y0, y1] of four fixed walls (bodies 0..3: bottom,
   right, top, left; overlapping at the corners as scenes build them) and one material (the
   grains' density and friction; k_n = 1e6). */
static inline pl_world *sc_world_box(double x0, double x1, double y0, double y1, double g, double dt,
                                     double density, double friction) {
    pl_world_def wd = pl_default_world_def();
    wd.energy_surge_ratio = 1e12; /* walls driving the fluid: see docs/stokes.md, Limits */
    wd.gravity = (pl_vec2){0, g};
    wd.dt = dt;
    pl_world *w = pl_world_create(&wd);
    pl_material_def md = pl_default_material_def();
    md.name = "grain";
    md.density = density;
    md.kn = 1e6;
    md.friction = friction;
    pl_world_add_material(w, &md);
    const double e = 0.1 * (x1 - x0);
    const pl_vec2 seg[4][2] = {{{x0 - e, y0}, {x1 + e, y0}},
                               {{x1, y0 - e}, {x1, y1 + e}},
                               {{x1 + e, y1}, {x0 - e, y1}},
                               {{x0, y1 + e}, {x0, y0 - e}}};
    for (int k = 0; k < 4; k++) {
        pl_body_def b = pl_default_body_def();
        b.shape = PL_SHAPE_SEGMENT;
        b.motion = PL_MOTION_FIXED;
        b.material = 0;
        b.a = seg[k][0];
        b.b = seg[k][1];
        pl_world_add_body(w, &b);
    }
    return w;
}

static inline int sc_world_disc(pl_world *w, pl_vec2 c, double r) {
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_DISC;
    b.material = 0;
    b.position = c;
    b.radius = r;
    return pl_world_add_body(w, &b);
}

/* The fluid rungs of the §5.1 comparison (docs/stokes.md, Cost) */
typedef enum { SC_RUNG_STOKES, SC_RUNG_HYDROSTATIC, SC_RUNG_DARCY } sc_rung;

/* Seed 003 §5.1 in CGS: a disc r = 0.5 cm, rho_s = 2 g/cm^3 at the centre of a box 5 cm wide and
   40 cm high filled to its top with a liquid rho_l = 1 g/cm^3, mu = 50 P; g = 980 cm/s^2 down,
   steps of 0.5 ms. The Darcy fluid (1 cm cells, Kozeny-Carman permeability, head 0 on the top
   side) starts from its static (hydrostatic) field, FIRST_STEP_STATIC: from zero pressure the
   water column first drains downwards through the grain and drags it faster than free fall.
   Returns the world, the disc's body id in *disc and in *st the model's refusal (PL_OK). */
static inline pl_world *sc_disc_rung(sc_rung m, int *disc, pl_status *st) {
    pl_world *w = sc_world_box(-2.5, 2.5, -20, 20, -980, 5e-4, 2.0, pl_default_material_def().friction);
    *disc = sc_world_disc(w, (pl_vec2){0, 0}, 0.5);
    *st = PL_OK;
    if (m == SC_RUNG_STOKES) {
        pl_stokes_def sd = pl_default_stokes_def();
        sd.viscosity = 50;
        sd.density = 1;
        sd.disc_elements = 32;
        sd.element_length = 0.25;
        *st = pl_world_attach_stokes(w, &sd);
    } else if (m == SC_RUNG_HYDROSTATIC) {
        pl_hydrostatic_def hd = pl_default_hydrostatic_def();
        hd.x_min = -2.5;
        hd.x_max = 2.5;
        hd.bottom = -20;
        hd.level = 20;
        hd.density = 1;
        *st = pl_world_attach_hydrostatic(w, &hd);
    } else {
        pl_fluid_quad_def q = pl_default_fluid_quad_def();
        q.corners[0] = (pl_vec2){-2.5, -20};
        q.corners[1] = (pl_vec2){2.5, -20};
        q.corners[2] = (pl_vec2){2.5, 20};
        q.corners[3] = (pl_vec2){-2.5, 20};
        q.ndivx = 5;
        q.ndivy = 40;
        if (pl_world_add_fluid_quad(w, &q) < 0) *st = PL_ERR_ARG;
        pl_darcy_def dd = pl_default_darcy_def();
        dd.on = 1;
        dd.density = 1;
        dd.viscosity = 50;
        dd.perm_mode = 1;
        dd.first_step_static = 1;
        if (*st == PL_OK) *st = pl_world_set_darcy(w, &dd);
        if (*st == PL_OK) pl_world_add_fluid_bc(w, (pl_vec2){-2.5, 20}, (pl_vec2){2.5, 20}, 0);
    }
    return w;
}
#endif
