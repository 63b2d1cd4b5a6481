/* The solid model class (porelab/solid.h, world/model.h): attach, parts meshed by gmsh, boundary
 * conditions, queries, and the class functions the world calls: advance (grain-edge contact
 * from the grain view, then one explicit step of the solid), loads (the contact forces on the
 * discs), the critical step, hash, snapshot, state image, field, cost. */
#define _POSIX_C_SOURCE 200809L
#include "solid/fic/solid_internal.h"
#include "core/clock.h"
#include "solid/fic/solid_mesh.h"
#include "core/alloc.h"
#include "world/model.h"
#include "porelab/world.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

typedef struct pl_solid {
    pl_solid_def def;
    pl_sf *sf;            /* NULL until the first part */
    int parts;
    /* contact results of the last advance, per body (scratch, rebuilt each step) */
    pl_vec2 *cf;
    double *cm;
    int cap;
    int32_t *cand;
    int cand_cap;
    pl_vec2 contact_total;
    double e_contact_spring; /* energy in the contact springs now, J/m */
    double e_contact_diss;   /* dissipated by dashpots and friction so far, J/m (state) */
    /* grain-edge bonds (state) and their law */
    pl_sf_bond *bonds;
    int nbond, bond_cap;
    pl_bond_def bond_law;
    double seconds;
    double seconds_contact; /* part of seconds: the grain-edge contact search and forces */
    long calls;
} pl_solid;


static pl_solid *get(const pl_world *w) { return w ? pl__world_model(w, &pl_solid_class) : NULL; }

static pl_status check_def(pl_world *w, const pl_solid_def *d) {
    char msg[320];
    if (!d) return pl__world_error(w, PL_ERR_ARG, "solid: no def given (use pl_default_solid_def())");
    if (pl_params_check_all(pl_solid_params, PL_SOLID_PARAM_COUNT, d, "solid", msg, sizeof msg) != PL_OK)
        return pl__world_error(w, PL_ERR_ARG, "%s", msg);
    return PL_OK;
}

pl_status pl_world_attach_solid(pl_world *w, const pl_solid_def *def) {
    if (!w) return PL_ERR_ARG;
    if (get(w)) return pl__world_error(w, PL_ERR_STATE, "solid: this world already has a solid (add parts to it)");
    pl_status st = check_def(w, def);
    if (st != PL_OK) return st;
    pl_solid *m = pl_calloc(1, sizeof *m);
    if (!m) return pl__world_error(w, PL_ERR_NOMEM, "solid: out of memory");
    m->def = *def;
    st = pl__world_attach(w, &pl_solid_class, m);
    if (st != PL_OK) pl_free(m);
    return st;
}

int pl_world_has_solid(const pl_world *w) { return get(w) != NULL; }

static int add_mesh(pl_world *w, pl_sf_mesh *mesh, pl_status st, const char *msg) {
    pl_solid *m = get(w);
    if (st == PL_OK && m->sf && (m->sf->heat || m->nbond > 0)) {
        pl_sf_mesh_free(mesh);
        return pl__world_error(w, PL_ERR_STATE,
                               "solid: add every part before solid_thermal and solid_bond (they hold per-node and "
                               "per-edge state of the parts given so far)");
    }
    if (st != PL_OK) return pl__world_error(w, st, "%s", msg);
    if (m->sf) {
        st = pl_sf_append(m->sf, mesh);
        if (st != PL_OK) st = pl__world_error(w, st, "%s", m->sf->err);
    } else {
        char err[320] = "solid: out of memory";
        m->sf = pl_sf_create(&m->def, mesh, err, sizeof err);
        if (!m->sf) st = pl__world_error(w, PL_ERR_ARG, "%s", err);
    }
    pl_sf_mesh_free(mesh);
    if (st != PL_OK) return st;
    m->sf->gravity = pl__world_gravity(w);
    pl__world_invalidate_dt(w);
    return m->parts++;
}

static pl_solid *need(pl_world *w, const char *fn) {
    pl_solid *m = get(w);
    if (!m && w) pl__world_error(w, PL_ERR_STATE, "%s: the world has no solid (attach one with w:solid{...})", fn);
    return m;
}

/* ------------------------------------------------------------------ bonds, heat and wear */

