/* Fluid layers: the Darcy mesh of porelab/fluid.h drawn with the generic field builders. */
#include "draw_field.h"
#include "draw_world.h"
#include "label_place.h"
#include "porelab/fluid.h"
#include "porelab/solid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int reserve_fluid(pl_render_scene *s, int nodes, int tris) {
    if (nodes > s->fluid_node_cap) {
        pl_vec2 *n = realloc(s->fluid_nodes, (size_t)nodes * sizeof *n);
        if (!n) return -1;
        s->fluid_nodes = n;
        double *v = realloc(s->fluid_values, (size_t)nodes * sizeof *v);
        if (!v) return -1;
        s->fluid_values = v;
        s->fluid_node_cap = nodes;
    }
    if (tris > s->fluid_tri_cap) {
        int *t = realloc(s->fluid_tris, (size_t)tris * 3u * sizeof *t);
        if (!t) return -1;
        s->fluid_tris = t;
        pl_vec2 *u = realloc(s->fluid_velocity, (size_t)tris * sizeof *u);
        if (!u) return -1;
        s->fluid_velocity = u;
        s->fluid_tri_cap = tris;
    }
    return 0;
}

int pl_render_scene_set_fluid(pl_render_scene *s, const pl_vec2 *nodes, const double *values,
                              int node_count, const int *tris, const pl_vec2 *velocity,
                              int tri_count, int field) {
    s->fluid_node_count = s->fluid_tri_count = 0;
    s->mesh_node_count = s->mesh_tri_count = 0;
    s->fluid_conductivity = 0.0;
    if (node_count <= 0 || tri_count <= 0) return 0;
    if (reserve_fluid(s, node_count, tri_count)) return -1;
    memcpy(s->fluid_nodes, nodes, (size_t)node_count * sizeof *nodes);
    memcpy(s->fluid_values, values, (size_t)node_count * sizeof *values);
    memcpy(s->fluid_tris, tris, (size_t)tri_count * 3u * sizeof *tris);
    for (int t = 0; t < tri_count; t++) {
        pl_vec2 z = {0.0, 0.0};
        s->fluid_velocity[t] = velocity ? velocity[t] : z;
    }
    s->fluid_node_count = node_count;
    s->fluid_tri_count = tri_count;
    s->fluid_field = field;
    return 0;
}

/* The model's own element mesh (PL_FLUID_ELEMENT_MESH) for the mesh layer; none (0 triangles)
   when the model draws its field on its elements directly. */
static int capture_elements(pl_render_scene *s, const pl_world *w) {
    s->mesh_node_count = s->mesh_tri_count = 0;
    int nt = 0;
    const int nn = pl_world_field_sample(w, PL_FLUID_ELEMENT_MESH, NULL, NULL, NULL, 0, 0, &nt);
    if (nn <= 0 || nt <= 0) return 0;
    pl_vec2 *xy = realloc(s->mesh_nodes, (size_t)nn * sizeof *xy);
    if (!xy) return -1;
    s->mesh_nodes = xy;
    int *tr = realloc(s->mesh_tris, (size_t)nt * 3u * sizeof *tr);
    if (!tr) return -1;
    s->mesh_tris = tr;
    int32_t *t32 = malloc((size_t)nt * 3u * sizeof *t32);
    double *val = malloc((size_t)nn * sizeof *val);
    if (!t32 || !val) {
        free(t32);
        free(val);
        return -1;
    }
    if (pl_world_field_sample(w, PL_FLUID_ELEMENT_MESH, xy, t32, val, nn, nt, &nt) == nn) {
        for (int k = 0; k < 3 * nt; k++) tr[k] = t32[k];
        s->mesh_node_count = nn;
        s->mesh_tri_count = nt;
    }
    free(t32);
    free(val);
    return 0;
}

/* A model without a Darcy mesh (hydrostatic water, resolved flow) gives its field sampled on
   linear triangles (pl_world_field_sample); resolved models also give the node velocities
   (PL_FLUID_VELOCITY_NODE_X/Y): triangle means for the arrows, and the speed field. */
