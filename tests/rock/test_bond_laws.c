/* Single bonds pulled, sheared and turned against the closed forms of the three laws
 * (seed 002 §3; docs/rock.md "Bond laws"). A fixed disc and a kinematic disc: the motion is
 * prescribed, so the opening u_n, slip u_t and rotation are known exactly at every step and
 * the bond force must follow the law's curve to rounding. */
#include "harness.h"
#include "porelab/bonds.h"
#include "porelab/world.h"
#include "dem/world_internal.h"
#include <string.h>

#define R0 1e-3
#define DT 1e-6

static pl_world *two_discs(pl_bond_def law, int *a, int *b) {
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, 0};
    wd.dt = DT;
    pl_world *w = pl_world_create(&wd);
    pl_material_def m = pl_default_material_def();
    m.name = "rock";
    m.density = 2600;
    m.kn = 1e7;
    const int mat = pl_world_add_material(w, &m);
    pl_world_set_bond_law(w, mat, mat, &law);
    pl_body_def d = pl_default_body_def();
    d.material = mat;
    d.radius = R0;
    d.motion = PL_MOTION_FIXED;
    d.position = (pl_vec2){0, 0};
    *a = pl_world_add_body(w, &d);
    d.motion = PL_MOTION_PRESCRIBED;
    d.position = (pl_vec2){2 * R0, 0};
    *b = pl_world_add_body(w, &d);
    return w;
}

static pl_bond_def law_of(pl_bond_law_kind kind) {
    pl_bond_def L = pl_default_bond_def();
    L.law = kind;
    L.kn = 1e7;  /* N/m */
    L.kt = 4e6;
    L.rn = 50;   /* N: u_e = 5 um */
    L.rt = 30;   /* N */
    L.soften = 4;
    return L;
}

static pl_bond_info bond0(const pl_world *w) {
    pl_bond_info o;
    memset(&o, 0, sizeof o);
    pl_world_copy_bonds(w, 0, &o, 1);
    return o;
}

/* Brittle in tension: N = k_n u_n until N first exceeds R_n, then 0 at once, in that step. */
static int brittle_pull(void) {
    int a, b;
    const pl_bond_def L = law_of(PL_BOND_BRITTLE);
    pl_world *w = two_discs(L, &a, &b);
    ENSURE(pl_world_add_bond(w, a, b) == 0);
    const double v = 0.01; /* m/s: 10 nm per step */
    pl_world_prescribe_velocity(w, b, (pl_vec2){v, 0}, 0);
    double last_n = 0, worst = 0;
    int broke_at = -1;
    for (int s = 0; s < 2000 && broke_at < 0; s++) {
        const double un = w->pos[b].x - w->pos[a].x - 2 * R0;
        ENSURE(pl_world_step(w, 1) == PL_OK);
        pl_bond_info o = bond0(w);
        if (o.state != PL_BOND_INTACT) {
            broke_at = s;
            ENSURE(o.state == PL_BOND_BROKEN_TENSION);
            /* the step it broke in had k_n u_n > R_n, the one before <= R_n */
            ENSURE(L.kn * un > L.rn);
            ENSURE(last_n <= L.rn);
            break;
        }
        worst = fmax(worst, fabs(o.n - L.kn * un));
        last_n = o.n;
    }
    ENSURE(broke_at > 0);
    ENSURE(worst <= 1e-6 * L.rn);
    /* the peak is R_n to within one step's increment k_n v dt (= 0.1 N here) */
    ENSURE(last_n <= L.rn && last_n > L.rn - L.kn * v * DT * 1.000001);
    ENSURE(pl_world_bond_count(w) == 0);
    ENSURE(pl_world_broken_bonds(w, broke_at, NULL, 0) == 1);
    ENSURE(pl_world_broken_bonds(w, broke_at + 1, NULL, 0) == 0);
    /* the energy it held is released: 1/2 R^2 / k_n to within the last increment */
    const pl_energy e = pl_world_energy(w);
    ENSURE_REL(e.fracture, 0.5 * last_n * last_n / L.kn, 0.01);
    fprintf(stderr, "  brittle pull: peak N = %.6g N (R_n = %g N, step increment %.3g N); fracture energy %.6g J\n",
            last_n, L.rn, L.kn * v * DT, e.fracture);
    pl_world_destroy(&w);
    return 0;
}