int pl_world_solid_bond(pl_world *w, const pl_bond_def *law, double gap) {
    pl_solid *m = need(w, "solid_bond");
    if (!m) return PL_ERR_STATE;
    if (!m->sf) return pl__world_error(w, PL_ERR_STATE, "solid_bond: the solid has no parts yet (mesh it first)");
    if (!law) return pl__world_error(w, PL_ERR_ARG, "solid_bond: no bond law given");
    if (!(gap >= 0) || !isfinite(gap))
        return pl__world_error(w, PL_ERR_ARG, "solid_bond: gap must be a finite distance >= 0 m (got %g)", gap);
    pl_bond_def d = *law;
    char msg[400];
    if (pl_bond_def_check(&d, "solid_bond", msg, sizeof msg) != PL_OK) return pl__world_error(w, PL_ERR_ARG, "%s", msg);
    if (m->nbond > 0 && memcmp(&d, &m->bond_law, sizeof d) != 0)
        return pl__world_error(w, PL_ERR_ARG,
                               "solid_bond: the solid's bonds already have a law; one law serves all grain-edge bonds "
                               "(call solid_bond again with the same law)");
    pl_status st = pl_sf_prepare(m->sf);
    if (st != PL_OK) return pl__world_error(w, st, "%s", m->sf->err);
    const pl_grain_view g = pl__world_grains(w);
    int made = 0;
    for (int i = 0; i < g.n; i++) {
        if (g.shape[i] != PL_SHAPE_DISC) continue;
        int dup = 0;
        for (int k = 0; k < m->nbond && !dup; k++) dup = m->bonds[k].grain == i && m->bonds[k].state == PL_BOND_INTACT;
        if (dup) continue;
        pl_sf_bond b;
        if (!pl_sf_bond_make(m->sf, i, g.pos[i], g.angle[i], g.radius[i], gap, &b)) continue;
        if (m->nbond == m->bond_cap) {
            const int c = m->bond_cap ? 2 * m->bond_cap : 64;
            pl_sf_bond *q = pl_realloc(m->bonds, sizeof *q * (size_t)c);
            if (!q) return pl__world_error(w, PL_ERR_NOMEM, "solid_bond: out of memory");
            m->bonds = q;
            m->bond_cap = c;
        }
        m->bonds[m->nbond++] = b;
        made++;
    }
    m->bond_law = d;
    pl__world_invalidate_dt(w);
    return made;
}

int pl_world_solid_bond_count(const pl_world *w, int *intact) {
    const pl_solid *m = get(w);
    int c = 0;
    if (m)
        for (int k = 0; k < m->nbond; k++) c += m->bonds[k].state == PL_BOND_INTACT;
    if (intact) *intact = c;
    return m ? m->nbond : 0;
}

int pl_world_solid_bonds(const pl_world *w, pl_bond_info *out, int cap) {
    const pl_solid *m = get(w);
    if (!m || !m->sf) return 0;
    int k = 0;
    for (; k < m->nbond && k < cap; k++) {
        const pl_sf_bond *b = &m->bonds[k];
        const double *x = m->sf->x;
        pl_bond_info *o = &out[k];
        memset(o, 0, sizeof *o);
        o->a = b->grain;
        o->b = b->a; /* the edge's first node */
        o->state = b->state;
        o->n = b->n, o->s = b->s, o->m = b->m, o->un = b->un, o->ut = b->ut;
        o->elastic = b->state == PL_BOND_INTACT ? b->elastic : 0;
        o->dissipated = b->h.dissipated;
        o->point = (pl_vec2){(1 - b->t0) * x[2 * b->a] + b->t0 * x[2 * b->b],
                             (1 - b->t0) * x[2 * b->a + 1] + b->t0 * x[2 * b->b + 1]};
        o->broken_step = -1;
        o->broken_time = b->broken_time;
    }
    return k;
}

pl_status pl_world_solid_thermal(pl_world *w, const pl_thermal_def *def, double fraction, double t0) {
    pl_solid *m = need(w, "solid_thermal");
    if (!m) return PL_ERR_STATE;
    if (!m->sf) return pl__world_error(w, PL_ERR_STATE, "solid_thermal: the solid has no parts yet (mesh it first)");
    if (!def) return pl__world_error(w, PL_ERR_ARG, "solid_thermal: no thermal definition");
    char msg[400];
    if (pl_params_check_all(pl_thermal_params, PL_THERMAL_PARAM_COUNT, def, "solid_thermal", msg, sizeof msg) != PL_OK)
        return pl__world_error(w, PL_ERR_ARG, "%s", msg);
    if (!(fraction >= 0 && fraction <= 1))
        return pl__world_error(w, PL_ERR_ARG, "solid_thermal: fraction must be in [0, 1] (got %g)", fraction);
    if (!(t0 > 0) || !isfinite(t0))
        return pl__world_error(w, PL_ERR_ARG, "solid_thermal: initial temperature must be > 0 K (got %g)", t0);
    pl_sf *s = m->sf;
    pl_status st = pl_sf_prepare(s);
    if (st != PL_OK) return pl__world_error(w, st, "%s", s->err);
    if (!s->heat) {
        s->heat = pl_calloc((size_t)s->nn, sizeof *s->heat);
        s->wear = pl_calloc((size_t)s->nn, sizeof *s->wear);
        if (!s->heat || !s->wear) {
            pl_free(s->heat), pl_free(s->wear);
            s->heat = s->wear = NULL;
            return pl__world_error(w, PL_ERR_NOMEM, "solid_thermal: out of memory");
        }
    }
    s->thermal = *def;
    s->heat_fraction = fraction;
    s->t0 = t0;
    return PL_OK;
}

