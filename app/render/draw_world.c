/* World snapshot and the body / force layers. */
#include "draw_world.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ----------------------------------------------------------------- snapshot */

void pl_render_scene_init(pl_render_scene *s) { memset(s, 0, sizeof *s); }

void pl_render_scene_free(pl_render_scene *s) {
    free(s->bodies);
    free(s->vert_first);
    free(s->verts);
    free(s->contacts);
    free(s->stress);
    free(s->values);
    free(s->material_names);
    free(s->fluid_nodes);
    free(s->fluid_values);
    free(s->fluid_tris);
    free(s->fluid_velocity);
    free(s->mesh_nodes);
    free(s->mesh_tris);
    free(s->temperature);
    free(s->hidden);
    free(s->bonds);
    pl_render_scene_init(s);
}

static int reserve(void **p, int *cap, int need, size_t elem) {
    if (need <= *cap) return 0;
    int nc = *cap ? *cap : 64;
    while (nc < need) nc *= 2;
    void *q = realloc(*p, (size_t)nc * elem);
    if (!q) return -1;
    *p = q;
    *cap = nc;
    return 0;
}

/* bodies, vert_first and stress share body_cap */
static int reserve_bodies(pl_render_scene *s, int need) {
    if (need < 1) need = 1; /* vert_first[0] exists even for a world without bodies */
    if (need <= s->body_cap) return 0;
    int nc = s->body_cap ? s->body_cap : 64;
    while (nc < need) nc *= 2;
    pl_body_info *b = realloc(s->bodies, (size_t)nc * sizeof *b);
    if (!b) return -1;
    s->bodies = b;
    int *vf = realloc(s->vert_first, (size_t)(nc + 1) * sizeof *vf);
    if (!vf) return -1;
    s->vert_first = vf;
    double *st = realloc(s->stress, (size_t)nc * sizeof *st);
    if (!st) return -1;
    s->stress = st;
    double *va = realloc(s->values, (size_t)nc * sizeof *va);
    if (!va) return -1;
    s->values = va;
    double *te = realloc(s->temperature, (size_t)nc * sizeof *te);
    if (!te) return -1;
    s->temperature = te;
    unsigned char *hd = realloc(s->hidden, (size_t)nc);
    if (!hd) return -1;
    s->hidden = hd;
    s->body_cap = nc;
    return 0;
}

int pl_render_scene_add_body(pl_render_scene *s, const pl_body_info *b, const pl_vec2 *verts,
                             int nverts) {
    if (reserve_bodies(s, s->body_count + 1)) return -1;
    if (nverts < 0) nverts = 0;
    if (reserve((void **)&s->verts, &s->vert_cap, s->vert_count + nverts, sizeof(pl_vec2))) return -1;
    if (s->body_count == 0) s->vert_first[0] = 0;
    s->bodies[s->body_count] = *b;
    s->stress[s->body_count] = 0.0;
    s->values[s->body_count] = 0.0;
    s->temperature[s->body_count] = NAN;
    s->hidden[s->body_count] = 0;
    if (nverts) memcpy(s->verts + s->vert_count, verts, (size_t)nverts * sizeof(pl_vec2));
    s->vert_count += nverts;
    s->body_count++;
    s->vert_first[s->body_count] = s->vert_count;
    return 0;
}

int pl_render_scene_add_contact(pl_render_scene *s, const pl_contact_info *c) {
    if (reserve((void **)&s->contacts, &s->contact_cap, s->contact_count + 1, sizeof *c)) return -1;
    s->contacts[s->contact_count++] = *c;
    return 0;
}

