/* Pore pressure from skeleton volume change (DESIGN §3; docs/soil.md §1): with
 * FLUID_CONSOLIDATION = 1 the Darcy field solves
 *
 *   (S + n rho_f g / K_f) dh/dt - div(D grad h) = -div(v_s)          (h total head, D = k rho_f g / mu)
 *
 * i.e. (n / K_f) dp/dt - div((k/mu) grad p_excess) = -d(eps_v)/dt divided by rho_f g. It is the
 * volume balance of the mixture: solids and fluid are incompressible except for the fluid's
 * K_f, so the total volume flux v_s + q (skeleton velocity plus Darcy flux relative to it) is
 * divergence-free up to the fluid's compression. Weak form with the nodal hat functions N_i:
 *
 *   src_i = -int N_i div(v_s) dA = int grad N_i . v_s dA
 *         = sum_e A_e grad N_i^e . vbar_e,         vbar_e = J_e / A_s,e
 *
 * where J_e = sum over grains g of int_{g cap e} v dA (the solid flux carried through element e)
 * and A_s,e its solid area (clamped >= 0.01 A_e as for the void ratio). Because grad N_i is
 * constant per element, A_e grad N_i^e . vbar_e = (b_i J_x + c_i J_y) / (2 A_s,e) with b, c of
 * seed 000 eq. 3.12. Velocities are the displacements since the last fluid update divided by
 * the fluid step, so the source integrates exactly the skeleton motion between updates however
 * many grain steps the fluid step spans. Discs contribute their translation (a disc turning
 * about its centre moves no area); polygons their translation and rotation (the displacement of
 * the centroid of the clipped piece). The boundary term of the weak form is dropped: the
 * skeleton does not cross the mesh boundary (walls), and where it leaves the porous region
 * (pure-fluid elements) vbar is its own and the mixture flux stays continuous. Summed over all
 * nodes the source vanishes (sum_i grad N_i = 0): the model conserves the mixture's volume. */
#include "fluid/fluid_internal.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

double pl_fl_storage_factor(const struct pl_fluid *f) {
    return (f->par.consolidation && f->stor) ? 1.0 : f->par.storage;
}

void pl_fl_consolidation_free(struct pl_fluid *f) {
    free(f->src); free(f->stor); free(f->stor_assembled); free(f->ref_pos); free(f->ref_ang);
    f->src = f->stor = f->stor_assembled = NULL;
    f->ref_pos = NULL;
    f->ref_ang = NULL;
    f->ref_n = f->ref_cap = 0;
    f->src_active = 0;
}

pl_status pl_fl_consolidation_alloc(struct pl_fluid *f) {
    if (f->src) return PL_OK;
    f->src = calloc((size_t)f->mesh.nn, sizeof(double));
    f->stor = calloc((size_t)f->mesh.ne, sizeof(double));
    f->stor_assembled = malloc(sizeof(double) * (size_t)f->mesh.ne);
    if (!f->src || !f->stor || !f->stor_assembled) return PL_ERR_NOMEM;
    for (int e = 0; e < f->mesh.ne; e++) f->stor_assembled[e] = -1;
    f->k_dirty = 1; /* the mass matrix now carries the storage */
    return PL_OK;
}

static pl_status ensure_ref(struct pl_fluid *f, int n) {
    if (n <= f->ref_cap) return PL_OK;
    int nc = n + 64;
    pl_vec2 *p = realloc(f->ref_pos, sizeof(pl_vec2) * (size_t)nc);
    if (!p) return PL_ERR_NOMEM;
    f->ref_pos = p;
    double *a = realloc(f->ref_ang, sizeof(double) * (size_t)nc);
    if (!a) return PL_ERR_NOMEM;
    f->ref_ang = a;
    f->ref_cap = nc;
    return PL_OK;
}

pl_status pl_fl_consolidation_reset(struct pl_fluid *f, const pl_fl_bodies *b, const double *angle) {
    pl_status st = ensure_ref(f, b->n);
    if (st != PL_OK) return st;
    for (int i = 0; i < b->n; i++) {
        f->ref_pos[i] = b->pos[i];
        f->ref_ang[i] = angle ? angle[i] : 0;
    }
    f->ref_n = b->n;
    if (f->src) memset(f->src, 0, sizeof(double) * (size_t)f->mesh.nn);
    if (f->src_active) f->static_valid = 0;
    f->src_active = 0;
    f->last_src_abs = 0;
    return PL_OK;
}

void pl_fl_consolidation_storage(struct pl_fluid *f) {
    const pl_fl_params *p = &f->par;
    const double cf = p->bulk_modulus > 0 ? p->density * p->g / p->bulk_modulus : 0;
    for (int e = 0; e < f->mesh.ne; e++) {
        double A = f->mesh.area[e], As = f->solid[e];
        if (As < 0.01 * A) As = 0.01 * A;
        if (As > 0.99 * A) As = 0.99 * A;
        double n = 1 - As / A; /* areal porosity: the 2D mixture's volume balance */
        double S = p->storage + n * cf;
        f->stor[e] = S;
        if (S != f->stor_assembled[e]) f->k_dirty = 1;
    }
}

