/* The live lab window: SDL2 + the OpenGL backend. One loop: events -> interactions ->
 * stepping -> draw list (scene, then HUD on top) -> GL -> swap. Keys: window_hud.c. */
#include "window.h"

#include <SDL.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "backend_gl.h"
#include "porelab/fluid.h"
#include "render/draw_world.h"
#include "scene_overlay.h"
#include "window_hud.h"
#include "window_picker.h"
#include "window_sim.h"

typedef struct win {
    SDL_Window *sdl;
    SDL_GLContext ctx;
    pl_gl *gl;      /* the window's renderer (PORELAB_WINDOW_SAMPLES, default as headless) */
    pl_gl *gl_shot; /* screenshots: the headless default, created on the first screenshot */
    pl_wsim sim;
    pl_draw_list scene_dl, hud, tmp;
    pl_render_scene rs; /* the world as drawn in the last frame */
    int rs_fluid;       /* rs holds the fluid field */
    int playing, show_help, show_hud, quit;
    long long speed;        /* steps per drawn frame */
    int mx, my, hover, grab, panning, pan_x, pan_y, param_sel, shots;
    char msg[256];
    double msg_until, fps, last_frame;
    pl_image img;
    int mouse_in;       /* the pointer is inside the window */
    /* the control panel at the right edge (outside the scene's area), while the HUD shows */
    int panel_w;
    int nhit;
    struct { pl_px_rect r; int kind, index; } hit[64]; /* clickable controls of the last frame */
    int picking, pick_first; /* the scene picker shows (from entry pick_first) */
    int show_charts;         /* the live charts show (when the scene declares any) */
    int hits_printed;        /* PORELAB_WINDOW_DEBUG: the controls' boxes were printed */
    pl_picker picker;
} win;

enum { HIT_PLAY = 0, HIT_STEP, HIT_RESTART, HIT_REWIND, HIT_LAYER, HIT_SLIDER, HIT_SCENES, HIT_CHARTS,
       HIT_PICK, HIT_PICK_MORE, HIT_PICK_BACK };
static const char *const hit_names[] = {"play", "step", "restart", "rewind", "layer", "slider", "scenes",
                                        "charts", "pick", "more", "back"};
static const unsigned panel_layers[] = {PL_LAYER_BODIES, PL_LAYER_FORCES, PL_LAYER_PRESSURE,
                                        PL_LAYER_ISOLINES, PL_LAYER_VELOCITY, PL_LAYER_OVERLAY};
static const char *const panel_layer_names[] = {"grains and bodies", "force chains", "pressure",
                                                "isolines", "velocity arrows", "scene labels"};

/* Width of the control panel: a quarter of the window, 220..320 px; 0 while the HUD is off. */
static int panel_width(const win *g)
{
    if (!g->show_hud) return 0;
    int w = g->sim.ropt.width / 4;
    return w < 220 ? 220 : w > 320 ? 320 : w;
}

static double now_s(void) { return (double)SDL_GetPerformanceCounter() / (double)SDL_GetPerformanceFrequency(); }

static void message(win *g, const char *fmt, double value)
{
    snprintf(g->msg, sizeof g->msg, fmt, value);
    g->msg_until = now_s() + 2.5;
}

static void *get_proc(const char *name)
{
    return SDL_GL_GetProcAddress(name);
}

static long long frame_interval(const win *g)
{
    long long k = pl_run_plan_frame_step(&g->sim.plan, 1);
    return k > 0 ? k : 1;
}

/* ------------------------------------------------------------------ camera */

/* Switches from the automatic camera to an explicit view rectangle that reproduces the
 * current picture exactly (same centre and scale), so pan and zoom start from it. */
static void manual_view(win *g)
{
    pl_render_options *o = &g->sim.ropt;
    if (!o->auto_camera) return;
    pl_camera cam = g->scene_dl.camera;
    double hw = 0.5 * cam.width / cam.scale, hh = 0.5 * cam.height / cam.scale;
    o->auto_camera = 0;
    o->view_lo = (pl_vec2){cam.center.x - hw, cam.center.y - hh};
    o->view_hi = (pl_vec2){cam.center.x + hw, cam.center.y + hh};
    char err[256];
    if (pl_render_build(g->sim.w, o, &g->tmp, err, sizeof err) == 0 && g->tmp.camera.scale > 0) {
        double f = g->tmp.camera.scale / cam.scale; /* scale ~ 1 / extent */
        o->view_lo = (pl_vec2){cam.center.x - hw * f, cam.center.y - hh * f};
        o->view_hi = (pl_vec2){cam.center.x + hw * f, cam.center.y + hh * f};
    }
}

static void zoom_at(win *g, int px, int py, double factor)
{
    manual_view(g);
    pl_render_options *o = &g->sim.ropt;
    pl_vec2 p = pl_camera_to_world(&g->scene_dl.camera, (pl_vec2){px, py});
    o->view_lo = (pl_vec2){p.x + (o->view_lo.x - p.x) * factor, p.y + (o->view_lo.y - p.y) * factor};
    o->view_hi = (pl_vec2){p.x + (o->view_hi.x - p.x) * factor, p.y + (o->view_hi.y - p.y) * factor};
}

static void pan_by(win *g, int dx, int dy)
{
    manual_view(g);
    pl_render_options *o = &g->sim.ropt;
    double s = g->scene_dl.camera.scale;
    double wx = -dx / s, wy = dy / s;
    o->view_lo.x += wx; o->view_hi.x += wx;
    o->view_lo.y += wy; o->view_hi.y += wy;
}

/* ------------------------------------------------------------------ picking */

static int body_at(win *g, pl_vec2 p)
{
    const pl_render_scene *s = &g->rs;
    double tol = 3.0 / g->scene_dl.camera.scale;
    for (int i = s->body_count - 1; i >= 0; i--) {
        const pl_body_info *b = &s->bodies[i];
        const pl_vec2 *v = s->verts + s->vert_first[i];
        int nv = s->vert_first[i + 1] - s->vert_first[i];
        double dx = p.x - b->position.x, dy = p.y - b->position.y;
        if (b->shape == PL_SHAPE_DISC) {
            if (dx * dx + dy * dy <= b->radius * b->radius) return i;
        } else if (b->shape == PL_SHAPE_POLYGON && nv >= 3) {
            int in = 1;
            for (int k = 0; k < nv && in; k++) {
                pl_vec2 a = v[k], c = v[(k + 1) % nv];
                if ((c.x - a.x) * (p.y - a.y) - (c.y - a.y) * (p.x - a.x) < 0) in = 0;
            }
            if (in) return i;
        } else if (b->shape == PL_SHAPE_SEGMENT && nv >= 2) {
            double ex = v[1].x - v[0].x, ey = v[1].y - v[0].y, l2 = ex * ex + ey * ey;
            double t = l2 > 0 ? ((p.x - v[0].x) * ex + (p.y - v[0].y) * ey) / l2 : 0;
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            double qx = v[0].x + t * ex - p.x, qy = v[0].y + t * ey - p.y;
            if (qx * qx + qy * qy <= tol * tol) return i;
        }
    }
    return -1;
}

