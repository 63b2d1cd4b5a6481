/* The resolved Navier–Stokes model class (porelab/navier_stokes.h, world/model.h): grain cores
 * at their predicted positions, the gmsh mesh of the pore space around them, one BDF2 step of
 * the system per fluid step, the stress integral on every core, and the model's state (mesh,
 * solution, BDF2 history, held loads) for hash, snapshot and restart files.
 *
 * State (saved, hashed, restored): the def; whether a mesh exists; the mesh (vertices,
 * triangles, boundary tags); the solution x and the BDF2 history x1, x2, tau1, nhist; the core
 * outlines the mesh was built around and the body of each hole; the grain steps since the last
 * fluid solve; the held force and moment per body; the step counter.
 * Cache (rebuilt on restore): edges, unknown numbering, Jacobian pattern, UMFPACK analysis.
 * Not state: CPU-time counters. */
#define _POSIX_C_SOURCE 200809L
#include "porelab/navier_stokes.h"
#include "core/alloc.h"
#include "fluid/navier_stokes/ns_internal.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include "world/model.h"
#include <math.h>
#include <stdio.h>
#include <umfpack.h>
#include <string.h>
#include <time.h>

typedef struct pl_ns {
    pl_navier_stokes_def def;
    int built;
    ns_system sys;
    /* cores of the current mesh */
    int nholes;
    int32_t *hole_body;     /* nholes */
    int32_t *core_off;      /* nholes + 1 */
    double *core_xy;        /* 2 core_off[nholes] */
    double *hole_motion;    /* 5 nholes: vx, vy, omega, cx, cy (predicted centroid) */
    /* held loads */
    int nbody;
    pl_vec2 *force;
    double *moment;
    int since;
    long steps;
    double fresh_angle;     /* smallest angle of the last full (gmsh) mesh, degrees */
    long nfluid;            /* fluid steps solved (state: the counters below are not) */
    /* counters (not state) */
    pl_ns_stats st;
    double seconds;
    long calls;
} pl_ns;

static double cpu_now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void free_cores(pl_ns *m) {
    pl_free_null(m->hole_body);
    pl_free_null(m->core_off);
    pl_free_null(m->core_xy);
    pl_free_null(m->hole_motion);
    m->nholes = 0;
}

static void free_state(pl_ns *m) {
    if (m->built) ns_system_free(&m->sys);
    m->built = 0;
    free_cores(m);
    pl_free_null(m->force);
    pl_free_null(m->moment);
    m->nbody = 0;
}

static pl_status check_def(pl_world *w, const pl_navier_stokes_def *d) {
    char msg[320];
    if (!d) return pl__world_error(w, PL_ERR_ARG, "navier_stokes: no def given (use pl_default_navier_stokes_def())");
    if (pl_params_check_all(pl_navier_stokes_params, pl_navier_stokes_param_count, d, "navier_stokes", msg,
                            sizeof msg) != PL_OK)
        return pl__world_error(w, PL_ERR_ARG, "%s", msg);
    if (!(d->x_max > d->x_min) || !(d->y_max > d->y_min))
        return pl__world_error(w, PL_ERR_ARG,
                               "navier_stokes: the box [%g, %g] x [%g, %g] m has no area (need x_max > x_min and "
                               "y_max > y_min)",
                               d->x_min, d->x_max, d->y_min, d->y_max);
    if (d->h_near > d->h_far)
        return pl__world_error(w, PL_ERR_ARG, "navier_stokes: h_near (%g m) must not exceed h_far (%g m)", d->h_near,
                               d->h_far);
    const double wmin = fmin(d->x_max - d->x_min, d->y_max - d->y_min);
    if (d->h_far > 0.5 * wmin)
        return pl__world_error(w, PL_ERR_ARG,
                               "navier_stokes: h_far (%g m) must be at most half the box's smaller side (%g m)",
                               d->h_far, 0.5 * wmin);
    return PL_OK;
}

pl_status pl_world_attach_navier_stokes(pl_world *w, const pl_navier_stokes_def *def) {
    if (!w) return PL_ERR_ARG;
    if (!ns_have_gmsh())
        return pl__world_error(w, PL_ERR_NOT_BUILT,
                               "navier_stokes: this build has no gmsh; the resolved Navier-Stokes model meshes the "
                               "pore space with gmsh's C API (install the Debian package libgmsh-dev and rebuild)");
    if (pl__world_model(w, &pl_navier_stokes_class))
        return pl__world_error(w, PL_ERR_STATE, "navier_stokes: this world already has Navier-Stokes water");
    pl_status st = check_def(w, def);
    if (st != PL_OK) return st;
    pl_ns *m = pl_calloc(1, sizeof *m);
    if (!m) return pl__world_error(w, PL_ERR_NOMEM, "navier_stokes: out of memory");
    m->def = *def;
    m->st.coupling_body = -1;
    st = pl__world_attach(w, &pl_navier_stokes_class, m);
    if (st != PL_OK) pl_free(m);
    return st;
}

int pl_world_has_navier_stokes(const pl_world *w) { return w && pl__world_model(w, &pl_navier_stokes_class) != NULL; }

/* ------------------------------------------------------------------ cores */

typedef struct cores {
    int n;
    int32_t *body, *off;
    double *xy, *motion;
} cores;

static void adopt_cores(pl_ns *m, cores *c);

static void cores_free(cores *c) {
    pl_free(c->body);
    pl_free(c->off);
    pl_free(c->xy);
    pl_free(c->motion);
    memset(c, 0, sizeof *c);
}

