/* Render options, layer parsing, frame layout, and the render-to-file/RGBA entry points. */
#include "render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"
#include "backend_cairo.h"
#include "draw_world.h"


static const char *const layer_names[] = {"bodies",  "forces",   "time",     "mesh",
                                          "pressure", "isolines", "velocity", "colorbar",
                                          "scalebar", "title",    "overlay",  "tangential",
                                          "bonds"};
#define LAYER_COUNT ((int)(sizeof layer_names / sizeof layer_names[0]))

const char *pl_render_layer_name(int bit) {
    return bit >= 0 && bit < LAYER_COUNT ? layer_names[bit] : NULL;
}

pl_render_options pl_default_render_options(void) {
    pl_render_options o;
    memset(&o, 0, sizeof o);
    o.width = 800;
    o.height = 600;
    o.layers = PL_LAYERS_DEFAULT;
    o.auto_camera = 1;
    o.margin = 0.05;
    o.background = pl_rgb(1, 1, 1);
    o.material_color_count = 0;
    o.wall_color = pl_rgb_hex(0x4A4A4F);
    o.force_color = pl_rgb_hex(0xA50F15);
    o.force_scale = 0.0;
    o.force_threshold = 0.02;
    o.force_max_width = 6.0;
    o.coloring = PL_COLOR_BY_MATERIAL;
    o.title[0] = 0;
    o.color_min = o.color_max = 0.0;
    o.overlay = NULL;
    o.time_offset = 0.0;
    o.fluid_field = 2; /* PL_FLUID_PRESSURE */
    o.isoline_count = 10;
    o.fluid_min = o.fluid_max = 0.0;
    o.velocity_scale = 0.0;
    o.has_excess_reference = 0;
    o.excess_reference = 0.0;
    o.record_from = 0.0;
    o.hidden_materials = 0;
    o.reserve_right = 0;
    return o;
}

int pl_render_parse_layers(const char *list, unsigned *layers, char *err, size_t errlen) {
    unsigned mask = *layers;
    const char *p = list ? list : "";
    int first = 1;
    while (1) {
        while (*p == ' ' || *p == ',') p++;
        if (!*p) break;
        const char *q = p;
        while (*q && *q != ',') q++;
        size_t len = (size_t)(q - p);
        while (len > 0 && p[len - 1] == ' ') len--;
        char name[32];
        int sign = 0; /* +1 add, -1 remove, 0 absolute */
        if (*p == '+' || *p == '-') {
            sign = *p == '+' ? 1 : -1;
            p++;
            len--;
        }
        if (len == 0 || len >= sizeof name) goto bad;
        memcpy(name, p, len);
        name[len] = 0;
        unsigned bits = 0;
        if (strcmp(name, "all") == 0) bits = (1u << LAYER_COUNT) - 1u;
        else if (strcmp(name, "none") == 0) bits = 0;
        else {
            int found = -1;
            for (int i = 0; i < LAYER_COUNT; i++)
                if (strcmp(name, layer_names[i]) == 0) found = i;
            if (found < 0) goto bad;
            bits = 1u << found;
        }
        if (sign == 0 && first) mask = 0; /* an absolute list replaces the mask */
        if (sign < 0) mask &= ~bits;
        else mask |= bits;
        first = 0;
        p = q;
        continue;
    bad:
        if (err && errlen) {
            size_t used = (size_t)snprintf(err, errlen, "unknown layer '%.*s' in \"%s\"; valid layers: ",
                                           (int)(q - p), p, list);
            for (int i = 0; i < LAYER_COUNT && used < errlen; i++)
                used += (size_t)snprintf(err + used, errlen - used, "%s, ", layer_names[i]);
            if (used < errlen)
                snprintf(err + used, errlen - used, "all, none (prefix + or - to add or remove)");
        }
        return -1;
    }
    *layers = mask;
    return 0;
}

