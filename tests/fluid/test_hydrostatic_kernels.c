/* Hydrostatic water kernels without a world (engine/src/fluid/hydrostatic/hydrostatic_internal.h).
 * References:
 * - disc segment: numerical quadrature (u = -r cos theta, 20,000 Simpson panels) at 9 depths, and
 *   the closed forms at depth 0 (nothing), r (half disc: pi r^2 / 2, centroid 4 r / (3 pi) below,
 *   J = pi r^4 / 4) and 2r (pi r^2, the centre, pi r^4 / 2); also with gravity tilted 30 degrees;
 * - polygons: a square rotated 45 degrees (half-diagonal d) cut at its centre (area d^2, centroid
 *   d/3 below) and at d/2 below it (d^2 / 4, centroid 2d/3 below); the triangle (0,0) (1,0) (0,1)
 *   cut at y = 1/2 (area 3/8, centroid (7/18, 2/9));
 * - the force and moment equal the pressure integral -∮ p n ds around the outline, done
 *   numerically (Gauss-Legendre on 400 pieces per edge), for tilted gravity too;
 * - a tilted box floating at half density: righting moment rho g A GZ with the wall-sided
 *   formula GZ = sin(theta) (GM + BM tan^2(theta) / 2), BM = L^2 / (12 d), GM = BM - BG; a tall
 *   box (GM < 0) gets a capsizing moment;
 * - the moving level's root to 1e-12; the drag force -beta A v and its dissipation. */
#include "harness.h"
#include "fluid/hydrostatic/hydrostatic_internal.h"
#include "geom/polygon.h"
#include <string.h>

#define PI 3.14159265358979323846

static pl_hs_water water(pl_vec2 gravity, double level) {
    pl_hydrostatic_def d = pl_default_hydrostatic_def();
    d.x_min = -10;
    d.x_max = 10;
    d.bottom = -10;
    d.level = level;
    return pl_hs_water_make(&d, gravity);
}

/* quadrature of the disc's part below u = s (u along up): area, first moment along up, J */
static void disc_quadrature(double r, double s, double *A, double *U, double *J) {
    double phi = acos(fmax(-1, fmin(1, -s / r)));
    const int n = 20000;
    const double h = phi / n;
    *A = *U = *J = 0;
    for (int k = 0; k <= n; k++) {
        const double th = k * h, wgt = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
        const double u = -r * cos(th), w = 2 * r * sin(th), du = r * sin(th);
        *A += wgt * w * du;
        *U += wgt * u * w * du;
        *J += wgt * (u * u * w + w * w * w / 12) * du;
    }
    *A *= h / 3;
    *U *= h / 3;
    *J *= h / 3;
}

static int test_disc_segment_quadrature(void) {
    const double r = 0.05;
    const pl_vec2 c = {0.3, 0.2};
    double worst = 0;
    for (int k = 0; k <= 8; k++) {
        const double depth = 2 * r * (k == 0 ? 1e-3 : k / 8.0);
        const double s = depth - r;
        pl_hs_part p;
        pl_hs_disc_segment(c, r, (pl_vec2){0, 1}, s, &p);
        double A, U, J;
        disc_quadrature(r, s, &A, &U, &J);
        const double e = fmax(fabs(p.area - A) / A, fmax(fabs(p.centroid.y - c.y - U / A) / r, fabs(p.j_c - J) / J));
        worst = fmax(worst, e);
        ENSURE_REL(p.area, A, 1e-9);
        ENSURE_NEAR(p.centroid.y - c.y, U / A, 1e-9 * r);
        ENSURE_NEAR(p.centroid.x, c.x, 1e-15);
        ENSURE_REL(p.j_c, J, 1e-9);
    }
    fprintf(stderr, "  disc segment vs quadrature, 9 depths: worst relative difference %.2e\n", worst);
    return 0;
}

