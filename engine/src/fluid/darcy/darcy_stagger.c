/* The staggering limit of the undrained grain-water coupling (docs/stability.md).
 *
 * Under FLUID_CONSOLIDATION with a compressible pore fluid (K_f > 0) a grain displaced by x
 * changes the solid volume of the elements around it, the pore pressure answers by about
 * (K_f / n) times that volume change over the pore area, and the pressure pushes the grain
 * back. For a grain of diameter d in elements of area A_e the solid area a move x pushes into
 * an element is about d x, the pressure rises by K_f d x / (n A_e) and acts across the grain's
 * diameter: an undrained spring k_u = K_f d^2 / (n A_e) per metre of depth (n the areal porosity
 * of the elements holding grains; for elements of the grain size this is docs/soil.md §2's
 * K_f / (n (1 - n)^2) up to a factor of order one). Seepage between neighbouring elements relaxes
 * it during a held step: backward Euler damps a pressure mode of the element size by
 * 1 + N dt / tau with tau = (n rho_f g / K_f) A_e / D (D the mean conductivity), so
 * k = k_u / (1 + N dt / tau). The grains see the pressure of the last fluid update, held for
 * FLUID_SOLVE_TIMESTEPS = N grain steps: the spring is integrated explicitly with the step
 * N dt, stable (central differences on a mass and a spring) while
 *
 *     N dt < dt_s = 2 sqrt(m_min / k)
 *
 * for the lightest dynamic grain m_min (tests/compare/stability/undrained_stagger.lua measures
 * the boundary: between 0.9 and 1.0 of dt_s). The check runs before each fluid update; FLUID_STAGGER_CHECK 0 turns it off (the
 * stability sweep of tests/compare/stability runs past it that way). */
#include "fluid/darcy/darcy_internal.h"
#include "world/model.h"
#include <math.h>

pl_status pl__fluid_stagger_check(pl_world *w, struct pl_fluid *f, const pl_grain_view *g, double dt) {
    const pl_fl_params *p = &f->par;
    if (!p->consolidation || !(p->bulk_modulus > 0) || !f->solid || !(dt > 0)) return PL_OK;
    double solid = 0, area = 0, cond = 0;
    int ne = 0;
    for (int e = 0; e < f->mesh.ne; e++)
        if (f->solid[e] > 0) {
            solid += f->solid[e];
            area += f->mesh.area[e];
            cond += f->perm_assembled ? f->perm_assembled[e] * f->mesh.area[e] : 0;
            ne++;
        }
    if (!(area > 0)) return PL_OK;
    double n = 1 - solid / area;
    n = fmin(fmax(n, 0.05), 0.95);
    int lightest = -1;
    for (int i = 0; i < g->n; i++)
        if (g->motion[i] == PL_MOTION_DYNAMIC && g->mass[i] > 0 && (lightest < 0 || g->mass[i] < g->mass[lightest]))
            lightest = i;
    if (lightest < 0) return PL_OK;
    const double d = 2 * g->radius[lightest], ae = area / ne, D = cond / area;
    const double step = dt * p->solve_every;
    /* the undrained spring, relaxed by the seepage between neighbouring elements during the
       held step (backward Euler damps a mode of the element size by 1 + step / tau) */
    const double tau = D > 0 ? n * p->density * p->g / p->bulk_modulus * ae / D
                             : INFINITY;
    const double k_undrained = p->bulk_modulus * d * d / (n * ae);
    const double k = isfinite(tau) && tau > 0 ? k_undrained / (1 + step / tau) : k_undrained;
    const double m = g->mass[lightest];
    const double lim = 2 * sqrt(m / k);
    f->stats.stagger_dt_limit = lim;
    f->stats.stagger_stiffness = k;
    if (!p->stagger_check || step <= lim) return PL_OK;
    /* k is proportional to K_f while the step is short against tau */
    const double kf_safe = 4 * m / (step * step) / k * p->bulk_modulus;
    return pl__world_error(
        w, PL_ERR_UNSTABLE,
        "fluid: the undrained grain-water coupling is past its staggering limit at t = %.6g s: the grains see "
        "the pore pressure of the last fluid update for dt x FLUID_SOLVE_TIMESTEPS = %.3g s x %d = %.3g s, "
        "above 2 sqrt(m / k) = %.3g s for the lightest grain (body %d, m = %.3g kg/m) on the water spring "
        "k = %.3g N/m (FLUID_BULK_MODULUS K_f = %.3g Pa, porosity n = %.2f of the "
        "elements holding grains); safe: a grain step dt <= %.3g s with FLUID_SOLVE_TIMESTEPS 1, or "
        "FLUID_BULK_MODULUS <= %.3g Pa (docs/stability.md; FLUID_STAGGER_CHECK 0 skips this check)",
        g->time, dt, p->solve_every, step, lim, lightest + 1, m, k, p->bulk_modulus, n, 0.5 * lim, kf_safe);
}
