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
#include "core/alloc.h"
#include "fluid/darcy/darcy_internal.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

double pl_fl_storage_factor(const struct pl_fluid *f) {
    return (f->par.consolidation && f->stor) ? 1.0 : f->par.storage;
}

void pl_fl_consolidation_free(struct pl_fluid *f) {
    pl_free(f->src); pl_free(f->stor); pl_free(f->stor_assembled); pl_free(f->ref_pos); pl_free(f->ref_ang);
    pl_free(f->vbar); pl_free(f->elem_bedge); pl_free(f->bchord);
    f->vbar = f->bchord = NULL;
    f->elem_bedge = NULL;
    f->src = f->stor = f->stor_assembled = NULL;
    f->ref_pos = NULL;
    f->ref_ang = NULL;
    f->ref_n = f->ref_cap = 0;
    f->src_active = 0;
}

pl_status pl_fl_consolidation_alloc(struct pl_fluid *f) {
    if (f->src) return PL_OK;
    f->src = pl_calloc((size_t)f->mesh.nn, sizeof(double));
    f->stor = pl_calloc((size_t)f->mesh.ne, sizeof(double));
    f->stor_assembled = pl_malloc(sizeof(double) * (size_t)f->mesh.ne);
    f->vbar = pl_calloc(2 * (size_t)f->mesh.ne, sizeof(double));
    f->elem_bedge = pl_malloc(sizeof(int32_t) * 3 * (size_t)f->mesh.ne);
    f->bchord = pl_calloc((size_t)f->mesh.nbe + 1, sizeof(double));
    if (!f->src || !f->stor || !f->stor_assembled || !f->vbar || !f->elem_bedge || !f->bchord) return PL_ERR_NOMEM;
    for (int e = 0; e < f->mesh.ne; e++) f->stor_assembled[e] = -1;
    /* boundary edges of each element (an oriented boundary edge a->b belongs to the element
       that has a->b among its counter-clockwise edges); found once per mesh */
    const pl_mesh *m = &f->mesh;
    for (int k = 0; k < 3 * m->ne; k++) f->elem_bedge[k] = -1;
    for (int e = 0; e < m->ne; e++) {
        const int32_t *v = &m->tri[3 * e];
        for (int k = 0; k < m->nbe; k++) {
            int a = m->bedge[2 * k], b = m->bedge[2 * k + 1];
            for (int q = 0; q < 3; q++)
                if (v[q] == a && v[(q + 1) % 3] == b) f->elem_bedge[3 * e + q] = k;
        }
    }
    f->k_dirty = 1; /* the mass matrix now carries the storage */
    return PL_OK;
}