/* Darcy velocity and porosity of the fluid element under p (0 when outside the mesh). */
static int fluid_element_at(win *g, pl_vec2 p, pl_vec2 *vel, double *porosity)
{
    const pl_render_scene *s = &g->rs;
    for (int t = 0; t < s->fluid_tri_count; t++) {
        const int *k = s->fluid_tris + 3 * t;
        pl_vec2 a = s->fluid_nodes[k[0]], b = s->fluid_nodes[k[1]], c = s->fluid_nodes[k[2]];
        double d1 = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        double d2 = (c.x - b.x) * (p.y - b.y) - (c.y - b.y) * (p.x - b.x);
        double d3 = (a.x - c.x) * (p.y - c.y) - (a.y - c.y) * (p.x - c.x);
        if ((d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0)) {
            *vel = s->fluid_velocity ? s->fluid_velocity[t] : (pl_vec2){0, 0};
            *porosity = NAN;
            int n = pl_world_fluid_triangle_count(g->sim.w);
            if (n > t) {
                double *por = malloc((size_t)n * sizeof *por);
                if (por && pl_world_fluid_copy_element_field(g->sim.w, PL_FLUID_POROSITY, por, n) > t)
                    *porosity = por[t];
                free(por);
            }
            return 1;
        }
    }
    return 0;
}

/* ------------------------------------------------------------------ drawing */

static int build_scene(win *g)
{
    char err[900];
    g->panel_w = panel_width(g);
    g->sim.ropt.reserve_right = g->panel_w;
    int present = pl_scene_overlay(g->sim.s, &g->sim.overlay);
    g->sim.ropt.overlay = present > 0 ? &g->sim.overlay : NULL;
    if (present < 0) snprintf(g->sim.error, sizeof g->sim.error, "%s", pl_scene_error(g->sim.s));
    /* what pl_render_build does, into the window's own scene copy: it keeps its buffers
     * between frames (a fresh copy per frame costs page faults on every frame) and serves
     * hovering and picking too */
    const unsigned fluid_layers = PL_LAYER_MESH | PL_LAYER_PRESSURE | PL_LAYER_ISOLINES |
                                  PL_LAYER_VELOCITY;
    if ((g->sim.ropt.layers & fluid_layers) && pl_world_prepare(g->sim.w) != PL_OK)
        snprintf(g->sim.error, sizeof g->sim.error, "%s", pl_world_last_error(g->sim.w));
    int rc = pl_render_scene_capture(&g->rs, g->sim.w);
    g->rs_fluid = 0;
    if (rc == 0 && (g->sim.ropt.layers & fluid_layers)) {
        rc = pl_render_scene_capture_fluid_opt(&g->rs, g->sim.w, &g->sim.ropt);
        g->rs_fluid = 1;
    }
    if (rc != 0) snprintf(err, sizeof err, "out of memory while reading the world");
    else rc = pl_render_build_scene(&g->scene_dl, &g->rs, &g->sim.ropt, err, sizeof err);
    if (rc != 0) {
        snprintf(g->sim.error, sizeof g->sim.error, "render: %s", err);
        return -1;
    }
    return 0;
}

static const char *coloring_name(int c)
{
    return c == PL_COLOR_BY_SPEED ? "speed" : c == PL_COLOR_BY_STRESS ? "stress" : "material";
}

static double measure(void *ud, const char *s, float size)
{
    return pl_gl_text_width((pl_gl *)ud, s, size);
}

/* A value with about four significant digits and its unit scaled (Pa -> kPa -> MPa). */
static void fmt_pa(char *out, size_t n, double v)
{
    double a = fabs(v);
    if (a < 0.05) snprintf(out, n, "0 Pa");
    else if (a < 1e3) snprintf(out, n, "%.1f Pa", v);
    else if (a < 1e6) snprintf(out, n, "%.3g kPa", v / 1e3);
    else snprintf(out, n, "%.4g MPa", v / 1e6);
}

static void fmt_speed(char *out, size_t n, double v)
{
    double a = fabs(v);
    if (a < 1e-4) snprintf(out, n, "0 m/s (at rest)");
    else if (a < 0.1) snprintf(out, n, "%.1f mm/s", v * 1e3);
    else snprintf(out, n, "%.3g m/s", v);
}

typedef struct panel_ctx {
    win *g;
    pl_draw_list *h;
    double x0, x1, y;
    float fs;
    pl_rgba ink;
} panel_ctx;

static void add_hit(win *g, pl_px_rect r, int kind, int index)
{
    if (g->nhit >= (int)(sizeof g->hit / sizeof g->hit[0])) return;
    g->hit[g->nhit].r = r;
    g->hit[g->nhit].kind = kind;
    g->hit[g->nhit].index = index;
    g->nhit++;
}

static void panel_text(panel_ctx *c, const char *text, float size, pl_rgba ink)
{
    pl_dl_text(c->h, PL_SPACE_PIXEL, (pl_vec2){c->x0, c->y + 0.5 * 1.3 * size}, text, size,
               PL_ANCHOR_LEFT | PL_ANCHOR_MIDDLE, 0.0f, ink, NULL);
    c->y += 1.3 * size;
}

static void panel_heading(panel_ctx *c, const char *text)
{
    c->y += 0.4 * c->fs;
    panel_text(c, text, c->fs, pl_rgb(0.65, 0.78, 1.0));
}

static void panel_button_i(panel_ctx *c, double x, double w, const char *label, int kind, int index, int on)
{
    pl_px_rect r = {x, c->y, x + w, c->y + 1.7 * c->fs};
    pl_vec2 box[4] = {{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}};
    pl_style st = pl_style_fill_stroke(on ? pl_rgb(0.25, 0.42, 0.70) : pl_rgb(0.22, 0.22, 0.26),
                                       pl_rgb(0.55, 0.55, 0.6), 1.0f);
    pl_dl_polygon(c->h, PL_SPACE_PIXEL, box, 4, &st);
    pl_dl_text(c->h, PL_SPACE_PIXEL, (pl_vec2){0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1)}, label,
               c->fs, PL_ANCHOR_CENTER | PL_ANCHOR_MIDDLE, 0.0f, c->ink, NULL);
    add_hit(c->g, r, kind, index);
}

static void panel_button(panel_ctx *c, double x, double w, const char *label, int kind, int on)
{
    panel_button_i(c, x, w, label, kind, 0, on);
}

/* Text cut to the panel's width (with an ellipsis); returns the bytes used of s. */
static size_t fit_text(win *g, const char *s, double width, float size, char *out, size_t n)
{
    size_t len = strlen(s), best = len;
    if (measure(g->gl, s, size) > width) {
        /* the longest prefix ending at a space that fits (with "…") */
        best = 0;
        for (size_t k = 1; k < len && k < n - 4; k++)
            if (s[k] == ' ') {
                char t[512];
                snprintf(t, sizeof t, "%.*s…", (int)k, s);
                if (measure(g->gl, t, size) <= width) best = k;
                else break;
            }
        if (best == 0) best = len < 20 ? len : 20;
    }
    snprintf(out, n, "%.*s", (int)best, s);
    return best;
}