int pl_render_scene_capture(pl_render_scene *s, const pl_world *w) {
    int n = pl_world_body_count(w);
    s->body_count = 0;
    s->vert_count = 0;
    s->contact_count = 0;
    s->fluid_node_count = s->fluid_tri_count = 0;
    if (reserve_bodies(s, n)) return -1;
    s->vert_first[0] = 0;
    pl_vec2 tmp[PL_MAX_POLY_VERTICES];
    for (int i = 0; i < n; i++) {
        pl_body_info b;
        if (pl_world_body_info(w, i, &b) != PL_OK) memset(&b, 0, sizeof b);
        int nv = b.shape == PL_SHAPE_DISC ? 0 : pl_world_body_vertices(w, i, tmp, PL_MAX_POLY_VERTICES);
        if (nv < 0) nv = 0;
        if (nv > PL_MAX_POLY_VERTICES) nv = PL_MAX_POLY_VERTICES;
        if (pl_render_scene_add_body(s, &b, tmp, nv)) return -1;
        s->temperature[i] = pl_world_body_temperature(w, i);
        s->hidden[i] = (unsigned char)pl_world_body_removed(w, i, NULL);
    }
    s->bond_count = 0;
    const int nbond = pl_world_bond_total(w);
    if (nbond > 0) {
        if (reserve((void **)&s->bonds, &s->bond_cap, nbond, sizeof(pl_bond_info))) return -1;
        s->bond_count = pl_world_copy_bonds(w, 0, s->bonds, nbond);
    }
    int nc = pl_world_contact_count(w);
    if (nc > 0) {
        if (reserve((void **)&s->contacts, &s->contact_cap, nc, sizeof(pl_contact_info))) return -1;
        s->contact_count = pl_world_copy_contacts(w, s->contacts, nc);
        if (s->contact_count < 0) s->contact_count = 0;
    }
    s->time = pl_world_time(w);
    pl_world_bounds(w, &s->lo, &s->hi);
    int nm = pl_world_material_count(w);
    if (nm < 0) nm = 0;
    if (reserve((void **)&s->material_names, &s->material_cap, nm > 0 ? nm : 1, sizeof(char[48])))
        return -1;
    s->material_count = nm;
    for (int m = 0; m < nm; m++) {
        pl_material_def md = pl_world_material(w, m);
        const char *name = md.name ? md.name : "?";
        strncpy(s->material_names[m], name, 47);
        s->material_names[m][47] = 0;
    }
    return 0;
}

int pl_render_scene_stress(pl_render_scene *s) {
    for (int i = 0; i < s->body_count; i++) s->stress[i] = 0.0;
    for (int k = 0; k < s->contact_count; k++) {
        const pl_contact_info *c = &s->contacts[k];
        if (c->a < 0 || c->b < 0 || c->a >= s->body_count || c->b >= s->body_count) continue;
        pl_vec2 n = c->normal, t = {-c->normal.y, c->normal.x};
        pl_vec2 f = {c->fn * n.x + c->ft * t.x, c->fn * n.y + c->ft * t.y}; /* on b */
        const pl_body_info *A = &s->bodies[c->a], *B = &s->bodies[c->b];
        pl_vec2 la = {c->point.x - A->position.x, c->point.y - A->position.y};
        pl_vec2 lb = {c->point.x - B->position.x, c->point.y - B->position.y};
        s->stress[c->a] += f.x * la.x + f.y * la.y;    /* -(-f) . la */
        s->stress[c->b] -= f.x * lb.x + f.y * lb.y;    /* -(f) . lb */
    }
    for (int i = 0; i < s->body_count; i++) {
        double A = s->bodies[i].area;
        s->stress[i] = A > 0.0 ? s->stress[i] / (2.0 * A) : 0.0;
    }
    return 0;
}

/* ------------------------------------------------------------------ bodies */

static pl_rgba material_color(const pl_render_options *opt, int m) {
    if (opt->material_color_count > 0) {
        int n = opt->material_color_count;
        if (n > PL_RENDER_MAX_MATERIAL_COLORS) n = PL_RENDER_MAX_MATERIAL_COLORS;
        return opt->material_colors[(m < 0 ? 0 : m) % n];
    }
    return pl_material_palette(m);
}

/* Distance from the centroid c to the boundary of a convex polygon along direction d. */
static double ray_to_boundary(pl_vec2 c, pl_vec2 d, const pl_vec2 *v, int n) {
    double best = INFINITY;
    for (int i = 0; i < n; i++) {
        pl_vec2 a = v[i], b = v[(i + 1) % n];
        pl_vec2 e = {b.x - a.x, b.y - a.y};
        double den = d.x * e.y - d.y * e.x;
        if (fabs(den) < 1e-300) continue;
        pl_vec2 ac = {a.x - c.x, a.y - c.y};
        double t = (ac.x * e.y - ac.y * e.x) / den;  /* along d */
        double u = (ac.x * d.y - ac.y * d.x) / den;  /* along e */
        if (t > 0.0 && u >= -1e-9 && u <= 1.0 + 1e-9 && t < best) best = t;
    }
    return isfinite(best) ? best : 0.0;
}