/* Brittle in shear: the kinematic disc spins, the slip is u_t = -l_b w t with l_b = r; the
   shear force S = k_t u_t until |S| exceeds R_t. */
static int brittle_shear(void) {
    int a, b;
    pl_bond_def L = law_of(PL_BOND_BRITTLE);
    L.kr = 1e-3;
    pl_world *w = two_discs(L, &a, &b);
    ENSURE(pl_world_add_bond(w, a, b) == 0);
    const double om = 5.0; /* rad/s: slip 5 nm per step */
    pl_world_prescribe_velocity(w, b, (pl_vec2){0, 0}, om);
    double last = 0, worst = 0, worst_m = 0;
    int broke = 0;
    for (int s = 0; s < 20000 && !broke; s++) {
        const double ut = -R0 * om * DT * (s + 1), rot = om * DT * (s + 1);
        ENSURE(pl_world_step(w, 1) == PL_OK);
        pl_bond_info o = bond0(w);
        if (o.state != PL_BOND_INTACT) {
            ENSURE(o.state == PL_BOND_BROKEN_SHEAR);
            ENSURE(fabs(L.kt * ut) > L.rt && fabs(last) <= L.rt);
            broke = 1;
            break;
        }
        worst = fmax(worst, fabs(o.s - L.kt * ut));
        worst_m = fmax(worst_m, fabs(o.m - L.kr * rot));
        last = o.s;
    }
    ENSURE(broke);
    ENSURE(worst <= 1e-6 * L.rt);
    ENSURE(worst_m <= 1e-9);
    ENSURE(fabs(last) > L.rt - L.kt * R0 * om * DT * 1.000001);
    fprintf(stderr, "  brittle shear: peak |S| = %.6g N (R_t = %g N)\n", fabs(last), L.rt);
    pl_world_destroy(&w);
    return 0;
}

/* Combined criterion: opening and slip together; breaks when (N/R_n)^2 + (S/R_t)^2 first
   exceeds 1, before either alone reaches its strength. */
static int brittle_combined(void) {
    int a, b;
    pl_bond_def L = law_of(PL_BOND_BRITTLE);
    L.combined = 1;
    pl_world *w = two_discs(L, &a, &b);
    ENSURE(pl_world_add_bond(w, a, b) == 0);
    pl_world_prescribe_velocity(w, b, (pl_vec2){0.005, 0}, 5.0);
    double prev = 0;
    int broke = 0;
    for (int s = 0; s < 20000; s++) {
        ENSURE(pl_world_step(w, 1) == PL_OK);
        pl_bond_info o = bond0(w);
        if (o.state != PL_BOND_INTACT) {
            ENSURE(o.state == PL_BOND_BROKEN_COMBINED);
            broke = 1;
            break;
        }
        prev = pow(o.n / L.rn, 2) + pow(o.s / L.rt, 2);
        ENSURE(o.n < L.rn && fabs(o.s) < L.rt);
    }
    ENSURE(broke);
    ENSURE(prev <= 1 && prev > 0.99);
    pl_world_destroy(&w);
    return 0;
}

/* Elasto-plastic with linear softening: monotonic pulling follows the elastic line to
   (u_e, R_n), then the softening line to (u_f, 0), u_f = soften u_e; the released energy at
   failure is the area under it, R_n u_f / 2. Unloading from the softening branch is elastic
   (slope k_n), reloading elastic up to the softened yield force. */
