/* The boundary-element Stokes model class (porelab/stokes.h, world/model.h): the boundary
 * built from the grain view (the world's wall segments as a convex container, discs and
 * convex polygons as particles), the solve when due, the held loads with buoyancy, the drag
 * stability check, the drawing field, and hash / snapshot / image / cost. The numerics live
 * in stokes_kernels.c and stokes_solve.c.
 *
 * State (saved, hashed, restored): the def, the grain-step counter (when the next solve is
 * due) and the held drag force and moment of every body (they act until the next solve).
 * Derived (rebuilt by the next solve): the boundary with its solved tractions, the
 * resistances, the per-body results. Cache: the container block's LU factor. */
#define _POSIX_C_SOURCE 200809L
#include "core/alloc.h"
#include "core/clock.h"
#include "fluid/stokes_bem/stokes_internal.h"
#include "porelab/fluid.h"
#include "porelab/stokes.h"
#include "porelab/world.h"
#include "world/model.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* The drawing field of the last solve (a cache: rebuilt when the solve count or the grid
   changes; the queries fill it through the model's pointer, the model itself stays const). */
typedef struct sb_field_cache {
    long solves;
    int grid, nn, nt, has_values;
    pl_vec2 *xy;
    int32_t *tri;
    double *val; /* 3 per node: u_x, u_y, dynamic pressure */
} sb_field_cache;

typedef struct pl_stokes {
    pl_stokes_def def;
    sb_field_cache *fc;
    /* state */
    int64_t steps;      /* grain steps advanced since attach */
    int nb;             /* bodies the held loads are sized for */
    pl_vec2 *force;     /* nb: held drag (without buoyancy), N/m */
    double *moment;     /* nb */
    /* derived: the last solve */
    pl_sb_rules rules;
    pl_sb_bnd bnd;
    pl_sb_solver solver;
    int32_t *curve_body; /* per curve: body index (container: -1) */
    int ccap;
    int nside;
    int32_t *side_body;  /* per container side: body index */
    int32_t *side_start; /* nside + 1: elements of side s */
    int scap;
    double *kres;        /* 9 per curve */
    size_t kcap;
    pl_stokes_body_result *res; /* nb */
    int solved;
    double level;        /* top of the container along up (for the drawing pressure) */
    double seconds;
    long calls, solves;
} pl_stokes;

typedef struct sb_snap {
    pl_stokes_def def;
    int64_t steps;
    int nb;
    /* followed by nb pl_vec2 and nb double */
} sb_snap;


static pl_status check_def(pl_world *w, const pl_stokes_def *d) {
    char msg[320];
    if (!d) return pl__world_error(w, PL_ERR_ARG, "stokes: no def given (use pl_default_stokes_def())");
    if (pl_params_check_all(pl_stokes_params, pl_stokes_param_count, d, "stokes", msg, sizeof msg) != PL_OK)
        return pl__world_error(w, PL_ERR_ARG, "%s", msg);
    if (d->container_count != 0 && (d->container_count < 3 || d->container_count > PL_STOKES_CONTAINER_MAX))
        return pl__world_error(w, PL_ERR_ARG,
                               "stokes: container must list 3 to %d walls (got %d); leave it out to use every wall",
                               PL_STOKES_CONTAINER_MAX, d->container_count);
    for (int k = 0; k < d->container_count; k++) {
        if (d->container[k] < 0)
            return pl__world_error(w, PL_ERR_ARG, "stokes: container wall %d is not a body index (got %d)", k + 1,
                                   d->container[k]);
        for (int j = 0; j < k; j++)
            if (d->container[j] == d->container[k])
                return pl__world_error(w, PL_ERR_ARG, "stokes: container lists wall %d twice", d->container[k]);
    }
    return PL_OK;
}

/* 1 when body i is one of the container's walls: every segment, or the chosen ones. */
static int is_side(const pl_stokes_def *d, const pl_grain_view *g, int i) {
    if (g->shape[i] != PL_SHAPE_SEGMENT) return 0;
    if (d->container_count == 0) return 1;
    for (int k = 0; k < d->container_count; k++)
        if (d->container[k] == i) return 1;
    return 0;
}

/* 1 when the point c lies in the fluid's container as far as choosing particles goes: always
   without a chosen container; with one, strictly on the inner side of every chosen wall's
   line (the container is convex; the inner side is that of the walls' mean midpoint). */
static int in_container(const pl_stokes_def *d, const pl_grain_view *g, pl_vec2 c) {
    if (d->container_count == 0) return 1;
    pl_vec2 cen = {0, 0};
    int n = 0;
    for (int k = 0; k < d->container_count; k++) {
        const int i = d->container[k];
        if (i >= g->n || g->shape[i] != PL_SHAPE_SEGMENT) return 0;
        const pl_vec2 *v = g->verts + g->vert_offset[i];
        cen.x += 0.5 * (v[0].x + v[1].x);
        cen.y += 0.5 * (v[0].y + v[1].y);
        n++;
    }
    cen.x /= n;
    cen.y /= n;
    for (int k = 0; k < d->container_count; k++) {
        const pl_vec2 *v = g->verts + g->vert_offset[d->container[k]];
        const pl_vec2 t = {v[1].x - v[0].x, v[1].y - v[0].y};
        const double sc = t.x * (c.y - v[0].y) - t.y * (c.x - v[0].x);
        const double sm = t.x * (cen.y - v[0].y) - t.y * (cen.x - v[0].x);
        if (!(sc * sm > 0)) return 0;
    }
    return 1;
}

static pl_status ensure_bodies(pl_stokes *m, int n) {
    if (n <= m->nb && m->force) return PL_OK;
    pl_vec2 *f = pl_realloc(m->force, (size_t)(n > 0 ? n : 1) * sizeof *f);
    if (!f) return PL_ERR_NOMEM;
    m->force = f;
    double *mo = pl_realloc(m->moment, (size_t)(n > 0 ? n : 1) * sizeof *mo);
    if (!mo) return PL_ERR_NOMEM;
    m->moment = mo;
    pl_stokes_body_result *r = pl_realloc(m->res, (size_t)(n > 0 ? n : 1) * sizeof *r);
    if (!r) return PL_ERR_NOMEM;
    m->res = r;
    for (int i = m->nb; i < n; i++) {
        m->force[i] = (pl_vec2){0, 0};
        m->moment[i] = 0;
        memset(&m->res[i], 0, sizeof m->res[i]);
    }
    m->nb = n;
    return PL_OK;
}

