/* Work of constant loads against the energy they put in (the load-work tallies).
 *
 * Derivation (central differences, Belytschko, Liu & Moran, Nonlinear Finite Elements, 2000,
 * §6.2.3): the integrators step v^{n+1/2} = v^{n-1/2} + dt M^-1 (f_ext^n - f_int^n) and
 * x^{n+1} = x^n + dt v^{n+1/2}. Dotting the velocity update with the mid-step velocity
 * v^n = (v^{n-1/2} + v^{n+1/2}) / 2 gives, exactly,
 *     (1/2) v^{n+1/2}.M v^{n+1/2} - (1/2) v^{n-1/2}.M v^{n-1/2} = dt (f_ext^n - f_int^n).v^n,
 * so the consistent work of a load over a step is f^n.v^n dt = f^n.(x^{n+1} - x^{n-1}) / 2
 * (the trapezoidal rule of Belytschko's energy balance). The start-of-step velocity
 * v^{n-1/2} instead misses (1/2) |v^{n+1/2} - v^{n-1/2}|^2 m per step, a bias of one half step.
 *
 * - a disc in free space pushed by a constant load from an attached model (the world's
 *   external-force column, world/models.c; tallied in dem/integrate.c): with f_int = 0 the
 *   identity above is exact, so the load's work equals the disc's kinetic energy to
 *   round-off (1e-12 relative); the start-of-step form is off by 1/(2N) after N steps (5e-4
 *   here), which the test would catch;
 * - the same disc pressed by the constant load against a fixed disc (a contact spring, no
 *   dashpot: an elastic bar of one spring): work = kinetic + elastic energy up to the
 *   O(dt) bounded difference between sum k x^n (x^{n+1} - x^{n-1})/2 and k x^2/2, i.e.
 *   |error| <= k x v dt / 2 ~ (omega dt / 2) W; the test checks it stays below omega dt of
 *   the work over 20 periods (no drift);
 * - an elastic bar of plain triangles (40x4, fixed at x = 0) under a constant end traction from
 *   rest: the solid's ledger, external work = strain energy + kinetic energy, within
 *   (omega_max dt)^2 of the work over five wave transits, and the error does not grow
 *   (its largest value over the last transit within 1.5 x that over the first). */
#include "harness.h"
#include "solid_test_util.h"
#include "porelab/world.h"
#include "world/model.h"
#include <math.h>
#include <stdlib.h>

/* ---- a test model: a constant force on one body ---- */
typedef struct const_load {
    int body;
    pl_vec2 f;
    double k; /* and a spring back to x = 0 (N/m): f - k x */
} const_load;

static const_load the_load;
static double build_v0 = 0; /* initial speed of the disc along x, m/s */

static pl_status cl_advance(void *self, pl_world *w, const pl_grain_view *g, double dt) {
    (void)self, (void)w, (void)g, (void)dt;
    return PL_OK;
}
static pl_status cl_loads(void *self, pl_world *w, const pl_grain_view *g, double dt, pl_vec2 *force, double *moment) {
    (void)w, (void)dt, (void)moment;
    const const_load *c = self;
    if (c->body < g->n && g->wants_load[c->body]) {
        force[c->body].x += c->f.x - c->k * g->pos[c->body].x;
        force[c->body].y += c->f.y - c->k * g->pos[c->body].y;
    }
    return PL_OK;
}
static uint64_t cl_hash(const void *self, uint64_t h) {
    (void)self;
    return h;
}
static void cl_destroy(void *self) { (void)self; }

static const pl_model_class const_load_class = {
    .name = "test_const_load", .label = "constant load on one body (test)", .advance = cl_advance,
    .loads = cl_loads, .hash = cl_hash, .destroy = cl_destroy};