static int nv_hidden_fill(pl_draw_list *dl, const pl_render_scene *s, int i, pl_rgba bg) {
    const pl_body_info *b = &s->bodies[i];
    pl_style st = pl_style_fill(bg);
    if (b->shape == PL_SHAPE_DISC) {
        pl_dl_circle(dl, PL_SPACE_WORLD, b->position, b->radius, &st);
        return 0;
    }
    int nv = s->vert_first[i + 1] - s->vert_first[i];
    if (nv >= 3) pl_dl_polygon(dl, PL_SPACE_WORLD, s->verts + s->vert_first[i], nv, &st);
    return 0;
}

void pl_draw_bodies(pl_draw_list *dl, const pl_render_scene *s, const pl_render_options *opt,
                    const double *values, pl_colormap map, double vmin, double vmax) {
    const double scale = dl->camera.scale;
    pl_rgba wall = opt->wall_color;
    pl_rgba wall_edge = pl_rgba_scale(wall, 0.6);
    pl_rgba wall_mark = pl_rgba_mix(wall, pl_rgb(1, 1, 1), 0.45);
    int by_material = opt->coloring == PL_COLOR_BY_MATERIAL || !values;
    /* pass 0: areas (discs, polygons); pass 1: wall segments on top */
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < s->body_count; i++) {
            const pl_body_info *b = &s->bodies[i];
            if (b->material >= 0 && b->material < 32 && (opt->hidden_materials >> b->material) & 1u) {
                /* hidden: filled with the background, no outline (it still masks a field
                 * drawn under it, as the helper it is masks it from the grains) */
                if (pass == 0 && nv_hidden_fill(dl, s, i, opt->background)) dl->failed = 1;
                continue;
            }
            int kinematic = b->motion != PL_MOTION_DYNAMIC;
            const pl_vec2 *v = s->verts + s->vert_first[i];
            int nv = s->vert_first[i + 1] - s->vert_first[i];
            if (b->shape == PL_SHAPE_SEGMENT) {
                if (pass == 1 && nv >= 2) {
                    float w = (float)fmax(2.5, 0.004 * (dl->camera.width + dl->camera.height));
                    pl_dl_line(dl, PL_SPACE_WORLD, v[0], v[1], wall, w);
                }
                continue;
            }
            if (pass != 0 || (s->hidden && s->hidden[i])) continue;
            pl_rgba fill, edge, mark;
            if (kinematic) {
                fill = wall;
                edge = wall_edge;
                mark = wall_mark;
            } else {
                fill = by_material ? material_color(opt, b->material)
                                   : pl_colormap_value(map, values[i], vmin, vmax);
                edge = pl_rgba_scale(fill, 0.5);
                mark = edge;
            }
            double r_px = b->radius * scale;
            float ow = (float)fmin(1.6, fmax(0.6, 0.06 * r_px));
            int detailed = r_px >= 3.0; /* outlines and marks only when they can be seen */
            pl_style st = detailed ? pl_style_fill_stroke(fill, edge, ow) : pl_style_fill(fill);
            pl_vec2 dir = {cos(b->angle), sin(b->angle)};
            /* rotation marks on moving bodies, and on prescribed bodies that turn or have
             * turned (a drum); a prescribed box that never turns is a wall */
            int marked = !kinematic ||
                         (b->motion == PL_MOTION_PRESCRIBED && (b->omega != 0.0 || b->angle != 0.0));
            if (b->shape == PL_SHAPE_DISC) {
                pl_dl_circle(dl, PL_SPACE_WORLD, b->position, b->radius, &st);
                if (detailed && marked) {
                    pl_vec2 tip = {b->position.x + b->radius * dir.x, b->position.y + b->radius * dir.y};
                    pl_dl_line(dl, PL_SPACE_WORLD, b->position, tip, mark, ow);
                }
            } else if (nv >= 3) {
                pl_dl_polygon(dl, PL_SPACE_WORLD, v, nv, &st);
                if (detailed && marked) {
                    double len = ray_to_boundary(b->position, dir, v, nv);
                    pl_vec2 tip = {b->position.x + len * dir.x, b->position.y + len * dir.y};
                    pl_dl_line(dl, PL_SPACE_WORLD, b->position, tip, mark, ow);
                }
            }
        }
    }
}

