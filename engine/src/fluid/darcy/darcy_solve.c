/* Solution of the Darcy system (seed 000 §3.9): static (§3.9.1) by sparse Cholesky (CHOLMOD,
 * numeric refactorization only when the matrix values changed), transient S dh/dt = div(K grad h)
 * (eq. 3.17) by the theta method (backward Euler by default, Crank-Nicolson) and by the thesis's
 * explicit update (§3.9.2, eq. 3.18) with a lumped storage matrix, sub-stepped to stay below its
 * stability limit 2 / lambda_max(M^-1 K) (bounded with Gershgorin circles). */
#define _POSIX_C_SOURCE 200809L
#include "fluid/darcy/darcy_internal.h"
#include "core/clock.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

double pl_fl_now(void) { return pl_clock_seconds(); }

void pl_fl_apply_dirichlet(struct pl_fluid *f, double *h) {
    const pl_fl_system *s = &f->sys;
    for (int i = 0; i < f->mesh.nn; i++)
        if (s->is_dir[i]) h[i] = s->dir_head[i] + pl_fl_z(f, f->mesh.xy[i]);
}

/* Numeric factorization of c M + theta K (free block), skipped when already current. */
static pl_status factorize(struct pl_fluid *f, double c, double theta) {
    pl_fl_system *s = &f->sys;
    if (s->nf == 0) return PL_OK;
    if (s->factorised && s->fact_c == c && s->fact_theta == theta) return PL_OK;
    double t0 = pl_fl_now();
    double *Ax = s->A->x;
    for (int p = 0; p < s->nnz; p++)
        if (s->amap[p] >= 0) Ax[s->amap[p]] = theta * s->kval[p] + c * s->mval[p];
    int ok = cholmod_factorize(s->A, s->L, &s->cc);
    f->stats.t_factor += pl_fl_now() - t0;
    if (!ok || s->cc.status == CHOLMOD_NOT_POSDEF || s->L->minor < s->L->n) {
        snprintf(f->msg, sizeof f->msg,
                 "fluid: the Darcy matrix is not positive definite (CHOLMOD status %d, pivot %d of %d); %s",
                 s->cc.status, (int)s->L->minor, s->nf,
                 c == 0 ? "a static solve needs a prescribed head on every connected fluid region"
                        : "check the permeabilities and the storage coefficient");
        s->factorised = 0;
        return PL_ERR_NUMERIC;
    }
    s->factorised = 1;
    s->fact_c = c;
    s->fact_theta = theta;
    f->stats.factorizations++;
    return PL_OK;
}

/* (c M + theta K) h_new = (c M - (1 - theta) K) h_old + f, prescribed heads eliminated. */
static pl_status theta_solve(struct pl_fluid *f, double c, double theta) {
    pl_fl_system *s = &f->sys;
    const int nn = f->mesh.nn;
    double *h = f->head, *r = s->work;
    pl_status st = factorize(f, c, theta);
    if (st != PL_OK) return st;
    double t0 = pl_fl_now();
    memcpy(r, s->fload, sizeof(double) * (size_t)nn);
    if (f->src_active && f->src) /* volume source of the skeleton (fluid_consolidation.c) */
        for (int j = 0; j < nn; j++) r[j] += f->src[j];
    pl_fl_add_frame_load(f, r); /* accelerating frame (pl_world_fluid_set_frame) */
    if (c != 0 || theta != 1) {
        for (int j = 0; j < nn; j++) {
            double hj = h[j];
            for (int p = s->colp[j]; p < s->colp[j + 1]; p++)
                r[s->rowi[p]] += (c * s->mval[p] - (1 - theta) * s->kval[p]) * hj;
        }
    }
    pl_fl_apply_dirichlet(f, h);
    for (int j = 0; j < nn; j++) {
        if (!s->is_dir[j]) continue;
        double hj = h[j];
        for (int p = s->colp[j]; p < s->colp[j + 1]; p++)
            if (!s->is_dir[s->rowi[p]]) r[s->rowi[p]] -= (c * s->mval[p] + theta * s->kval[p]) * hj;
    }
    if (s->nf > 0) {
        double *b = s->rhs->x;
        for (int k = 0; k < s->nf; k++) b[k] = r[s->free_node[k]];
        if (!cholmod_solve2(CHOLMOD_A, s->L, s->rhs, NULL, &s->sol, NULL, &s->wy, &s->we, &s->cc)) {
            snprintf(f->msg, sizeof f->msg, "fluid: CHOLMOD solve failed (status %d)", s->cc.status);
            return PL_ERR_NUMERIC;
        }
        const double *x = s->sol->x;
        for (int k = 0; k < s->nf; k++) h[s->free_node[k]] = x[k];
    }
    f->stats.solves++;
    f->stats.t_solve += pl_fl_now() - t0;
    f->have_solution = 1;
    return PL_OK;
}