/* ------------------------------------------------------------------ the boundary */

typedef struct side_line {
    int body;
    pl_vec2 p, q, mid;
    double ang;
} side_line;

static int cmp_side(const void *a, const void *b) {
    const double x = ((const side_line *)a)->ang, y = ((const side_line *)b)->ang;
    return x < y ? -1 : (x > y ? 1 : 0);
}

static double cross(pl_vec2 a, pl_vec2 b) { return a.x * b.y - a.y * b.x; }

/* Polar second moment about the centroid of a polygon (m^4). */
static double polygon_j(const pl_vec2 *v, int n, pl_vec2 c) {
    double j = 0;
    for (int k = 0; k < n; k++) {
        const pl_vec2 a = {v[k].x - c.x, v[k].y - c.y}, b = {v[(k + 1) % n].x - c.x, v[(k + 1) % n].y - c.y};
        const double cr = a.x * b.y - b.x * a.y;
        j += cr * (a.x * a.x + a.x * b.x + b.x * b.x + a.y * a.y + a.y * b.y + b.y * b.y);
    }
    return fabs(j) / 12;
}

static pl_status grow_curves(pl_stokes *m, int nc) {
    if (nc <= m->ccap) return PL_OK;
    const int cap = nc + 16;
    int32_t *cb = pl_realloc(m->curve_body, (size_t)cap * sizeof *cb);
    if (!cb) return PL_ERR_NOMEM;
    m->curve_body = cb;
    m->ccap = cap;
    return PL_OK;
}

/* Builds the boundary from the view: the container (curve 0, counter-clockwise) from the wall
   segments, then every disc and polygon (clockwise), with their rigid-body velocities. */