static pl_world *load_world(int with_wall, double F, int *disc, double *mass, double *kn) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, 0};
    wd.dt = 1e-5;
    pl_world *w = pl_world_create(&wd);
    pl_material_def md = pl_default_material_def();
    md.density = 2000;
    md.kn = 1e6;
    md.name = "glass"; /* no dashpot (cn = 0, restitution off) */
    md.friction = 0;
    const int mat = pl_world_add_material(w, &md);
    if (mat < 0) {
        fprintf(stderr, "%s\n", pl_world_last_error(w));
        return NULL;
    }
    const double r = 0.01;
    pl_body_def bd = pl_default_body_def();
    bd.shape = PL_SHAPE_DISC;
    bd.material = mat;
    bd.radius = r;
    bd.velocity = (pl_vec2){build_v0, 0};
    *disc = pl_world_add_body(w, &bd);
    if (with_wall) { /* touching, unloaded */
        bd.position = (pl_vec2){-2 * r, 0};
        bd.motion = PL_MOTION_FIXED;
        if (pl_world_add_body(w, &bd) < 0) {
            fprintf(stderr, "%s\n", pl_world_last_error(w));
            return NULL;
        }
    }
    pl_body_info bi;
    pl_world_body_info(w, *disc, &bi);
    *mass = bi.mass;
    *kn = md.kn;
    the_load = (const_load){*disc, {-F, 0}, 0};
    if (*disc < 0 || pl__world_attach(w, &const_load_class, &the_load) != PL_OK) {
        fprintf(stderr, "%s\n", pl_world_last_error(w));
        return NULL;
    }
    return w;
}

static int test_free_disc(void) {
    int disc;
    double m, kn;
    pl_world *w = load_world(0, 2.0, &disc, &m, &kn);
    ENSURE(w);
    const int N = 1000;
    ENSURE(pl_world_step(w, N) == PL_OK);
    const pl_energy e = pl_world_energy(w);
    /* energies are reported at the last force evaluation with the synchronous velocity
       (dem/diagnostics.c); at t = 0 that velocity is F dt / 2m, not the 0 reported before the
       first step */
    const double dt = pl_world_dt(w), v0 = 2.0 * dt / (2 * m), ke0 = 0.5 * m * v0 * v0;
    const double err = (e.external - (e.kinetic - ke0)) / e.kinetic;
    fprintf(stderr, "free disc, constant model load, %d steps: work %.12g J/m, kinetic %.12g J/m (%+.2e)\n", N,
            e.external, e.kinetic, err);
    pl_validation("solids.load_work_free", "disc under a constant model load: work against kinetic energy",
                  "m (v1^2 - v0^2)/2 = F . (v0 + v1)/2 dt (central differences)", "1e-12",
                  "%+.1e after %d steps", err, N);
    ENSURE(fabs(err) < 1e-12);
    pl_world_destroy(&w);
    return 0;
}

/* The disc on a spring of the model (F = -k x, a varying load) released at x = 0 with speed
   v0: kinetic energy + k x^2 / 2 - (the model's work + k x^2 / 2) = 0, i.e. work = change of
   kinetic energy. The mid-step work is the trapezoidal rule (bounded error O((omega dt)^2));
   the start-of-step velocity would be the right-end rule, whose error -k sum dx^2 / 2 grows
   by about pi omega dt KE0 per period (the test's no-growth check would fail). */
static int test_model_spring(void) {
    int disc;
    double m, kn;
    const double k = 1e5, v0 = 1;
    build_v0 = v0;
    pl_world *w = load_world(0, 0, &disc, &m, &kn);
    build_v0 = 0;
    ENSURE(w);
    the_load.k = k;
    const double dt = pl_world_dt(w), omega = sqrt(k / m), period = 2 * M_PI / omega, ke0 = 0.5 * m * v0 * v0;
    double first = 0, last = 0;
    while (pl_world_time(w) < 50 * period) {
        if (pl_world_step(w, 1) != PL_OK) {
            fprintf(stderr, "%s\n", pl_world_last_error(w));
            return 1;
        }
        const pl_energy e = pl_world_energy(w);
        const double err = fabs(e.external - (e.kinetic - ke0)) / ke0;
        if (pl_world_time(w) < 5 * period) first = fmax(first, err);
        if (pl_world_time(w) > 45 * period) last = fmax(last, err);
    }
    fprintf(stderr, "disc on a model spring, 50 periods (omega dt = %.3g): largest |work - change of kinetic| %.3e "
                    "of the kinetic energy in periods 1-5, %.3e in 46-50 (bound (omega dt)^2 = %.3e)\n",
            omega * dt, first, last, omega * omega * dt * dt);
    pl_validation("solids.load_work_spring", "disc on a spring load of a model, 50 periods",
                  "work = change of kinetic energy (trapezoidal work, central differences)", "(omega dt)^2, no growth",
                  "%.1e of KE0 (periods 1-5), %.1e (46-50)", first, last);
    ENSURE(first < omega * omega * dt * dt && last < omega * omega * dt * dt);
    ENSURE(last < 1.5 * first + 1e-12);
    pl_world_destroy(&w);
    return 0;
}