static pl_rgba material_fill(const pl_render_options *opt, int m) {
    if (opt->material_color_count > 0) {
        int n = opt->material_color_count > PL_RENDER_MAX_MATERIAL_COLORS
                    ? PL_RENDER_MAX_MATERIAL_COLORS : opt->material_color_count;
        return opt->material_colors[m % n];
    }
    return pl_material_palette(m);
}

/* Quantity used to colour bodies, with its colour map and display unit. */
typedef struct quantity {
    int active;
    pl_colormap map;
    double vmin, vmax;     /* in SI units */
    double unit_factor;    /* displayed = SI * factor */
    char label[64];
    double auto_lo, auto_hi; /* the frame's own range, before a fixed one */
} quantity;

static void body_quantity(pl_render_scene *s, const pl_render_options *opt, quantity *q) {
    memset(q, 0, sizeof *q);
    q->unit_factor = 1.0;
    if (opt->coloring == PL_COLOR_BY_MATERIAL || !(opt->layers & PL_LAYER_BODIES)) return;
    q->active = 1;
    double lo = INFINITY, hi = -INFINITY;
    if (opt->coloring == PL_COLOR_BY_SPEED) {
        for (int i = 0; i < s->body_count; i++) {
            const pl_body_info *b = &s->bodies[i];
            s->values[i] = hypot(b->velocity.x, b->velocity.y);
            if (b->motion == PL_MOTION_DYNAMIC && b->shape != PL_SHAPE_SEGMENT && s->values[i] > hi)
                hi = s->values[i];
        }
        lo = 0.0;
        /* a resting world is not "fastest": below 1 cm/s the bar keeps a 0..0.01 m/s range */
        if (!(hi >= 0.01)) hi = 0.01;
        q->map = PL_CMAP_SEQUENTIAL;
        snprintf(q->label, sizeof q->label, "speed (m/s)");
    } else if (opt->coloring == PL_COLOR_BY_TEMPERATURE) {
        for (int i = 0; i < s->body_count; i++) {
            s->values[i] = s->temperature[i];
            const pl_body_info *b = &s->bodies[i];
            if (b->shape == PL_SHAPE_SEGMENT || s->hidden[i] || !isfinite(s->values[i])) continue;
            if (s->values[i] < lo) lo = s->values[i];
            if (s->values[i] > hi) hi = s->values[i];
        }
        q->map = PL_CMAP_SEQUENTIAL;
        snprintf(q->label, sizeof q->label, "temperature (K)");
    } else {
        pl_render_scene_stress(s);
        for (int i = 0; i < s->body_count; i++) {
            s->values[i] = s->stress[i];
            const pl_body_info *b = &s->bodies[i];
            if (b->motion != PL_MOTION_DYNAMIC || b->shape == PL_SHAPE_SEGMENT) continue;
            if (s->values[i] < lo) lo = s->values[i];
            if (s->values[i] > hi) hi = s->values[i];
        }
        q->map = PL_CMAP_SEQUENTIAL;
        if (lo < 0.0) { /* tension present: diverging map centred on zero */
            double m = fmax(-lo, hi);
            lo = -m;
            hi = m;
            q->map = PL_CMAP_DIVERGING;
        } else {
            lo = 0.0;
        }
    }
    if (!isfinite(hi) || !isfinite(lo)) { lo = 0.0; hi = 0.0; }
    q->auto_lo = lo;
    q->auto_hi = hi;
    if (opt->color_max > opt->color_min) {
        lo = opt->color_min;
        hi = opt->color_max;
        /* speed and compressive stress are one-signed: the sequential map starts at zero */
        if (q->map == PL_CMAP_SEQUENTIAL && lo > 0.0) lo = 0.0;
    }
    if (!(hi > lo)) hi = lo + 1.0; /* nothing moving / no stress yet: keep a valid bar */
    q->vmin = lo;
    q->vmax = hi;
    if (opt->coloring == PL_COLOR_BY_STRESS) {
        double m = fmax(fabs(lo), fabs(hi));
        const char *unit = "Pa";
        if (m >= 1e9) { q->unit_factor = 1e-9; unit = "GPa"; }
        else if (m >= 1e6) { q->unit_factor = 1e-6; unit = "MPa"; }
        else if (m >= 1e3) { q->unit_factor = 1e-3; unit = "kPa"; }
        snprintf(q->label, sizeof q->label, "mean stress (%s)", unit);
    }
}