/* The scene picker: the shipped scenes, two lines each (name, description), in pages. */
static void build_picker(win *g, panel_ctx *c, double H)
{
    char l[512];
    panel_heading(c, "choose a scene (click one)");
    if (g->picker.n == 0) {
        panel_text(c, "no scenes folder found", c->fs, c->ink);
        panel_text(c, "(set PORELAB_SCENES)", 11.0f, c->ink);
    }
    double bw = (c->x1 - c->x0 - 6.0) / 2.0;
    double bottom = H - 1.7 * c->fs - 12.0;
    int k = g->pick_first;
    if (k >= g->picker.n) k = g->pick_first = 0;
    for (; k < g->picker.n && c->y + 2.6 * c->fs < bottom; k++) {
        const pl_picker_entry *e = &g->picker.e[k];
        int current = strcmp(e->path, g->sim.path) == 0;
        double y0 = c->y;
        panel_text(c, e->name, c->fs, current ? pl_rgb(1.0, 0.85, 0.45) : c->ink);
        /* the description on up to two lines */
        const char *d = e->desc;
        for (int line = 0; line < 2 && *d; line++) {
            size_t used = fit_text(g, d, c->x1 - c->x0 - 8.0, 10.5f, l, sizeof l);
            if (line == 1 && used < strlen(d)) strncat(l, "…", sizeof l - strlen(l) - 1);
            double save = c->x0;
            c->x0 += 8.0;
            panel_text(c, l, 10.5f, pl_rgb(0.75, 0.75, 0.72));
            c->x0 = save;
            d += used;
            while (*d == ' ') d++;
        }
        add_hit(g, (pl_px_rect){c->x0 - 4, y0, c->x1, c->y}, HIT_PICK, k);
        c->y += 3.0;
    }
    c->y = bottom;
    panel_button(c, c->x0, bw, "back", HIT_PICK_BACK, 0);
    if (g->picker.n > 0) panel_button(c, c->x0 + bw + 6.0, bw, k < g->picker.n ? "more" : "first page", HIT_PICK_MORE, 0);
    if (g->picker.n > 0) g->hit[g->nhit - 1].index = k < g->picker.n ? k : 0;
}

/* The live charts from c->y down to H (each at most 190 px high; none below 90 px each
 * unless `all`, the charts view, which gives them the whole rest). */
static void draw_charts(win *g, panel_ctx *c, double H, int all)
{
    const pl_live *lv = &g->sim.live;
    if (lv->ncharts <= 0) return;
    double room = H - c->y - 8.0, ch = room / lv->ncharts;
    if (ch > 190.0 && !all) ch = 190.0;
    if (ch > 260.0) ch = 260.0;
    if (ch < (all ? 60.0 : 90.0)) return;
    double y0 = all ? c->y + 6.0 : H - lv->ncharts * ch;
    for (int k = 0; k < lv->ncharts; k++)
        pl_live_draw(lv, k, c->h, c->x0, y0 + k * ch + 4.0, c->x1, y0 + (k + 1) * ch - 6.0, measure, g->gl);
    c->y = y0 + lv->ncharts * ch;
}

/* PORELAB_WINDOW_DEBUG: the controls' boxes once per layout change, for tests that click. */
static void print_hits(win *g)
{
    if (!getenv("PORELAB_WINDOW_DEBUG")) return;
    int sig = g->nhit * 131 + g->picking * 7 + g->pick_first * 1009 + g->show_charts;
    if (g->hits_printed == sig + 1) return;
    g->hits_printed = sig + 1;
    for (int i = 0; i < g->nhit; i++)
        printf("control: %s %d %.0f %.0f %.0f %.0f%s%s\n", hit_names[g->hit[i].kind], g->hit[i].index,
               g->hit[i].r.x0, g->hit[i].r.y0, g->hit[i].r.x1, g->hit[i].r.y1, g->hit[i].kind == HIT_PICK ? " " : "",
               g->hit[i].kind == HIT_PICK ? g->picker.e[g->hit[i].index].name : "");
    printf("controls: %d\n", g->nhit);
    fflush(stdout);
}