static int test_disc_segment_closed_forms(void) {
    const double r = 0.05;
    const pl_vec2 c = {0, 0}, up = {0, 1};
    pl_hs_part p;
    pl_hs_disc_segment(c, r, up, -r, &p); /* depth 0 */
    ENSURE(p.area == 0);
    pl_hs_disc_segment(c, r, up, 0, &p); /* depth r */
    ENSURE_REL(p.area, PI * r * r / 2, 1e-14);
    ENSURE_NEAR(p.centroid.y, -4 * r / (3 * PI), 1e-15);
    ENSURE_REL(p.j_c, PI * r * r * r * r / 4, 1e-14);
    pl_hs_disc_segment(c, r, up, r, &p); /* depth 2r */
    ENSURE_REL(p.area, PI * r * r, 1e-15);
    ENSURE_NEAR(p.centroid.y, 0, 1e-18);
    ENSURE_REL(p.j_c, PI * r * r * r * r / 2, 1e-15);
    /* barely wetted: area of the segment of height e is (4/3) sqrt(2 r e) e (1 + O(e/r)) */
    const double e = 1e-9 * r;
    pl_hs_disc_segment(c, r, up, e - r, &p);
    /* (s = e - r itself carries r x 1e-16 of roundoff: 1e-7 of e) */
    ENSURE_REL(p.area, 4.0 / 3.0 * sqrt(2 * r * e) * e, 1e-6);
    ENSURE_NEAR(p.centroid.y, -r + 0.6 * e, 1e-6 * e); /* 3/5 of the height from the vertex */
    /* tilted gravity (30 degrees): the same segment turned, centroid along up; the world-level
       entry point (pl_hs_disc_part) agrees */
    const double a = 30 * PI / 180;
    const pl_vec2 g = {9.81 * sin(a), -9.81 * cos(a)};
    pl_hs_water wt = water(g, 0.01);
    pl_hs_disc_part(&wt, wt.level, c, r, &p);
    double A, U, J;
    disc_quadrature(r, 0.01, &A, &U, &J);
    ENSURE_REL(p.area, A, 1e-9);
    ENSURE_NEAR(p.centroid.x, U / A * wt.up.x, 1e-12);
    ENSURE_NEAR(p.centroid.y, U / A * wt.up.y, 1e-12);
    fprintf(stderr, "  closed forms at depth 0, r, 2r; tilted up = (%.4f, %.4f): centroid (%.6f, %.6f)\n", wt.up.x,
            wt.up.y, p.centroid.x, p.centroid.y);
    return 0;
}