/* ------------------------------------------------------------------ forces */

typedef struct force_ref {
    double fn;
    int index;
} force_ref;

static int cmp_force(const void *a, const void *b) {
    const force_ref *x = a, *y = b;
    if (x->fn != y->fn) return x->fn < y->fn ? -1 : 1;
    return x->index - y->index;
}

static pl_vec2 chain_end(const pl_render_scene *s, int body, pl_vec2 contact_point) {
    if (body < 0 || body >= s->body_count) return contact_point;
    const pl_body_info *b = &s->bodies[body];
    return b->shape == PL_SHAPE_SEGMENT ? contact_point : b->position;
}

static double auto_force_scale(const pl_render_scene *s, const pl_render_options *opt) {
    if (opt->force_scale > 0.0) return opt->force_scale;
    double m = 0.0;
    for (int k = 0; k < s->contact_count; k++)
        if (s->contacts[k].fn > m) m = s->contacts[k].fn;
    return m;
}

double pl_draw_force_chains(pl_draw_list *dl, const pl_render_scene *s,
                            const pl_render_options *opt) {
    double scale = auto_force_scale(s, opt);
    if (!(scale > 0.0) || s->contact_count == 0) return 0.0;
    force_ref *order = malloc((size_t)s->contact_count * sizeof *order);
    if (!order) {
        dl->failed = 1;
        return 0.0;
    }
    double thr = opt->force_threshold * scale;
    int n = 0;
    for (int k = 0; k < s->contact_count; k++) {
        double fn = s->contacts[k].fn;
        if (fn > thr && fn > 0.0) {
            order[n].fn = fn;
            order[n].index = k;
            n++;
        }
    }
    /* by force, then contact index: the bits of a positive double order as the double, and
     * the stable radix sort keeps the index order of equal forces */
    uint64_t *keys = malloc((size_t)(n > 0 ? n : 1) * sizeof *keys);
    int32_t *idx = malloc((size_t)(n > 0 ? n : 1) * sizeof *idx);
    int sorted = 0;
    if (keys && idx) {
        for (int i = 0; i < n; i++) {
            memcpy(&keys[i], &order[i].fn, sizeof keys[i]);
            idx[i] = order[i].index;
        }
        if (pl_radix_sort_u64(keys, idx, n) == 0) {
            for (int i = 0; i < n; i++) {
                memcpy(&order[i].fn, &keys[i], sizeof keys[i]);
                order[i].index = idx[i];
            }
            sorted = 1;
        }
    }
    free(keys);
    free(idx);
    if (!sorted) qsort(order, (size_t)n, sizeof *order, cmp_force);
    pl_rgba strong = opt->force_color;
    pl_rgba weak = pl_rgba_mix(strong, pl_rgb(1, 1, 1), 0.6);
    double wmax = opt->force_max_width > 0.0 ? opt->force_max_width : 6.0;
    /* Forces are drawn in 32 classes of equal width and colour (1/32 of the scale each, so
     * widths are within wmax/64 of exact), one batch of segments per class, weakest class
     * first: a few dozen strokes instead of one per contact. */
    enum { CLASSES = 32, TOP = 48 }; /* classes above the scale up to 1.5 x scale */
    int cls_prev = -1, in_batch = 0;
    for (int i = 0; i < n; i++) {
        const pl_contact_info *c = &s->contacts[order[i].index];
        double f = c->fn / scale;
        if (f > 1.5) f = 1.5;
        int cls = (int)floor(f * CLASSES);
        if (cls >= TOP) cls = TOP - 1;
        /* batches of at most 64 segments: cairo strokes one batch as one path, and very long
         * paths of crossing segments tessellate slower than several short ones */
        if (cls != cls_prev || in_batch == 64) {
            in_batch = 0;
            double fc = (cls + 0.5) / CLASSES;
            float w = (float)fmax(0.5, wmax * fc);
            pl_dl_segments_begin(dl, PL_SPACE_WORLD, pl_rgba_mix(weak, strong, fc > 1.0 ? 1.0 : fc), w);
            cls_prev = cls;
        }
        pl_dl_segment_add(dl, chain_end(s, c->a, c->point), chain_end(s, c->b, c->point));
        in_batch++;
    }
    free(order);
    return scale;
}