static pl_status build(pl_stokes *m, pl_world *w, const pl_grain_view *g) {
    const pl_stokes_def *d = &m->def;
    pl_sb_bnd *b = &m->bnd;
    pl_sb_bnd_clear(b);
    for (int k = 0; k < d->container_count; k++) {
        const int i = d->container[k];
        if (i >= g->n || g->shape[i] != PL_SHAPE_SEGMENT)
            return pl__world_error(w, PL_ERR_ARG,
                                   "stokes: container wall %d (body %d) is not a wall segment of this world (it has %d "
                                   "bodies); list the walls made by w:wall{}",
                                   k + 1, i, g->n);
    }
    int nw = 0;
    for (int i = 0; i < g->n; i++) nw += is_side(d, g, i);
    if (nw < 3)
        return pl__world_error(w, PL_ERR_STATE,
                               "stokes: the fluid needs a closed container of at least 3 wall segments (the world has "
                               "%d); in 2D an unbounded Stokes flow has no solution (Stokes' paradox)",
                               nw);
    side_line *sl = pl_malloc((size_t)nw * sizeof *sl);
    if (!sl) return pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
    pl_vec2 cen = {0, 0};
    for (int i = 0, k = 0; i < g->n; i++) {
        if (!is_side(d, g, i)) continue;
        const pl_vec2 *v = g->verts + g->vert_offset[i];
        sl[k] = (side_line){i, v[0], v[1], {0.5 * (v[0].x + v[1].x), 0.5 * (v[0].y + v[1].y)}, 0};
        cen.x += sl[k].mid.x / nw;
        cen.y += sl[k].mid.y / nw;
        k++;
    }
    for (int k = 0; k < nw; k++) sl[k].ang = atan2(sl[k].mid.y - cen.y, sl[k].mid.x - cen.x);
    qsort(sl, (size_t)nw, sizeof *sl, cmp_side);
    /* corners: intersections of consecutive wall lines */
    pl_vec2 *corner = pl_malloc((size_t)nw * sizeof *corner);
    if (!corner) {
        pl_free(sl);
        return pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
    }
    pl_status st = PL_OK;
    for (int k = 0; k < nw && st == PL_OK; k++) {
        const side_line *A = &sl[(k + nw - 1) % nw], *B = &sl[k];
        const pl_vec2 da = {A->q.x - A->p.x, A->q.y - A->p.y}, db = {B->q.x - B->p.x, B->q.y - B->p.y};
        const double den = cross(da, db);
        if (fabs(den) < 1e-12 * hypot(da.x, da.y) * hypot(db.x, db.y)) {
            st = pl__world_error(w, PL_ERR_STATE,
                                 "stokes: walls %d and %d are parallel neighbours; the container must be a convex "
                                 "polygon of wall segments, one per side",
                                 A->body, B->body);
            break;
        }
        const double s = cross((pl_vec2){B->p.x - A->p.x, B->p.y - A->p.y}, db) / den;
        corner[k] = (pl_vec2){A->p.x + s * da.x, A->p.y + s * da.y}; /* start of side k */
    }
    /* convex and counter-clockwise */
    for (int k = 0; k < nw && st == PL_OK; k++) {
        const pl_vec2 a = corner[k], bq = corner[(k + 1) % nw], c = corner[(k + 2) % nw];
        if (cross((pl_vec2){bq.x - a.x, bq.y - a.y}, (pl_vec2){c.x - bq.x, c.y - bq.y}) <= 0)
            st = pl__world_error(w, PL_ERR_STATE,
                                 "stokes: the wall segments do not bound a convex container (at the corner of walls "
                                 "%d and %d); the fluid's container must be convex",
                                 sl[(k) % nw].body, sl[(k + 1) % nw].body);
    }
    if (st == PL_OK && (pl_sb_bnd_curve(b, cen, 0) != PL_OK || grow_curves(m, 1) != PL_OK))
        st = pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
    if (st == PL_OK && nw + 1 > m->scap) {
        pl_free(m->side_body);
        pl_free(m->side_start);
        m->side_body = pl_malloc((size_t)(nw + 1) * sizeof *m->side_body);
        m->side_start = pl_malloc((size_t)(nw + 1) * sizeof *m->side_start);
        m->scap = (m->side_body && m->side_start) ? nw + 1 : 0;
        if (!m->scap) st = pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
    }
    const pl_vec2 up = (g->gravity.x != 0 || g->gravity.y != 0)
                           ? (pl_vec2){-g->gravity.x / hypot(g->gravity.x, g->gravity.y),
                                       -g->gravity.y / hypot(g->gravity.x, g->gravity.y)}
                           : (pl_vec2){0, 1};
    m->level = -INFINITY;
    if (st == PL_OK) m->curve_body[0] = -1;
    m->nside = 0;
    for (int k = 0; k < nw && st == PL_OK; k++) {
        const pl_vec2 p = corner[k], q = corner[(k + 1) % nw];
        const double L = hypot(q.x - p.x, q.y - p.y);
        m->level = fmax(m->level, p.x * up.x + p.y * up.y);
        int nel = d->wall_elements;
        if (d->element_length > 0) {
            const double want = ceil(L / d->element_length);
            if (want > nel) nel = want > 1e6 ? 1000000 : (int)want;
        }
        const int e0 = b->ne;
        m->side_body[k] = sl[k].body;
        m->side_start[k] = e0;
        if (pl_sb_bnd_line(b, p, q, nel) != PL_OK) {
            st = pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
            break;
        }
        const int i = sl[k].body;
        const pl_vec2 n = pl_sb_normal(p, q);
        const int held = i == d->load_wall;
        double load = d->load_force;
        if (held && d->load_contacts) { /* the unbalanced part (seed §5.3.2): contacts push along n */
            pl_body_info bi;
            if (pl_world_body_info(w, i, &bi) == PL_OK) load -= bi.force.x * n.x + bi.force.y * n.y;
        }
        if (held && fabs(n.x) > 1e-9 && fabs(n.y) > 1e-9) {
            st = pl__world_error(w, PL_ERR_ARG,
                                 "stokes: load_wall %d is inclined (normal (%.3g, %.3g)); a wall held by a force must "
                                 "be horizontal or vertical",
                                 i, n.x, n.y);
            break;
        }
        for (int e = e0; e < b->ne; e++)
            for (int mm = 0; mm < 2; mm++) {
                const pl_vec2 x = pl_sb_node_pos(b->a[e], b->b[e], mm);
                b->u[4 * e + 2 * mm] = g->vel[i].x - g->omega[i] * (x.y - g->pos[i].y);
                b->u[4 * e + 2 * mm + 1] = g->vel[i].y + g->omega[i] * (x.x - g->pos[i].x);
                if (held) {
                    /* the wall pushes the fluid along -n with load_force / L: t = σ n = -(F/L) n */
                    const int comp = fabs(n.x) > fabs(n.y) ? 0 : 1;
                    b->kind[4 * e + 2 * mm + comp] = PL_SB_TRAC;
                    b->t[4 * e + 2 * mm + comp] = -(load / L) * (comp == 0 ? n.x : n.y);
                }
            }
        m->nside = k + 1;
    }
    if (st == PL_OK) m->side_start[nw] = b->ne;
    b->nfixed = 1;
    if (st == PL_OK && d->load_wall >= 0) {
        int found = 0;
        for (int k = 0; k < nw; k++) found |= sl[k].body == d->load_wall;
        if (!found)
            st = pl__world_error(w, PL_ERR_ARG, "stokes: load_wall %d is not one of the container's wall segments",
                                 d->load_wall);
    }
    /* particles */
    const double sh = 0.5 * d->gap;
    for (int i = 0; i < g->n && st == PL_OK; i++) {
        if (g->shape[i] == PL_SHAPE_SEGMENT || !in_container(d, g, g->pos[i])) continue;
        const pl_vec2 c = g->pos[i];
        /* inside the container */
        for (int k = 0; k < nw; k++) {
            const pl_vec2 p = corner[k], q = corner[(k + 1) % nw];
            const pl_vec2 n = pl_sb_normal(p, q);
            const double dist = -((c.x - p.x) * n.x + (c.y - p.y) * n.y);
            const double reach = (g->shape[i] == PL_SHAPE_DISC ? g->radius[i] : 0) - sh;
            if (dist <= reach) {
                st = pl__world_error(w, PL_ERR_STATE,
                                     "stokes: body %d at (%g, %g) m reaches through the container side of wall %d at "
                                     "t = %g s (distance %g m, reach %g m); the fluid needs every particle inside, "
                                     "with a gap: set gap > %g m",
                                     i, c.x, c.y, sl[k].body, g->time, dist, reach + sh, 2 * (reach + sh - dist));
                break;
            }
        }
        if (st != PL_OK) break;
        const int resist = d->check_stability && g->motion[i] == PL_MOTION_DYNAMIC;
        if (grow_curves(m, b->ncurve + 1) != PL_OK) {
            st = pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
            break;
        }
        const int cidx = b->ncurve;
        if (g->shape[i] == PL_SHAPE_DISC) {
            const double r = g->radius[i] - sh;
            if (!(r > 0)) {
                st = pl__world_error(w, PL_ERR_ARG, "stokes: gap %g m shrinks disc %d (radius %g m) to nothing",
                                     d->gap, i, g->radius[i]);
                break;
            }
            /* start the elements at the disc's angle so that a spinning disc keeps its nodes */
            if (pl_sb_bnd_curve(b, c, resist) != PL_OK) {
                st = pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
                break;
            }
            const int ne = d->disc_elements;
            for (int k = 0; k < ne && st == PL_OK; k++) {
                const double t0 = g->angle[i] - 2 * M_PI * k / ne, t1 = g->angle[i] - 2 * M_PI * (k + 1) / ne;
                if (pl_sb_bnd_line(b, (pl_vec2){c.x + r * cos(t0), c.y + r * sin(t0)},
                                   (pl_vec2){c.x + r * cos(t1), c.y + r * sin(t1)}, 1) != PL_OK)
                    st = pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
            }
        } else {
            const pl_vec2 *v = g->verts + g->vert_offset[i];
            const int nv = g->vert_count[i];
            double area2 = 0, per = 0;
            for (int k = 0; k < nv; k++) {
                area2 += cross(v[k], v[(k + 1) % nv]);
                per += hypot(v[(k + 1) % nv].x - v[k].x, v[(k + 1) % nv].y - v[k].y);
            }
            if (pl_sb_bnd_curve(b, c, resist) != PL_OK) {
                st = pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
                break;
            }
            /* clockwise: reverse a counter-clockwise outline; shrink each vertex by gap/2 towards c */
            for (int k = 0; k < nv && st == PL_OK; k++) {
                const int k0 = area2 > 0 ? (nv - k) % nv : k, k1 = area2 > 0 ? (nv - k - 1 + nv) % nv : (k + 1) % nv;
                pl_vec2 p = v[k0], q = v[k1];
                const double rp = hypot(p.x - c.x, p.y - c.y), rq = hypot(q.x - c.x, q.y - c.y);
                if (!(rp > sh && rq > sh)) {
                    st = pl__world_error(w, PL_ERR_ARG, "stokes: gap %g m shrinks polygon %d to nothing", d->gap, i);
                    break;
                }
                p = (pl_vec2){c.x + (p.x - c.x) * (1 - sh / rp), c.y + (p.y - c.y) * (1 - sh / rp)};
                q = (pl_vec2){c.x + (q.x - c.x) * (1 - sh / rq), c.y + (q.y - c.y) * (1 - sh / rq)};
                const double L = hypot(q.x - p.x, q.y - p.y);
                int nel = (int)lround(d->polygon_elements * L / per);
                if (nel < 1) nel = 1;
                if (pl_sb_bnd_line(b, p, q, nel) != PL_OK) st = pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
            }
        }
        if (st != PL_OK) break;
        m->curve_body[cidx] = i;
        pl_sb_bnd_rigid(b, cidx, g->vel[i], g->omega[i]);
    }
    /* particles must not overlap (the fluid domain would not be one region) */
    for (int c1 = 1; c1 < b->ncurve && st == PL_OK; c1++)
        for (int c2 = c1 + 1; c2 < b->ncurve && st == PL_OK; c2++) {
            const int i = m->curve_body[c1], j = m->curve_body[c2];
            const double rr = (g->shape[i] == PL_SHAPE_DISC ? g->radius[i] : g->radius[i]) +
                              (g->shape[j] == PL_SHAPE_DISC ? g->radius[j] : g->radius[j]);
            const double dd = hypot(g->pos[i].x - g->pos[j].x, g->pos[i].y - g->pos[j].y);
            if (g->shape[i] == PL_SHAPE_DISC && g->shape[j] == PL_SHAPE_DISC && dd <= rr - 2 * sh)
                st = pl__world_error(w, PL_ERR_STATE,
                                     "stokes: discs %d and %d overlap by %g m at t = %g s; the fluid needs a connected "
                                     "domain between them: set gap > %g m (Tan 1990 section 3.4)",
                                     i, j, rr - dd, g->time, rr - dd);
        }
    pl_free(corner);
    pl_free(sl);
    return st;
}