static int capture_generic(pl_render_scene *s, const pl_world *w, int field) {
    int nt = 0;
    const int speed = field == PL_RENDER_FLUID_SPEED;
    const int q = speed ? PL_FLUID_VELOCITY_NODE_X : field;
    const int nn = pl_world_field_sample(w, q, NULL, NULL, NULL, 0, 0, &nt);
    if (nn <= 0 || nt <= 0) return 0;
    if (reserve_fluid(s, nn, nt)) return -1;
    int32_t *tri = malloc((size_t)nt * 3u * sizeof *tri);
    if (!tri) return -1;
    pl_world_field_sample(w, q, s->fluid_nodes, tri, s->fluid_values, nn, nt, &nt);
    for (int k = 0; k < 3 * nt; k++) s->fluid_tris[k] = tri[k];
    for (int t = 0; t < nt; t++) s->fluid_velocity[t] = (pl_vec2){0.0, 0.0};
    double *vx = malloc((size_t)nn * 2u * sizeof *vx);
    int nt2 = 0;
    if (vx && pl_world_field_sample(w, PL_FLUID_VELOCITY_NODE_X, NULL, NULL, NULL, 0, 0, &nt2) == nn && nt2 == nt) {
        pl_vec2 *xy = malloc((size_t)nn * sizeof *xy);
        int32_t *tr = malloc((size_t)nt * 3u * sizeof *tr);
        if (xy && tr && pl_world_field_sample(w, PL_FLUID_VELOCITY_NODE_X, xy, tr, vx, nn, nt, &nt2) == nn &&
            pl_world_field_sample(w, PL_FLUID_VELOCITY_NODE_Y, xy, tr, vx + nn, nn, nt, &nt2) == nn) {
            for (int t = 0; t < nt; t++) {
                pl_vec2 u = {0.0, 0.0};
                for (int c = 0; c < 3; c++) {
                    u.x += vx[tri[3 * t + c]] / 3.0;
                    u.y += vx[nn + tri[3 * t + c]] / 3.0;
                }
                s->fluid_velocity[t] = u;
            }
            if (speed)
                for (int i = 0; i < nn; i++) s->fluid_values[i] = hypot(vx[i], vx[nn + i]);
        }
        free(xy);
        free(tr);
    }
    free(vx);
    free(tri);
    s->fluid_conductivity = 0.0;
    s->fluid_node_count = nn;
    s->fluid_tri_count = nt;
    return capture_elements(s, w);
}

int pl_render_scene_capture_fluid(pl_render_scene *s, const pl_world *w, int field) {
    s->fluid_node_count = s->fluid_tri_count = 0;
    s->mesh_node_count = s->mesh_tri_count = 0;
    s->fluid_field = field;
    int nn = pl_world_fluid_node_count(w), nt = pl_world_fluid_triangle_count(w);
    if (nn <= 0 || nt <= 0) return capture_generic(s, w, field);
    if (reserve_fluid(s, nn, nt)) return -1;
    double *tmp = malloc((size_t)nt * 2u * sizeof *tmp);
    if (!tmp) return -1;
    nn = pl_world_fluid_copy_nodes(w, s->fluid_nodes, nn);
    nt = pl_world_fluid_copy_triangles(w, s->fluid_tris, nt);
    int nv = pl_world_fluid_copy_node_field(w, (pl_fluid_node_field)field, s->fluid_values, nn);
    for (int i = nv < 0 ? 0 : nv; i < nn; i++) s->fluid_values[i] = NAN;
    int nx = pl_world_fluid_copy_element_field(w, PL_FLUID_VELOCITY_X, tmp, nt);
    int ny = pl_world_fluid_copy_element_field(w, PL_FLUID_VELOCITY_Y, tmp + nt, nt);
    for (int t = 0; t < nt; t++) {
        s->fluid_velocity[t].x = t < nx ? tmp[t] : 0.0;
        s->fluid_velocity[t].y = t < ny ? tmp[nt + t] : 0.0;
    }
    s->fluid_conductivity = 0.0;
    int nk = pl_world_fluid_copy_element_field(w, PL_FLUID_PERM_X, tmp, nt);
    int nk2 = pl_world_fluid_copy_element_field(w, PL_FLUID_PERM_Y, tmp + nt, nt);
    for (int t = 0; t < nk; t++) s->fluid_conductivity = fmax(s->fluid_conductivity, tmp[t]);
    for (int t = 0; t < nk2; t++) s->fluid_conductivity = fmax(s->fluid_conductivity, tmp[nt + t]);
    free(tmp);
    s->fluid_node_count = nn > 0 ? nn : 0;
    s->fluid_tri_count = nt > 0 ? nt : 0;
    return 0;
}