void pl_draw_tangential(pl_draw_list *dl, const pl_render_scene *s, const pl_render_options *opt,
                        double scale) {
    /* with an automatic scale, the largest tangential force gets the full arrow length */
    if (!(opt->force_scale > 0.0)) {
        scale = 0.0;
        for (int k = 0; k < s->contact_count; k++)
            if (fabs(s->contacts[k].ft) > scale) scale = fabs(s->contacts[k].ft);
    }
    if (!(scale > 0.0)) return;
    pl_rgba col = pl_rgb_hex(0x12706B);
    double wmax = opt->force_max_width > 0.0 ? opt->force_max_width : 6.0;
    double len_max_px = fmax(18.0, 5.0 * wmax);
    for (int k = 0; k < s->contact_count; k++) {
        const pl_contact_info *c = &s->contacts[k];
        double f = fabs(c->ft) / scale;
        if (!(f > opt->force_threshold) || f == 0.0) continue;
        if (f > 1.5) f = 1.5;
        double sign = c->ft >= 0.0 ? 1.0 : -1.0;
        pl_vec2 t = {-c->normal.y * sign, c->normal.x * sign};
        pl_vec2 p = pl_camera_to_px(&dl->camera, c->point);
        double len = len_max_px * f;
        /* screen y is down */
        pl_vec2 tail = {p.x - 0.5 * len * t.x, p.y + 0.5 * len * t.y};
        pl_vec2 tip = {p.x + 0.5 * len * t.x, p.y - 0.5 * len * t.y};
        pl_dl_arrow(dl, PL_SPACE_PIXEL, tail, tip, col, 2.5f, (float)fmin(9.0, 0.45 * len));
    }
}

/* ------------------------------------------------------------------ bonds */

void pl_draw_bonds(pl_draw_list *dl, const pl_render_scene *s) {
    const pl_rgba intact = pl_rgb_hex(0x6C757D), tension = pl_rgb_hex(0xD00000), shear = pl_rgb_hex(0x1D4ED8);
    const float thin = (float)fmax(0.5, fmin(1.2, 0.05 * dl->camera.scale * 1e-3));
    for (int k = 0; k < s->bond_count; k++) {
        const pl_bond_info *b = &s->bonds[k];
        if (b->a < 0 || b->b < 0 || b->a >= s->body_count || b->b >= s->body_count) continue;
        if (b->state == PL_BOND_BROKEN_REMOVED) continue;
        const pl_body_info *A = &s->bodies[b->a], *B = &s->bodies[b->b];
        if (b->state == PL_BOND_INTACT) {
            pl_dl_line(dl, PL_SPACE_WORLD, A->position, B->position, intact, thin);
            continue;
        }
        /* the crack: across the bond through its point, as long as the smaller disc */
        const double dx = B->position.x - A->position.x, dy = B->position.y - A->position.y, d = hypot(dx, dy);
        if (!(d > 0)) continue;
        /* grains flown apart (a chip): the crack has opened into free space, nothing to draw */
        if (d - A->radius - B->radius > fmin(A->radius, B->radius)) continue;
        const double h = 0.9 * fmin(A->radius, B->radius);
        const pl_vec2 t = {-dy / d * h, dx / d * h};
        const pl_vec2 p0 = {b->point.x - t.x, b->point.y - t.y}, p1 = {b->point.x + t.x, b->point.y + t.y};
        const double px = 2 * h * dl->camera.scale;
        const float wd = (float)fmax(1.5, fmin(4.0, 0.25 * px));
        pl_dl_line(dl, PL_SPACE_WORLD, p0, p1, b->state == PL_BOND_BROKEN_TENSION ? tension : shear, wd);
    }
}