/* Cores of every disc and polygon whose centroid is in the box, predicted over tau. */
static pl_status make_cores(pl_ns *m, pl_world *w, const pl_grain_view *g, double tau, cores *c) {
    const pl_navier_stokes_def *d = &m->def;
    memset(c, 0, sizeof *c);
    int nb = 0, nvtx = 0;
    for (int i = 0; i < g->n; i++) {
        if (g->shape[i] != PL_SHAPE_DISC && g->shape[i] != PL_SHAPE_POLYGON) continue;
        if (g->pos[i].x <= d->x_min || g->pos[i].x >= d->x_max || g->pos[i].y <= d->y_min || g->pos[i].y >= d->y_max)
            continue;
        nb++;
        nvtx += g->shape[i] == PL_SHAPE_DISC ? d->disc_sides : g->vert_count[i];
    }
    c->body = pl_malloc(sizeof(int32_t) * (size_t)(nb + 1));
    c->off = pl_malloc(sizeof(int32_t) * (size_t)(nb + 1));
    c->xy = pl_malloc(sizeof(double) * (size_t)(2 * nvtx + 1));
    c->motion = pl_malloc(sizeof(double) * (size_t)(5 * nb + 1));
    if (!c->body || !c->off || !c->xy || !c->motion) return pl__world_error(w, PL_ERR_NOMEM, "navier_stokes: out of memory");
    const double margin = 0.25 * d->h_near;
    int k = 0, v = 0;
    c->off[0] = 0;
    for (int i = 0; i < g->n; i++) {
        if (g->shape[i] != PL_SHAPE_DISC && g->shape[i] != PL_SHAPE_POLYGON) continue;
        if (g->pos[i].x <= d->x_min || g->pos[i].x >= d->x_max || g->pos[i].y <= d->y_min || g->pos[i].y >= d->y_max)
            continue;
        const double cx = g->pos[i].x + g->vel[i].x * tau, cy = g->pos[i].y + g->vel[i].y * tau;
        const double rot = g->omega[i] * tau, cr = cos(rot), sr = sin(rot), f = d->core_fraction;
        const int v0 = v;
        if (g->shape[i] == PL_SHAPE_DISC) {
            const double R = f * g->radius[i];
            for (int j = 0; j < d->disc_sides; j++) {
                const double a = g->angle[i] + rot + 2.0 * 3.14159265358979323846 * j / d->disc_sides;
                c->xy[2 * v] = cx + R * cos(a);
                c->xy[2 * v + 1] = cy + R * sin(a);
                v++;
            }
        } else {
            const int o = g->vert_offset[i], nv = g->vert_count[i];
            double area2 = 0;
            for (int j = 0; j < nv; j++) {
                const pl_vec2 a = g->verts[o + j], b = g->verts[o + (j + 1) % nv];
                area2 += a.x * b.y - a.y * b.x;
            }
            for (int jj = 0; jj < nv; jj++) {
                const int j = area2 > 0 ? jj : nv - 1 - jj; /* counter-clockwise */
                const double rx = g->verts[o + j].x - g->pos[i].x, ry = g->verts[o + j].y - g->pos[i].y;
                c->xy[2 * v] = cx + f * (cr * rx - sr * ry);
                c->xy[2 * v + 1] = cy + f * (sr * rx + cr * ry);
                v++;
            }
        }
        for (int j = v0; j < v; j++) {
            const double x = c->xy[2 * j], y = c->xy[2 * j + 1];
            if (x < d->x_min + margin || x > d->x_max - margin || y < d->y_min + margin || y > d->y_max - margin)
                return pl__world_error(w, PL_ERR_STATE,
                                       "navier_stokes: at t = %g s the core of body %d reaches (%g, %g) m, within "
                                       "h_near/4 of the fluid box [%g, %g] x [%g, %g]: lower core_fraction or move the "
                                       "box sides away from the grains",
                                       g->time, i, x, y, d->x_min, d->x_max, d->y_min, d->y_max);
        }
        c->body[k] = i;
        double *mo = c->motion + 5 * k;
        mo[0] = g->vel[i].x;
        mo[1] = g->vel[i].y;
        mo[2] = g->omega[i];
        mo[3] = cx;
        mo[4] = cy;
        k++;
        c->off[k] = v;
    }
    c->n = k;
    return PL_OK;
}

static int cores_equal(const pl_ns *m, const cores *c) {
    if (m->nholes != c->n) return 0;
    if (memcmp(m->hole_body, c->body, sizeof(int32_t) * (size_t)c->n)) return 0;
    if (memcmp(m->core_off, c->off, sizeof(int32_t) * (size_t)(c->n + 1))) return 0;
    return memcmp(m->core_xy, c->xy, sizeof(double) * 2 * (size_t)c->off[c->n]) == 0;
}

/* ------------------------------------------------------------------ boundary conditions */

static void bc_fn(void *ctx, int tag, double x, double y, double *u, double *v) {
    const pl_ns *m = ctx;
    const pl_navier_stokes_def *d = &m->def;
    *u = *v = 0;
    if (tag == NS_TAG_TOP) {
        *u = d->lid_velocity;
    } else if (tag == NS_TAG_LEFT && d->inflow_velocity != 0) {
        const double s = (y - d->y_min) / (d->y_max - d->y_min);
        *u = 4.0 * d->inflow_velocity * s * (1.0 - s);
    } else if (tag >= NS_TAG_HOLE0) {
        const double *mo = m->hole_motion + 5 * (tag - NS_TAG_HOLE0);
        *u = mo[0] - mo[2] * (y - mo[4]);
        *v = mo[1] + mo[2] * (x - mo[3]);
    }
}

static void set_bc(pl_ns *m) {
    uint8_t tk[NS_TAG_HOLE0];
    tk[0] = 0;
    tk[NS_TAG_BOTTOM] = NS_BC_VELOCITY;
    tk[NS_TAG_RIGHT] = m->def.open_right ? NS_BC_NATURAL : NS_BC_VELOCITY;
    tk[NS_TAG_TOP] = m->def.open_top ? NS_BC_NATURAL : NS_BC_VELOCITY;
    tk[NS_TAG_LEFT] = NS_BC_VELOCITY;
    uint8_t *all = pl_malloc((size_t)m->sys.ntags + 1);
    if (!all) return;
    memcpy(all, tk, sizeof tk);
    for (int t = NS_TAG_HOLE0; t <= m->sys.ntags; t++) all[t] = NS_BC_VELOCITY;
    ns_system_set_bc(&m->sys, all, bc_fn, m);
    pl_free(all);
}

/* ------------------------------------------------------------------ remesh + interpolation */

/* Old solution and history onto the new system's nodes (point values; a node the old mesh does
   not cover, uncovered by a core that moved away, takes the rigid velocity of the nearest core). */