static pl_status ensure_ref(struct pl_fluid *f, int n) {
    if (n <= f->ref_cap) return PL_OK;
    int nc = n + 64;
    pl_vec2 *p = pl_realloc(f->ref_pos, sizeof(pl_vec2) * (size_t)nc);
    if (!p) return PL_ERR_NOMEM;
    f->ref_pos = p;
    double *a = pl_realloc(f->ref_ang, sizeof(double) * (size_t)nc);
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

/* Length of segment a-b inside the disc (c, r). */
static double chord_disc(pl_vec2 a, pl_vec2 b, pl_vec2 c, double r) {
    pl_vec2 d = {b.x - a.x, b.y - a.y}, o = {a.x - c.x, a.y - c.y};
    double A = d.x * d.x + d.y * d.y, B = o.x * d.x + o.y * d.y, C = o.x * o.x + o.y * o.y - r * r;
    double disc = B * B - A * C;
    if (A <= 0 || disc <= 0) return 0;
    double sq = sqrt(disc), t1 = (-B - sq) / A, t2 = (-B + sq) / A;
    if (t1 < 0) t1 = 0;
    if (t2 > 1) t2 = 1;
    return t2 > t1 ? (t2 - t1) * sqrt(A) : 0;
}

/* Length of segment a-b inside a convex counter-clockwise polygon. */
static double chord_poly(pl_vec2 a, pl_vec2 b, const pl_vec2 *v, int n) {
    double t0 = 0, t1 = 1;
    pl_vec2 d = {b.x - a.x, b.y - a.y};
    if (!pl_fl_clip_segment_convex(a, d, v, n, &t0, &t1)) return 0;
    return t1 > t0 ? (t1 - t0) * sqrt(d.x * d.x + d.y * d.y) : 0;
}

pl_status pl_fl_consolidation_source(struct pl_fluid *f, const pl_fl_bodies *b, const double *angle, double dt) {
    double t0 = pl_fl_now();
    const pl_mesh *m = &f->mesh;
    const int nn = m->nn;
    pl_status st = ensure_ref(f, b->n);
    if (st != PL_OK) return st;
    /* bodies added since the last update: no displacement yet */
    for (int i = f->ref_n; i < b->n; i++) {
        f->ref_pos[i] = b->pos[i];
        f->ref_ang[i] = angle ? angle[i] : 0;
    }
    f->ref_n = b->n;
    /* covers are sorted by body: each (body, element) piece adds its solid flux J to its
       element; pieces in elements on the mesh boundary also measure how much of the boundary
       edge the body covers */
    memset(f->src, 0, sizeof(double) * (size_t)nn);
    memset(f->vbar, 0, sizeof(double) * 2 * (size_t)m->ne);
    memset(f->bchord, 0, sizeof(double) * (size_t)m->nbe);
    const double inv_dt = 1.0 / dt;
    for (int i = 0; i < f->cover_bodies && i < b->n; i++) {
        int k0 = f->body_cover_start[i], k1 = f->body_cover_start[i + 1];
        if (k0 == k1) continue;
        pl_vec2 d = {b->pos[i].x - f->ref_pos[i].x, b->pos[i].y - f->ref_pos[i].y};
        double dth = 0;
        if (b->shape[i] == PL_SHAPE_POLYGON && angle) dth = angle[i] - f->ref_ang[i];
        const pl_vec2 *pv = b->shape[i] == PL_SHAPE_POLYGON ? &b->verts[b->vert_offset[i]] : NULL;
        const int pn = pv ? b->vert_count[i] : 0;
        /* a grain pressed into a wall at the mesh's edge (pieces flagged outside: its part beyond
           the boundary folded into the boundary element, docs/fluid.md §6.1) does not cross the
           boundary as a solid: no boundary term, its whole area moves with it inside the mesh,
           as the forces assume (the same pieces: the coupling stays work-consistent) */
        int folded = 0;
        for (int k = k0; k < k1; k++) folded |= f->cover[k].outside;
        for (int k = k0; k < k1; k++) {
            const pl_fl_cover *cv = &f->cover[k];
            int e = cv->elem;
            double a = cv->area;
            if (!(a > 0)) continue;
            const int32_t *v = &m->tri[3 * e];
            for (int q = 0; q < 3 && !folded; q++) {
                int be = f->elem_bedge[3 * e + q];
                if (be < 0) continue;
                pl_vec2 p0 = m->xy[m->bedge[2 * be]], p1 = m->xy[m->bedge[2 * be + 1]];
                f->bchord[be] += pv ? chord_poly(p0, p1, pv, pn) : chord_disc(p0, p1, b->pos[i], b->radius[i]);
            }
            if (d.x == 0 && d.y == 0 && dth == 0) continue;
            pl_vec2 dd = d;
            if (dth != 0) {
                /* displacement of the piece's centroid by the rotation about the body centroid
                   (a piece beyond the boundary: the centroid of the body's piece in that element,
                   within the element's size of the sliver) */
                pl_vec2 t[3] = {m->xy[v[0]], m->xy[v[1]], m->xy[v[2]]};
                pl_vec2 c = b->pos[i];
                clip_centroid(t, pv, pn, &c);
                dd.x += -dth * (c.y - b->pos[i].y);
                dd.y += dth * (c.x - b->pos[i].x);
            }
            f->vbar[2 * e] += a * dd.x * inv_dt;
            f->vbar[2 * e + 1] += a * dd.y * inv_dt;
        }
    }
    /* vbar_e = J_e / A_s,e; node i of e gets A_e grad N_i . vbar_e = (b_i vx + c_i vy) / 2 */
    for (int e = 0; e < m->ne; e++) {
        double A = m->area[e], As = f->solid[e];
        if (As < 0.01 * A) As = 0.01 * A;
        double vx = f->vbar[2 * e] / As, vy = f->vbar[2 * e + 1] / As;
        f->vbar[2 * e] = vx;
        f->vbar[2 * e + 1] = vy;
        if (vx == 0 && vy == 0) continue;
        const int32_t *v = &m->tri[3 * e];
        const double *bc = &m->bc[6 * e];
        for (int q = 0; q < 3; q++) f->src[v[q]] += 0.5 * (bc[q] * vx + bc[3 + q] * vy);
    }
    /* boundary term -int N_i vbar . n ds of the weak form, on the part of each boundary edge
       covered by solids (a body crossing the mesh boundary, e.g. a piston: the skeleton outside
       moves with it); elsewhere the boundary is a fixed wall for the skeleton (term dropped) */
    for (int e = 0; e < m->ne; e++) {
        for (int q = 0; q < 3; q++) {
            int be = f->elem_bedge[3 * e + q];
            if (be < 0 || !(f->bchord[be] > 0)) continue;
            int ia = m->bedge[2 * be], ib = m->bedge[2 * be + 1];
            pl_vec2 p0 = m->xy[ia], p1 = m->xy[ib];
            double L = hypot(p1.x - p0.x, p1.y - p0.y);
            double cover = f->bchord[be] < L ? f->bchord[be] : L;
            /* outward normal of a counter-clockwise edge times its length: (dy, -dx) */
            double fl = f->vbar[2 * e] * (p1.y - p0.y) - f->vbar[2 * e + 1] * (p1.x - p0.x);
            double t = 0.5 * fl * cover / L;
            f->src[ia] -= t;
            f->src[ib] -= t;
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