/* Below max(absolute floor, PL_FLUID_NOISE_REL x the field's span) a node value is round-off,
 * drawn as zero (Pa fields and m fields; the span is max(v, 0) - min(v, 0) over the nodes, so a
 * 10 MPa field drops values under 10 Pa, a 100 Pa field those under 0.01 Pa), and an automatic
 * range never spans less than the floors (a field of 1e-11 Pa is not drawn as full scale). */
#define PL_FLUID_NOISE_PA 1e-2
#define PL_FLUID_NOISE_M 1e-6
#define PL_FLUID_NOISE_REL 1e-6
#define PL_FLUID_FLOOR_PA 1.0
#define PL_FLUID_FLOOR_M 1e-4

static int field_is_pa(int field) {
    return field == PL_FLUID_PRESSURE || field == PL_FLUID_EXCESS_PRESSURE || field == PL_SOLID_FIELD_MISES ||
           field == PL_SOLID_FIELD_PRESSURE;
}

void pl_render_scene_denoise_fluid(pl_render_scene *s) {
    double lo = 0.0, hi = 0.0;
    for (int i = 0; i < s->fluid_node_count; i++)
        if (isfinite(s->fluid_values[i])) {
            lo = fmin(lo, s->fluid_values[i]);
            hi = fmax(hi, s->fluid_values[i]);
        }
    double noise = fmax(field_is_pa(s->fluid_field) ? PL_FLUID_NOISE_PA : PL_FLUID_NOISE_M,
                        PL_FLUID_NOISE_REL * (hi - lo));
    for (int i = 0; i < s->fluid_node_count; i++)
        if (fabs(s->fluid_values[i]) < noise) s->fluid_values[i] = 0.0;
}

int pl_render_scene_capture_fluid_opt(pl_render_scene *s, const pl_world *w,
                                      const pl_render_options *opt) {
    int rc = pl_render_scene_capture_fluid(s, w, opt->fluid_field);
    if (rc || !opt->has_excess_reference || opt->fluid_field != PL_FLUID_EXCESS_PRESSURE) return rc;
    /* excess pressure from the hydrostatic state of head h0: rho_f g (h - h0), with rho_f g
     * from the pressure and the pressure head of the same nodes */
    int nn = s->fluid_node_count;
    if (nn <= 0) return 0;
    double *h = malloc((size_t)nn * 3u * sizeof *h);
    if (!h) return -1;
    double *p = h + nn, *ph = h + 2 * nn;
    if (pl_world_fluid_copy_node_field(w, PL_FLUID_HEAD, h, nn) == nn &&
        pl_world_fluid_copy_node_field(w, PL_FLUID_PRESSURE, p, nn) == nn &&
        pl_world_fluid_copy_node_field(w, PL_FLUID_PRESSURE_HEAD, ph, nn) == nn) {
        int best = -1;
        for (int i = 0; i < nn; i++)
            if (isfinite(ph[i]) && (best < 0 || fabs(ph[i]) > fabs(ph[best]))) best = i;
        if (best >= 0 && fabs(ph[best]) > 0.0) {
            double rg = p[best] / ph[best];
            for (int i = 0; i < nn; i++) s->fluid_values[i] = rg * (h[i] - opt->excess_reference);
        }
    }
    free(h);
    return 0;
}