static void build_hud(win *g)
{
    pl_draw_list *h = &g->hud;
    pl_draw_list_clear(h);
    h->camera = g->scene_dl.camera;
    g->nhit = 0;
    float fs = 13.0f;
    pl_rgba ink = pl_rgb(0.95, 0.95, 0.92);
    if (g->grab >= 0 && g->grab < g->rs.body_count) { /* the spring */
        pl_vec2 a = pl_camera_to_px(&h->camera, g->rs.bodies[g->grab].position);
        pl_dl_line(h, PL_SPACE_PIXEL, a, (pl_vec2){g->mx, g->my}, pl_rgb_hex(0xE08020), 2.0f);
    }
    if (!g->show_hud || g->panel_w <= 0) return;
    double W = h->camera.width, H = h->camera.height, P = g->panel_w;
    /* the panel: a dark strip right of the scene's area; nothing of the HUD is drawn left of
     * W - P (checked by tests/gl/test_window_xvfb.sh) */
    pl_vec2 strip[4] = {{W - P, 0}, {W, 0}, {W, H}, {W - P, H}};
    pl_style bg = pl_style_fill(pl_rgb(0.12, 0.12, 0.14));
    pl_dl_polygon(h, PL_SPACE_PIXEL, strip, 4, &bg);
    panel_ctx c = {g, h, W - P + 10.0, W - 10.0, 8.0, fs, ink};
    double bw = (c.x1 - c.x0 - 6.0) / 2.0;
    char l[256];
    pl_world *w = g->sim.w;

    /* transport */
    panel_button(&c, c.x0, bw, g->playing ? "pause" : "play", HIT_PLAY, g->playing);
    panel_button(&c, c.x0 + bw + 6.0, bw, "one step", HIT_STEP, 0);
    c.y += 1.7 * fs + 5.0;
    panel_button(&c, c.x0, bw, "restart", HIT_RESTART, 0);
    panel_button(&c, c.x0 + bw + 6.0, bw, "rewind", HIT_REWIND, 0);
    c.y += 1.7 * fs + 5.0;
    /* longer jumps back, so that a replay of an event seconds ago needs no keyboard */
    panel_button_i(&c, c.x0, bw, "back 1 s", HIT_REWIND, 1, 0);
    panel_button_i(&c, c.x0 + bw + 6.0, bw, "back to start", HIT_REWIND, 2, 0);
    c.y += 1.7 * fs + 5.0;
    panel_button(&c, c.x0, bw, "scenes", HIT_SCENES, g->picking);
    panel_button(&c, c.x0 + bw + 6.0, bw, "charts", HIT_CHARTS, g->show_charts && g->sim.live.ncharts > 0);
    c.y += 1.7 * fs + 6.0;
    if (g->picking) {
        build_picker(g, &c, H);
        print_hits(g);
        return;
    }
    snprintf(l, sizeof l, "t = %.3f s   %s%s%s", pl_world_time(w),
             g->sim.stopped ? "stopped" : g->playing ? "playing" : "paused",
             g->sim.ropt.coloring == PL_COLOR_BY_MATERIAL ? "" : "   by ",
             g->sim.ropt.coloring == PL_COLOR_BY_MATERIAL ? "" : coloring_name(g->sim.ropt.coloring));
    panel_text(&c, l, fs, ink);

    if (g->show_help) {
        panel_heading(&c, "keys (h hides)");
        for (int i = 0; i < pl_hud_help_count; i++) { /* one entry per line */
            const char *p = pl_hud_help[i];
            while (*p) {
                while (*p == ' ') p++;
                const char *q = strstr(p, "  ");
                size_t len = q ? (size_t)(q - p) : strlen(p);
                if (len > 0 && c.y < H - 2 * fs) {
                    snprintf(l, sizeof l, "%.*s", (int)len, p);
                    panel_text(&c, l, 11.0f, ink);
                }
                p += len;
            }
        }
        return;
    }

    const pl_live *lv = &g->sim.live;
    if (g->show_charts && lv->ncharts > 0) { /* the charts instead of the controls below */
        draw_charts(g, &c, H, 1);
        print_hits(g);
        return;
    }

    /* layers */
    panel_heading(&c, "show");
    for (int i = 0; i < (int)(sizeof panel_layers / sizeof panel_layers[0]); i++) {
        int on = (g->sim.ropt.layers & panel_layers[i]) != 0;
        pl_px_rect r = {c.x0, c.y + 2.0, c.x0 + fs, c.y + 2.0 + fs};
        pl_vec2 box[4] = {{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}};
        pl_style st = on ? pl_style_fill_stroke(pl_rgb(0.35, 0.6, 0.95), ink, 1.0f)
                         : pl_style_stroke(ink, 1.0f);
        pl_dl_polygon(h, PL_SPACE_PIXEL, box, 4, &st);
        pl_dl_text(h, PL_SPACE_PIXEL, (pl_vec2){c.x0 + 1.6 * fs, c.y + 0.65 * 1.3 * fs},
                   panel_layer_names[i], fs, PL_ANCHOR_LEFT | PL_ANCHOR_MIDDLE, 0.0f, ink, NULL);
        add_hit(g, (pl_px_rect){c.x0, c.y, c.x1, c.y + 1.3 * fs}, HIT_LAYER, i);
        c.y += 1.45 * fs;
    }

    /* parameters: sliders */
    if (g->sim.nparams > 0) panel_heading(&c, "parameters (drag or click)");
    for (int i = 0; i < g->sim.nparams && c.y < H - 12 * fs; i++) {
        const pl_wparam *q = &g->sim.params[i];
        snprintf(l, sizeof l, "%s: %.4g %s", q->name, q->value, q->unit);
        panel_text(&c, l, fs, i == g->param_sel ? pl_rgb(1.0, 0.85, 0.45) : ink);
        double y = c.y + 0.5 * fs, f = q->max > q->min ? (q->value - q->min) / (q->max - q->min) : 0.0;
        f = f < 0 ? 0 : f > 1 ? 1 : f;
        pl_dl_line(h, PL_SPACE_PIXEL, (pl_vec2){c.x0, y}, (pl_vec2){c.x1, y}, pl_rgb(0.5, 0.5, 0.55), 3.0f);
        pl_style knob = pl_style_fill(pl_rgb(1.0, 0.85, 0.45));
        pl_dl_circle(h, PL_SPACE_PIXEL, (pl_vec2){c.x0 + f * (c.x1 - c.x0), y}, 0.45 * fs, &knob);
        add_hit(g, (pl_px_rect){c.x0, y - 0.6 * fs, c.x1, y + 0.6 * fs}, HIT_SLIDER, i);
        c.y += 1.3 * fs;
    }

    /* materials of the moving bodies: colour, name, density */
    panel_heading(&c, "materials");
    for (int m = 0; m < g->rs.material_count && c.y < H - 8 * fs; m++) {
        int used = 0;
        for (int i = 0; i < g->rs.body_count && !used; i++)
            used = g->rs.bodies[i].material == m && g->rs.bodies[i].motion == PL_MOTION_DYNAMIC &&
                   g->rs.bodies[i].shape != PL_SHAPE_SEGMENT;
        if (!used) continue;
        pl_rgba col = g->sim.ropt.material_color_count > 0
                          ? g->sim.ropt.material_colors[m % g->sim.ropt.material_color_count]
                          : pl_material_palette(m);
        col.a = 1.0f;
        pl_style st = pl_style_fill_stroke(col, ink, 1.0f);
        pl_dl_circle(h, PL_SPACE_PIXEL, (pl_vec2){c.x0 + 0.5 * fs, c.y + 0.65 * fs}, 0.45 * fs, &st);
        pl_material_def md = pl_world_material(w, m);
        snprintf(l, sizeof l, "%s, %.0f kg/m\u00B3", g->rs.material_names[m], md.density);
        pl_dl_text(h, PL_SPACE_PIXEL, (pl_vec2){c.x0 + 1.4 * fs, c.y + 0.65 * fs}, l, fs,
                   PL_ANCHOR_LEFT | PL_ANCHOR_MIDDLE, 0.0f, ink, NULL);
        c.y += 1.35 * fs;
    }

    /* values under the cursor, only where they mean something */
    if (g->mouse_in && g->mx < W - P) {
        panel_heading(&c, "under the cursor");
        char v1[64];
        pl_vec2 p = pl_camera_to_world(&h->camera, (pl_vec2){g->mx, g->my});
        snprintf(l, sizeof l, "x = %.1f mm, y = %.1f mm", 1e3 * p.x, 1e3 * p.y);
        panel_text(&c, l, fs, ink);
        if (g->hover >= 0 && g->hover < g->rs.body_count) {
            const pl_body_info *b = &g->rs.bodies[g->hover];
            const char *mot = b->motion == PL_MOTION_DYNAMIC ? "" : b->motion == PL_MOTION_FIXED ? ", fixed" : ", driven";
            snprintf(l, sizeof l, "%s%s", b->material < g->rs.material_count ? g->rs.material_names[b->material] : "body", mot);
            panel_text(&c, l, fs, ink);
            if (b->motion == PL_MOTION_DYNAMIC) {
                fmt_speed(v1, sizeof v1, hypot(b->velocity.x, b->velocity.y));
                snprintf(l, sizeof l, "speed %s", v1);
                panel_text(&c, l, fs, ink);
                if (b->area > 0) {
                    snprintf(l, sizeof l, "mass %.3g kg per m, density %.0f kg/m\u00B3", b->mass, b->mass / b->area);
                    panel_text(&c, l, 11.0f, ink);
                }
                if (g->rs.stress && fabs(g->rs.stress[g->hover]) > 0.05) {
                    fmt_pa(v1, sizeof v1, g->rs.stress[g->hover]);
                    snprintf(l, sizeof l, "mean stress %s", v1);
                    panel_text(&c, l, fs, ink);
                }
            }
        } else if (pl_world_fluid_node_count(w) > 0) {
            double pr = 0, head = NAN;
            if (pl_world_fluid_pressure_at(w, p, &pr, &head)) {
                fmt_pa(v1, sizeof v1, pr);
                snprintf(l, sizeof l, "water pressure %s", v1);
                panel_text(&c, l, fs, ink);
                pl_vec2 v;
                double por;
                if (fluid_element_at(g, p, &v, &por)) {
                    fmt_speed(v1, sizeof v1, hypot(v.x, v.y));
                    snprintf(l, sizeof l, "Darcy velocity %s", v1);
                    panel_text(&c, l, fs, ink);
                    if (por < 0.99) { /* among grains only */
                        snprintf(l, sizeof l, "porosity %.2f", por);
                        panel_text(&c, l, fs, ink);
                    }
                }
            }
        } else if (g->rs.fluid_tri_count > 0 && g->rs.fluid_field == PL_FLUID_PRESSURE) {
            const pl_render_scene *s = &g->rs;
            for (int t = 0; t < s->fluid_tri_count; t++) {
                const int *k = s->fluid_tris + 3 * t;
                const pl_vec2 a = s->fluid_nodes[k[0]], b = s->fluid_nodes[k[1]], cc = s->fluid_nodes[k[2]];
                const double det = (b.x - a.x) * (cc.y - a.y) - (cc.x - a.x) * (b.y - a.y);
                if (det == 0) continue;
                const double l1 = ((p.x - a.x) * (cc.y - a.y) - (cc.x - a.x) * (p.y - a.y)) / det;
                const double l2 = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / det;
                if (l1 < -1e-9 || l2 < -1e-9 || l1 + l2 > 1 + 1e-9) continue;
                const double pr = (1 - l1 - l2) * s->fluid_values[k[0]] + l1 * s->fluid_values[k[1]] +
                                  l2 * s->fluid_values[k[2]];
                fmt_pa(v1, sizeof v1, pr);
                snprintf(l, sizeof l, "water pressure %s", v1);
                panel_text(&c, l, fs, ink);
                break;
            }
        }
    }

    /* messages and errors, wrapped to the panel */
    const char *texts[2] = {g->msg[0] && now_s() < g->msg_until ? g->msg : "", g->sim.error};
    for (int k = 0; k < 2; k++) {
        const char *p = texts[k];
        size_t len = strlen(p), per = (size_t)((c.x1 - c.x0) / (0.55 * 11.0));
        if (per < 10) per = 10;
        for (size_t off = 0; off < len && c.y < H - 1.5 * fs; off += per) {
            snprintf(l, sizeof l, "%.*s", (int)(per < 200 ? per : 200), p + off);
            panel_text(&c, l, 11.0f, k ? pl_rgb_hex(0xFF8080) : pl_rgb(1.0, 0.85, 0.45));
        }
    }
    draw_charts(g, &c, H, 0); /* in the room left, if there is enough */
    print_hits(g);
}