static int test_polygon_parts(void) {
    const pl_vec2 g = {0, -9.81};
    const double d = 0.1;
    const pl_vec2 sq[4] = {{0, -d}, {d, 0}, {0, d}, {-d, 0}}; /* square rotated 45 degrees */
    pl_hs_water wt = water(g, 0);
    pl_hs_part p;
    pl_hs_polygon_part(&wt, 0, sq, 4, (pl_vec2){0, 0}, &p);
    ENSURE_REL(p.area, d * d, 1e-14);
    ENSURE_NEAR(p.centroid.y, -d / 3, 1e-15);
    ENSURE_NEAR(p.centroid.x, 0, 1e-15);
    pl_hs_polygon_part(&wt, -d / 2, sq, 4, (pl_vec2){0, 0}, &p);
    ENSURE_REL(p.area, d * d / 4, 1e-14);
    ENSURE_NEAR(p.centroid.y, -2 * d / 3, 1e-15);
    const pl_vec2 tri[3] = {{0, 0}, {1, 0}, {0, 1}};
    pl_hs_polygon_part(&wt, 0.5, tri, 3, (pl_vec2){1.0 / 3, 1.0 / 3}, &p);
    ENSURE_REL(p.area, 0.375, 1e-14);
    ENSURE_NEAR(p.centroid.x, 7.0 / 18, 1e-14);
    ENSURE_NEAR(p.centroid.y, 2.0 / 9, 1e-14);
    /* fully submerged and fully dry */
    pl_hs_polygon_part(&wt, 2, tri, 3, (pl_vec2){1.0 / 3, 1.0 / 3}, &p);
    ENSURE_REL(p.area, 0.5, 1e-15);
    pl_hs_polygon_part(&wt, -1, tri, 3, (pl_vec2){1.0 / 3, 1.0 / 3}, &p);
    ENSURE(p.area == 0);
    /* crossing the side wall x_max = 0.5 of a narrow tank, surface y = 0.5: the square
       [0, 1] x [0, 1] keeps [0, 0.5] x [0, 0.5] */
    pl_hydrostatic_def hd = pl_default_hydrostatic_def();
    hd.x_min = -1;
    hd.x_max = 0.5;
    hd.bottom = 0;
    hd.level = 0.5;
    pl_hs_water nt = pl_hs_water_make(&hd, g);
    const pl_vec2 box[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    pl_hs_polygon_part(&nt, 0.5, box, 4, (pl_vec2){0.5, 0.5}, &p);
    ENSURE_REL(p.area, 0.25, 1e-14);
    ENSURE_NEAR(p.centroid.x, 0.25, 1e-14);
    ENSURE_NEAR(p.centroid.y, 0.25, 1e-14);
    /* a disc across that wall: the disc-polygon clip (quarter disc below the surface at its
       centre and left of the wall through its centre) */
    pl_hs_disc_part(&nt, 0.5, (pl_vec2){0.5, 0.5}, 0.1, &p);
    ENSURE_REL(p.area, PI * 0.01 / 4, 1e-12);
    ENSURE_NEAR(p.centroid.x, 0.5 - 0.4 / (3 * PI), 1e-12);
    ENSURE_NEAR(p.centroid.y, 0.5 - 0.4 / (3 * PI), 1e-12);
    fprintf(stderr, "  rotated square at 0 and -d/2, triangle at 1/2, wall cuts: hand values to 1e-14\n");
    return 0;
}

/* -∮ p n ds and its moment about c, numerically (p = rho g (level - h) where positive) */
static void pressure_integral(const pl_hs_water *wt, const pl_vec2 *v, int n, pl_vec2 c, pl_vec2 *F, double *M) {
    static const double gx[3] = {-0.7745966692414834, 0, 0.7745966692414834}, gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    const int pieces = 400;
    *F = (pl_vec2){0, 0};
    *M = 0;
    for (int k = 0; k < n; k++) {
        const pl_vec2 a = v[k], b = v[(k + 1) % n];
        const pl_vec2 e = {b.x - a.x, b.y - a.y};
        const pl_vec2 nrm_ds = {e.y, -e.x}; /* outward normal x length (counter-clockwise) */
        for (int j = 0; j < pieces; j++)
            for (int q = 0; q < 3; q++) {
                const double t = (j + 0.5 + 0.5 * gx[q]) / pieces, wq = gw[q] * 0.5 / pieces;
                const pl_vec2 x = {a.x + t * e.x, a.y + t * e.y};
                const double depth = wt->level - (x.x * wt->up.x + x.y * wt->up.y);
                const double p = depth > 0 ? wt->rho * wt->g * depth : 0;
                const pl_vec2 f = {-p * nrm_ds.x * wq, -p * nrm_ds.y * wq};
                F->x += f.x;
                F->y += f.y;
                *M += (x.x - c.x) * f.y - (x.y - c.y) * f.x;
            }
    }
}

static int test_force_is_pressure_integral(void) {
    const double angles[3] = {0, 20, -35};
    double worst = 0;
    for (int a = 0; a < 3; a++) {
        const double ga = angles[a] * PI / 180;
        pl_hs_water wt = water((pl_vec2){9.81 * sin(ga), -9.81 * cos(ga)}, 0.013);
        /* a pentagon turned by 0.3 rad, partially submerged */
        pl_vec2 v[5];
        for (int k = 0; k < 5; k++) {
            const double t = 0.3 + 2 * PI * k / 5, rr = 0.05 * (1 + 0.2 * (k % 2));
            v[k] = (pl_vec2){0.01 + rr * cos(t), rr * sin(t)};
        }
        const pl_vec2 c = pl_poly_centroid(v, 5);
        pl_hs_part p;
        pl_hs_polygon_part(&wt, wt.level, v, 5, c, &p);
        pl_vec2 F, Fn;
        double Mom, Mn;
        pl_hs_load(&wt, &p, c, (pl_vec2){0, 0}, 0, &F, &Mom);
        pressure_integral(&wt, v, 5, c, &Fn, &Mn);
        const double fs = wt.rho * wt.g * pl_poly_signed_area(v, 5);
        ENSURE_NEAR(F.x, Fn.x, 1e-7 * fs);
        ENSURE_NEAR(F.y, Fn.y, 1e-7 * fs);
        ENSURE_NEAR(Mom, Mn, 1e-7 * fs * 0.05);
        worst = fmax(worst, fmax(hypot(F.x - Fn.x, F.y - Fn.y) / fs, fabs(Mom - Mn) / (fs * 0.05)));
        /* the disc: pressure integral over a 4096-gon */
        pl_vec2 dv[4096];
        const double r = 0.04;
        for (int k = 0; k < 4096; k++) dv[k] = (pl_vec2){0.02 + r * cos(2 * PI * k / 4096), r * sin(2 * PI * k / 4096)};
        pl_hs_disc_part(&wt, wt.level, (pl_vec2){0.02, 0}, r, &p);
        pl_hs_load(&wt, &p, (pl_vec2){0.02, 0}, (pl_vec2){0, 0}, 0, &F, &Mom);
        pressure_integral(&wt, dv, 4096, (pl_vec2){0.02, 0}, &Fn, &Mn);
        const double fd = wt.rho * wt.g * PI * r * r;
        ENSURE_NEAR(F.x, Fn.x, 2e-6 * fd); /* the 4096-gon's own area differs by 4e-7 */
        ENSURE_NEAR(F.y, Fn.y, 2e-6 * fd);
        ENSURE_NEAR(Mom, 0, 1e-12 * fd * r); /* pressure is normal to a circle: no moment */
    }
    fprintf(stderr, "  force and moment = -∮ p n ds (gravity 0, 20, -35 degrees): worst relative %.2e\n", worst);
    return 0;
}

static void box(double L, double H, double th, pl_vec2 v[4]) {
    const pl_vec2 b[4] = {{-L / 2, -H / 2}, {L / 2, -H / 2}, {L / 2, H / 2}, {-L / 2, H / 2}};
    for (int k = 0; k < 4; k++) v[k] = (pl_vec2){cos(th) * b[k].x - sin(th) * b[k].y, sin(th) * b[k].x + cos(th) * b[k].y};
}

static int test_tilted_box_righting_moment(void) {
    pl_hs_water wt = water((pl_vec2){0, -9.81}, 0);
    /* half density: the centroid on the waterline at any heel (the line through the centre
       bisects the box) */
    const double L = 0.2, H = 0.1, d = H / 2, A = L * d;
    const double BM = L * L / (12 * d), BG = (H - d) / 2, GM = BM - BG;
    for (int k = 1; k <= 3; k++) {
        const double th = k * 5 * PI / 180;
        pl_vec2 v[4];
        box(L, H, th, v);
        pl_hs_part p;
        pl_hs_polygon_part(&wt, 0, v, 4, (pl_vec2){0, 0}, &p);
        pl_vec2 F;
        double M;
        pl_hs_load(&wt, &p, (pl_vec2){0, 0}, (pl_vec2){0, 0}, 0, &F, &M);
        const double GZ = sin(th) * (GM + 0.5 * BM * tan(th) * tan(th));
        const double Mref = -wt.rho * wt.g * A * GZ;
        fprintf(stderr, "  box %.2f x %.2f heeled %2.0f deg: M = %.9f N m (wall-sided rho g A GZ: %.9f)\n", L, H,
                th * 180 / PI, M, Mref);
        ENSURE_REL(p.area, A, 1e-13);
        ENSURE_REL(M, Mref, 1e-12);
        ENSURE(M < 0); /* righting: against the heel */
    }
    /* metacentric height from the small-angle slope: M / theta -> -rho g A GM */
    pl_vec2 v[4];
    const double th = 1e-4;
    box(L, H, th, v);
    pl_hs_part p;
    pl_hs_polygon_part(&wt, 0, v, 4, (pl_vec2){0, 0}, &p);
    pl_vec2 F;
    double M;
    pl_hs_load(&wt, &p, (pl_vec2){0, 0}, (pl_vec2){0, 0}, 0, &F, &M);
    const double GM_measured = -M / (wt.rho * wt.g * A * sin(th));
    fprintf(stderr, "  metacentric height GM = %.9f m (BM - BG = %.9f)\n", GM_measured, GM);
    ENSURE_REL(GM_measured, GM, 1e-6);
    /* a tall box at half density is unstable (GM = H'^2... < 0): the moment follows the heel */
    box(0.1, 0.2, 5 * PI / 180, v);
    pl_hs_polygon_part(&wt, 0, v, 4, (pl_vec2){0, 0}, &p);
    pl_hs_load(&wt, &p, (pl_vec2){0, 0}, (pl_vec2){0, 0}, 0, &F, &M);
    fprintf(stderr, "  tall box 0.1 x 0.2 heeled 5 deg: M = %+.6f N m (capsizing, GM = %.5f m)\n", M,
            0.01 / (12 * 0.1) - 0.05);
    ENSURE(M > 0);
    return 0;
}

/* a grain view of one polygon and one disc */
typedef struct view_store {
    uint8_t shape[3], motion[3], wants[3];
    pl_vec2 pos[3], vel[3], verts[8];
    double angle[3], omega[3], radius[3], area[3];
    int32_t off[3], cnt[3];
    pl_grain_view g;
} view_store;

static void make_view(view_store *s, pl_vec2 block_c, double L, double H, pl_vec2 disc_c, double r) {
    memset(s, 0, sizeof *s);
    s->shape[0] = PL_SHAPE_POLYGON;
    s->pos[0] = block_c;
    box(L, H, 0, s->verts);
    for (int k = 0; k < 4; k++) {
        s->verts[k].x += block_c.x;
        s->verts[k].y += block_c.y;
    }
    s->off[0] = 0;
    s->cnt[0] = 4;
    s->area[0] = L * H;
    s->radius[0] = 0.5 * hypot(L, H);
    s->shape[1] = PL_SHAPE_DISC;
    s->pos[1] = disc_c;
    s->radius[1] = r;
    s->area[1] = PI * r * r;
    s->shape[2] = PL_SHAPE_SEGMENT; /* a wall: no area */
    s->off[2] = 4;
    s->cnt[2] = 2;
    s->verts[4] = (pl_vec2){-1, 0};
    s->verts[5] = (pl_vec2){1, 0};
    for (int i = 0; i < 3; i++) s->wants[i] = i < 2;
    s->g = (pl_grain_view){.n = 3, .shape = s->shape, .motion = s->motion, .pos = s->pos, .vel = s->vel,
                           .angle = s->angle, .omega = s->omega, .radius = s->radius, .area = s->area,
                           .vert_offset = s->off, .vert_count = s->cnt, .verts = s->verts, .wants_load = s->wants,
                           .time = 0, .gravity = {0, -9.81}};
}

static int test_moving_level_root(void) {
    pl_hydrostatic_def d = pl_default_hydrostatic_def();
    d.x_min = 0;
    d.x_max = 0.2;
    d.bottom = 0;
    d.level = 0.1;
    pl_hs_water wt = pl_hs_water_make(&d, (pl_vec2){0, -9.81});
    const double a_water = 0.2 * 0.1; /* poured before the bodies went in */
    view_store s;
    /* block 0.08 x 0.04 straddling the surface, a disc r = 0.01 fully under water */
    make_view(&s, (pl_vec2){0.06, 0.1}, 0.08, 0.04, (pl_vec2){0.15, 0.03}, 0.01);
    int evals = 0;
    const double L = pl_hs_solve_level(&wt, &s.g, a_water, d.level, &evals);
    /* by hand: the disc adds pi r^2 below; the block's submerged height is L - 0.08 (its
       bottom at 0.08): 0.2 (L - 0) - pi r^2 - 0.08 (L - 0.08) = 0.02 */
    const double Lref = (0.02 + PI * 1e-4 - 0.08 * 0.08) / (0.2 - 0.08);
    fprintf(stderr, "  moving level: %.15f m (by hand %.15f), %d area evaluations\n", L, Lref, evals);
    ENSURE_NEAR(L, Lref, 1e-12 * 0.2);
    ENSURE(evals < 40);
    /* a tilted gravity: residual at the root is zero to roundoff */
    const double ga = 10 * PI / 180;
    s.g.gravity = (pl_vec2){9.81 * sin(ga), -9.81 * cos(ga)};
    pl_hs_water wt2 = pl_hs_water_make(&d, s.g.gravity);
    const double L2 = pl_hs_solve_level(&wt2, &s.g, a_water, d.level, &evals);
    const double res = pl_hs_tank_area(&wt2, L2) - pl_hs_solid_area(&wt2, L2, &s.g) - a_water;
    fprintf(stderr, "  gravity 10 degrees: level %.12f m, residual %.2e m^2, %d evaluations\n", L2, res, evals);
    ENSURE(fabs(res) < 1e-13 * a_water * 10);
    return 0;
}

static int test_drag(void) {
    pl_hydrostatic_def d = pl_default_hydrostatic_def();
    d.x_min = -1;
    d.x_max = 1;
    d.level = 2;
    d.drag = 50;
    pl_hs_water wt = pl_hs_water_make(&d, (pl_vec2){0, -9.81});
    pl_vec2 v[4];
    box(0.2, 0.1, 0.2, v);
    for (int k = 0; k < 4; k++) v[k].y += 1;
    const pl_vec2 c = {0, 1};
    pl_hs_part p;
    pl_hs_polygon_part(&wt, wt.level, v, 4, c, &p);
    pl_vec2 F;
    double M;
    pl_hs_load(&wt, &p, c, (pl_vec2){0.3, -0.1}, 0, &F, &M);
    const double fb = 1000 * 9.81 * 0.02;
    ENSURE_NEAR(F.x, -50 * 0.02 * 0.3, 1e-12);
    ENSURE_NEAR(F.y, fb + 50 * 0.02 * 0.1, 1e-9);
    ENSURE_NEAR(M, 0, 1e-12);
    /* pure spin: moment -beta omega J (J of the box about its centre) */
    pl_hs_load(&wt, &p, c, (pl_vec2){0, 0}, 2, &F, &M);
    ENSURE_REL(M, -50 * 2 * pl_poly_polar_moment(v, 4), 1e-12);
    /* dissipation: F_d . v + M_d omega = -beta ∫ |v(x)|^2 dA < 0 for a half-submerged body */
    d.level = 1;
    wt = pl_hs_water_make(&d, (pl_vec2){0, -9.81});
    pl_hs_polygon_part(&wt, wt.level, v, 4, c, &p);
    const pl_vec2 vel = {0.2, 0.5};
    const double om = -3;
    pl_hs_load(&wt, &p, c, vel, om, &F, &M);
    const pl_vec2 Fd = {F.x, F.y - 1000 * 9.81 * p.area};
    const double Mb = (p.centroid.x - c.x) * 1000 * 9.81 * p.area;
    const double power = Fd.x * vel.x + Fd.y * vel.y + (M - Mb) * om;
    fprintf(stderr, "  drag: power of the drag on a half-submerged spinning box %.6f W (< 0)\n", power);
    ENSURE(power < 0);
    return 0;
}

/* the drawing field: at most 3 triangles covering the water body, pressures exact at the nodes */
static int test_field(void) {
    const double ga = 15 * PI / 180;
    pl_hydrostatic_def d = pl_default_hydrostatic_def();
    d.x_min = 0;
    d.x_max = 0.4;
    d.level = 0.3;
    pl_hs_water wt = pl_hs_water_make(&d, (pl_vec2){9.81 * sin(ga), -9.81 * cos(ga)});
    pl_vec2 xy[8];
    int32_t tri[18];
    double val[8];
    int nt = 0;
    const int nn = pl_hs_field(&wt, d.level, xy, tri, val, &nt);
    ENSURE(nn >= 3 && nt == nn - 2);
    double area = 0;
    for (int t = 0; t < nt; t++) {
        const pl_vec2 a = xy[tri[3 * t]], b = xy[tri[3 * t + 1]], c = xy[tri[3 * t + 2]];
        const double at = 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
        ENSURE(at > 0);
        area += at;
    }
    ENSURE_REL(area, pl_hs_tank_area(&wt, d.level), 1e-14);
    for (int k = 0; k < nn; k++) {
        const double depth = d.level - (xy[k].x * wt.up.x + xy[k].y * wt.up.y);
        ENSURE_NEAR(val[k], 1000 * 9.81 * fmax(depth, 0), 1e-9);
    }
    fprintf(stderr, "  field: %d nodes, %d triangles, area %.6f m^2 (gravity at 15 degrees)\n", nn, nt, area);
    return 0;
}

int main(void) {
    RUN(test_field);
    RUN(test_disc_segment_quadrature);
    RUN(test_disc_segment_closed_forms);
    RUN(test_polygon_parts);
    RUN(test_force_is_pressure_integral);
    RUN(test_tilted_box_righting_moment);
    RUN(test_moving_level_root);
    RUN(test_drag);
    return pl_test_report();
}