static int plastic_pull(void) {
    int a, b;
    const pl_bond_def L = law_of(PL_BOND_PLASTIC);
    pl_world *w = two_discs(L, &a, &b);
    ENSURE(pl_world_add_bond(w, a, b) == 0);
    const double ue = L.rn / L.kn, uf = L.soften * ue, v = 0.01;
    pl_world_prescribe_velocity(w, b, (pl_vec2){v, 0}, 0);
    double worst = 0, area = 0, u_prev = 0, n_prev = 0;
    int broke = 0, unloaded = 0;
    for (int s = 0; s < 100000 && !broke; s++) {
        const double un = w->pos[b].x - w->pos[a].x - 2 * R0;
        ENSURE(pl_world_step(w, 1) == PL_OK);
        pl_bond_info o = bond0(w);
        if (o.state != PL_BOND_INTACT) {
            ENSURE(o.state == PL_BOND_BROKEN_TENSION);
            ENSURE(un >= uf - 2 * v * DT && un <= uf + v * DT);
            area += 0.5 * (n_prev + 0) * (un - u_prev);
            broke = 1;
            break;
        }
        if (!unloaded) {
            const double ref = un <= ue ? L.kn * un : L.rn * (uf - un) / (uf - ue);
            worst = fmax(worst, fabs(o.n - ref));
        }
        area += 0.5 * (n_prev + o.n) * (un - u_prev);
        u_prev = un;
        n_prev = o.n;
        /* at half way down the softening branch: unload by 1 um and check the elastic slope */
        if (!unloaded && un > 0.5 * (ue + uf)) {
            const double n0 = o.n, u0 = un;
            pl_world_prescribe_velocity(w, b, (pl_vec2){-v, 0}, 0);
            ENSURE(pl_world_step(w, 100) == PL_OK);
            o = bond0(w);
            const double u1 = w->pos[b].x - w->pos[a].x - 2 * R0 + v * DT; /* position at the last evaluation */
            /* the first of the 100 steps still evaluates at u0 + v dt, on the softening line */
            const double up = u0 + v * DT, npeak = L.rn * (uf - up) / (uf - ue);
            (void)n0;
            ENSURE_NEAR(o.n, npeak - L.kn * (up - u1), 1e-6 * L.rn);
            pl_world_prescribe_velocity(w, b, (pl_vec2){v, 0}, 0);
            ENSURE(pl_world_step(w, 100) == PL_OK);
            unloaded = 1;
            n_prev = bond0(w).n;
            u_prev = w->pos[b].x - w->pos[a].x - 2 * R0 - v * DT; /* at the last evaluation */
        }
    }
    ENSURE(broke && unloaded);
    ENSURE(worst <= 1e-6 * L.rn);
    const pl_energy e = pl_world_energy(w);
    const double exact = 0.5 * L.rn * uf;
    ENSURE_REL(e.fracture, exact, 2e-3);
    fprintf(stderr, "  plastic: |N - closed form| <= %.2g N; released %.6g J, R_n u_f / 2 = %.6g J, area %.6g J\n",
            worst, e.fracture, exact, area);
    pl_world_destroy(&w);
    return 0;
}

/* Damage with linear strain softening: N = (1 - w) k_n u, unloading to the origin along the
   secant, failure at u_f; the energy the bond released equals the area under the force-
   opening curve traced to failure (unloading and reloading included), R_n u_f / 2. */