static void screenshot(win *g)
{
    char err[900], path[PATH_MAX + 64];
    /* a renderer with the headless settings, so the file equals `--renderer gl` whatever
     * sample count the window itself uses */
    if (!g->gl_shot) g->gl_shot = pl_gl_create(get_proc, 0, err, sizeof err);
    if (!g->gl_shot || build_scene(g) != 0 ||
        pl_gl_render(g->gl_shot, &g->scene_dl, err, sizeof err) != 0 ||
        pl_gl_read(g->gl_shot, &g->img, err, sizeof err) != 0) {
        message(g, "screenshot failed", 0);
        return;
    }
    snprintf(path, sizeof path, "%s/screenshot_%03d.png", g->sim.out_dir, g->shots++);
    char mk[PATH_MAX + 16];
    snprintf(mk, sizeof mk, "%s", g->sim.out_dir);
    for (char *c = mk + 1; *c; c++)
        if (*c == '/') { *c = 0; mkdir(mk, 0777); *c = '/'; }
    mkdir(mk, 0777);
    if (pl_png_write(path, &g->img, 6, 1, err, sizeof err) != 0) {
        snprintf(g->sim.error, sizeof g->sim.error, "screenshot: %s", err);
        return;
    }
    const pl_camera *c = &g->scene_dl.camera;
    printf("screenshot: %s (t = %.9g s, step %lld, state-hash %016llx)\n", path,
           pl_world_time(g->sim.w), pl_wsim_steps(&g->sim),
           (unsigned long long)pl_world_state_hash(g->sim.w));
    /* the view, so that pixels can be mapped to the world: x_px = (x - cx) s + px, y_px =
     * py - (y - cy) s */
    if (getenv("PORELAB_WINDOW_DEBUG")) /* for tests that click into the scene */
        printf("camera: scale %.9g center %.9g %.9g px_center %.9g %.9g\n", c->scale, c->center.x,
               c->center.y, c->px_center.x, c->px_center.y);
    fflush(stdout);
    snprintf(g->msg, sizeof g->msg, "wrote %.200s", path);
    g->msg_until = now_s() + 2.5;
}

/* ------------------------------------------------------------------ input */

static void toggle_layer(win *g, unsigned bits, const char *name)
{
    g->sim.ropt.layers ^= bits;
    snprintf(g->msg, sizeof g->msg, "%s %s", name, (g->sim.ropt.layers & bits) ? "on" : "off");
    g->msg_until = now_s() + 2.0;
}

static void rewind_to(win *g, long long step)
{
    double t0 = now_s();
    if (pl_wsim_rewind(&g->sim, step) == 0) {
        message(g, "rewound (%.2f s)", now_s() - t0);
        char from[64] = "the start";
        if (g->sim.last_rewind_from >= 0)
            snprintf(from, sizeof from, "the snapshot at step %lld", g->sim.last_rewind_from);
        printf("rewind: step %lld (t = %.9g s), replayed from %s in %.3f s\n",
               pl_wsim_steps(&g->sim), pl_world_time(g->sim.w), from, now_s() - t0);
        fflush(stdout);
    }
    g->playing = 0;
    g->grab = -1;
}

static void color_range(win *g, double f)
{
    pl_render_options *o = &g->sim.ropt;
    if (o->coloring == PL_COLOR_BY_MATERIAL) {
        /* the range keys then act on the fluid field */
        if (!(o->fluid_max > o->fluid_min)) {
            double lo = INFINITY, hi = -INFINITY;
            for (int i = 0; i < g->rs.fluid_node_count; i++) {
                lo = fmin(lo, g->rs.fluid_values[i]);
                hi = fmax(hi, g->rs.fluid_values[i]);
            }
            if (!(hi > lo)) return;
            o->fluid_min = lo;
            o->fluid_max = hi;
        }
        double c = 0.5 * (o->fluid_min + o->fluid_max), h = 0.5 * (o->fluid_max - o->fluid_min) * f;
        o->fluid_min = c - h;
        o->fluid_max = c + h;
        return;
    }
    if (!(o->color_max > o->color_min)) {
        double hi = 0;
        for (int i = 0; i < g->rs.body_count; i++) {
            const pl_body_info *b = &g->rs.bodies[i];
            double v = o->coloring == PL_COLOR_BY_SPEED ? hypot(b->velocity.x, b->velocity.y)
                                                       : (g->rs.stress ? fabs(g->rs.stress[i]) : 0);
            if (b->motion == PL_MOTION_DYNAMIC && v > hi) hi = v;
        }
        if (!(hi > 0)) return;
        o->color_min = 0;
        o->color_max = hi;
    }
    o->color_max *= f;
}