static void interpolate(const ns_system *o, ns_system *n, const cores *c) {
    int hint = 0;
    for (int j = 0; j < n->nvel; j++) {
        const double x = n->vxy[2 * j], y = n->vxy[2 * j + 1];
        double l1, l2;
        const int t = ns_system_locate(o, x, y, hint, &l1, &l2);
        if (t >= 0) {
            hint = t;
            ns_system_point(o, o->x, t, l1, l2, &n->x[j], &n->x[n->nvel + j], NULL);
            ns_system_point(o, o->x1, t, l1, l2, &n->x1[j], &n->x1[n->nvel + j], NULL);
            ns_system_point(o, o->x2, t, l1, l2, &n->x2[j], &n->x2[n->nvel + j], NULL);
            continue;
        }
        int best = -1;
        double bd = 1e300;
        for (int k = 0; k < c->n; k++) {
            const double dx = x - c->motion[5 * k + 3], dy = y - c->motion[5 * k + 4];
            if (dx * dx + dy * dy < bd) {
                bd = dx * dx + dy * dy;
                best = k;
            }
        }
        double u = 0, v = 0;
        if (best >= 0) {
            const double *mo = c->motion + 5 * best;
            u = mo[0] - mo[2] * (y - mo[4]);
            v = mo[1] + mo[2] * (x - mo[3]);
        }
        n->x[j] = n->x1[j] = n->x2[j] = u;
        n->x[n->nvel + j] = n->x1[n->nvel + j] = n->x2[n->nvel + j] = v;
    }
    for (int i = 0; i < n->mesh.nv; i++) {
        double l1, l2, q = 0;
        const int t = ns_system_locate(o, n->mesh.xy[2 * i], n->mesh.xy[2 * i + 1], hint, &l1, &l2);
        if (t >= 0) ns_system_point(o, o->x, t, l1, l2, NULL, NULL, &q);
        n->x[2 * n->nvel + i] = q;
    }
    n->tau1 = o->tau1;
    n->nhist = o->nhist;
}

static pl_status remesh(pl_ns *m, pl_world *w, cores *c) {
    const pl_navier_stokes_def *d = &m->def;
    char msg[400] = "";
    double t0 = cpu_now();
    ns_domain dom = {d->x_min, d->y_min, d->x_max, d->y_max, d->h_near, d->h_far,
                     0.0, d->grade_distance, c->n, c->off, c->xy, 0};
    if (c->n == 0) dom.h_near = d->h_far;
    ns_mesh mesh;
    if (ns_mesh_domain(&dom, &mesh, msg, sizeof msg))
        return pl__world_error(w, PL_ERR_NUMERIC, "navier_stokes: meshing the pore space at t = %g s failed: %s",
                               pl__world_time(w), msg);
    ns_system ns;
    if (ns_system_init(&ns, &mesh, d->element, NS_TAG_HOLE0 - 1 + c->n)) {
        ns_system_free(&ns);
        return pl__world_error(w, PL_ERR_NOMEM, "navier_stokes: out of memory for the system");
    }
    m->st.t_mesh += cpu_now() - t0;
    m->st.remeshes++;
    t0 = cpu_now();
    if (m->built) {
        interpolate(&m->sys, &ns, c);
        /* carry the solver counters over */
        ns.st.t_assemble = m->sys.st.t_assemble;
        ns.st.t_symbolic = m->sys.st.t_symbolic;
        ns.st.t_numeric = m->sys.st.t_numeric;
        ns.st.t_solve = m->sys.st.t_solve;
        ns.st.n_symbolic = m->sys.st.n_symbolic;
        ns.st.n_numeric = m->sys.st.n_numeric;
        ns.st.n_solve = m->sys.st.n_solve;
        ns_system_free(&m->sys);
    }
    m->st.t_interp += cpu_now() - t0;
    m->sys = ns;
    m->built = 1;
    m->fresh_angle = ns_mesh_min_angle(&m->sys.mesh);
    adopt_cores(m, c);
    return PL_OK;
}

/* Takes the cores c over as the mesh's cores. */
static void adopt_cores(pl_ns *m, cores *c) {
    free_cores(m);
    m->nholes = c->n;
    m->hole_body = c->body;
    m->core_off = c->off;
    m->core_xy = c->xy;
    m->hole_motion = c->motion;
    memset(c, 0, sizeof *c);
}

static int same_topology(const pl_ns *m, const cores *c) {
    return m->built && m->nholes == c->n && !memcmp(m->hole_body, c->body, sizeof(int32_t) * (size_t)c->n) &&
           !memcmp(m->core_off, c->off, sizeof(int32_t) * (size_t)(c->n + 1));
}

/* The smallest angle relocation may reach: remesh_angle, or 3/4 of the smallest angle of the last
   gmsh mesh when gmsh itself could not reach remesh_angle (tight gaps between cores). */
static double ns_relocation_floor(const pl_ns *m) {
    return fmin(m->def.remesh_angle, 0.75 * m->fresh_angle);
}

/* Mesh relaxation: the vertices on each core move with the core's rigid motion from the mesh's
   cores to c, the box sides stay, the interior follows by Jacobi sweeps of the Laplacian of the
   displacement (the neighbours' mean). Refused (-1, mesh unchanged) when a triangle inverts or
   the smallest angle falls below remesh_angle; 0 when the solution has been carried over. */