/* Solves the flow for the view; fills the per-body results and (with hold) the held loads. */
static pl_status solve(pl_stokes *m, pl_world *w, const pl_grain_view *g, int hold) {
    if (ensure_bodies(m, g->n) != PL_OK) return pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
    pl_status st = build(m, w, g);
    if (st != PL_OK) return st;
    pl_sb_bnd *b = &m->bnd;
    /* an incompressible fluid in a container whose walls all move with given velocities needs
       zero net flux through them */
    int held = 0;
    for (int d = 0; d < 4 * b->curve_start[1]; d++) held |= b->kind[d] != PL_SB_VEL;
    if (!held) {
        double q = 0, qa = 0;
        for (int e = 0; e < b->curve_start[1]; e++) {
            const pl_vec2 n = pl_sb_normal(b->a[e], b->b[e]);
            const double L = hypot(b->b[e].x - b->a[e].x, b->b[e].y - b->a[e].y);
            const double *u = b->u + 4 * e;
            const double un = 0.5 * L * ((u[0] + u[2]) * n.x + (u[1] + u[3]) * n.y);
            q += un;
            qa += fabs(un);
        }
        if (fabs(q) > 1e-3 * qa && fabs(q) > 0)
            return pl__world_error(w, PL_ERR_STATE,
                                   "stokes: at t = %g s the container's walls change the fluid's area at %g m^2/s; an "
                                   "incompressible fluid cannot follow: hold one wall by a force (load_wall, "
                                   "load_force) or move the walls at constant area",
                                   g->time, q);
    }
    const size_t kneed = (size_t)9 * (size_t)b->ncurve;
    if (kneed > m->kcap) {
        pl_free(m->kres);
        m->kres = pl_malloc(kneed * sizeof *m->kres);
        m->kcap = m->kres ? kneed : 0;
        if (!m->kres) return pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
    }
    st = pl_sb_solve(&m->solver, b, &m->rules, m->def.viscosity, m->kres);
    if (st != PL_OK)
        return pl__world_error(w, st, "stokes: the boundary-element system is singular at t = %g s (%d elements); "
                                      "check that no particle touches another or a wall (gap)",
                               g->time, b->ne);
    m->solves++;
    m->solved = 1;
    for (int i = 0; i < g->n; i++) {
        memset(&m->res[i], 0, sizeof m->res[i]);
        m->res[i].dt_safe = INFINITY;
        if (hold) {
            m->force[i] = (pl_vec2){0, 0};
            m->moment[i] = 0;
        }
    }
    for (int c = 1; c < b->ncurve; c++) {
        const int i = m->curve_body[c];
        pl_stokes_body_result *r = &m->res[i];
        pl_sb_curve_load(b, b->t, b->curve_start[c], b->curve_start[c + 1], g->pos[i], &r->drag, &r->moment);
        r->buoyancy = (pl_vec2){-m->def.density * g->area[i] * g->gravity.x, -m->def.density * g->area[i] * g->gravity.y};
        if (b->resist[c]) {
            const double *K = m->kres + 9 * c;
            const double a = K[0], dd = K[4], o = 0.5 * (K[1] + K[3]);
            r->k_trans = 0.5 * (a + dd) + sqrt(0.25 * (a - dd) * (a - dd) + o * o);
            r->k_rot = K[8];
            double inertia;
            if (g->shape[i] == PL_SHAPE_DISC) inertia = 0.5 * g->mass[i] * g->radius[i] * g->radius[i];
            else
                inertia = g->area[i] > 0 ? g->mass[i] / g->area[i] *
                                               polygon_j(g->verts + g->vert_offset[i], g->vert_count[i], g->pos[i])
                                         : 0;
            const double t1 = r->k_trans > 0 ? 2 * g->mass[i] / r->k_trans : INFINITY;
            const double t2 = r->k_rot > 0 ? 2 * inertia / r->k_rot : INFINITY;
            r->dt_safe = fmin(t1, t2);
        }
        if (hold) {
            m->force[i] = r->drag;
            m->moment[i] = r->moment;
        }
    }
    for (int k = 0; k < m->nside; k++) {
        const int i = m->side_body[k];
        pl_stokes_body_result *r = &m->res[i];
        pl_vec2 F;
        double M;
        pl_sb_curve_load(b, b->t, m->side_start[k], m->side_start[k + 1], g->pos[i], &F, &M);
        r->drag.x += F.x;
        r->drag.y += F.y;
        r->moment += M;
        if (hold && g->wants_load[i]) {
            m->force[i] = r->drag;
            m->moment[i] = r->moment;
        }
    }
    return PL_OK;
}