static int test_bar_traction(void) {
    const pl_solid_def d = sf_steel(PL_SOLID_PLAIN);
    const double L = 10, H = 1, t = 1e6;
    pl_sf *s = sf_rect(&d, 0, 0, L, H, 40, 4);
    ENSURE(s);
    ENSURE(pl_sf_add_set(s, -1e-9, -1, 1e-9, H + 1, 3, 0, 0) >= 0);
    ENSURE(pl_sf_add_traction(s, L - 1e-9, -1, L + 1e-9, H + 1, t, 0, 0) > 0);
    const double c = sqrt(d.young / ((1 - d.poisson * d.poisson) * d.density)), transit = L / c;
    const double dt = 0.5 * s->dt_crit;
    double first = 0, last = 0, wmax = 0, exact = 0;
    double *un = malloc(sizeof *un * 2 * (size_t)s->nn);
    ENSURE(un);
    while (s->time < 5 * transit) {
        const double U = pl_sf_elastic_energy(s); /* at the step's start, as kinetic and the work */
        for (int k = 0; k < 2 * s->nn; k++) un[k] = s->x[k] - s->X[k];
        ENSURE(pl_sf_step(s, dt, NULL) == PL_OK);
        /* the discrete invariant: W^n = v^{n+1/2}.M v^{n+1/2} / 2 + u^n.K u^{n+1} / 2 (f_prev = K u^{n+1}) */
        double inv = 0;
        for (int k = 0; k < 2 * s->nn; k++) inv += 0.5 * s->m[k / 2] * s->v[k] * s->v[k] + 0.5 * un[k] * s->f_prev[k];
        exact = fmax(exact, fabs(s->e.external - inv));
        const double err = fabs(s->e.external - U - s->e.kinetic);
        wmax = fmax(wmax, s->e.external);
        if (s->time < transit) first = fmax(first, err);
        if (s->time > 4 * transit) last = fmax(last, err);
    }
    fprintf(stderr, "bar under a constant end traction, 5 transits: largest |work - strain - kinetic| %.3e of the "
                    "work (first transit %.3e, last %.3e)\n",
            fmax(first, last) / wmax, first / wmax, last / wmax);
    pl_validation("solids.load_work_bar", "elastic bar (plain triangles) under a constant end traction, 5 transits",
                  "work = strain + kinetic energy (central differences, mid-step work)", "1 %, no growth",
                  "%.1e of the work, last/first transit %.2f", fmax(first, last) / wmax, last / first);
    ENSURE(wmax > 0);
    ENSURE(fmax(first, last) / wmax < 0.01);
    ENSURE(last < 1.5 * first);
    fprintf(stderr, "bar: largest |work - (v.M v / 2 at the half step + u^n.K u^(n+1) / 2)| %.3e of the work\n",
            exact / wmax);
    ENSURE(exact / wmax < 1e-10); /* round-off over 1e4 steps */
    free(un);
    pl_sf_destroy(s);
    return 0;
}

int main(void) {
    RUN(test_free_disc);
    RUN(test_model_spring);
    RUN(test_bar_traction);
    return pl_test_report();
}