static void spring(win *g);

static void key(win *g, SDL_Keycode k, Uint16 mod)
{
    pl_render_options *o = &g->sim.ropt;
    long long steps = pl_wsim_steps(&g->sim);
    int shift = (mod & KMOD_SHIFT) != 0;
    switch (k) {
    case SDLK_ESCAPE: case SDLK_q: g->quit = 1; break;
    case SDLK_SPACE: g->playing = !g->playing; break;
    case SDLK_s: spring(g); pl_wsim_advance(&g->sim, frame_interval(g)); g->playing = 0; break;
    case SDLK_PERIOD: spring(g); pl_wsim_advance(&g->sim, 1); g->playing = 0; break;
    case SDLK_PLUS: case SDLK_EQUALS: case SDLK_KP_PLUS:
    case SDLK_MINUS: case SDLK_KP_MINUS:
        if ((k == SDLK_MINUS || k == SDLK_KP_MINUS) ? g->speed > 1 : g->speed < (1LL << 40))
            g->speed = (k == SDLK_MINUS || k == SDLK_KP_MINUS) ? g->speed / 2 : g->speed * 2;
        message(g, "%.0f steps per frame", (double)g->speed);
        printf("speed: %lld steps per frame\n", g->speed);
        fflush(stdout);
        break;
    case SDLK_r:
        if (pl_wsim_load(&g->sim, !shift) == 0) message(g, shift ? "restarted with the scene's values" : "restarted", 0);
        g->grab = -1; /* a playing lab keeps playing from the start */
        break;
    case SDLK_LEFT: case SDLK_BACKSPACE: rewind_to(g, steps - frame_interval(g)); break;
    case SDLK_PAGEDOWN: rewind_to(g, steps - (long long)llround(1.0 / pl_world_dt(g->sim.w))); break;
    case SDLK_HOME: rewind_to(g, 0); break;
    case SDLK_1: toggle_layer(g, PL_LAYER_BODIES, "bodies"); break;
    case SDLK_2: toggle_layer(g, PL_LAYER_FORCES, "force chains"); break;
    case SDLK_3: toggle_layer(g, PL_LAYER_PRESSURE, "pressure"); break;
    case SDLK_4: toggle_layer(g, PL_LAYER_ISOLINES, "isolines"); break;
    case SDLK_5: toggle_layer(g, PL_LAYER_VELOCITY, "velocity"); break;
    case SDLK_6: toggle_layer(g, PL_LAYER_MESH, "mesh"); break;
    case SDLK_7: toggle_layer(g, PL_LAYER_TIME | PL_LAYER_TITLE | PL_LAYER_COLORBAR | PL_LAYER_SCALEBAR, "labels"); break;
    case SDLK_8: toggle_layer(g, PL_LAYER_TANGENTIAL, "tangential forces"); break;
    case SDLK_9: toggle_layer(g, PL_LAYER_OVERLAY, "scene overlay"); break;
    case SDLK_c: o->coloring = (pl_body_coloring)((o->coloring + 1) % 3); o->color_min = o->color_max = 0; break;
    case SDLK_f:
        o->fluid_field = o->fluid_field == PL_FLUID_PRESSURE ? PL_FLUID_EXCESS_PRESSURE
                       : o->fluid_field == PL_FLUID_EXCESS_PRESSURE ? PL_FLUID_HEAD : PL_FLUID_PRESSURE;
        o->fluid_min = o->fluid_max = 0;
        message(g, o->fluid_field == PL_FLUID_PRESSURE ? "field: pore pressure"
                 : o->fluid_field == PL_FLUID_EXCESS_PRESSURE ? "field: excess pore pressure" : "field: total head", 0);
        break;
    case SDLK_a: o->color_min = o->color_max = 0; o->fluid_min = o->fluid_max = 0; message(g, "automatic colour range", 0); break;
    case SDLK_LEFTBRACKET: color_range(g, 1.0 / 1.5); break;
    case SDLK_RIGHTBRACKET: color_range(g, 1.5); break;
    case SDLK_z: /* the scene's own view */
        o->auto_camera = g->sim.scene_auto_camera;
        o->view_lo = g->sim.scene_view_lo;
        o->view_hi = g->sim.scene_view_hi;
        break;
    case SDLK_TAB: if (g->sim.nparams > 0) g->param_sel = (g->param_sel + 1) % g->sim.nparams; break;
    case SDLK_UP: case SDLK_DOWN:
        if (g->sim.nparams > 0) {
            pl_wparam *q = &g->sim.params[g->param_sel];
            pl_wsim_set_param(&g->sim, g->param_sel, q->value + (k == SDLK_UP ? q->step : -q->step));
        }
        break;
    case SDLK_p: case SDLK_F12: screenshot(g); break;
    case SDLK_h: case SDLK_F1: g->show_help = !g->show_help; break;
    case SDLK_i: g->show_hud = !g->show_hud; break;
    case SDLK_x:
        if (g->hover >= 0 && g->rs.bodies[g->hover].shape != PL_SHAPE_SEGMENT)
            pl_wsim_set_motion(&g->sim, g->hover, g->rs.bodies[g->hover].motion == PL_MOTION_FIXED
                                                       ? PL_MOTION_DYNAMIC : PL_MOTION_FIXED);
        break;
    default: break;
    }
}

static void release_grab(win *g)
{
    if (g->grab >= 0) pl_wsim_set_load(&g->sim, g->grab, (pl_vec2){0, 0});
    g->grab = -1;
}

/* Mouse positions come in window points; the picture is in drawable pixels (they differ on
 * high-DPI displays). */
static void to_px(win *g, int x, int y, int *px, int *py)
{
    int ww, wh, dw, dh;
    SDL_GetWindowSize(g->sdl, &ww, &wh);
    SDL_GL_GetDrawableSize(g->sdl, &dw, &dh);
    *px = ww > 0 ? (int)((long)x * dw / ww) : x;
    *py = wh > 0 ? (int)((long)y * dh / wh) : y;
}

/* Opens another scene (the picker): on failure the current one stays, with the message. */
static void open_scene(win *g, const char *path)
{
    char old[PATH_MAX];
    snprintf(old, sizeof old, "%s", g->sim.path);
    snprintf(g->sim.path, sizeof g->sim.path, "%s", path);
    /* a fresh view for the new scene: its own size-independent camera and layers */
    pl_render_options keep = g->sim.ropt;
    if (pl_wsim_load(&g->sim, 0) != 0) {
        snprintf(g->sim.path, sizeof g->sim.path, "%s", old);
        printf("open: failed, the previous scene stays: %s\n", g->sim.error);
        fflush(stdout);
        return;
    }
    g->sim.ropt.layers = g->sim.scene_layers;
    g->sim.ropt.coloring = (pl_body_coloring)g->sim.scene_coloring;
    g->sim.ropt.fluid_field = g->sim.scene_fluid_field;
    g->sim.ropt.auto_camera = g->sim.scene_auto_camera;
    g->sim.ropt.view_lo = g->sim.scene_view_lo;
    g->sim.ropt.view_hi = g->sim.scene_view_hi;
    g->sim.ropt.color_min = g->sim.ropt.color_max = 0;
    g->sim.ropt.width = keep.width;
    g->sim.ropt.height = keep.height;
    g->picking = 0;
    g->grab = -1;
    g->param_sel = 0;
    g->show_charts = g->sim.live.ncharts > 0;
    char title[PATH_MAX + 32];
    snprintf(title, sizeof title, "porelab - %.*s", PATH_MAX, g->sim.path);
    SDL_SetWindowTitle(g->sdl, title);
    message(g, "opened the scene", 0);
    printf("open: %s\n", g->sim.path);
    fflush(stdout);
}