int pl_fluid_field_range(const pl_render_scene *s, const pl_render_options *opt, double *vmin,
                         double *vmax, pl_colormap *map, char *label, size_t labellen,
                         double *unit_factor) {
    if (s->fluid_node_count <= 0) return 0;
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < s->fluid_node_count; i++) {
        double v = s->fluid_values[i];
        if (!isfinite(v)) continue;
        if (v < lo) lo = v;
        if (v > hi) hi = v;
    }
    if (!isfinite(lo)) lo = hi = 0.0;
    int field = s->fluid_field;
    int is_pa = field_is_pa(field);
    int is_vel = field == PL_FLUID_VELOCITY_NODE_X || field == PL_FLUID_VELOCITY_NODE_Y ||
                 field == PL_RENDER_FLUID_SPEED;
    *map = PL_CMAP_SEQUENTIAL;
    int zero_based = is_pa || is_vel || field == PL_FLUID_PRESSURE_HEAD || field >= PL_SOLID_FIELD_MISES;
    if (opt->fluid_max > opt->fluid_min) {
        lo = opt->fluid_min;
        hi = opt->fluid_max;
        /* a fixed range that crosses zero is a signed field: diverging, symmetric */
        if (lo < 0.0 && hi > 0.0) {
            double m = fmax(-lo, hi);
            lo = -m;
            hi = m;
            *map = PL_CMAP_DIVERGING;
        } else if (zero_based) { /* one sign: the sequential map starts at zero */
            if (lo > 0.0) lo = 0.0;
            if (hi < 0.0) hi = 0.0;
        }
    } else {
        /* automatic: the house style's rules (docs/rendering.md). A field of one sign gets the
         * sequential map from zero; a signed field (a real negative part, not round-off) the
         * diverging map, symmetric about zero; never narrower than the floor. */
        double floor_v = is_pa ? PL_FLUID_FLOOR_PA : PL_FLUID_FLOOR_M;
        int signed_field = lo < 0.0 && hi > 0.0 && -lo > 0.02 * hi && hi > 0.02 * -lo;
        if (signed_field && zero_based) {
            double m = fmax(fmax(-lo, hi), floor_v);
            lo = -m;
            hi = m;
            *map = PL_CMAP_DIVERGING;
        } else if (zero_based && lo >= -0.02 * fabs(hi) && hi > 0.0) {
            lo = 0.0;
            if (hi < floor_v) hi = floor_v;
        } else if (zero_based && hi <= 0.02 * fabs(lo) && lo < 0.0) {
            hi = 0.0;
            if (lo > -floor_v) lo = -floor_v;
        } else if (hi - lo < floor_v) { /* uniform: a window of the floor around it */
            double c = 0.5 * (lo + hi);
            if (zero_based && c == 0.0) {
                lo = 0.0;
                hi = floor_v;
            } else {
                lo = c - 0.5 * floor_v;
                hi = c + 0.5 * floor_v;
            }
        }
    }
    *vmin = lo;
    *vmax = hi;
    *unit_factor = 1.0;
    static const char *const solid[4] = {"von Mises stress", "plastic strain", "mean stress", "displacement"};
    const int sq = field - PL_SOLID_FIELD_MISES;
    const char *name = sq >= 0 && sq < 4 ? solid[sq]
                       : field == PL_FLUID_HEAD ? "total head"
                       : field == PL_FLUID_PRESSURE_HEAD ? "pressure head"
                       : field == PL_FLUID_EXCESS_PRESSURE ? "excess pore pressure"
                       : field == PL_FLUID_VELOCITY_NODE_X ? "fluid velocity x"
                       : field == PL_FLUID_VELOCITY_NODE_Y ? "fluid velocity y"
                       : field == PL_RENDER_FLUID_SPEED ? "fluid speed"
                                                           : "pore pressure";
    const char *unit = field == PL_SOLID_FIELD_PLASTIC_STRAIN ? "1" : "m";
    if (is_vel) {
        unit = "m/s";
        if (fmax(fabs(lo), fabs(hi)) < 0.1) { *unit_factor = 1e3; unit = "mm/s"; }
    }
    if (is_pa) {
        double m = fmax(fabs(lo), fabs(hi));
        unit = "Pa";
        if (m >= 1e6) { *unit_factor = 1e-6; unit = "MPa"; }
        else if (m >= 1e3) { *unit_factor = 1e-3; unit = "kPa"; }
    }
    snprintf(label, labellen, "%s (%s)", name, unit);
    return 1;
}