/* ------------------------------------------------------------------ public API */

static pl_stokes *model(const pl_world *w) { return w ? pl__world_model(w, &pl_stokes_class) : NULL; }

static void *sb_create(void) {
    pl_stokes *m = pl_calloc(1, sizeof *m);
    if (!m) return NULL;
    m->def = pl_default_stokes_def();
    m->fc = pl_calloc(1, sizeof *m->fc);
    if (!m->fc || pl_sb_rules_init(&m->rules) != PL_OK) {
        pl_free(m->fc);
        pl_free(m);
        return NULL;
    }
    return m;
}

pl_status pl_world_attach_stokes(pl_world *w, const pl_stokes_def *def) {
    if (!w) return PL_ERR_ARG;
    if (model(w))
        return pl__world_error(w, PL_ERR_STATE,
                               "stokes: this world already has the Stokes fluid (change it with "
                               "pl_world_stokes_redefine / w:stokes_set{...})");
    pl_status st = check_def(w, def);
    if (st != PL_OK) return st;
    pl_stokes *m = sb_create();
    if (!m) return pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory (or LAPACK dstev failed)");
    m->def = *def;
    st = pl__world_attach(w, &pl_stokes_class, m);
    if (st != PL_OK) pl_free(m);
    return st;
}

int pl_world_has_stokes(const pl_world *w) { return model(w) != NULL; }

pl_status pl_world_stokes_def(const pl_world *w, pl_stokes_def *out) {
    const pl_stokes *m = model(w);
    if (!m || !out) return PL_ERR_STATE;
    *out = m->def;
    return PL_OK;
}

pl_status pl_world_stokes_redefine(pl_world *w, const pl_stokes_def *def) {
    pl_stokes *m = model(w);
    if (!m)
        return w ? pl__world_error(w, PL_ERR_STATE, "stokes_set: the world has no Stokes fluid (add it with w:stokes{...})")
                 : PL_ERR_ARG;
    pl_status st = check_def(w, def);
    if (st != PL_OK) return st;
    m->def = *def;
    return PL_OK;
}

pl_status pl_world_stokes_solve(pl_world *w) {
    pl_stokes *m = model(w);
    if (!m) return w ? pl__world_error(w, PL_ERR_STATE, "stokes: the world has no Stokes fluid") : PL_ERR_ARG;
    const pl_grain_view g = pl__world_grains(w);
    return solve(m, w, &g, 0);
}

pl_status pl_world_stokes_body(const pl_world *w, int body, pl_stokes_body_result *out) {
    const pl_stokes *m = model(w);
    if (!m || !m->solved) return PL_ERR_STATE;
    if (body < 0 || body >= m->nb || !out) return PL_ERR_ARG;
    *out = m->res[body];
    return PL_OK;
}

double pl_world_stokes_wall_pressure(const pl_world *w, int body) {
    const pl_stokes *m = model(w);
    if (!m || !m->solved) return NAN;
    for (int k = 0; k < m->nside; k++) {
        if (m->side_body[k] != body) continue;
        double s = 0, len = 0;
        for (int e = m->side_start[k]; e < m->side_start[k + 1]; e++) {
            const pl_vec2 n = pl_sb_normal(m->bnd.a[e], m->bnd.b[e]);
            const double L = hypot(m->bnd.b[e].x - m->bnd.a[e].x, m->bnd.b[e].y - m->bnd.a[e].y);
            const double *t = m->bnd.t + 4 * e;
            s -= 0.5 * L * ((t[0] + t[2]) * n.x + (t[1] + t[3]) * n.y);
            len += L;
        }
        return len > 0 ? s / len : NAN;
    }
    return NAN;
}

double pl_world_stokes_wall_flux(const pl_world *w, int body) {
    const pl_stokes *m = model(w);
    if (!m || !m->solved) return NAN;
    double q = 0;
    int found = 0;
    for (int k = 0; k < m->nside; k++) {
        if (m->side_body[k] != body) continue;
        q += pl_sb_curve_flux(&m->bnd, m->side_start[k], m->side_start[k + 1]);
        found = 1;
    }
    return found ? q : NAN;
}

/* 1 when p is inside the container and outside every (shrunk) particle, by margin h. */
static int in_fluid(const pl_stokes *m, pl_vec2 p, double h) {
    const pl_sb_bnd *b = &m->bnd;
    for (int c = 0; c < b->ncurve; c++) {
        /* winding: the container contains p, no particle does; margin from every element */
        double wind = 0;
        for (int e = b->curve_start[c]; e < b->curve_start[c + 1]; e++) {
            const pl_vec2 a = {b->a[e].x - p.x, b->a[e].y - p.y}, q = {b->b[e].x - p.x, b->b[e].y - p.y};
            wind += atan2(cross(a, q), a.x * q.x + a.y * q.y);
            const double dx = q.x - a.x, dy = q.y - a.y, L2 = dx * dx + dy * dy;
            double s = L2 > 0 ? -(a.x * dx + a.y * dy) / L2 : 0;
            s = s < 0 ? 0 : (s > 1 ? 1 : s);
            if (hypot(a.x + s * dx, a.y + s * dy) < h) return 0;
        }
        const int inside = fabs(wind) > M_PI;
        if (c == 0 && !inside) return 0;
        if (c > 0 && inside) return 0;
    }
    return 1;
}

pl_status pl_world_stokes_point(const pl_world *w, pl_vec2 p, pl_vec2 *velocity, double *pressure) {
    const pl_stokes *m = model(w);
    if (!m || !m->solved) return PL_ERR_STATE;
    if (!in_fluid(m, p, 0)) return PL_ERR_ARG;
    pl_vec2 u;
    double pr;
    pl_sb_interior(&m->rules, &m->bnd, m->def.viscosity, p, &u, &pr);
    if (velocity) *velocity = u;
    if (pressure) *pressure = pr;
    return PL_OK;
}

int pl_world_stokes_unknowns(const pl_world *w) {
    const pl_stokes *m = model(w);
    return m && m->solved ? m->solver.n : 0;
}

/* ------------------------------------------------------------------ class functions */

static pl_status sb_prepare(void *self, pl_world *w) {
    pl_stokes *m = self;
    const pl_grain_view g = pl__world_grains(w);
    return solve(m, w, &g, 0);
}