/* Area and centroid of a convex polygon clipped by a triangle (Sutherland-Hodgman). */
#define CL_MAX 160
static double clip_centroid(const pl_vec2 t[3], const pl_vec2 *v, int n, pl_vec2 *cen) {
    pl_vec2 buf[2][CL_MAX];
    int cnt = n < CL_MAX / 2 ? n : CL_MAX / 2;
    memcpy(buf[0], v, sizeof(pl_vec2) * (size_t)cnt);
    int cur = 0;
    for (int k = 0; k < 3 && cnt > 0; k++) {
        pl_vec2 a = t[k], bb = t[(k + 1) % 3];
        pl_vec2 ab = {bb.x - a.x, bb.y - a.y};
        const pl_vec2 *in = buf[cur];
        pl_vec2 *out = buf[1 - cur];
        int m = 0;
        for (int i = 0; i < cnt && m < CL_MAX - 2; i++) {
            pl_vec2 p = in[i], q = in[(i + 1) % cnt];
            double sp = ab.x * (p.y - a.y) - ab.y * (p.x - a.x);
            double sq = ab.x * (q.y - a.y) - ab.y * (q.x - a.x);
            if (sp >= 0) out[m++] = p;
            if ((sp >= 0) != (sq >= 0)) {
                double u = sp / (sp - sq);
                out[m++] = (pl_vec2){p.x + u * (q.x - p.x), p.y + u * (q.y - p.y)};
            }
        }
        cnt = m;
        cur = 1 - cur;
    }
    double a2 = 0, cx = 0, cy = 0;
    const pl_vec2 *P = buf[cur];
    for (int i = 0; i < cnt; i++) {
        pl_vec2 p = P[i], q = P[(i + 1) % cnt];
        double c = p.x * q.y - q.x * p.y;
        a2 += c;
        cx += (p.x + q.x) * c;
        cy += (p.y + q.y) * c;
    }
    if (!(a2 > 0)) return 0;
    cen->x = cx / (3 * a2);
    cen->y = cy / (3 * a2);
    return 0.5 * a2;
}

pl_status pl_fl_consolidation_source(struct pl_fluid *f, const pl_fl_bodies *b, const double *angle, double dt) {
    double t0 = pl_fl_now();
    const pl_fl_mesh *m = &f->mesh;
    const int nn = m->nn;
    pl_status st = ensure_ref(f, b->n);
    if (st != PL_OK) return st;
    /* bodies added since the last update: no displacement yet */
    for (int i = f->ref_n; i < b->n; i++) {
        f->ref_pos[i] = b->pos[i];
        f->ref_ang[i] = angle ? angle[i] : 0;
    }
    f->ref_n = b->n;
    /* covers are sorted by body: each (body, element) piece adds its solid flux to the
       element's three nodes */
    memset(f->src, 0, sizeof(double) * (size_t)nn);
    const double inv_dt = 1.0 / dt;
    for (int i = 0; i < f->cover_bodies && i < b->n; i++) {
        int k0 = f->body_cover_start[i], k1 = f->body_cover_start[i + 1];
        if (k0 == k1) continue;
        pl_vec2 d = {b->pos[i].x - f->ref_pos[i].x, b->pos[i].y - f->ref_pos[i].y};
        double dth = 0;
        if (b->shape[i] == PL_SHAPE_POLYGON && angle) dth = angle[i] - f->ref_ang[i];
        if (d.x == 0 && d.y == 0 && dth == 0) continue;
        for (int k = k0; k < k1; k++) {
            const pl_fl_cover *cv = &f->cover[k];
            int e = cv->elem;
            double a = cv->area;
            if (!(a > 0)) continue;
            pl_vec2 dd = d;
            const int32_t *v = &m->tri[3 * e];
            if (dth != 0) {
                /* displacement of the piece's centroid by the rotation about the body centroid */
                pl_vec2 t[3] = {m->xy[v[0]], m->xy[v[1]], m->xy[v[2]]};
                pl_vec2 c = b->pos[i];
                clip_centroid(t, &b->verts[b->vert_offset[i]], b->vert_count[i], &c);
                dd.x += -dth * (c.y - b->pos[i].y);
                dd.y += dth * (c.x - b->pos[i].x);
            }
            double A = m->area[e], As = f->solid[e];
            if (As < 0.01 * A) As = 0.01 * A;
            /* J_e piece = a * dd / dt; node i of e gets (b_i Jx + c_i Jy) / (2 As) */
            double jx = a * dd.x * inv_dt, jy = a * dd.y * inv_dt;
            const double *bc = &m->bc[6 * e];
            double s = 0.5 / As;
            for (int q = 0; q < 3; q++) f->src[v[q]] += s * (bc[q] * jx + bc[3 + q] * jy);
        }
    }
    for (int i = 0; i < b->n; i++) {
        f->ref_pos[i] = b->pos[i];
        f->ref_ang[i] = angle ? angle[i] : 0;
    }
    double sabs = 0;
    for (int i = 0; i < nn; i++) sabs += fabs(f->src[i]);
    f->last_src_abs = sabs;
    f->src_active = 1;
    f->static_valid = 0;
    f->t_source += pl_fl_now() - t0;
    return PL_OK;
}