/* A click on the control panel; 1 when it hit a control (or the panel). */
static int panel_click(win *g, int x, int y, int drag)
{
    if (g->panel_w <= 0 || x < g->sim.ropt.width - g->panel_w) return 0;
    for (int i = 0; i < g->nhit; i++) {
        const pl_px_rect r = g->hit[i].r;
        if (x < r.x0 || x > r.x1 || y < r.y0 || y > r.y1) continue;
        if (drag && g->hit[i].kind != HIT_SLIDER) return 1;
        switch (g->hit[i].kind) {
        case HIT_PLAY: key(g, SDLK_SPACE, 0); break;
        case HIT_STEP: key(g, SDLK_s, 0); break;
        case HIT_RESTART: key(g, SDLK_r, 0); break;
        case HIT_REWIND: key(g, g->hit[i].index == 1 ? SDLK_PAGEDOWN : g->hit[i].index == 2 ? SDLK_HOME : SDLK_LEFT, 0); break;
        case HIT_SCENES:
            g->picking = !g->picking;
            if (g->picking) pl_picker_scan(&g->picker, g->sim.path);
            break;
        case HIT_CHARTS:
            g->show_charts = !g->show_charts;
            if (g->sim.live.ncharts == 0) message(g, "this scene records no live charts", 0);
            break;
        case HIT_PICK_BACK: g->picking = 0; break;
        case HIT_PICK_MORE: g->pick_first = g->hit[i].index; break;
        case HIT_PICK: open_scene(g, g->picker.e[g->hit[i].index].path); break;
        case HIT_LAYER: {
            int k = g->hit[i].index;
            toggle_layer(g, panel_layers[k], panel_layer_names[k]);
            break;
        }
        case HIT_SLIDER: {
            int k = g->hit[i].index;
            pl_wparam *q = &g->sim.params[k];
            double f = (x - r.x0) / (r.x1 - r.x0);
            double v = q->min + (f < 0 ? 0 : f > 1 ? 1 : f) * (q->max - q->min);
            if (q->step > 0) v = q->min + floor((v - q->min) / q->step + 0.5) * q->step;
            g->param_sel = k;
            pl_wsim_set_param(&g->sim, k, v);
            break;
        }
        default: break;
        }
        return 1;
    }
    return 1;
}

static void event(win *g, const SDL_Event *e)
{
    int x, y;
    switch (e->type) {
    case SDL_QUIT: g->quit = 1; break;
    case SDL_KEYDOWN: key(g, e->key.keysym.sym, e->key.keysym.mod); break;
    case SDL_MOUSEMOTION:
        to_px(g, e->motion.x, e->motion.y, &x, &y);
        g->mouse_in = 1;
        if ((e->motion.state & SDL_BUTTON_LMASK) && g->grab < 0 && !g->panning &&
            panel_click(g, x, y, 1)) {
            g->mx = x;
            g->my = y;
            break;
        }
        if (g->panning) pan_by(g, x - g->mx, y - g->my);
        g->mx = x;
        g->my = y;
        break;
    case SDL_MOUSEBUTTONDOWN:
        to_px(g, e->button.x, e->button.y, &g->mx, &g->my);
        if (e->button.button == SDL_BUTTON_LEFT && panel_click(g, g->mx, g->my, 0)) break;
        g->hover = body_at(g, pl_camera_to_world(&g->scene_dl.camera, (pl_vec2){g->mx, g->my}));
        if (e->button.button == SDL_BUTTON_LEFT) {
            if (g->hover >= 0 && g->rs.bodies[g->hover].motion == PL_MOTION_DYNAMIC &&
                g->rs.bodies[g->hover].shape != PL_SHAPE_SEGMENT)
                g->grab = g->hover;
            else
                g->panning = 1;
        } else if (e->button.button == SDL_BUTTON_MIDDLE) {
            g->panning = 1;
        } else if (e->button.button == SDL_BUTTON_RIGHT) {
            key(g, SDLK_x, 0);
        }
        break;
    case SDL_MOUSEBUTTONUP:
        if (e->button.button == SDL_BUTTON_LEFT) release_grab(g);
        g->panning = 0;
        break;
    case SDL_MOUSEWHEEL:
        if (e->wheel.y != 0) zoom_at(g, g->mx, g->my, pow(0.85, e->wheel.y));
        break;
    case SDL_WINDOWEVENT:
        if (e->window.event == SDL_WINDOWEVENT_LEAVE) g->mouse_in = 0; /* no stale readout */
        if (e->window.event == SDL_WINDOWEVENT_ENTER) g->mouse_in = 1;
        if (e->window.event == SDL_WINDOWEVENT_SIZE_CHANGED) {
            int w, h;
            SDL_GL_GetDrawableSize(g->sdl, &w, &h);
            if (w >= 16 && h >= 16) {
                g->sim.ropt.width = w;
                g->sim.ropt.height = h;
            }
        }
        break;
    default: break;
    }
}

/* The spring of a grabbed grain: critically damped at 3 Hz (softer when a drawn frame spans
 * a long simulated time), relative to the grain's mass, towards the cursor. */
static void spring(win *g)
{
    if (g->grab < 0 || g->sim.stopped) return;
    pl_body_info b;
    if (pl_world_body_info(g->sim.w, g->grab, &b) != PL_OK || b.motion != PL_MOTION_DYNAMIC) {
        g->grab = -1;
        return;
    }
    pl_vec2 t = pl_camera_to_world(&g->scene_dl.camera, (pl_vec2){g->mx, g->my});
    /* the force is updated once per drawn frame and held over its steps: keep omega times
     * the frame's simulated duration below 0.5 so the pull cannot overshoot and grow */
    double om = 2.0 * M_PI * 3.0, held = (double)g->speed * pl_world_dt(g->sim.w);
    if (held > 0.0 && om * held > 0.5) om = 0.5 / held;
    pl_vec2 f = {b.mass * (om * om * (t.x - b.position.x) - 2.0 * om * b.velocity.x),
                 b.mass * (om * om * (t.y - b.position.y) - 2.0 * om * b.velocity.y)};
    pl_wsim_set_load(&g->sim, g->grab, f);
}

/* ------------------------------------------------------------------ main */