static pl_status sb_advance(void *self, pl_world *w, const pl_grain_view *g, double dt) {
    pl_stokes *m = self;
    const double t0 = pl_clock_seconds();
    pl_status st = PL_OK;
    if (m->steps % m->def.solve_every == 0) {
        st = solve(m, w, g, 1);
        if (st == PL_OK && m->def.check_stability) {
            const double hold = m->def.solve_every * dt;
            for (int c = 1; c < m->bnd.ncurve; c++) {
                const int i = m->curve_body[c];
                const pl_stokes_body_result *r = &m->res[i];
                if (!m->bnd.resist[c] || hold < r->dt_safe) continue;
                st = pl__world_error(w, PL_ERR_UNSTABLE,
                                     "stokes: explicit drag unstable at t = %g s: body %d (mass %g kg/m, drag "
                                     "resistance K = %g N s/m^2, spin resistance %g N s) needs solve_every x dt < "
                                     "2 min(m/K, I/K_rot) = %g s, but it is %d x %g s; use dt <= %g s (half the "
                                     "limit) or solve_every = 1",
                                     g->time, i, g->mass[i], r->k_trans, r->k_rot, r->dt_safe, m->def.solve_every,
                                     dt, 0.5 * r->dt_safe / m->def.solve_every);
                break;
            }
        }
    }
    if (st == PL_OK) m->steps++;
    m->seconds += pl_clock_seconds() - t0;
    return st;
}

static pl_status sb_loads(void *self, pl_world *w, const pl_grain_view *g, double dt, pl_vec2 *force,
                          double *moment) {
    (void)dt;
    pl_stokes *m = self;
    if (ensure_bodies(m, g->n) != PL_OK) return pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
    for (int i = 0; i < g->n; i++) {
        if (!g->wants_load[i]) continue;
        force[i].x += m->force[i].x;
        force[i].y += m->force[i].y;
        moment[i] += m->moment[i];
        if (g->shape[i] != PL_SHAPE_SEGMENT && in_container(&m->def, g, g->pos[i])) {
            /* buoyancy of the fully submerged grain (4.39) */
            force[i].x -= m->def.density * g->area[i] * g->gravity.x;
            force[i].y -= m->def.density * g->area[i] * g->gravity.y;
        }
    }
    m->calls++;
    return PL_OK;
}

static void def_values(const pl_stokes_def *d, double v[PL_STOKES_PARAM_COUNT]) {
    for (int k = 0; k < PL_STOKES_PARAM_COUNT; k++) v[k] = pl_param_read(&pl_stokes_params[k], d);
}

static uint64_t sb_hash(const void *self, uint64_t h) {
    const pl_stokes *m = self;
    double v[PL_STOKES_PARAM_COUNT];
    def_values(&m->def, v);
    h = pl_hash_bytes(h, v, sizeof v);
    if (m->def.container_count > 0) { /* only when chosen: scenes without one keep their hashes */
        h = pl_hash_bytes(h, &m->def.container_count, sizeof m->def.container_count);
        h = pl_hash_bytes(h, m->def.container, (size_t)m->def.container_count * sizeof m->def.container[0]);
    }
    h = pl_hash_bytes(h, &m->steps, sizeof m->steps);
    const int32_t nb = m->nb;
    h = pl_hash_bytes(h, &nb, sizeof nb);
    if (m->nb > 0) {
        h = pl_hash_bytes(h, m->force, (size_t)m->nb * sizeof *m->force);
        h = pl_hash_bytes(h, m->moment, (size_t)m->nb * sizeof *m->moment);
    }
    return h;
}

static void *sb_snapshot(const void *self, size_t *bytes) {
    const pl_stokes *m = self;
    const size_t sz = sizeof(sb_snap) + (size_t)m->nb * (sizeof(pl_vec2) + sizeof(double));
    sb_snap *s = pl_malloc(sz);
    if (!s) return NULL;
    s->def = m->def;
    s->steps = m->steps;
    s->nb = m->nb;
    unsigned char *p = (unsigned char *)(s + 1);
    if (m->nb > 0) {
        memcpy(p, m->force, (size_t)m->nb * sizeof(pl_vec2));
        memcpy(p + (size_t)m->nb * sizeof(pl_vec2), m->moment, (size_t)m->nb * sizeof(double));
    }
    if (bytes) *bytes = sz;
    return s;
}

static pl_status sb_restore(void *self, pl_world *w, const void *snap) {
    pl_stokes *m = self;
    const sb_snap *s = snap;
    if (ensure_bodies(m, s->nb) != PL_OK) return pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
    m->def = s->def;
    m->steps = s->steps;
    m->nb = s->nb;
    const unsigned char *p = (const unsigned char *)(s + 1);
    if (s->nb > 0) {
        memcpy(m->force, p, (size_t)s->nb * sizeof(pl_vec2));
        memcpy(m->moment, p + (size_t)s->nb * sizeof(pl_vec2), (size_t)s->nb * sizeof(double));
    }
    m->solved = 0;
    m->solves++; /* the drawing cache describes another state now */
    return PL_OK;
}

static void sb_snapshot_free(void *snap) { pl_free(snap); }

/* Image: layout word, the def's parameters as doubles (table order), the chosen container
   (count and PL_STOKES_CONTAINER_MAX body indices, int32), steps, nb, force[nb], moment[nb]. */
static uint64_t layout_word(void) {
    uint64_t h = PL_HASH_SEED;
    const uint32_t sizes[4] = {PL_STOKES_PARAM_COUNT, (uint32_t)sizeof(int64_t), (uint32_t)sizeof(pl_vec2),
                               (uint32_t)sizeof(double)};
    h = pl_hash_bytes(h, "stokes-bem-2", 12);
    return pl_hash_bytes(h, sizes, sizeof sizes);
}

static pl_status sb_save(const void *self, pl_image *img) {
    const pl_stokes *m = self;
    const uint64_t lw = layout_word();
    double v[PL_STOKES_PARAM_COUNT];
    def_values(&m->def, v);
    const int32_t nb = m->nb;
    pl_status st = pl__image_put(img, &lw, sizeof lw);
    int32_t box[1 + PL_STOKES_CONTAINER_MAX] = {m->def.container_count};
    for (int k = 0; k < PL_STOKES_CONTAINER_MAX; k++) box[1 + k] = m->def.container[k];
    if (st == PL_OK) st = pl__image_put(img, v, sizeof v);
    if (st == PL_OK) st = pl__image_put(img, box, sizeof box);
    if (st == PL_OK) st = pl__image_put(img, &m->steps, sizeof m->steps);
    if (st == PL_OK) st = pl__image_put(img, &nb, sizeof nb);
    if (st == PL_OK) st = pl__image_put_array(img, m->force, sizeof(pl_vec2), (size_t)m->nb);
    if (st == PL_OK) st = pl__image_put_array(img, m->moment, sizeof(double), (size_t)m->nb);
    return st;
}

