/* Saturated-soil diagnostics (porelab/soil.h, docs/soil.md §3): effective stress from the
 * contacts, pore and excess pore pressure averaged over a region, total stress, and access to
 * the consolidation source. */
#include "world/model.h"
#include "fluid/darcy/darcy_internal.h"
#include "fluid/darcy/darcy_world.h"
#include "porelab/soil.h"
#include <math.h>
#include <string.h>

/* Area of triangle t clipped to the axis-aligned box [lo, hi] and the integral of a linear
   field with nodal values p over the clipped part (exact: Sutherland-Hodgman on 4 half-planes). */
static double clip_box_integral(const pl_vec2 t[3], const double p[3], pl_vec2 lo, pl_vec2 hi, double *integral) {
    /* vertices carry (x, y, value) */
    double buf[2][16][3];
    int cnt = 3, cur = 0;
    for (int k = 0; k < 3; k++) { buf[0][k][0] = t[k].x; buf[0][k][1] = t[k].y; buf[0][k][2] = p[k]; }
    for (int side = 0; side < 4 && cnt > 0; side++) {
        int m = 0;
        for (int i = 0; i < cnt; i++) {
            const double *a = buf[cur][i], *b = buf[cur][(i + 1) % cnt];
            double sa, sb;
            switch (side) {
            case 0: sa = a[0] - lo.x; sb = b[0] - lo.x; break;
            case 1: sa = hi.x - a[0]; sb = hi.x - b[0]; break;
            case 2: sa = a[1] - lo.y; sb = b[1] - lo.y; break;
            default: sa = hi.y - a[1]; sb = hi.y - b[1]; break;
            }
            if (sa >= 0) { memcpy(buf[1 - cur][m], a, sizeof(double) * 3); m++; }
            if ((sa >= 0) != (sb >= 0) && m < 15) {
                double u = sa / (sa - sb);
                for (int c = 0; c < 3; c++) buf[1 - cur][m][c] = a[c] + u * (b[c] - a[c]);
                m++;
            }
            if (m >= 15) break;
        }
        cnt = m;
        cur = 1 - cur;
    }
    double area = 0, integ = 0;
    for (int i = 1; i + 1 < cnt; i++) { /* fan: linear field integrates to area x mean of corners */
        const double *a = buf[cur][0], *b = buf[cur][i], *c = buf[cur][i + 1];
        double A = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
        area += A;
        integ += A * (a[2] + b[2] + c[2]) / 3.0;
    }
    *integral = integ;
    return area;
}

pl_status pl_world_soil_region(pl_world *w, pl_vec2 lo, pl_vec2 hi, pl_soil_region *out) {
    if (!w || !out) return PL_ERR_ARG;
    memset(out, 0, sizeof *out);
    if (!(hi.x > lo.x && hi.y > lo.y))
        return pl__world_error(w, PL_ERR_ARG, "soil_region: hi must lie above and right of lo (got lo = (%g, %g), hi = (%g, %g))",
                         lo.x, lo.y, hi.x, hi.y);
    out->bodies = pl_world_stress_in_region(w, lo, hi, out->eff);
    struct pl_fluid *f = pl__darcy(w);
    if (f && f->built && f->head) {
        const pl_mesh *m = &f->mesh;
        double href = 0;
        int nref = 0;
        for (int i = 0; i < m->nn; i++)
            if (f->sys.is_dir && f->sys.is_dir[i]) { href += f->head[i]; nref++; }
        href = nref ? href / nref : 0;
        const double rg = f->par.density * f->par.g;
        double A = 0, U = 0, UE = 0;
        for (int e = 0; e < m->ne; e++) {
            const int32_t *v = &m->tri[3 * e];
            pl_vec2 t[3] = {m->xy[v[0]], m->xy[v[1]], m->xy[v[2]]};
            if (fmax(t[0].x, fmax(t[1].x, t[2].x)) < lo.x || fmin(t[0].x, fmin(t[1].x, t[2].x)) > hi.x ||
                fmax(t[0].y, fmax(t[1].y, t[2].y)) < lo.y || fmin(t[0].y, fmin(t[1].y, t[2].y)) > hi.y)
                continue;
            double p[3], pe[3], ip, ie;
            for (int k = 0; k < 3; k++) {
                p[k] = pl_fl_node_pressure(f, v[k]);
                pe[k] = rg * (f->head[v[k]] - href);
            }
            double a = clip_box_integral(t, p, lo, hi, &ip);
            clip_box_integral(t, pe, lo, hi, &ie);
            A += a; U += ip; UE += ie;
        }
        out->area = A;
        if (A > 0) { out->u = U / A; out->u_excess = UE / A; }
    }
    /* geostatic overburden: a body at elevation y (along -gravity) above lo weighs on every
       level between lo and y, so its share of the mean over the region's height H is
       clamp((y - lo) / H, 0, 1) of its submerged weight, over the column width W */
    const pl_grain_view g = pl__world_grains(w);
    const double gm = -g.gravity.y;
    if (g.gravity.x == 0 && gm > 0) { /* defined for gravity along -y only */
        const double rho_f = f && f->built && f->head ? f->par.density : 0;
        const double H = hi.y - lo.y, W = hi.x - lo.x;
        double s = 0;
        for (int i = 0; i < g.n; i++) {
            if (g.motion[i] != PL_MOTION_DYNAMIC) continue;
            const pl_vec2 c = g.pos[i];
            if (c.x < lo.x || c.x > hi.x || c.y <= lo.y) continue;
            double wt = g.mass[i] * gm;
            if (rho_f > 0) {
                double p, h;
                if (pl_fl_pressure_at(f, c, &p, &h) >= 0 && p > 0) wt -= rho_f * gm * g.area[i];
            }
            const double fr = (c.y - lo.y) / H;
            s += wt * (fr < 1 ? fr : 1);
        }
        out->overburden = s / W;
    }
    for (int k = 0; k < 4; k++) out->total[k] = out->eff[k];
    out->total[0] += out->u;
    out->total[3] += out->u;
    return PL_OK;
}

pl_status pl_world_soil_reset(pl_world *w) {
    struct pl_fluid *f = pl__darcy(w);
    if (!f) return PL_OK;
    pl_fl_bodies b = pl__fluid_world_bodies(w);
    pl_status st = pl_fl_consolidation_reset(f, &b, pl__world_grains(w).angle);
    if (st != PL_OK) return pl__world_error(w, st, "soil_reset: out of memory");
    return PL_OK;
}

pl_status pl_world_soil_stats(const pl_world *w, double *t_source, double *last_source_abs) {
    const struct pl_fluid *f = pl__darcy(w);
    if (t_source) *t_source = f ? f->t_source : 0;
    if (last_source_abs) *last_source_abs = f ? f->last_src_abs : 0;
    return PL_OK;
}

int pl_world_soil_copy_source(pl_world *w, double *out, int cap) {
    struct pl_fluid *f = pl__darcy(w);
    if (!f || !f->src || !f->built) return 0;
    int n = f->mesh.nn < cap ? f->mesh.nn : cap;
    memcpy(out, f->src, sizeof(double) * (size_t)n);
    return n;
}