static int relocate(pl_ns *m, const cores *c) {
    ns_system *s = &m->sys;
    ns_mesh *M = &s->mesh;
    const int nv = M->nv;
    double *old = pl_malloc(sizeof(double) * (size_t)(4 * nv + 2 * s->nvel + 3 * s->nunk));
    uint8_t *fixed = pl_calloc((size_t)nv + 1, 1);
    int32_t *deg = pl_calloc((size_t)nv + 1, sizeof(int32_t));
    if (!old || !fixed || !deg) {
        pl_free(old);
        pl_free(fixed);
        pl_free(deg);
        return -1;
    }
    double *d = old + 2 * nv, *ovxy = old + 4 * nv, *ox = ovxy + 2 * s->nvel;
    memcpy(old, M->xy, sizeof(double) * 2 * (size_t)nv);
    memset(d, 0, sizeof(double) * 2 * (size_t)nv);
    for (int e = 0; e < M->ne; e++) {
        deg[M->edge[2 * e]]++;
        deg[M->edge[2 * e + 1]]++;
        const int tag = M->edge_tag[e];
        if (tag <= 0) continue;
        for (int k = 0; k < 2; k++) {
            const int v = M->edge[2 * e + k];
            fixed[v] = 1;
            if (tag < NS_TAG_HOLE0) continue;
            const int h = tag - NS_TAG_HOLE0;
            const double *mo = m->hole_motion + 5 * h, *mn = c->motion + 5 * h;
            const double *p0 = m->core_xy + 2 * m->core_off[h], *q0 = c->xy + 2 * c->off[h];
            const double ax = p0[0] - mo[3], ay = p0[1] - mo[4], bx = q0[0] - mn[3], by = q0[1] - mn[4];
            const double th = atan2(ax * by - ay * bx, ax * bx + ay * by), ct = cos(th), st = sin(th);
            const double rx = old[2 * v] - mo[3], ry = old[2 * v + 1] - mo[4];
            d[2 * v] = mn[3] + ct * rx - st * ry - old[2 * v];
            d[2 * v + 1] = mn[4] + st * rx + ct * ry - old[2 * v + 1];
        }
    }
    /* Jacobi sweeps; the sum over neighbours through the edge list */
    double *acc = pl_malloc(sizeof(double) * 2 * (size_t)nv);
    if (!acc) {
        pl_free(old);
        pl_free(fixed);
        pl_free(deg);
        return -1;
    }
    for (int sweep = 0; sweep < 40; sweep++) {
        memset(acc, 0, sizeof(double) * 2 * (size_t)nv);
        for (int e = 0; e < M->ne; e++) {
            const int a = M->edge[2 * e], b = M->edge[2 * e + 1];
            acc[2 * a] += d[2 * b];
            acc[2 * a + 1] += d[2 * b + 1];
            acc[2 * b] += d[2 * a];
            acc[2 * b + 1] += d[2 * a + 1];
        }
        for (int v = 0; v < nv; v++)
            if (!fixed[v] && deg[v] > 0) {
                d[2 * v] = acc[2 * v] / deg[v];
                d[2 * v + 1] = acc[2 * v + 1] / deg[v];
            }
    }
    pl_free(acc);
    for (int v = 0; v < nv; v++) {
        M->xy[2 * v] = old[2 * v] + d[2 * v];
        M->xy[2 * v + 1] = old[2 * v + 1] + d[2 * v + 1];
    }
    int ok = 1;
    for (int t = 0; t < M->nt && ok; t++) {
        const int32_t *v = M->tri + 3 * t;
        const double *p0 = M->xy + 2 * v[0], *p1 = M->xy + 2 * v[1], *p2 = M->xy + 2 * v[2];
        ok = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]) > 0;
    }
    if (ok && m->def.remesh_angle > 0) ok = ns_mesh_min_angle(M) >= ns_relocation_floor(m);
    if (!ok || m->def.remesh_angle <= 0) {
        memcpy(M->xy, old, sizeof(double) * 2 * (size_t)nv);
        pl_free(old);
        pl_free(fixed);
        pl_free(deg);
        return -1;
    }
    /* carry the solution over: the old geometry as a read-only view */
    memcpy(ovxy, s->vxy, sizeof(double) * 2 * (size_t)s->nvel);
    memcpy(ox, s->x, sizeof(double) * (size_t)s->nunk);
    memcpy(ox + s->nunk, s->x1, sizeof(double) * (size_t)s->nunk);
    memcpy(ox + 2 * s->nunk, s->x2, sizeof(double) * (size_t)s->nunk);
    ns_system o = *s;
    o.mesh.xy = old;
    o.vxy = ovxy;
    o.x = ox;
    o.x1 = ox + s->nunk;
    o.x2 = ox + 2 * s->nunk;
    ns_system_update_geometry(s);
    interpolate(&o, s, c);
    pl_free(old);
    pl_free(fixed);
    pl_free(deg);
    return 0;
}

/* ------------------------------------------------------------------ class functions */

static void *ns_create(void) {
    pl_ns *m = pl_calloc(1, sizeof *m);
    if (m) m->def = pl_default_navier_stokes_def();
    return m;
}

static pl_status ensure_bodies(pl_ns *m, pl_world *w, int n) {
    if (m->nbody == n) return PL_OK;
    pl_vec2 *f = pl_calloc((size_t)n + 1, sizeof *f);
    double *mo = pl_calloc((size_t)n + 1, sizeof *mo);
    if (!f || !mo) {
        pl_free(f);
        pl_free(mo);
        return pl__world_error(w, PL_ERR_NOMEM, "navier_stokes: out of memory");
    }
    for (int i = 0; i < n && i < m->nbody; i++) {
        f[i] = m->force[i];
        mo[i] = m->moment[i];
    }
    pl_free(m->force);
    pl_free(m->moment);
    m->force = f;
    m->moment = mo;
    m->nbody = n;
    return PL_OK;
}

/* Polar moment of inertia about the centroid, kg m per m thickness. */
static double body_inertia(const pl_grain_view *g, int i) {
    if (g->shape[i] == PL_SHAPE_DISC) return 0.5 * g->mass[i] * g->radius[i] * g->radius[i];
    const int o = g->vert_offset[i], nv = g->vert_count[i];
    double a2 = 0, j = 0;
    for (int k = 0; k < nv; k++) {
        const double ax = g->verts[o + k].x - g->pos[i].x, ay = g->verts[o + k].y - g->pos[i].y;
        const double bx = g->verts[o + (k + 1) % nv].x - g->pos[i].x, by = g->verts[o + (k + 1) % nv].y - g->pos[i].y;
        const double c = ax * by - ay * bx;
        a2 += c;
        j += c * (ax * ax + ax * bx + bx * bx + ay * ay + ay * by + by * by);
    }
    return a2 != 0 ? g->mass[i] * (j / 12.0) / (0.5 * a2) : 0.0;
}

/* The explicit coupling's limit (porelab/navier_stokes.h). For each dynamic grain and each of
   its rigid motions (vx, vy, omega), the fluid response D = -dF/dv comes from the factorised
   Jacobian of the step just solved: a unit change of the prescribed core velocity changes the
   solution by J^-1 e (e = 1 on the core's Dirichlet rows of that motion; the Dirichlet residual
   is x - g), whose stress integral is dF. With the load relaxed by beta and applied over the next
   fluid step tau, F' = (1 - beta) F + beta F_new(v), v' = v + tau F' / m, and F_new responding
   as -rho_a (v - v_prev) - kappa v (added mass, drag; units of m / tau) the characteristic
   polynomial z^2 + (beta (1 + rho_a + kappa) - 2) z + 1 - beta (1 + rho_a) has its roots in the
   unit circle when beta (1 + rho_a) < 2 and kappa beta < 4 - 2 beta (1 + rho_a); both hold
   when beta (1 + D tau / m) < 2, D tau / m = rho_a + kappa (the Jacobian gives their sum). */