static pl_status sb_load(void *self, pl_world *w, pl_image *img) {
    pl_stokes *m = self;
    uint64_t lw = 0;
    double v[PL_STOKES_PARAM_COUNT];
    int64_t steps = 0;
    int32_t nb = 0;
    pl_status st = pl__image_get(img, &lw, sizeof lw);
    if (st == PL_OK && lw != layout_word())
        return pl__world_error(w, PL_ERR_IO, "load: the image's stokes section has another layout");
    int32_t box[1 + PL_STOKES_CONTAINER_MAX] = {0};
    if (st == PL_OK) st = pl__image_get(img, v, sizeof v);
    if (st == PL_OK) st = pl__image_get(img, box, sizeof box);
    if (st == PL_OK) st = pl__image_get(img, &steps, sizeof steps);
    if (st == PL_OK) st = pl__image_get(img, &nb, sizeof nb);
    if (st != PL_OK) return st;
    if (nb < 0 || (size_t)nb * (sizeof(pl_vec2) + sizeof(double)) > pl__image_left(img) || steps < 0)
        return pl__world_error(w, PL_ERR_IO, "load: the image's stokes section is damaged (body count %d)", (int)nb);
    pl_stokes_def d = m->def;
    for (int k = 0; k < PL_STOKES_PARAM_COUNT; k++) pl_param_write(&pl_stokes_params[k], &d, v[k]);
    d.container_count = box[0];
    for (int k = 0; k < PL_STOKES_CONTAINER_MAX; k++) d.container[k] = box[1 + k];
    if (check_def(w, &d) != PL_OK)
        return pl__world_error(w, PL_ERR_IO, "load: the image's stokes section is damaged (a field is out of its range)");
    if (ensure_bodies(m, nb) != PL_OK) return pl__world_error(w, PL_ERR_NOMEM, "stokes: out of memory");
    st = pl__image_get_array(img, m->force, sizeof(pl_vec2), (size_t)nb);
    if (st == PL_OK) st = pl__image_get_array(img, m->moment, sizeof(double), (size_t)nb);
    if (st != PL_OK) return st;
    m->def = d;
    m->steps = steps;
    m->nb = nb;
    m->solved = 0;
    m->solves++;
    return PL_OK;
}

/* The point 'margin' into the fluid from the boundary point nearest to p (the fluid lies on
   the left of every element); 0 if that point is not in the fluid (a narrow gap). */
static int snap_to_fluid(const pl_stokes *m, pl_vec2 p, double margin, pl_vec2 *out) {
    const pl_sb_bnd *b = &m->bnd;
    double best = INFINITY;
    pl_vec2 q = p;
    for (int e = 0; e < b->ne; e++) {
        const double dx = b->b[e].x - b->a[e].x, dy = b->b[e].y - b->a[e].y, L2 = dx * dx + dy * dy;
        double s = L2 > 0 ? ((p.x - b->a[e].x) * dx + (p.y - b->a[e].y) * dy) / L2 : 0;
        s = s < 0 ? 0 : (s > 1 ? 1 : s);
        const pl_vec2 c = {b->a[e].x + s * dx, b->a[e].y + s * dy};
        const double d = hypot(p.x - c.x, p.y - c.y);
        if (d < best) {
            best = d;
            const pl_vec2 n = pl_sb_normal(b->a[e], b->b[e]);
            q = (pl_vec2){c.x - margin * n.x, c.y - margin * n.y};
        }
    }
    if (!in_fluid(m, q, 0.5 * margin)) return 0;
    *out = q;
    return 1;
}

/* A triangle whose three nodes were all snapped onto outlines and whose centroid lies in a
   particle covers the particle, not the fluid (the renderer would draw its mean velocity
   there): left out. Triangles with a grid node in the fluid are kept. */
static int keep_triangle(const pl_stokes *m, const pl_vec2 *xy, int nfluid, int a, int b, int c) {
    if (a < nfluid || b < nfluid || c < nfluid) return 1;
    const pl_vec2 g = {(xy[a].x + xy[b].x + xy[c].x) / 3, (xy[a].y + xy[b].y + xy[c].y) / 3};
    return in_fluid(m, g, 0);
}

/* Drawing field: a grid over the container (field_grid points along its longer side), nodes in
   the fluid, two triangles per cell whose corners are all in the fluid. Values: pressure
   (dynamic + ρ_l |g| (level - height), level = the container's top), excess pressure (the
   dynamic part), pressure head, head, and the velocity components (PL_FLUID_VELOCITY_NODE_X/Y).
   The grid and the values are cached per solve (sb_field_cache). */