int pl_render_build_scene(pl_draw_list *dl, pl_render_scene *s, const pl_render_options *opt,
                          char *err, size_t errlen) {
    int W = opt->width, H = opt->height;
    if (W < 16 || H < 16 || W > 16384 || H > 16384) {
        snprintf(err, errlen, "image size %dx%d is out of range (16..16384 pixels each side)", W, H);
        return -1;
    }
    int W_img = W;
    /* a host's panel at the right edge: everything of the scene is laid out left of it */
    if (opt->reserve_right > 0 && opt->reserve_right < W - 64) W -= opt->reserve_right;
    pl_draw_list_clear(dl);
    dl->background = opt->background;
    unsigned L = opt->layers;
    float fs = pl_render_font_size(W, H);

    pl_render_scene_denoise_fluid(s);
    quantity q;
    body_quantity(s, opt, &q);
    if (q.active && q.auto_hi > q.auto_lo) {
        dl->auto_color_set = 1;
        dl->auto_color_lo = q.auto_lo;
        dl->auto_color_hi = q.auto_hi;
    }
    /* the colour bar shows the fluid field when it is drawn, else the body quantity */
    quantity fq;
    memset(&fq, 0, sizeof fq);
    if ((L & (PL_LAYER_PRESSURE | PL_LAYER_ISOLINES)) &&
        pl_fluid_field_range(s, opt, &fq.vmin, &fq.vmax, &fq.map, fq.label, sizeof fq.label,
                             &fq.unit_factor)) {
        fq.active = (L & PL_LAYER_PRESSURE) != 0;
        pl_render_options auto_opt = *opt;
        auto_opt.fluid_min = auto_opt.fluid_max = 0.0;
        double alo, ahi, uf;
        pl_colormap am;
        char al[64];
        pl_fluid_field_range(s, &auto_opt, &alo, &ahi, &am, al, sizeof al, &uf);
        dl->auto_field_set = 1;
        dl->auto_field_lo = alo;
        dl->auto_field_hi = ahi;
    }
    const quantity *bar = fq.active ? &fq : &q;

    /* Layout: a top band for title/time, a bottom band for the scale bar, a right band for
     * the colour bar or material legend; the scene is fitted into what remains. */
    int has_title = (L & PL_LAYER_TITLE) && opt->title[0];
    double top_h = (has_title || (L & PL_LAYER_TIME)) ? 2.0 * fs : 0.0;
    double bot_h = (L & PL_LAYER_SCALEBAR) ? 2.4 * fs : 0.0;
    double right_w = 0.0;
    /* material legend: the materials of moving bodies, then one entry for fixed bodies and
     * walls (drawn in the wall colour whatever their material) */
    int legend_n = 0;
    pl_rgba legend_colors[PL_RENDER_MAX_MATERIAL_COLORS + 1];
    char legend_names[PL_RENDER_MAX_MATERIAL_COLORS + 1][48];
    if ((L & PL_LAYER_COLORBAR) && !bar->active && (L & PL_LAYER_BODIES)) {
        int any_fixed = 0;
        for (int m = 0; m < s->material_count && legend_n < PL_RENDER_MAX_MATERIAL_COLORS; m++) {
            int used = 0;
            if (m < 32 && (opt->hidden_materials >> m) & 1u) continue;
            for (int i = 0; i < s->body_count && !used; i++)
                used = s->bodies[i].material == m && s->bodies[i].motion == PL_MOTION_DYNAMIC &&
                       s->bodies[i].shape != PL_SHAPE_SEGMENT;
            if (!used) continue;
            legend_colors[legend_n] = material_fill(opt, m);
            snprintf(legend_names[legend_n], 48, "%s", s->material_names[m]);
            legend_n++;
        }
        for (int i = 0; i < s->body_count && !any_fixed; i++)
            any_fixed = s->bodies[i].motion != PL_MOTION_DYNAMIC || s->bodies[i].shape == PL_SHAPE_SEGMENT;
        if (any_fixed) {
            legend_colors[legend_n] = opt->wall_color;
            snprintf(legend_names[legend_n], 48, "fixed, walls");
            legend_n++;
        }
    }
    if (L & PL_LAYER_COLORBAR) {
        if (bar->active) {
            right_w = fmax(7.0 * fs, 0.52 * 0.9 * fs * (double)strlen(bar->label) + 1.6 * fs);
        } else if (legend_n > 0) {
            size_t longest = 8;
            for (int m = 0; m < legend_n; m++)
                if (strlen(legend_names[m]) > longest) longest = strlen(legend_names[m]);
            right_w = 0.55 * 0.85 * fs * (double)longest + 3.0 * fs;
        }
    }
    if (right_w > 0.45 * W) right_w = 0.45 * W;
    pl_px_rect area = {0.0, top_h, W - right_w, H - bot_h};
    if (opt->auto_camera || !(opt->view_hi.x > opt->view_lo.x) || !(opt->view_hi.y > opt->view_lo.y))
        dl->camera = pl_camera_fit(s->lo, s->hi, W_img, H, area, opt->margin);
    else
        dl->camera = pl_camera_fit(opt->view_lo, opt->view_hi, W_img, H, area, 0.0);
    dl->clip = area;
    /* walls that run out of a scene's view at its top end a little below the title band, so
     * the time stamp and title never sit on a wall line */
    if (top_h > 0.0) dl->clip.y0 += 0.5 * fs;
    dl->has_clip = 1;

    /* Scene layers, back to front: fluid field and mesh, bodies, isolines and velocity
     * arrows, force chains, overlays. */
    pl_draw_fluid(dl, s, opt, L & (PL_LAYER_PRESSURE | PL_LAYER_MESH));
    if (L & PL_LAYER_BODIES) {
        dl->current_layer = 0;
        pl_draw_bodies(dl, s, opt, q.active ? s->values : NULL, q.map, q.vmin, q.vmax);
    }
    double vscale = pl_draw_fluid(dl, s, opt, L & (PL_LAYER_ISOLINES | PL_LAYER_VELOCITY));
    double fscale = 0.0;
    if (L & PL_LAYER_FORCES) {
        dl->current_layer = 1;
        fscale = pl_draw_force_chains(dl, s, opt);
    }
    if (L & PL_LAYER_BONDS) {
        dl->current_layer = 12;
        pl_draw_bonds(dl, s);
    }
    if (L & PL_LAYER_TANGENTIAL) {
        dl->current_layer = 11;
        pl_draw_tangential(dl, s, opt, fscale);
    }
    if ((L & PL_LAYER_OVERLAY) && opt->overlay) {
        dl->current_layer = 10;
        int first = dl->prim_count;
        pl_draw_list_append(dl, opt->overlay);
        /* a scene's text stays readable at the output size (house style, rule 5) */
        const float floor_px = PL_OVERLAY_TEXT_MIN * fs;
        for (int i = first; i < dl->prim_count; i++)
            if (dl->prims[i].kind == PL_PRIM_TEXT && dl->prims[i].size < floor_px)
                dl->prims[i].size = floor_px;
    }

    /* Annotations */
    if (L & PL_LAYER_TIME) {
        dl->current_layer = 2;
        pl_draw_time_stamp(dl, (pl_vec2){0.8 * fs, 0.5 * top_h}, s->time + opt->time_offset, fs);
    }
    if (has_title) {
        dl->current_layer = 9;
        /* centred, unless it would run into the time stamp: then just right of it
         * (widths estimated at 0.56 em per character of DejaVu Sans) */
        double title_w = 0.56 * 1.15 * fs * (double)strlen(opt->title);
        double time_end = (L & PL_LAYER_TIME) ? 0.8 * fs + 0.56 * fs * 14.0 + 1.0 * fs : 0.0;
        double cx = 0.5 * W;
        if (cx - 0.5 * title_w < time_end) cx = time_end + 0.5 * title_w;
        pl_draw_title(dl, (pl_vec2){cx, 0.5 * top_h}, opt->title, fs);
    }
    if (L & PL_LAYER_SCALEBAR) {
        dl->current_layer = 8;
        pl_draw_scale_bar(dl, (pl_vec2){area.x0 + 1.0 * fs, H - 0.8 * fs}, area.x1 - area.x0, fs);
    }
    if (vscale > 0.0) {
        dl->current_layer = 6;
        pl_vec2 at = bot_h > 0.0 ? (pl_vec2){area.x1 - 9.0 * fs, H - 0.9 * fs}
                                 : (pl_vec2){area.x1 - 9.0 * fs, area.y1 - 1.0 * fs};
        pl_draw_velocity_key(dl, at, vscale, fs);
    }
    if (L & PL_LAYER_COLORBAR) {
        dl->current_layer = 7;
        double x0 = W - right_w + 0.9 * fs;
        if (bar->active) {
            pl_px_rect r = {x0, area.y0 + 2.2 * fs, x0 + 1.1 * fs, area.y1 - 1.0 * fs};
            if (r.y1 - r.y0 < 3.0 * fs) r.y1 = r.y0 + 3.0 * fs;
            pl_draw_colorbar(dl, r, bar->map, bar->vmin * bar->unit_factor,
                             bar->vmax * bar->unit_factor, bar->label, fs);
        } else if (legend_n > 0) {
            pl_draw_material_legend(dl, (pl_vec2){x0, area.y0 + 1.0 * fs},
                                    (const char(*)[48])legend_names, legend_colors, legend_n, fs);
        }
    }
    if (dl->failed) {
        snprintf(err, errlen, "out of memory while building the frame");
        return -1;
    }
    return 0;
}