static pl_status check_coupling(pl_ns *m, pl_world *w, const pl_grain_view *g, double tau) {
    ns_system *s = &m->sys;
    const double t0 = cpu_now();
    const double beta = m->def.force_relaxation;
    double *e = pl_calloc((size_t)s->nunk, sizeof(double)), *dx = pl_malloc(sizeof(double) * (size_t)s->nunk);
    if (!e || !dx) {
        pl_free(e);
        pl_free(dx);
        return pl__world_error(w, PL_ERR_NOMEM, "navier_stokes: out of memory");
    }
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    umfpack_di_defaults(control);
    double *keep = s->x;
    double worst = 0, worst_s = 0, s_tr = 0, s_rot = 0;
    int worst_b = -1, worst_dir = 0;
    pl_status st = PL_OK;
    for (int k = 0; k < m->nholes && st == PL_OK; k++) {
        const int b = m->hole_body[k];
        if (g->motion[b] != PL_MOTION_DYNAMIC || !g->wants_load[b] || !(g->mass[b] > 0)) continue;
        const double cx = m->hole_motion[5 * k + 3], cy = m->hole_motion[5 * k + 4];
        const double inertia = body_inertia(g, b);
        for (int dir = 0; dir < 3; dir++) {
            memset(e, 0, sizeof(double) * (size_t)s->nunk);
            for (int j = 0; j < s->nvel; j++) {
                if (s->node_tag[j] != NS_TAG_HOLE0 + k) continue;
                const double rx = s->vxy[2 * j] - cx, ry = s->vxy[2 * j + 1] - cy;
                e[j] = dir == 0 ? 1.0 : dir == 1 ? 0.0 : -ry;
                e[s->nvel + j] = dir == 0 ? 0.0 : dir == 1 ? 1.0 : rx;
            }
            if (umfpack_di_solve(UMFPACK_A, s->Ap, s->Ai, s->Ax, dx, e, s->numeric, control, info) != UMFPACK_OK) {
                st = pl__world_error(w, PL_ERR_NUMERIC, "navier_stokes: the coupling check's solve failed");
                break;
            }
            double fx, fy, mz;
            s->x = dx;
            ns_system_force_line(s, NS_TAG_HOLE0 + k, m->def.density, cx, cy, &fx, &fy, &mz);
            s->x = keep;
            const double D = dir == 0 ? -fx : dir == 1 ? -fy : -mz;
            const double mass = dir == 2 ? inertia : g->mass[b];
            if (!(mass > 0)) continue;
            const double sr = fmax(D, 0.0) * tau / mass, r = beta * (1.0 + sr);
            if (dir == 2) s_rot = fmax(s_rot, sr);
            else s_tr = fmax(s_tr, sr);
            if (r > worst) {
                worst = r;
                worst_s = sr;
                worst_b = b;
                worst_dir = dir;
            }
        }
    }
    s->x = keep;
    pl_free(e);
    pl_free(dx);
    m->st.t_stability += cpu_now() - t0;
    m->st.coupling_ratio = worst;
    m->st.coupling_body = worst_b;
    m->st.coupling_translation = s_tr;
    m->st.coupling_rotation = s_rot;
    if (st != PL_OK) return st;
    if (worst >= 2.0) {
        static const char *const what[3] = {"x velocity", "y velocity", "rotation"};
        return pl__world_error(w, PL_ERR_STATE,
                               "navier_stokes: at t = %g s the explicit fluid-grain coupling of body %d is unstable: "
                               "its fluid force responds to its %s as D tau / %s = %.3g over the fluid step tau = %g "
                               "s (added mass and drag), so force_relaxation (beta = %g) must satisfy beta (1 + %.3g) "
                               "< 2, i.e. beta < %.3g; set force_relaxation <= %.2g (a smaller fluid step, "
                               "solve_every or dt, lowers only the drag part)",
                               g->time, worst_b, what[worst_dir], worst_dir == 2 ? "I" : "m", worst_s, tau, beta, worst_s,
                               2.0 / (1.0 + worst_s), floor(1.6 / (1.0 + worst_s) * 100.0) / 100.0);
    }
    return PL_OK;
}

static pl_status fluid_step(pl_ns *m, pl_world *w, const pl_grain_view *g, double tau) {
    cores c;
    pl_status st = make_cores(m, w, g, tau, &c);
    if (st != PL_OK) {
        cores_free(&c);
        return st;
    }
    int moved = 0;
    /* The first fluid step meshes afresh even when a host prepared a mesh before it (to draw the
       field at t = 0, ns_prepare): preparing must not change what the steps do, so a run gives
       the same state whether or not its frames show the fluid. */
    const int fresh = m->nfluid == 0;
    if (fresh && m->built) { /* the prepared mesh and its (rest) field go: nothing is carried over */
        ns_system_free(&m->sys);
        m->built = 0;
    }
    if (!m->built || !cores_equal(m, &c)) {
        moved = m->built;
        const double t0 = cpu_now();
        if (!fresh && same_topology(m, &c) && relocate(m, &c) == 0) {
            adopt_cores(m, &c);
            m->st.relocations++;
            m->st.t_relocate += cpu_now() - t0;
        } else {
            m->st.t_relocate += cpu_now() - t0;
            st = remesh(m, w, &c);
            cores_free(&c);
            if (st != PL_OK) return st;
        }
    } else {
        /* same outlines: keep the mesh and its analysis; the velocities may differ */
        memcpy(m->hole_motion, c.motion, sizeof(double) * 5 * (size_t)c.n);
        cores_free(&c);
    }
    ns_system *s = &m->sys;
    s->nu = m->def.viscosity / m->def.density;
    s->fx = g->gravity.x;
    s->fy = g->gravity.y;
    s->convect = 1;
    set_bc(m);
    if (moved && m->def.project && s->nhist > 0) {
        /* the interpolated fields onto the discretely divergence-free ones (flux conserving) */
        const double t0 = cpu_now();
        const ns_stats keep = s->st;
        char pmsg[200] = "";
        double *const X[2] = {s->x1, s->x2};
        const int rc = ns_system_project_many(s, X, s->nhist > 1 ? 2 : 1, pmsg, sizeof pmsg);
        /* the Newton start: the projected last solution (x equals x1 after the last step) */
        memcpy(s->x, s->x1, sizeof(double) * 2 * (size_t)s->nvel);
        s->st = keep;
        m->st.t_project += cpu_now() - t0;
        if (rc)
            return pl__world_error(w, PL_ERR_NUMERIC, "navier_stokes: at t = %g s, after the mesh changed: %s", g->time,
                                   pmsg);
    }
    const int first = s->nhist == 0; /* state, unlike the counters: the first step loads in full */
    if (first) ns_system_push_history(s, 0.0);
    char msg[400] = "";
    const long it0 = s->st.n_numeric;
    if (ns_system_solve(s, tau, m->def.newton_tol, m->def.newton_max, msg, sizeof msg))
        return pl__world_error(w, PL_ERR_NUMERIC,
                               "navier_stokes: fluid step at t = %g s (tau = %g s, %d unknowns): %s; a smaller "
                               "solve_every or time step, or a finer mesh, may help",
                               g->time, tau, s->nunk, msg);
    m->st.newton_iters += s->st.n_numeric - it0;
    if (m->def.stability_every >= 0 &&
        (m->nfluid == 0 || (m->def.stability_every > 0 && m->nfluid % m->def.stability_every == 0)))
        if ((st = check_coupling(m, w, g, tau)) != PL_OK) return st;
    ns_system_push_history(s, tau);
    const double t0 = cpu_now();
    if ((st = ensure_bodies(m, w, g->n)) != PL_OK) return st;
    /* relaxed loads: the first fluid step applies its load in full */
    const double beta = first ? 1.0 : m->def.force_relaxation;
    uint8_t *hit = pl_calloc((size_t)m->nbody + 1, 1);
    if (!hit) return pl__world_error(w, PL_ERR_NOMEM, "navier_stokes: out of memory");
    for (int k = 0; k < m->nholes; k++) {
        const int b = m->hole_body[k];
        double fx, fy, mz;
        ns_system_force_line(s, NS_TAG_HOLE0 + k, m->def.density, m->hole_motion[5 * k + 3],
                             m->hole_motion[5 * k + 4], &fx, &fy, &mz);
        m->force[b].x += beta * (fx - m->force[b].x);
        m->force[b].y += beta * (fy - m->force[b].y);
        m->moment[b] += beta * (mz - m->moment[b]);
        hit[b] = 1;
    }
    for (int i = 0; i < m->nbody; i++)
        if (!hit[i]) {
            m->force[i] = (pl_vec2){0, 0};
            m->moment[i] = 0;
        }
    pl_free(hit);
    m->st.t_forces += cpu_now() - t0;
    m->st.fluid_steps++;
    m->nfluid++;
    return PL_OK;
}