static int damage_pull(void) {
    int a, b;
    const pl_bond_def L = law_of(PL_BOND_DAMAGE);
    pl_world *w = two_discs(L, &a, &b);
    ENSURE(pl_world_add_bond(w, a, b) == 0);
    const double ue = L.rn / L.kn, uf = L.soften * ue, v = 0.01;
    pl_world_prescribe_velocity(w, b, (pl_vec2){v, 0}, 0);
    double area = 0, u_prev = 0, n_prev = 0, worst = 0, kap = 0;
    int broke = 0, phase = 0; /* 0 loading, 1 unloading, 2 reloading */
    for (int s = 0; s < 200000 && !broke; s++) {
        const double un = w->pos[b].x - w->pos[a].x - 2 * R0;
        ENSURE(pl_world_step(w, 1) == PL_OK);
        pl_bond_info o = bond0(w);
        const double nn = o.state == PL_BOND_INTACT ? o.n : 0;
        area += 0.5 * (n_prev + nn) * (un - u_prev);
        u_prev = un;
        n_prev = nn;
        if (o.state != PL_BOND_INTACT) {
            ENSURE(o.state == PL_BOND_BROKEN_TENSION);
            ENSURE(un >= uf && un <= uf + v * DT * 1.0001);
            broke = 1;
            break;
        }
        kap = fmax(kap, un);
        const double om = kap <= ue ? 0 : 1 - (ue / kap) * (uf - kap) / (uf - ue);
        worst = fmax(worst, fabs(o.n - (un > 0 ? (1 - om) * L.kn * un : L.kn * un)));
        if (phase == 0 && un > 0.6 * uf) {
            phase = 1;
            pl_world_prescribe_velocity(w, b, (pl_vec2){-v, 0}, 0);
        } else if (phase == 1 && un < 0.2 * uf) {
            phase = 2;
            pl_world_prescribe_velocity(w, b, (pl_vec2){v, 0}, 0);
        }
    }
    ENSURE(broke && phase == 2);
    ENSURE(worst <= 1e-6 * L.rn);
    const pl_energy e = pl_world_energy(w);
    const double exact = 0.5 * L.rn * uf;
    /* released energy vs the closed form (exact in the law) and vs the traced area (trapezoids
       of 10 nm steps on a 20 um curve) */
    ENSURE_REL(e.fracture, exact, 1e-9);
    ENSURE_REL(area, exact, 2e-3);
    fprintf(stderr, "  damage: released %.8g J, R_n u_f / 2 = %.8g J, area under the traced curve %.8g J (%.2g %%)\n",
            e.fracture, exact, area, 100 * (area - exact) / exact);
    pl_world_destroy(&w);
    return 0;
}

/* Damage in compression is undamaged (crack closure); tension_only keeps shear brittle. */
static int damage_tension_only(void) {
    int a, b;
    pl_bond_def L = law_of(PL_BOND_DAMAGE);
    L.tension_only = 1;
    pl_world *w = two_discs(L, &a, &b);
    ENSURE(pl_world_add_bond(w, a, b) == 0);
    pl_world_prescribe_velocity(w, b, (pl_vec2){0, 0}, 5.0);
    int broke = 0;
    double last = 0;
    for (int s = 0; s < 20000 && !broke; s++) {
        ENSURE(pl_world_step(w, 1) == PL_OK);
        pl_bond_info o = bond0(w);
        if (o.state != PL_BOND_INTACT) {
            ENSURE(o.state == PL_BOND_BROKEN_SHEAR);
            broke = 1;
        } else {
            ENSURE(o.damage == 0);
            last = o.s;
        }
    }
    ENSURE(broke);
    ENSURE(fabs(last) <= L.rt && fabs(last) > L.rt - L.kt * R0 * 5.0 * DT * 1.0001);
    pl_world_destroy(&w);
    return 0;
}

/* Bad input: a clear message naming the argument and range. */
static int bad_input(void) {
    int a, b;
    pl_bond_def L = law_of(PL_BOND_BRITTLE);
    pl_world *w = two_discs(L, &a, &b);
    L.rn = 0;
    ENSURE(pl_world_set_bond_law(w, 0, 0, &L) == PL_ERR_ARG);
    ENSURE(strstr(pl_world_last_error(w), "rn") != NULL);
    L = law_of(PL_BOND_PLASTIC);
    L.soften = 0.5;
    ENSURE(pl_world_set_bond_law(w, 0, 0, &L) == PL_ERR_ARG);
    ENSURE(strstr(pl_world_last_error(w), "soften") != NULL);
    ENSURE(pl_world_set_bond_law(w, 0, 3, &L) == PL_ERR_ARG);
    ENSURE(pl_world_add_bond(w, a, a) < 0);
    ENSURE(pl_world_add_bond(w, a, 7) < 0);
    ENSURE(pl_world_bond_touching(w, -1) < 0);
    ENSURE(strstr(pl_world_last_error(w), "gap") != NULL);
    ENSURE(pl_world_add_bond(w, a, b) == 0);
    ENSURE(pl_world_add_bond(w, b, a) < 0); /* already bonded */
    ENSURE(pl_world_bond_touching(w, 0) == 0);
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(brittle_pull);
    RUN(brittle_shear);
    RUN(brittle_combined);
    RUN(plastic_pull);
    RUN(damage_pull);
    RUN(damage_tension_only);
    RUN(bad_input);
    return pl_test_report();
}