static int field_grid(const pl_stokes *m, sb_field_cache *fc) {
    if (fc->solves == m->solves && fc->grid == m->def.field_grid && fc->xy) return 0;
    pl_free(fc->xy);
    pl_free(fc->tri);
    pl_free(fc->val);
    memset(fc, 0, sizeof *fc);
    const pl_sb_bnd *b = &m->bnd;
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int e = 0; e < b->curve_start[1]; e++) {
        x0 = fmin(x0, b->a[e].x);
        x1 = fmax(x1, b->a[e].x);
        y0 = fmin(y0, b->a[e].y);
        y1 = fmax(y1, b->a[e].y);
    }
    const int ng = m->def.field_grid;
    const double h = fmax(x1 - x0, y1 - y0) / (ng - 1);
    /* the grid spans the container's box exactly (spacing hx, hy close to h) */
    const int nx = (int)ceil((x1 - x0) / h - 1e-9) + 1, ny = (int)ceil((y1 - y0) / h - 1e-9) + 1;
    const double hx = (x1 - x0) / (nx - 1), hy = (y1 - y0) / (ny - 1), ox = x0, oy = y0;
    int32_t *idx = pl_malloc((size_t)nx * (size_t)ny * sizeof *idx);
    fc->xy = pl_malloc((size_t)nx * (size_t)ny * sizeof *fc->xy);
    fc->tri = pl_malloc((size_t)nx * (size_t)ny * 6 * sizeof *fc->tri);
    fc->val = pl_malloc((size_t)nx * (size_t)ny * 3 * sizeof *fc->val);
    if (!idx || !fc->xy || !fc->tri || !fc->val) {
        pl_free(idx);
        return -1;
    }
    int nn = 0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            const pl_vec2 p = {ox + i * hx, oy + j * hy};
            const int in = in_fluid(m, p, 0.05 * h);
            idx[j * nx + i] = in ? nn : -2;
            if (in) fc->xy[nn++] = p;
        }
    const int nfluid = nn; /* nodes [0, nfluid) are grid points in the fluid, the rest snapped */
    /* nodes of cells cut by a boundary (inside a particle, outside the container or too close
       to an element) move to the nearest boundary point, 0.05 h into the fluid, so that the
       cut cells are drawn up to the outline (the bodies are drawn over the field) instead of
       leaving a blocky hole around each grain */
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            if (idx[j * nx + i] != -2) continue;
            int near = 0;
            for (int dj = -1; dj <= 1 && !near; dj++)
                for (int di = -1; di <= 1 && !near; di++) {
                    const int ii = i + di, jj = j + dj;
                    near = ii >= 0 && jj >= 0 && ii < nx && jj < ny && idx[jj * nx + ii] >= 0;
                }
            idx[j * nx + i] = -1;
            if (!near) continue;
            const pl_vec2 p = {ox + i * hx, oy + j * hy};
            pl_vec2 q;
            if (snap_to_fluid(m, p, 0.05 * h, &q)) {
                idx[j * nx + i] = nn;
                fc->xy[nn++] = q;
            }
        }
    int t = 0;
    for (int j = 0; j + 1 < ny; j++)
        for (int i = 0; i + 1 < nx; i++) {
            const int a = idx[j * nx + i], bq = idx[j * nx + i + 1], c = idx[(j + 1) * nx + i + 1],
                      d = idx[(j + 1) * nx + i];
            if (a >= 0 && bq >= 0 && c >= 0 && keep_triangle(m, fc->xy, nfluid, a, bq, c)) {
                fc->tri[3 * t] = a;
                fc->tri[3 * t + 1] = bq;
                fc->tri[3 * t + 2] = c;
                t++;
            }
            if (a >= 0 && c >= 0 && d >= 0 && keep_triangle(m, fc->xy, nfluid, a, c, d)) {
                fc->tri[3 * t] = a;
                fc->tri[3 * t + 1] = c;
                fc->tri[3 * t + 2] = d;
                t++;
            }
        }
    pl_free(idx);
    fc->nn = nn;
    fc->nt = t;
    fc->grid = ng;
    fc->solves = m->solves;
    return 0;
}

static int sb_field(const void *self, const pl_world *w, int quantity, pl_vec2 *xy, int32_t *tri, double *value,
                    int cap_nodes, int cap_tris, int *nt) {
    const pl_stokes *m = self;
    sb_field_cache *fc = m->fc;
    *nt = 0;
    if (!m->solved || m->bnd.ncurve < 1 || !fc) return 0;
    if (quantity < PL_FLUID_HEAD || quantity > PL_FLUID_VELOCITY_NODE_Y) return 0;
    if (field_grid(m, fc) != 0) return 0;
    *nt = fc->nt;
    const int nn = fc->nn;
    if (nn > cap_nodes || fc->nt > cap_tris || !xy || !tri || !value) return nn;
    if (!fc->has_values) {
        for (int k = 0; k < nn; k++) {
            pl_vec2 u;
            double pd;
            pl_sb_interior(&m->rules, &m->bnd, m->def.viscosity, fc->xy[k], &u, &pd);
            fc->val[3 * k] = u.x;
            fc->val[3 * k + 1] = u.y;
            fc->val[3 * k + 2] = pd;
        }
        fc->has_values = 1;
    }
    const pl_vec2 gv = pl__world_gravity(w);
    const double gg = hypot(gv.x, gv.y);
    const pl_vec2 up = gg > 0 ? (pl_vec2){-gv.x / gg, -gv.y / gg} : (pl_vec2){0, 1};
    const double rg = m->def.density * gg;
    for (int k = 0; k < nn; k++) {
        const pl_vec2 p = fc->xy[k];
        const double pd = fc->val[3 * k + 2];
        const double z = p.x * up.x + p.y * up.y;
        const double ptot = pd + rg * (m->level - z);
        xy[k] = p;
        switch (quantity) {
        case PL_FLUID_PRESSURE: value[k] = ptot; break;
        case PL_FLUID_EXCESS_PRESSURE: value[k] = pd; break;
        case PL_FLUID_PRESSURE_HEAD: value[k] = rg > 0 ? ptot / rg : 0; break;
        case PL_FLUID_HEAD: value[k] = (rg > 0 ? ptot / rg : 0) + z; break;
        case PL_FLUID_VELOCITY_NODE_X: value[k] = fc->val[3 * k]; break;
        default: value[k] = fc->val[3 * k + 1]; break;
        }
    }
    memcpy(tri, fc->tri, (size_t)fc->nt * 3 * sizeof *tri);
    return nn;
}

static double sb_cost(const void *self, long *calls) {
    const pl_stokes *m = self;
    if (calls) *calls = m->calls;
    return m->seconds;
}

static void sb_destroy(void *self) {
    pl_stokes *m = self;
    if (!m) return;
    pl_sb_bnd_free(&m->bnd);
    pl_sb_solver_free(&m->solver);
    pl_free(m->curve_body);
    pl_free(m->side_body);
    pl_free(m->side_start);
    pl_free(m->kres);
    pl_free(m->force);
    pl_free(m->moment);
    pl_free(m->res);
    if (m->fc) {
        pl_free(m->fc->xy);
        pl_free(m->fc->tri);
        pl_free(m->fc->val);
        pl_free(m->fc);
    }
    pl_free(m);
}

const pl_model_class pl_stokes_class = {
    .name = "stokes",
    .label = "resolved Stokes flow by boundary elements (Tan 1990)",
    .def_size = sizeof(pl_stokes_def),
    .params = pl_stokes_params,
    .nparams = PL_STOKES_PARAM_COUNT,
    .create = sb_create,
    .prepare = sb_prepare,
    .advance = sb_advance,
    .loads = sb_loads,
    .hash = sb_hash,
    .snapshot = sb_snapshot,
    .restore = sb_restore,
    .snapshot_free = sb_snapshot_free,
    .save = sb_save,
    .load = sb_load,
    .field = sb_field,
    .cost = sb_cost,
    .destroy = sb_destroy,
};