static pl_status ns_prepare(void *self, pl_world *w) {
    pl_ns *m = self;
    if (m->built) return PL_OK;
    const pl_grain_view g = pl__world_grains(w);
    cores c;
    pl_status st = make_cores(m, w, &g, 0.0, &c);
    if (st == PL_OK) st = remesh(m, w, &c);
    cores_free(&c);
    return st;
}

static pl_status ns_advance(void *self, pl_world *w, const pl_grain_view *g, double dt) {
    pl_ns *m = self;
    const double t0 = cpu_now();
    pl_status st = PL_OK;
    if (m->nfluid == 0 || m->since >= m->def.solve_every) {
        st = fluid_step(m, w, g, dt * m->def.solve_every);
        m->since = 0;
    }
    m->since++;
    m->steps++;
    m->seconds += cpu_now() - t0;
    return st;
}

static pl_status ns_loads(void *self, pl_world *w, const pl_grain_view *g, double dt, pl_vec2 *force,
                          double *moment) {
    (void)w;
    (void)dt;
    pl_ns *m = self;
    for (int i = 0; i < g->n && i < m->nbody; i++) {
        if (!g->wants_load[i]) continue;
        force[i].x += m->force[i].x;
        force[i].y += m->force[i].y;
        moment[i] += m->moment[i];
    }
    m->calls++;
    return PL_OK;
}

/* ------------------------------------------------------------------ state image */

/* One byte layout serves snapshot, restart file and hash: a header of counts, then the arrays. */
typedef struct ns_head {
    uint32_t magic, version;
    int32_t built, nhist, since, nbody, nholes, ncore, nv, nt, ne, nunk, kind;
    int64_t steps, nfluid;
    double tau1, fresh_angle;
    pl_navier_stokes_def def;
} ns_head;
#define NS_MAGIC 0x4e535431u

typedef struct packer {
    uint8_t *p;
    size_t n, cap;
} packer;

static void put(packer *k, const void *data, size_t bytes) {
    if (k->p && k->n + bytes <= k->cap) memcpy(k->p + k->n, data, bytes);
    k->n += bytes;
}

static void pack(const pl_ns *m, packer *k) {
    ns_head h;
    memset(&h, 0, sizeof h);
    h.magic = NS_MAGIC;
    h.version = 2;
    h.built = m->built;
    h.since = m->since;
    h.nbody = m->nbody;
    h.nholes = m->nholes;
    h.ncore = m->nholes ? m->core_off[m->nholes] : 0;
    h.steps = m->steps;
    h.fresh_angle = m->fresh_angle;
    h.nfluid = m->nfluid;
    h.def = m->def;
    if (m->built) {
        h.nhist = m->sys.nhist;
        h.nv = m->sys.mesh.nv;
        h.nt = m->sys.mesh.nt;
        h.ne = m->sys.mesh.ne;
        h.nunk = m->sys.nunk;
        h.kind = m->sys.kind;
        h.tau1 = m->sys.tau1;
    }
    put(k, &h, sizeof h);
    put(k, m->force, sizeof(pl_vec2) * (size_t)m->nbody);
    put(k, m->moment, sizeof(double) * (size_t)m->nbody);
    if (m->nholes) {
        put(k, m->hole_body, sizeof(int32_t) * (size_t)m->nholes);
        put(k, m->core_off, sizeof(int32_t) * (size_t)(m->nholes + 1));
        put(k, m->core_xy, sizeof(double) * 2 * (size_t)h.ncore);
        put(k, m->hole_motion, sizeof(double) * 5 * (size_t)m->nholes);
    }
    if (m->built) {
        const ns_mesh *M = &m->sys.mesh;
        put(k, M->xy, sizeof(double) * 2 * (size_t)M->nv);
        put(k, M->tri, sizeof(int32_t) * 3 * (size_t)M->nt);
        put(k, M->edge_tag, sizeof(int32_t) * (size_t)M->ne);
        put(k, m->sys.x, sizeof(double) * (size_t)m->sys.nunk);
        put(k, m->sys.x1, sizeof(double) * (size_t)m->sys.nunk);
        put(k, m->sys.x2, sizeof(double) * (size_t)m->sys.nunk);
    }
}

static void *pack_alloc(const pl_ns *m, size_t *bytes) {
    packer k = {NULL, 0, 0};
    pack(m, &k);
    k.cap = k.n;
    k.p = pl_malloc(k.cap);
    if (!k.p) return NULL;
    k.n = 0;
    pack(m, &k);
    *bytes = k.n;
    return k.p;
}