pl_status pl_world_solid_thermal_totals(const pl_world *w, double *heat, double *wear, double *t_max) {
    const pl_solid *m = get(w);
    if (!m || !m->sf || !m->sf->heat) return PL_ERR_STATE;
    const pl_sf *s = m->sf;
    double q = 0, v = 0, tm = s->t0;
    for (int i = 0; i < s->nn; i++) {
        q += s->heat[i];
        v += s->wear[i];
        tm = fmax(tm, pl_sf_node_temperature(s, i));
    }
    if (heat) *heat = q;
    if (wear) *wear = v;
    if (t_max) *t_max = tm;
    return PL_OK;
}

int pl_world_solid_rectangle(pl_world *w, double x0, double y0, double x1, double y1, int nx, int ny) {
    pl_solid *m = need(w, "solid_rectangle");
    if (!m) return PL_ERR_STATE;
    if (!(x1 > x0 && y1 > y0))
        return pl__world_error(w, PL_ERR_ARG, "solid_rectangle: need x1 > x0 and y1 > y0 (got %g..%g, %g..%g)", x0, x1,
                               y0, y1);
    const pl_vec2 c[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    pl_sf_mesh mesh;
    char msg[320];
    pl_status st = pl_sf_mesh_quad(c, nx, ny, m->def.formulation == PL_SOLID_Q1P0, &mesh, msg, sizeof msg);
    return add_mesh(w, &mesh, st, msg);
}

int pl_world_solid_quad(pl_world *w, const pl_vec2 c[4], int nx, int ny) {
    pl_solid *m = need(w, "solid_quad");
    if (!m) return PL_ERR_STATE;
    pl_sf_mesh mesh;
    char msg[320];
    pl_status st = pl_sf_mesh_quad(c, nx, ny, m->def.formulation == PL_SOLID_Q1P0, &mesh, msg, sizeof msg);
    return add_mesh(w, &mesh, st, msg);
}

int pl_world_solid_annulus(pl_world *w, double cx, double cy, double ri, double ro, double a0, double a1, int nr,
                           int nt) {
    pl_solid *m = need(w, "solid_annulus");
    if (!m) return PL_ERR_STATE;
    pl_sf_mesh mesh;
    char msg[320];
    pl_status st = pl_sf_mesh_annulus(cx, cy, ri, ro, a0, a1, nr, nt, m->def.formulation == PL_SOLID_Q1P0, &mesh,
                                      msg, sizeof msg);
    return add_mesh(w, &mesh, st, msg);
}

int pl_world_solid_polygon(pl_world *w, const pl_vec2 *verts, int n, double h) {
    pl_solid *m = need(w, "solid_polygon");
    if (!m) return PL_ERR_STATE;
    if (m->def.formulation == PL_SOLID_Q1P0)
        return pl__world_error(w, PL_ERR_ARG,
                               "solid_polygon: unstructured polygons are meshed with triangles; the Q1/P0 "
                               "formulation takes rectangles, quads and annuli");
    pl_sf_mesh mesh;
    char msg[320];
    pl_status st = pl_sf_mesh_polygon(verts, n, h, &mesh, msg, sizeof msg);
    return add_mesh(w, &mesh, st, msg);
}

int pl_world_solid_mesh_file(pl_world *w, const char *path) {
    pl_solid *m = need(w, "solid_mesh");
    if (!m) return PL_ERR_STATE;
    pl_sf_mesh mesh;
    char msg[320];
    pl_status st = pl_sf_mesh_read(path, m->def.formulation == PL_SOLID_Q1P0, &mesh, msg, sizeof msg);
    return add_mesh(w, &mesh, st, msg);
}

static pl_sf *need_sf(pl_world *w, const char *fn) {
    pl_solid *m = need(w, fn);
    if (!m) return NULL;
    if (!m->sf) pl__world_error(w, PL_ERR_STATE, "%s: the solid has no part yet (add one with w:solid_rectangle{...})", fn);
    return m->sf;
}

int pl_world_solid_fix(pl_world *w, double x0, double y0, double x1, double y1, int mask) {
    return pl_world_solid_velocity(w, x0, y0, x1, y1, mask, 0, 0);
}

int pl_world_solid_velocity(pl_world *w, double x0, double y0, double x1, double y1, int mask, double vx, double vy) {
    pl_sf *s = need_sf(w, "solid_fix/velocity");
    if (!s) return PL_ERR_STATE;
    if (mask < 1 || mask > 3) return pl__world_error(w, PL_ERR_ARG, "solid_fix: mask must be 1 (x), 2 (y) or 3 (both); got %d", mask);
    if (pl_sf_nodes_in_box(s, x0, y0, x1, y1, NULL, 0) == 0)
        return pl__world_error(w, PL_ERR_ARG, "solid_fix: no node of the solid lies in the box [%g, %g] x [%g, %g]", x0,
                               x1, y0, y1);
    const int k = pl_sf_add_set(s, x0, y0, x1, y1, mask, vx, vy);
    return k >= 0 ? k : pl__world_error(w, PL_ERR_NOMEM, "solid_fix: out of memory");
}

int pl_world_solid_initial_velocity(pl_world *w, double x0, double y0, double x1, double y1, double vx, double vy) {
    pl_sf *s = need_sf(w, "solid_initial_velocity");
    if (!s) return PL_ERR_STATE;
    int n = 0;
    for (int i = 0; i < s->nn; i++) {
        const double x = s->x[2 * i], y = s->x[2 * i + 1];
        if (!(x >= x0 && x <= x1 && y >= y0 && y <= y1)) continue;
        if (!(s->fix[i] & 1)) s->v[2 * i] = vx;
        if (!(s->fix[i] & 2)) s->v[2 * i + 1] = vy;
        n++;
    }
    if (n == 0)
        return pl__world_error(w, PL_ERR_ARG, "solid_initial_velocity: no node of the solid lies in the box [%g, %g] x [%g, %g]",
                               x0, x1, y0, y1);
    return n;
}

int pl_world_solid_traction(pl_world *w, double x0, double y0, double x1, double y1, double tx, double ty, double pn) {
    pl_sf *s = need_sf(w, "solid_traction");
    if (!s) return PL_ERR_STATE;
    const int n = pl_sf_add_traction(s, x0, y0, x1, y1, tx, ty, pn);
    if (n == 0)
        return pl__world_error(w, PL_ERR_ARG,
                               "solid_traction: no boundary edge of the solid has both nodes in the box [%g, %g] x "
                               "[%g, %g]",
                               x0, x1, y0, y1);
    return n;
}

pl_status pl_world_solid_reaction(const pl_world *w, int set, pl_vec2 *force) {
    const pl_solid *m = get(w);
    if (!m || !m->sf || set < 0 || set >= m->sf->nsets) return PL_ERR_ARG;
    force->x = m->sf->sets[set].reaction[0];
    force->y = m->sf->sets[set].reaction[1];
    return PL_OK;
}

pl_status pl_world_solid_displacement(const pl_world *w, pl_vec2 X, pl_vec2 *u) {
    const pl_solid *m = get(w);
    if (!m || !m->sf) return PL_ERR_STATE;
    const pl_sf *s = m->sf;
    int best = 0;
    double bd = INFINITY;
    for (int i = 0; i < s->nn; i++) {
        const double d = hypot(s->X[2 * i] - X.x, s->X[2 * i + 1] - X.y);
        if (d < bd) bd = d, best = i;
    }
    u->x = s->x[2 * best] - s->X[2 * best];
    u->y = s->x[2 * best + 1] - s->X[2 * best + 1];
    return PL_OK;
}

int pl_world_solid_node_count(const pl_world *w) {
    const pl_solid *m = get(w);
    return m && m->sf ? m->sf->nn : 0;
}
int pl_world_solid_element_count(const pl_world *w) {
    const pl_solid *m = get(w);
    return m && m->sf ? m->sf->ne : 0;
}

double pl_world_solid_critical_dt(const pl_world *w, int *element) {
    const pl_solid *m = get(w);
    if (element) *element = m && m->sf ? m->sf->dt_elem : -1;
    return m && m->sf ? m->sf->dt_crit : INFINITY;
}

void pl_world_solid_cost(const pl_world *w, double *solid_seconds, double *contact_seconds) {
    const pl_solid *m = get(w);
    *solid_seconds = m ? m->seconds - m->seconds_contact : 0;
    *contact_seconds = m ? m->seconds_contact : 0;
}

pl_status pl_world_solid_energy(const pl_world *w, pl_solid_energy *out) {
    const pl_solid *m = get(w);
    if (!m || !m->sf) return PL_ERR_STATE;
    const pl_sf *s = m->sf;
    out->kinetic = s->e.kinetic;
    out->internal = s->e.internal;
    out->external = s->e.external;
    out->damping = s->e.damping;
    out->plastic = s->e.plastic;
    out->contact = s->e.contact;
    out->elastic = pl_sf_elastic_energy(s);
    return PL_OK;
}

pl_status pl_world_solid_extremes(const pl_world *w, double *mises_max, double *plastic_max) {
    const pl_solid *m = get(w);
    if (!m || !m->sf) return PL_ERR_STATE;
    const pl_sf *s = m->sf;
    double a = 0, b = 0;
    for (size_t ip = 0; ip < (size_t)s->ne * s->nip; ip++) {
        a = fmax(a, pl_sf_mises(&s->s[4 * ip]));
        b = fmax(b, s->alpha[ip]);
    }
    *mises_max = a;
    *plastic_max = b;
    return PL_OK;
}

pl_vec2 pl_world_solid_contact_force(const pl_world *w) {
    const pl_solid *m = get(w);
    return m ? m->contact_total : (pl_vec2){0, 0};
}

/* ------------------------------------------------------------------ class functions */

static void *sd_create(void) {
    pl_solid *m = pl_calloc(1, sizeof *m);
    if (m) m->def = pl_default_solid_def();
    return m;
}

static pl_status grow_contact(pl_solid *m, int n) {
    if (n <= m->cap) return PL_OK;
    const int c = n + 64;
    pl_vec2 *f = pl_realloc(m->cf, sizeof *f * (size_t)c);
    if (f) m->cf = f;
    double *q = pl_realloc(m->cm, sizeof *q * (size_t)c);
    if (q) m->cm = q;
    if (!f || !q) return PL_ERR_NOMEM;
    m->cap = c;
    return PL_OK;
}

static double contact_dt(const pl_solid *m, const pl_grain_view *g, int *what);

static pl_status sd_advance(void *self, pl_world *w, const pl_grain_view *g, double dt) {
    pl_solid *m = self;
    if (!m->sf) return PL_OK;
    const double t0 = pl_clock_seconds();
    pl_sf *s = m->sf;
    s->gravity = g->gravity;
    int what;
    const double dtc = contact_dt(m, g, &what);
    if (dt > dtc)
        return pl__world_error(w, PL_ERR_UNSTABLE,
                               "solid: the time step %.4g s exceeds the grain-edge contact limit 2 sqrt(m/k_n) = %.4g s "
                               "of the lightest %s (k_n = %g N/m per m) at t = %.6g s; set dt <= %.4g s, dt = 0 "
                               "(automatic), or lower contact_stiffness",
                               dt, dtc, what ? "disc" : "boundary node", s->def.contact_stiffness, g->time,
                               0.9 * dtc);
    if (grow_contact(m, g->n) != PL_OK) return pl__world_error(w, PL_ERR_NOMEM, "solid: out of memory (contacts)");
    for (int i = 0; i < g->n; i++) m->cf[i] = (pl_vec2){0, 0}, m->cm[i] = 0;
    memset(s->fc, 0, sizeof *s->fc * 2 * (size_t)s->nn);
    m->contact_total = (pl_vec2){0, 0};
    m->e_contact_spring = 0;
    /* discs near the solid's box, from the grains' neighbour grid */
    double lx = INFINITY, ly = INFINITY, hx = -INFINITY, hy = -INFINITY;
    for (int k = 0; k < s->nbedge; k++) {
        const int a = s->bedge[2 * k];
        lx = fmin(lx, s->x[2 * a]), hx = fmax(hx, s->x[2 * a]);
        ly = fmin(ly, s->x[2 * a + 1]), hy = fmax(hy, s->x[2 * a + 1]);
    }
    int nc = g->n > 0 ? pl__world_bodies_near(w, (pl_vec2){lx, ly}, (pl_vec2){hx, hy}, m->cand, m->cand_cap) : 0;
    if (nc > m->cand_cap) {
        int32_t *c = pl_realloc(m->cand, sizeof *c * (size_t)(nc + 64));
        if (!c) return pl__world_error(w, PL_ERR_NOMEM, "solid: out of memory (contact candidates)");
        m->cand = c;
        m->cand_cap = nc + 64;
        nc = pl__world_bodies_near(w, (pl_vec2){lx, ly}, (pl_vec2){hx, hy}, m->cand, m->cand_cap);
    }
    for (int k = 0; k < nc; k++) {
        const int i = m->cand[k];
        pl_sf_contact_out o;
        if (g->shape[i] == PL_SHAPE_DISC) {
            pl_sf_disc_contact(s, g->pos[i], g->vel[i], g->omega[i], g->radius[i], dt, s->fc, &o);
            o.spring = 0.5 * s->def.contact_stiffness * o.overlap * o.overlap;
        } else if (g->shape[i] == PL_SHAPE_POLYGON && g->vert_count[i] >= 3) {
            pl_sf_polygon_contact(s, g->pos[i], g->vel[i], g->omega[i], &g->verts[g->vert_offset[i]],
                                  g->vert_count[i], dt, s->fc, &o);
        } else {
            continue;
        }
        if (s->heat && (o.heat_grain > 0 || o.wear_work > 0)) {
            const pl_status hs = pl_world_body_contact_heat(w, i, o.heat_grain, o.wear_work);
            if (hs != PL_OK) return hs;
        }
        if (!o.touching) continue;
        m->cf[i] = (pl_vec2){o.fx, o.fy};
        m->cm[i] = o.m;
        m->contact_total.x -= o.fx;
        m->contact_total.y -= o.fy;
        m->e_contact_diss += o.e_dashpot + o.e_friction;
        m->e_contact_spring += o.spring;
    }
    /* bonds, in parallel with the contacts (as the grains' parallel bonds) */
    for (int k = 0; k < m->nbond; k++) {
        pl_sf_bond *bd = &m->bonds[k];
        if (bd->state != PL_BOND_INTACT || bd->grain >= g->n) continue;
        const int i = bd->grain;
        pl_sf_contact_out o;
        memset(&o, 0, sizeof o);
        m->e_contact_diss += pl_sf_bond_force(s, &m->bond_law, bd, g->pos[i], g->angle[i], g->radius[i], s->fc, &o);
        if (bd->state != PL_BOND_INTACT) {
            bd->broken_time = g->time + dt;
            continue;
        }
        m->cf[i].x += o.fx;
        m->cf[i].y += o.fy;
        m->cm[i] += o.m;
        m->contact_total.x -= o.fx;
        m->contact_total.y -= o.fy;
    }
    const double t1 = pl_clock_seconds();
    m->seconds_contact += t1 - t0;
    pl_status st = pl_sf_step(s, dt, s->fc);
    m->seconds += pl_clock_seconds() - t0;
    if (st != PL_OK) return pl__world_error(w, st, "%s", s->err);
    return PL_OK;
}

static pl_status sd_loads(void *self, pl_world *w, const pl_grain_view *g, double dt, pl_vec2 *force,
                          double *moment) {
    (void)w;
    (void)dt;
    pl_solid *m = self;
    if (!m->sf) return PL_OK;
    for (int i = 0; i < g->n && i < m->cap; i++) {
        if (!g->wants_load[i]) continue;
        force[i].x += m->cf[i].x;
        force[i].y += m->cf[i].y;
        moment[i] += m->cm[i];
    }
    m->calls++;
    return PL_OK;
}

/* Smallest of the element bound and the contact springs' limits 2 sqrt(m / k_n) for the
   lightest boundary node and the lightest dynamic disc of the world. */
static double contact_dt(const pl_solid *m, const pl_grain_view *g, int *what) {
    const pl_sf *s = m->sf;
    /* an intact bond acts in parallel with the contact spring */
    const double k = s->def.contact_stiffness + (m->nbond > 0 ? fmax(m->bond_law.kn, m->bond_law.kt) : 0);
    double mmin = INFINITY;
    *what = 0;
    if (!(k > 0)) return INFINITY;
    for (int q = 0; q < s->nbedge; q++) mmin = fmin(mmin, s->m[s->bedge[2 * q]]);
    for (int i = 0; i < g->n; i++)
        if ((g->shape[i] == PL_SHAPE_DISC || g->shape[i] == PL_SHAPE_POLYGON) && g->motion[i] == PL_MOTION_DYNAMIC &&
            g->mass[i] / (g->shape[i] == PL_SHAPE_POLYGON ? 2 : 1) < mmin) {
            /* a polygon may rest on two vertices at once: two springs on its mass */
            mmin = g->mass[i] / (g->shape[i] == PL_SHAPE_POLYGON ? 2 : 1);
            *what = 1;
        }
    const double c = s->def.contact_damping, zeta = c / (2 * sqrt(k * mmin));
    return 2 * sqrt(mmin / k) * (sqrt(1 + zeta * zeta) - zeta);
}

static double sd_critical_dt(const void *self, const pl_world *w) {
    const pl_solid *m = self;
    if (!m->sf) return INFINITY;
    int what;
    const pl_grain_view g = pl__world_grains(w);
    return fmin(m->sf->dt_crit, contact_dt(m, &g, &what));
}

static double sd_stored_energy(const void *self) {
    const pl_solid *m = self;
    if (!m->sf) return 0;
    double eb = 0;
    for (int k = 0; k < m->nbond; k++)
        if (m->bonds[k].state == PL_BOND_INTACT) eb += m->bonds[k].elastic;
    return m->sf->e.kinetic + pl_sf_elastic_energy(m->sf) + m->e_contact_spring + eb;
}

static uint64_t sd_hash(const void *self, uint64_t h) {
    const pl_solid *m = self;
    if (!m->sf) return h;
    h = pl_sf_hash(m->sf, h);
    h = pl_hash_bytes(h, &m->e_contact_diss, sizeof m->e_contact_diss);
    /* bonds and the element side's heat and wear only when the scene uses them (so that other
       scenes keep their hashes) */
    if (m->nbond > 0) h = pl_hash_bytes(h, m->bonds, sizeof *m->bonds * (size_t)m->nbond);
    if (m->sf->heat) {
        h = pl_hash_bytes(h, m->sf->heat, sizeof(double) * (size_t)m->sf->nn);
        h = pl_hash_bytes(h, m->sf->wear, sizeof(double) * (size_t)m->sf->nn);
    }
    return h;
}

/* The state: what pl_sf_hash folds (sizes first, then the arrays in a fixed order). */
typedef struct sd_arrays {
    double *ptr;
    size_t n;
} sd_arrays;

static int state_arrays(const pl_solid *m, sd_arrays *a) {
    const pl_sf *s = m->sf;
    const size_t N = (size_t)s->nn, I = (size_t)s->ne * s->nip;
    int k = 0;
    a[k++] = (sd_arrays){s->x, 2 * N};
    a[k++] = (sd_arrays){s->v, 2 * N};
    a[k++] = (sd_arrays){s->p, N};
    a[k++] = (sd_arrays){s->pi, 2 * N};
    a[k++] = (sd_arrays){s->gv, N};
    a[k++] = (sd_arrays){s->f_prev, 2 * N};
    a[k++] = (sd_arrays){s->s, 4 * I};
    a[k++] = (sd_arrays){s->pe, I};
    a[k++] = (sd_arrays){s->ep, 4 * I};
    a[k++] = (sd_arrays){s->alpha, I};
    if (s->heat) {
        a[k++] = (sd_arrays){s->heat, N};
        a[k++] = (sd_arrays){s->wear, N};
    }
    /* the bonds, as raw doubles (pl_sf_bond holds int32 pairs and doubles: a whole number of
       doubles) */
    if (m->nbond > 0) a[k++] = (sd_arrays){(double *)m->bonds, sizeof *m->bonds / sizeof(double) * (size_t)m->nbond};
    return k;
}

static void scalars(const pl_solid *m, double *v) {
    const pl_sf *s = m->sf;
    v[0] = s->e.kinetic; v[1] = s->e.internal; v[2] = s->e.external; v[3] = s->e.damping;
    v[4] = s->e.plastic; v[5] = s->e.contact; v[6] = s->time; v[7] = (double)s->step;
    v[8] = m->e_contact_diss; v[9] = s->dt_crit;
}

static void set_scalars(pl_solid *m, const double *v) {
    pl_sf *s = m->sf;
    s->e.kinetic = v[0]; s->e.internal = v[1]; s->e.external = v[2]; s->e.damping = v[3];
    s->e.plastic = v[4]; s->e.contact = v[5]; s->time = v[6]; s->step = (int64_t)v[7];
    m->e_contact_diss = v[8]; s->dt_crit = v[9];
}

#define SD_NSCAL 10

/* Bonds and heat in one word: 2 nbond + (heat on). */
static int64_t extra_state(const pl_solid *m) { return 2 * (int64_t)m->nbond + (m->sf && m->sf->heat ? 1 : 0); }
_Static_assert(sizeof(pl_sf_bond) % sizeof(double) == 0, "pl_sf_bond must be a whole number of doubles");

static void *sd_snapshot(const void *self, size_t *bytes) {
    const pl_solid *m = self;
    if (!m->sf) {
        int64_t *z = pl_calloc(1, sizeof *z * 3);
        if (bytes) *bytes = sizeof *z * 3;
        return z;
    }
    sd_arrays a[12];
    const int na = state_arrays(m, a);
    size_t tot = 3 * sizeof(int64_t) + SD_NSCAL * sizeof(double);
    for (int k = 0; k < na; k++) tot += a[k].n * sizeof(double);
    char *buf = pl_malloc(tot);
    if (!buf) return NULL;
    int64_t sz[3] = {m->sf->nn, m->sf->ne, extra_state(m)};
    memcpy(buf, sz, sizeof sz);
    size_t off = sizeof sz;
    double sc[SD_NSCAL];
    scalars(m, sc);
    memcpy(buf + off, sc, sizeof sc);
    off += sizeof sc;
    for (int k = 0; k < na; k++) {
        memcpy(buf + off, a[k].ptr, a[k].n * sizeof(double));
        off += a[k].n * sizeof(double);
    }
    if (bytes) *bytes = tot;
    return buf;
}

static pl_status sd_restore(void *self, pl_world *w, const void *snap) {
    pl_solid *m = self;
    const char *buf = snap;
    int64_t sz[3];
    memcpy(sz, buf, sizeof sz);
    if (!m->sf) {
        if (sz[0] == 0) return PL_OK;
        return pl__world_error(w, PL_ERR_STATE,
                               "solid: the snapshot holds a solid of %lld nodes but this world's solid has no parts "
                               "(build the same scene first)",
                               (long long)sz[0]);
    }
    if (sz[0] != m->sf->nn || sz[1] != m->sf->ne)
        return pl__world_error(w, PL_ERR_STATE,
                               "solid: the snapshot's solid has %lld nodes and %lld elements, this one %d and %d",
                               (long long)sz[0], (long long)sz[1], m->sf->nn, m->sf->ne);
    if (sz[2] != extra_state(m))
        return pl__world_error(w, PL_ERR_STATE,
                               "solid: the snapshot's solid has %lld grain-edge bonds (heat %s), this one %d (heat %s)",
                               (long long)(sz[2] / 2), sz[2] % 2 ? "on" : "off", m->nbond,
                               m->sf->heat ? "on" : "off");
    size_t off = sizeof sz;
    double sc[SD_NSCAL];
    memcpy(sc, buf + off, sizeof sc);
    off += sizeof sc;
    set_scalars(m, sc);
    sd_arrays a[12];
    const int na = state_arrays(m, a);
    for (int k = 0; k < na; k++) {
        memcpy(a[k].ptr, buf + off, a[k].n * sizeof(double));
        off += a[k].n * sizeof(double);
    }
    return PL_OK;
}

static void sd_snapshot_free(void *snap) { pl_free(snap); }

/* Image layout: layout word (hash of the sizes), nn, ne (int64), SD_NSCAL doubles, then the
   state arrays of state_arrays() as counted arrays. */
static uint64_t layout_word(int64_t nn, int64_t ne, int64_t extra) {
    const int64_t v[4] = {nn, ne, SD_NSCAL, extra};
    /* without bonds and heat: the layout of the images written before they existed */
    return pl_hash_bytes(0x736f6c6964ull, v, extra ? sizeof v : 3 * sizeof(int64_t));
}

static pl_status sd_save(const void *self, pl_image *img) {
    const pl_solid *m = self;
    const int64_t sz[2] = {m->sf ? m->sf->nn : 0, m->sf ? m->sf->ne : 0};
    const uint64_t lw = layout_word(sz[0], sz[1], extra_state(m));
    pl_status st = pl__image_put(img, &lw, sizeof lw);
    if (st == PL_OK) st = pl__image_put(img, sz, sizeof sz);
    if (st != PL_OK || !m->sf) return st;
    double sc[SD_NSCAL];
    scalars(m, sc);
    st = pl__image_put(img, sc, sizeof sc);
    sd_arrays a[12];
    const int na = state_arrays(m, a);
    for (int k = 0; k < na && st == PL_OK; k++) st = pl__image_put_array(img, a[k].ptr, sizeof(double), a[k].n);
    return st;
}

static pl_status sd_load(void *self, pl_world *w, pl_image *img) {
    pl_solid *m = self;
    uint64_t lw;
    int64_t sz[2];
    pl_status st = pl__image_get(img, &lw, sizeof lw);
    if (st == PL_OK) st = pl__image_get(img, sz, sizeof sz);
    if (st != PL_OK) return pl__world_error(w, PL_ERR_IO, "load: the image's solid section is damaged");
    const int64_t nn = m->sf ? m->sf->nn : 0, ne = m->sf ? m->sf->ne : 0;
    if (lw != layout_word(sz[0], sz[1], extra_state(m)) || sz[0] != nn || sz[1] != ne)
        return pl__world_error(w, PL_ERR_IO,
                               "load: the image's solid has %lld nodes and %lld elements, this scene's %lld and %lld "
                               "(load into the scene that saved it)",
                               (long long)sz[0], (long long)sz[1], (long long)nn, (long long)ne);
    if (!m->sf) return PL_OK;
    double sc[SD_NSCAL];
    st = pl__image_get(img, sc, sizeof sc);
    sd_arrays a[12];
    const int na = state_arrays(m, a);
    for (int k = 0; k < na && st == PL_OK; k++) st = pl__image_get_array(img, a[k].ptr, sizeof(double), a[k].n);
    if (st != PL_OK) return pl__world_error(w, PL_ERR_IO, "load: the image's solid section is damaged");
    set_scalars(m, sc);
    return PL_OK;
}

static int sd_field(const void *self, const pl_world *w, int quantity, pl_vec2 *xy, int32_t *tri, double *value,
                    int cap_nodes, int cap_tris, int *nt) {
    (void)w;
    const pl_solid *m = self;
    *nt = 0;
    if (!m->sf || quantity < PL_SOLID_FIELD_MISES || quantity > PL_SOLID_FIELD_DISPLACEMENT) return 0;
    const pl_sf *s = m->sf;
    const int ntri = s->nen == 3 ? s->ne : 2 * s->ne;
    *nt = ntri;
    if (s->nn > cap_nodes || ntri > cap_tris || !xy || !tri || !value) return s->nn;
    double *work = pl_malloc(sizeof *work * (size_t)s->nn);
    if (!work) return 0;
    pl_sf_nodal_field(s, quantity, value, work);
    pl_free(work);
    for (int i = 0; i < s->nn; i++) xy[i] = (pl_vec2){s->x[2 * i], s->x[2 * i + 1]};
    for (int e = 0, k = 0; e < s->ne; e++) {
        const int32_t *c = &s->conn[(size_t)e * s->nen];
        tri[k++] = c[0]; tri[k++] = c[1]; tri[k++] = c[2];
        if (s->nen == 4) {
            tri[k++] = c[0]; tri[k++] = c[2]; tri[k++] = c[3];
        }
    }
    return s->nn;
}

static double sd_cost(const void *self, long *calls) {
    const pl_solid *m = self;
    if (calls) *calls = m->calls;
    return m->seconds;
}

static void sd_destroy(void *self) {
    pl_solid *m = self;
    pl_sf_destroy(m->sf);
    pl_free(m->bonds);
    pl_free(m->cf);
    pl_free(m->cm);
    pl_free(m->cand);
    pl_free(m);
}

const pl_model_class pl_solid_class = {
    .name = "solid",
    .label = "finite-element solid (plane strain, explicit, FIC triangles / Q1P0, J2)",
    .def_size = sizeof(pl_solid_def),
    .params = pl_solid_params,
    .nparams = PL_SOLID_PARAM_COUNT,
    .create = sd_create,
    .advance = sd_advance,
    .loads = sd_loads,
    .hash = sd_hash,
    .snapshot = sd_snapshot,
    .restore = sd_restore,
    .snapshot_free = sd_snapshot_free,
    .save = sd_save,
    .load = sd_load,
    .field = sd_field,
    .cost = sd_cost,
    .destroy = sd_destroy,
    .critical_dt = sd_critical_dt,
    .stored_energy = sd_stored_energy,
};