/* What isoline labels keep clear of: walls, fixed and prescribed bodies, every body that is
 * not a disc (pistons, buildings, blocks), discs much larger than the grains (pipes), and the
 * scene's overlay text; the grains themselves where the labels can (see pl_draw_isolines). */
void pl_fluid_label_obstacles(pl_obstacles *o, const pl_draw_list *dl, const pl_render_scene *s,
                              const pl_render_options *opt) {
    const pl_camera *cam = &dl->camera;
    double rsum = 0.0;
    int nd = 0;
    for (int i = 0; i < s->body_count; i++)
        if (s->bodies[i].shape == PL_SHAPE_DISC && s->bodies[i].motion == PL_MOTION_DYNAMIC) {
            rsum += s->bodies[i].radius;
            nd++;
        }
    double rgrain = nd ? rsum / nd : 0.0;
    pl_vec2 px[64];
    for (int i = 0; i < s->body_count && (opt->layers & PL_LAYER_BODIES); i++) {
        const pl_body_info *b = &s->bodies[i];
        if (b->material >= 0 && b->material < 32 && (opt->hidden_materials >> b->material) & 1u)
            continue;
        if (b->shape == PL_SHAPE_DISC) {
            if (b->motion == PL_MOTION_DYNAMIC && b->radius <= 3.0 * rgrain) {
                pl_obstacles_add_grain(o, pl_camera_to_px(cam, b->position), b->radius * cam->scale + 1.0);
                continue;
            }
            pl_obstacles_add_circle(o, pl_camera_to_px(cam, b->position), b->radius * cam->scale + 1.0);
            continue;
        }
        int nv = s->vert_first[i + 1] - s->vert_first[i];
        if (nv < 2 || nv > 64) continue;
        for (int k = 0; k < nv; k++) px[k] = pl_camera_to_px(cam, s->verts[s->vert_first[i] + k]);
        pl_obstacles_add_polygon(o, px, nv);
    }
    const pl_draw_list *ov = (opt->layers & PL_LAYER_OVERLAY) ? opt->overlay : NULL;
    for (int k = 0; ov && k < ov->prim_count; k++) {
        const pl_prim *p = &ov->prims[k];
        if (p->kind != PL_PRIM_TEXT) continue;
        pl_vec2 at = p->space == PL_SPACE_WORLD ? pl_camera_to_px(cam, ov->points[p->first])
                                                : ov->points[p->first];
        double w = 0.58 * p->size * (double)strlen(ov->text + p->text), h = 0.9 * p->size;
        double cx = PL_ANCHOR_H(p->anchor) == PL_ANCHOR_CENTER ? at.x
                    : PL_ANCHOR_H(p->anchor) == PL_ANCHOR_RIGHT ? at.x - 0.5 * w : at.x + 0.5 * w;
        double cy = PL_ANCHOR_V(p->anchor) == PL_ANCHOR_TOP ? at.y + 0.5 * h
                    : PL_ANCHOR_V(p->anchor) == PL_ANCHOR_MIDDLE ? at.y : at.y - 0.5 * h;
        pl_obstacles_add_box(o, (pl_label_box){{cx, cy}, 0.5 * w + 2.0, 0.5 * h + 2.0, 0.0});
    }
}