typedef struct reader {
    const uint8_t *p;
    size_t n, at;
} reader;

static int get(reader *r, void *data, size_t bytes) {
    if (r->at + bytes > r->n) return -1;
    memcpy(data, r->p + r->at, bytes);
    r->at += bytes;
    return 0;
}

static void *get_array(reader *r, size_t bytes) {
    if (r->at + bytes > r->n) return NULL;
    void *a = pl_malloc(bytes ? bytes : 1);
    if (a) get(r, a, bytes);
    return a;
}

/* Rebuilds the model from a packed image; -1 when damaged. */
static int unpack(pl_ns *m, const uint8_t *p, size_t n) {
    reader r = {p, n, 0};
    ns_head h;
    if (get(&r, &h, sizeof h) || h.magic != NS_MAGIC || h.version != 2) return -1;
    if (h.nbody < 0 || h.nholes < 0 || h.ncore < 0 || h.nv < 0 || h.nt < 0 || h.ne < 0 || h.nunk < 0) return -1;
    free_state(m);
    m->def = h.def;
    m->since = h.since;
    m->steps = h.steps;
    m->fresh_angle = h.fresh_angle;
    m->nfluid = h.nfluid;
    m->nbody = h.nbody;
    m->force = get_array(&r, sizeof(pl_vec2) * (size_t)h.nbody);
    m->moment = get_array(&r, sizeof(double) * (size_t)h.nbody);
    if (!m->force || !m->moment) return -1;
    if (h.nholes) {
        m->nholes = h.nholes;
        m->hole_body = get_array(&r, sizeof(int32_t) * (size_t)h.nholes);
        m->core_off = get_array(&r, sizeof(int32_t) * (size_t)(h.nholes + 1));
        m->core_xy = get_array(&r, sizeof(double) * 2 * (size_t)h.ncore);
        m->hole_motion = get_array(&r, sizeof(double) * 5 * (size_t)h.nholes);
        if (!m->hole_body || !m->core_off || !m->core_xy || !m->hole_motion) return -1;
    }
    if (h.built) {
        ns_mesh M;
        memset(&M, 0, sizeof M);
        M.nv = h.nv;
        M.nt = h.nt;
        M.xy = get_array(&r, sizeof(double) * 2 * (size_t)h.nv);
        M.tri = get_array(&r, sizeof(int32_t) * 3 * (size_t)h.nt);
        int32_t *tags = get_array(&r, sizeof(int32_t) * (size_t)h.ne);
        if (!M.xy || !M.tri || !tags || ns_mesh_build_edges(&M) || M.ne != h.ne) {
            pl_free(tags);
            ns_mesh_free(&M);
            return -1;
        }
        memcpy(M.edge_tag, tags, sizeof(int32_t) * (size_t)h.ne);
        pl_free(tags);
        if (ns_system_init(&m->sys, &M, h.kind, NS_TAG_HOLE0 - 1 + h.nholes) || m->sys.nunk != h.nunk) {
            ns_system_free(&m->sys);
            return -1;
        }
        m->built = 1;
        if (get(&r, m->sys.x, sizeof(double) * (size_t)h.nunk) || get(&r, m->sys.x1, sizeof(double) * (size_t)h.nunk) ||
            get(&r, m->sys.x2, sizeof(double) * (size_t)h.nunk))
            return -1;
        m->sys.nhist = h.nhist;
        m->sys.tau1 = h.tau1;
    }
    return r.at == n ? 0 : -1;
}

static uint64_t ns_hash(const void *self, uint64_t h) {
    size_t n = 0;
    void *p = pack_alloc(self, &n);
    if (!p) return h ^ 0xdeadull;
    h = pl_hash_bytes(h, p, n);
    pl_free(p);
    return h;
}

static void *ns_snapshot(const void *self, size_t *bytes) {
    size_t n = 0;
    uint8_t *p = pack_alloc(self, &n);
    if (!p) return NULL;
    /* prefix the size so restore knows the length */
    uint8_t *s = pl_malloc(n + sizeof(uint64_t));
    if (!s) {
        pl_free(p);
        return NULL;
    }
    const uint64_t len = n;
    memcpy(s, &len, sizeof len);
    memcpy(s + sizeof len, p, n);
    pl_free(p);
    if (bytes) *bytes = n + sizeof len;
    return s;
}

static pl_status ns_restore(void *self, pl_world *w, const void *snap) {
    uint64_t len;
    memcpy(&len, snap, sizeof len);
    if (unpack(self, (const uint8_t *)snap + sizeof len, (size_t)len))
        return pl__world_error(w, PL_ERR_STATE, "navier_stokes: the snapshot could not be restored (out of memory)");
    return PL_OK;
}

static void ns_snapshot_free(void *snap) { pl_free(snap); }

static pl_status ns_save(const void *self, pl_image *img) {
    size_t n = 0;
    void *p = pack_alloc(self, &n);
    if (!p) return PL_ERR_NOMEM;
    const uint64_t len = n;
    pl_status st = pl__image_put(img, &len, sizeof len);
    if (st == PL_OK) st = pl__image_put(img, p, n);
    pl_free(p);
    return st;
}

static pl_status ns_load(void *self, pl_world *w, pl_image *img) {
    uint64_t len;
    pl_status st = pl__image_get(img, &len, sizeof len);
    if (st != PL_OK) return st;
    if (len > pl__image_left(img))
        return pl__world_error(w, PL_ERR_IO, "load: the Navier-Stokes section is shorter than its length word");
    uint8_t *p = pl_malloc((size_t)len + 1);
    if (!p) return pl__world_error(w, PL_ERR_NOMEM, "load: out of memory");
    st = pl__image_get(img, p, (size_t)len);
    if (st == PL_OK && unpack(self, p, (size_t)len))
        st = pl__world_error(w, PL_ERR_IO, "load: the image's Navier-Stokes section is damaged");
    pl_free(p);
    if (st == PL_OK && check_def(w, &((pl_ns *)self)->def) != PL_OK)
        st = pl__world_error(w, PL_ERR_IO, "load: the image's Navier-Stokes def is out of range");
    return st;
}

/* ------------------------------------------------------------------ field and queries */

/* Linear sub-triangles: the quadratic elements split into four through the edge midpoints (nodes
   = vertices, then edge midpoints: the velocity nodes), MINI into its three vertices. */
