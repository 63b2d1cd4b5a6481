/* Shared set-ups of the boundary-element Stokes tests and benchmark (seed 003 §4.4): a channel
 * box with inlet/outlet profiles and a disc or rectangle inside, solved with the kernels of
 * fluid/stokes_bem/stokes_internal.h (no world). */
#ifndef PL_TEST_STOKES_CASES_H
#define PL_TEST_STOKES_CASES_H
#include "fluid/stokes_bem/stokes_internal.h"
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
#endif