double pl_draw_fluid(pl_draw_list *dl, const pl_render_scene *s, const pl_render_options *opt,
                     unsigned layers) {
    if (s->fluid_node_count <= 0 || s->fluid_tri_count <= 0) return 0.0;
    const pl_vec2 *nodes = s->fluid_nodes;
    const int *tris = s->fluid_tris;
    int nt = s->fluid_tri_count;
    double vmin, vmax, uf;
    pl_colormap map;
    char label[64];
    pl_fluid_field_range(s, opt, &vmin, &vmax, &map, label, sizeof label, &uf);
    if (layers & PL_LAYER_PRESSURE) {
        dl->current_layer = 4;
        pl_draw_field_fill(dl, nodes, tris, nt, s->fluid_values, map, vmin, vmax);
    }
    if (layers & PL_LAYER_MESH) {
        dl->current_layer = 3;
        pl_rgba c = {0.25f, 0.35f, 0.55f, 0.45f};
        const int own = s->mesh_tri_count > 0;
        /* a resolved model's elements over the sequential map (dark at zero): light lines */
        if (own && (opt->layers & PL_LAYER_PRESSURE) && map == PL_CMAP_SEQUENTIAL)
            c = (pl_rgba){0.85f, 0.90f, 1.0f, 0.30f};
        if (pl_draw_mesh_wire(dl, own ? s->mesh_nodes : nodes, own ? s->mesh_tris : tris,
                              own ? s->mesh_tri_count : nt, c, 0.6f))
            dl->failed = 1;
    }
    /* velocity arrows before the isolines, so that isoline labels (white boxes) lie on top of
     * the arrows rather than under them */
    double vscale = 0.0;
    if (layers & PL_LAYER_VELOCITY) {
        dl->current_layer = 6;
        /* provisional automatic scale (refined per screen cell below) */
        double vmax_v = 0.0, area = 0.0;
        for (int t = 0; t < nt; t++) {
            double v = hypot(s->fluid_velocity[t].x, s->fluid_velocity[t].y);
            if (v > vmax_v) vmax_v = v;
            const pl_vec2 *a = &nodes[tris[3 * t]], *b = &nodes[tris[3 * t + 1]], *c = &nodes[tris[3 * t + 2]];
            area += 0.5 * fabs((b->x - a->x) * (c->y - a->y) - (c->x - a->x) * (b->y - a->y));
        }
        double h = sqrt(area / nt);
        /* still water: round-off velocities (hydraulic gradient below 1e-9) draw nothing */
        if (s->fluid_conductivity > 0.0 && vmax_v < 1e-9 * s->fluid_conductivity) vmax_v = 0.0;
        vscale = vmax_v > 0.0 ? (opt->velocity_scale > 0.0 ? opt->velocity_scale : 1.5 * h / vmax_v) : 0.0;
        if (vscale > 0.0) {
            /* one arrow per screen cell of about 2.5 font sizes: the mean velocity of the
             * elements whose centroids fall in the cell, drawn at their mean centroid */
            float fs = pl_render_font_size(dl->camera.width, dl->camera.height);
            double cell = fmax(14.0, 2.5 * fs);
            int gx = (int)(dl->camera.width / cell) + 1, gy = (int)(dl->camera.height / cell) + 1;
            size_t ncell = (size_t)gx * (size_t)gy;
            double *acc = calloc(ncell * 5u, sizeof *acc); /* sum x, y, vx, vy, count */
            pl_vec2 *at = malloc(ncell * sizeof *at), *vv = malloc(ncell * sizeof *vv);
            if (!acc || !at || !vv) {
                free(acc); free(at); free(vv);
                dl->failed = 1;
                return 0.0;
            }
            double vcell = 0.0;
            for (int t = 0; t < nt; t++) {
                const pl_vec2 *a = &nodes[tris[3 * t]], *b = &nodes[tris[3 * t + 1]], *c = &nodes[tris[3 * t + 2]];
                pl_vec2 ct = {(a->x + b->x + c->x) / 3.0, (a->y + b->y + c->y) / 3.0};
                pl_vec2 px = pl_camera_to_px(&dl->camera, ct);
                int ix = (int)floor(px.x / cell), iy = (int)floor(px.y / cell);
                if (ix < 0 || iy < 0 || ix >= gx || iy >= gy) continue;
                double *e = acc + 5u * ((size_t)iy * (size_t)gx + (size_t)ix);
                e[0] += ct.x; e[1] += ct.y;
                e[2] += s->fluid_velocity[t].x; e[3] += s->fluid_velocity[t].y;
                e[4] += 1.0;
            }
            int n = 0;
            for (size_t k = 0; k < ncell; k++) {
                double *e = acc + 5u * k;
                if (e[4] <= 0.0) continue;
                at[n] = (pl_vec2){e[0] / e[4], e[1] / e[4]};
                vv[n] = (pl_vec2){e[2] / e[4], e[3] / e[4]};
                double v = hypot(vv[n].x, vv[n].y);
                if (v > vcell) vcell = v;
                n++;
            }
            /* automatic scale: the fastest cell arrow spans 0.9 cells */
            if (vcell > 0.0) dl->auto_vscale = 0.9 * cell / dl->camera.scale / vcell;
            if (!(opt->velocity_scale > 0.0) && vcell > 0.0) vscale = dl->auto_vscale;
            pl_draw_arrows(dl, at, vv, n, vscale, pl_rgb(0.05, 0.12, 0.30), 1.2f, 2.5);
            free(acc);
            free(at);
            free(vv);
        }
    }
    if (layers & PL_LAYER_ISOLINES) {
        dl->current_layer = 5;
        double levels[64], step = 0.0;
        int count = opt->isoline_count > 0 ? opt->isoline_count : 10;
        if (count > 60) count = 60;
        /* levels chosen in display units so labels are round numbers */
        int nl = pl_nice_levels(vmin * uf, vmax * uf, count, levels, 64, &step);
        for (int i = 0; i < nl; i++) levels[i] /= uf;
        pl_isolines iso;
        pl_isolines_init(&iso);
        if (pl_isolines_extract(nodes, s->fluid_node_count, tris, nt, s->fluid_values, levels, nl,
                                &iso) == 0) {
            /* labels in display units, with the unit ("2 kPa") */
            for (int l = 0; l < iso.line_count; l++) iso.levels[l] *= uf;
            pl_isoline_style st = pl_default_isoline_style();
            float fs = pl_render_font_size(dl->camera.width, dl->camera.height);
            st.label_size = fmaxf(10.5f, 0.85f * fs);
            char fmt[32];
            const char *open = strrchr(label, '('), *close = strrchr(label, ')');
            if (open && close && close > open + 1 && close - open < 12)
                snprintf(fmt, sizeof fmt, "%%g %.*s", (int)(close - open - 1), open + 1);
            else
                snprintf(fmt, sizeof fmt, "%%g");
            st.label_format = fmt;
            pl_obstacles avoid;
            pl_obstacles_init(&avoid);
            pl_fluid_label_obstacles(&avoid, dl, s, opt);
            st.avoid = &avoid;
            pl_draw_isolines(dl, &iso, &st);
            if (avoid.failed) dl->failed = 1;
            pl_obstacles_free(&avoid);
        } else {
            dl->failed = 1;
        }
        pl_isolines_free(&iso);
    }
    return vscale;
}

void pl_draw_velocity_key(pl_draw_list *dl, pl_vec2 at, double velocity_scale, float fs) {
    if (!(velocity_scale > 0.0)) return;
    /* a round velocity whose arrow is about 3 font sizes long */
    double v = pl_nice_number(3.0 * fs / (velocity_scale * dl->camera.scale), 1);
    double px = v * velocity_scale * dl->camera.scale;
    pl_rgba ink = pl_rgb(0.05, 0.12, 0.30);
    pl_dl_arrow(dl, PL_SPACE_PIXEL, at, (pl_vec2){at.x + px, at.y}, ink, 1.3f, (float)fmin(0.35 * px, 10.0));
    char buf[64];
    snprintf(buf, sizeof buf, "%g m/s", v);
    pl_dl_text(dl, PL_SPACE_PIXEL, (pl_vec2){at.x + px + 0.4 * fs, at.y}, buf, 0.85f * fs,
               PL_ANCHOR_LEFT | PL_ANCHOR_MIDDLE, 0.0f, pl_rgb(0.13, 0.13, 0.15), NULL);
}