pl_status pl_render_prepare(pl_world *w, const pl_render_options *opt, int vtk) {
    return (opt->layers & PL_RENDER_FLUID_LAYERS) || vtk ? pl_world_prepare(w) : PL_OK;
}

int pl_render_build(const pl_world *w, const pl_render_options *opt, pl_draw_list *dl,
                    char *err, size_t errlen) {
    pl_render_scene s;
    pl_render_scene_init(&s);
    int rc = pl_render_scene_capture(&s, w);
    if (rc == 0 && (opt->layers & PL_RENDER_FLUID_LAYERS))
        rc = pl_render_scene_capture_fluid_opt(&s, w, opt);
    if (rc) snprintf(err, errlen, "out of memory while reading the world");
    else rc = pl_render_build_scene(dl, &s, opt, err, errlen);
    pl_render_scene_free(&s);
    return rc;
}

int pl_render_to_file(const pl_world *w, const pl_render_options *opt, const char *path,
                      char *err, size_t errlen) {
    if (pl_file_format(path) < 0) {
        snprintf(err, errlen, "%s: unknown image format (valid extensions: .png, .svg, .pdf)", path);
        return -1;
    }
    pl_draw_list dl;
    pl_draw_list_init(&dl);
    int rc = pl_render_build(w, opt, &dl, err, errlen);
    if (rc == 0 && pl_file_format(path) == 0) {
        rc = pl_cairo_write_file(&dl, path, 6, err, errlen); /* pl_png_write renames itself */
    } else if (rc == 0) {
        /* SVG/PDF: cairo writes the temporary, which is renamed into place when complete */
        pl_atomic_file af;
        rc = pl_atomic_file_begin(&af, path, err, errlen);
        if (rc == 0) {
            rc = pl_cairo_write_file(&dl, af.tmp_path, 6, err, errlen);
            rc = pl_atomic_file_end(&af, rc == 0, err, errlen);
        }
    }
    pl_draw_list_free(&dl);
    return rc;
}