static int ns_field(const void *self, const pl_world *w, int quantity, pl_vec2 *xy, int32_t *tri, double *value,
                    int cap_nodes, int cap_tris, int *nt) {
    (void)w;
    const pl_ns *m = self;
    *nt = 0;
    if (!m->built) return 0;
    if (quantity != PL_FLUID_PRESSURE && quantity != PL_NS_FIELD_SPEED && quantity != PL_NS_FIELD_VELOCITY_X &&
        quantity != PL_NS_FIELD_VELOCITY_Y && quantity != PL_FLUID_VELOCITY_NODE_X &&
        quantity != PL_FLUID_VELOCITY_NODE_Y && quantity != PL_FLUID_ELEMENT_MESH)
        return 0;
    const ns_system *s = &m->sys;
    const ns_mesh *M = &s->mesh;
    if (quantity == PL_FLUID_ELEMENT_MESH) { /* the triangles themselves, for the mesh layer */
        *nt = M->nt;
        if (M->nv > cap_nodes || M->nt > cap_tris || !xy || !tri || !value) return M->nv;
        for (int j = 0; j < M->nv; j++) {
            xy[j] = (pl_vec2){M->xy[2 * j], M->xy[2 * j + 1]};
            value[j] = 0.0;
        }
        memcpy(tri, M->tri, sizeof(int32_t) * 3 * (size_t)M->nt);
        return M->nv;
    }
    if (quantity == PL_FLUID_VELOCITY_NODE_X) quantity = PL_NS_FIELD_VELOCITY_X;
    if (quantity == PL_FLUID_VELOCITY_NODE_Y) quantity = PL_NS_FIELD_VELOCITY_Y;
    const int quad = s->kind != NS_EL_MINI;
    const int nn = M->nv + (quad ? M->ne : 0), ntr = quad ? 4 * M->nt : M->nt;
    *nt = ntr;
    if (nn > cap_nodes || ntr > cap_tris || !xy || !tri || !value) return nn;
    for (int j = 0; j < nn; j++) {
        xy[j] = (pl_vec2){s->vxy[2 * j], s->vxy[2 * j + 1]};
        const double u = s->x[j], v = s->x[s->nvel + j];
        double q;
        if (j < M->nv) q = s->x[2 * s->nvel + j];
        else {
            const int e = j - M->nv;
            q = 0.5 * (s->x[2 * s->nvel + M->edge[2 * e]] + s->x[2 * s->nvel + M->edge[2 * e + 1]]);
        }
        value[j] = quantity == PL_FLUID_PRESSURE ? m->def.density * q
                   : quantity == PL_NS_FIELD_SPEED ? sqrt(u * u + v * v)
                   : quantity == PL_NS_FIELD_VELOCITY_X ? u
                                                       : v;
    }
    for (int t = 0; t < M->nt; t++) {
        const int32_t *v = M->tri + 3 * t;
        if (!quad) {
            for (int i = 0; i < 3; i++) tri[3 * t + i] = v[i];
            continue;
        }
        const int32_t e0 = M->nv + M->tri_edge[3 * t], e1 = M->nv + M->tri_edge[3 * t + 1],
                      e2 = M->nv + M->tri_edge[3 * t + 2];
        const int32_t sub[12] = {v[0], e0, e2, e0, v[1], e1, e2, e1, v[2], e0, e1, e2};
        memcpy(tri + 12 * t, sub, sizeof sub);
    }
    return nn;
}

int pl_world_navier_stokes_at(const pl_world *w, pl_vec2 p, pl_vec2 *velocity, double *pressure) {
    const pl_ns *m = w ? pl__world_model(w, &pl_navier_stokes_class) : NULL;
    if (velocity) *velocity = (pl_vec2){0, 0};
    if (pressure) *pressure = 0;
    if (!m || !m->built) return 0;
    double u = 0, v = 0, q = 0;
    if (ns_system_eval(&m->sys, p.x, p.y, 0, &u, &v, &q) < 0) return 0;
    if (velocity) *velocity = (pl_vec2){u, v};
    if (pressure) *pressure = m->def.density * q;
    return 1;
}

pl_status pl_world_navier_stokes_body_force(const pl_world *w, int body, pl_vec2 *force, double *moment) {
    const pl_ns *m = w ? pl__world_model(w, &pl_navier_stokes_class) : NULL;
    if (!m) return PL_ERR_STATE;
    if (body < 0) return PL_ERR_ARG;
    if (force) *force = body < m->nbody ? m->force[body] : (pl_vec2){0, 0};
    if (moment) *moment = body < m->nbody ? m->moment[body] : 0;
    return PL_OK;
}

pl_status pl_world_navier_stokes_stats(const pl_world *w, pl_ns_stats *out) {
    const pl_ns *m = w ? pl__world_model(w, &pl_navier_stokes_class) : NULL;
    if (!m || !out) return PL_ERR_STATE;
    *out = m->st;
    if (m->built) {
        const ns_system *s = &m->sys;
        out->vertices = s->mesh.nv;
        out->triangles = s->mesh.nt;
        out->unknowns = s->nunk;
        out->min_angle = ns_mesh_min_angle(&s->mesh);
        out->nnz_matrix = s->st.nnz_matrix;
        out->nnz_lu = s->st.nnz_lu;
        out->symbolic = s->st.n_symbolic;
        out->numeric = s->st.n_numeric;
        out->t_assembly = s->st.t_assemble;
        out->t_factor = s->st.t_symbolic + s->st.t_numeric;
        out->t_solve = s->st.t_solve;
    }
    return PL_OK;
}

static double ns_cost(const void *self, long *calls) {
    const pl_ns *m = self;
    if (calls) *calls = m->calls;
    return m->seconds;
}

static void ns_destroy(void *self) {
    pl_ns *m = self;
    free_state(m);
    pl_free(m);
}

const pl_model_class pl_navier_stokes_class = {
    .name = "navier_stokes",
    .label = "resolved Navier-Stokes (P2+bubble/P1 on a gmsh mesh of the pore space, Mueller et al. 2020)",
    .def_size = sizeof(pl_navier_stokes_def),
    .params = pl_navier_stokes_params,
    .nparams = PL_NAVIER_STOKES_PARAM_COUNT,
    .create = ns_create,
    .prepare = ns_prepare,
    .advance = ns_advance,
    .loads = ns_loads,
    .hash = ns_hash,
    .snapshot = ns_snapshot,
    .restore = ns_restore,
    .snapshot_free = ns_snapshot_free,
    .save = ns_save,
    .load = ns_load,
    .field = ns_field,
    .cost = ns_cost,
    .destroy = ns_destroy,
};