int pl_window_main(const pl_opts *o)
{
    static win G;
    win *g = &G;
    memset(g, 0, sizeof *g);
    g->sim.o = o;
    snprintf(g->sim.path, sizeof g->sim.path, "%s", o->positional[0]);
    if (pl_opts_has(o, "--out"))
        snprintf(g->sim.out_dir, sizeof g->sim.out_dir, "%s", pl_opts_get(o, "--out"));
    else
        pl_cli_default_out(o->positional[0], g->sim.out_dir, sizeof g->sim.out_dir);
    pl_draw_list_init(&g->sim.overlay);
    if (pl_wsim_load(&g->sim, 0) != 0) {
        fprintf(stderr, "porelab: %s\n", g->sim.error);
        pl_wsim_free(&g->sim);
        return PL_EXIT_FAIL;
    }
    if (pl_opts_size(o, "--size", &g->sim.ropt.width, &g->sim.ropt.height) != 0) return PL_EXIT_USAGE;
    const char *layers = pl_opts_get(o, "--layers");
    if (layers) {
        char err[512];
        if (pl_render_parse_layers(layers, &g->sim.ropt.layers, err, sizeof err) != 0) {
            fprintf(stderr, "porelab %s: --layers: %s\n", o->cmd->command, err);
            return PL_EXIT_USAGE;
        }
    }
    g->speed = frame_interval(g);
    long long sp = 0;
    if (pl_opts_count(o, "--speed", 1, &sp) != 0) return PL_EXIT_USAGE;
    if (sp > 0) g->speed = sp;
    g->playing = !pl_opts_has(o, "--paused");
    g->show_hud = 1;
    g->show_charts = 0; /* the controls first; the charts button shows the live charts */
    g->grab = g->hover = -1;

    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        fprintf(stderr, "porelab: cannot open a window: %s\n  (no display? on a server use "
                        "porelab run --renderer gl, or run the window under xvfb-run)\n",
                SDL_GetError());
        pl_wsim_free(&g->sim);
        return PL_EXIT_FAIL;
    }
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 2);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 1);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    /* never larger than the screen: scaled down (aspect kept) to the display's usable area */
    SDL_Rect usable;
    if (SDL_GetDisplayUsableBounds(0, &usable) == 0 && usable.w > 100 && usable.h > 100) {
        double f = fmin(0.95 * usable.w / g->sim.ropt.width, 0.92 * usable.h / g->sim.ropt.height);
        if (f < 1.0) {
            g->sim.ropt.width = (int)(g->sim.ropt.width * f);
            g->sim.ropt.height = (int)(g->sim.ropt.height * f);
        }
    }
    char title[PATH_MAX + 32];
    snprintf(title, sizeof title, "porelab - %.*s", PATH_MAX, g->sim.path);
    g->sdl = SDL_CreateWindow(title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                              g->sim.ropt.width, g->sim.ropt.height,
                              SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE);
    g->ctx = g->sdl ? SDL_GL_CreateContext(g->sdl) : NULL;
    char err[1024];
    const char *ws = getenv("PORELAB_WINDOW_SAMPLES");
    if (g->ctx) g->gl = pl_gl_create(get_proc, ws && atoi(ws) > 0 ? atoi(ws) : 0, err, sizeof err);
    else snprintf(err, sizeof err, "%s", SDL_GetError());
    if (!g->gl) {
        fprintf(stderr, "porelab: cannot start OpenGL in the window: %s\n", err);
        if (g->ctx) SDL_GL_DeleteContext(g->ctx);
        if (g->sdl) SDL_DestroyWindow(g->sdl);
        SDL_Quit();
        pl_wsim_free(&g->sim);
        return PL_EXIT_FAIL;
    }
    const char *vs = getenv("PORELAB_VSYNC");
    SDL_GL_SetSwapInterval(vs && vs[0] == '0' ? 0 : 1);
    printf("porelab view: %s on %s (%s, %d samples); h for help\n", o->positional[0],
           pl_gl_renderer_name(g->gl), pl_gl_version(g->gl), pl_gl_samples(g->gl));
    fflush(stdout);
    pl_render_scene_init(&g->rs);
    double last_watch = now_s(), t_start = now_s();
    long frames = 0;
    g->last_frame = now_s();
    while (!g->quit) {
        SDL_Event e;
        while (SDL_PollEvent(&e)) event(g, &e);
        double t = now_s();
        if (t - last_watch > 0.5) {
            last_watch = t;
            if (pl_wsim_file_changed(&g->sim)) {
                if (pl_wsim_load(&g->sim, 1) == 0) {
                    message(g, "scene reloaded", 0);
                    printf("reload: ok\n");
                } else {
                    printf("reload: failed, the previous scene stays: %s\n", g->sim.error);
                }
                fflush(stdout);
                g->grab = -1;
            }
        }
        if (g->playing && !g->sim.stopped) {
            spring(g);
            long long n = g->speed;
            long long end = g->sim.plan.total_steps, now = pl_wsim_steps(&g->sim);
            if (now < end && now + n >= end) { /* pause at the scene's end time */
                n = end - now;
                g->playing = 0;
                snprintf(g->msg, sizeof g->msg, "end of the scene's run (space continues)");
                g->msg_until = t + 4.0;
            }
            pl_wsim_advance(&g->sim, n);
        }
        if (build_scene(g) != 0) break;
        if (g->show_hud) {
            pl_render_scene_stress(&g->rs);
            if (!g->rs_fluid && pl_world_prepare(g->sim.w) == PL_OK && pl_world_fluid_node_count(g->sim.w) > 0)
                pl_render_scene_capture_fluid_opt(&g->rs, g->sim.w, &g->sim.ropt);
            g->hover = body_at(g, pl_camera_to_world(&g->scene_dl.camera, (pl_vec2){g->mx, g->my}));
        }
        build_hud(g);
        if (pl_gl_render_over(g->gl, &g->scene_dl, &g->hud, err, sizeof err) != 0) {
            fprintf(stderr, "porelab: %s\n", err);
            break;
        }
        int dw, dh;
        SDL_GL_GetDrawableSize(g->sdl, &dw, &dh);
        pl_gl_present(g->gl, dw, dh);
        SDL_GL_SwapWindow(g->sdl);
        frames++;
        double t1 = now_s(), dt = t1 - g->last_frame;
        g->last_frame = t1;
        if (dt > 0) g->fps = g->fps > 0 ? 0.9 * g->fps + 0.1 / dt : 1.0 / dt;
    }
    double wall = now_s() - t_start;
    printf("porelab view: %ld frames in %.2f s (mean %.1f frames per second)\n", frames, wall,
           wall > 0 ? frames / wall : 0.0);
    pl_render_scene_free(&g->rs);
    pl_draw_list_free(&g->scene_dl);
    pl_draw_list_free(&g->hud);
    pl_draw_list_free(&g->tmp);
    pl_image_free(&g->img);
    pl_gl_destroy(&g->gl);
    pl_gl_destroy(&g->gl_shot);
    SDL_GL_DeleteContext(g->ctx);
    SDL_DestroyWindow(g->sdl);
    SDL_Quit();
    pl_wsim_free(&g->sim);
    return PL_EXIT_OK;
}