int pl_render_to_rgba(const pl_world *w, const pl_render_options *opt, unsigned char **rgba,
                      char *err, size_t errlen) {
    pl_draw_list dl;
    pl_draw_list_init(&dl);
    int rc = pl_render_build(w, opt, &dl, err, errlen);
    if (rc == 0) {
        pl_image img = {opt->width, opt->height, *rgba};
        rc = pl_cairo_rasterize(&dl, &img, err, errlen);
        *rgba = img.rgba;
    }
    pl_draw_list_free(&dl);
    return rc;
}

/* ------------------------------------------------------ fixed ranges across a run */

void pl_render_ranges_apply(pl_render_ranges *r, const pl_render_options *opt,
                            pl_render_options *out) {
    *out = *opt;
    if (!r) return;
    /* what the scene fixed itself is drawn as given; its automatic range is still tracked (it
       is not used) but never reported as having grown */
    r->field_fixed = opt->fluid_max > opt->fluid_min;
    r->color_fixed = opt->color_max > opt->color_min;
    r->vscale_fixed = opt->velocity_scale > 0.0;
    if (r->field_set && !(opt->fluid_max > opt->fluid_min)) {
        out->fluid_min = r->field_lo;
        out->fluid_max = r->field_hi;
    }
    if (r->color_set && !(opt->color_max > opt->color_min)) {
        out->color_min = r->color_lo;
        out->color_max = r->color_hi;
    }
    if (r->vscale_set && !(opt->velocity_scale > 0.0)) out->velocity_scale = r->vscale;
}