pl_status pl_fl_solve_static(struct pl_fluid *f) {
    if (f->static_valid) {
        f->stats.skipped++;
        return PL_OK;
    }
    if (f->sys.nf == f->mesh.nn) {
        snprintf(f->msg, sizeof f->msg,
                 "fluid: a static solve needs at least one prescribed-head line (add_fluid_bc) touching the mesh; "
                 "none of the %d lines prescribes a node",
                 f->nl);
        return PL_ERR_STATE;
    }
    pl_status st = theta_solve(f, 0.0, 1.0);
    if (st == PL_OK) f->static_valid = 1;
    return st;
}

double pl_fl_explicit_dt_limit(const struct pl_fluid *f) {
    const pl_fl_system *s = &f->sys;
    double lam = 0;
    for (int j = 0; j < f->mesh.nn; j++) {
        if (s->is_dir[j]) continue;
        double sum = 0;
        for (int p = s->colp[j]; p < s->colp[j + 1]; p++) sum += fabs(s->kval[p]);
        double l = sum / (pl_fl_storage_factor(f) * s->mlump[j]);
        if (l > lam) lam = l;
    }
    return lam > 0 ? 2.0 / lam : INFINITY;
}

static pl_status explicit_advance(struct pl_fluid *f, double dt) {
    pl_fl_system *s = &f->sys;
    const int nn = f->mesh.nn;
    double *h = f->head, *r = s->work;
    double t0 = pl_fl_now();
    double lim = pl_fl_explicit_dt_limit(f);
    f->stats.explicit_dt_limit = lim;
    double safe = f->par.explicit_safety * lim;
    double nsub_d = ceil(dt / safe);
    if (!(nsub_d <= 1e7)) {
        snprintf(f->msg, sizeof f->msg,
                 "fluid: the explicit method would need %.3g sub-steps for a fluid step of %g s (stability limit "
                 "%.3g s); use FLUID_METHOD 0 (implicit) or a larger FLUID_STORAGE",
                 nsub_d, dt, lim);
        return PL_ERR_NUMERIC;
    }
    int nsub = nsub_d < 1 ? 1 : (int)nsub_d;
    double h_dt = dt / nsub;
    pl_fl_apply_dirichlet(f, h);
    for (int it = 0; it < nsub; it++) {
        memcpy(r, s->fload, sizeof(double) * (size_t)nn);
        if (f->src_active && f->src)
            for (int j = 0; j < nn; j++) r[j] += f->src[j];
        pl_fl_add_frame_load(f, r);
        for (int j = 0; j < nn; j++) {
            double hj = h[j];
            for (int p = s->colp[j]; p < s->colp[j + 1]; p++) r[s->rowi[p]] -= s->kval[p] * hj;
        }
        const double sf = pl_fl_storage_factor(f);
        for (int i = 0; i < nn; i++)
            if (!s->is_dir[i]) h[i] += h_dt * r[i] / (sf * s->mlump[i]);
    }
    f->stats.last_substeps = nsub;
    f->stats.substeps += nsub;
    f->stats.t_solve += pl_fl_now() - t0;
    f->have_solution = 1;
    return PL_OK;
}

pl_status pl_fl_advance(struct pl_fluid *f, double dt) {
    const pl_fl_params *p = &f->par;
    /* under FLUID_CONSOLIDATION the storage S + n rho g / K_f sits in the mass matrix */
    const int cons = p->consolidation && f->stor;
    const double stor = cons ? (p->storage > 0 || p->bulk_modulus > 0 ? 1.0 : 0.0) : p->storage;
    if (f->src_active) f->static_valid = 0; /* the source changes every update */
    if (p->method == 3 || stor <= 0 || !(dt > 0)) return pl_fl_solve_static(f);
    f->static_valid = 0;
    f->stats.last_substeps = 0;
    f->time += dt;
    switch (p->method) {
    case 1: return theta_solve(f, stor / dt, 0.5);
    case 2: return explicit_advance(f, dt);
    default: return theta_solve(f, stor / dt, 1.0);
    }
}

double pl_fl_line_inflow(const struct pl_fluid *f, int line) {
    const pl_fl_system *s = &f->sys;
    double q = 0;
    for (int j = 0; j < f->mesh.nn; j++) {
        if (s->dir_line[j] != line) continue;
        /* (K h)_j by symmetry = column j dotted with h */
        double kh = 0;
        for (int p = s->colp[j]; p < s->colp[j + 1]; p++) kh += s->kval[p] * f->head[s->rowi[p]];
        q += kh - s->fload[j];
    }
    return q;
}