void pl_render_ranges_update(pl_render_ranges *r, const pl_draw_list *dl) {
    if (dl->auto_field_set && dl->auto_field_hi > dl->auto_field_lo) {
        if (!r->field_set) {
            r->field_lo = dl->auto_field_lo;
            r->field_hi = dl->auto_field_hi;
            r->field_set = 1;
        } else if (dl->auto_field_lo < r->field_lo || dl->auto_field_hi > r->field_hi) {
            r->field_lo = fmin(r->field_lo, dl->auto_field_lo);
            r->field_hi = fmax(r->field_hi, dl->auto_field_hi);
            r->field_changed = 1;
        }
    }
    if (dl->auto_color_set && dl->auto_color_hi > dl->auto_color_lo) {
        if (!r->color_set) {
            r->color_lo = dl->auto_color_lo;
            r->color_hi = dl->auto_color_hi;
            r->color_set = 1;
        } else if (dl->auto_color_lo < r->color_lo || dl->auto_color_hi > r->color_hi) {
            r->color_lo = fmin(r->color_lo, dl->auto_color_lo);
            r->color_hi = fmax(r->color_hi, dl->auto_color_hi);
            r->color_changed = 1;
        }
    }
    if (dl->auto_vscale > 0.0) {
        if (!r->vscale_set) {
            r->vscale = dl->auto_vscale;
            r->vscale_set = 1;
        } else if (dl->auto_vscale < r->vscale) {
            r->vscale = dl->auto_vscale;
            r->vscale_changed = 1;
        }
    }
    r->frames++;
}

void pl_render_ranges_note(const pl_render_ranges *r, FILE *out) {
    if (!r || !out) return;
    if (r->field_changed && !r->field_fixed)
        fprintf(out, "porelab: note: the fluid colour range grew during the run (it is never "
                     "re-fitted per frame, only widened); for one range from the first frame set "
                     "render.fluid_range = { %.4g, %.4g }\n", r->field_lo, r->field_hi);
    if (r->color_changed && !r->color_fixed)
        fprintf(out, "porelab: note: the body colour range grew during the run; for one range "
                     "from the first frame set render.color_range = { %.4g, %.4g }\n",
                r->color_lo, r->color_hi);
    if (r->vscale_changed && !r->vscale_fixed)
        fprintf(out, "porelab: note: the velocity arrows were shortened during the run to fit "
                     "faster flow; for one scale from the first frame set "
                     "render.velocity_scale = %.4g (m per m/s)\n", r->vscale);
}
