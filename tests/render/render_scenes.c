/* Deterministic test worlds for the render tests (see render_scenes.h). The pile is built
 * with graded initial overlaps (larger at the bottom, like a pile under its own weight) and
 * stepped only twice, so contact forces come from the placed geometry and the pictures do
 * not depend on the details of settling dynamics. */
#include "render_scenes.h"

#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "porelab/fluid.h"

static int add_material(pl_world *w, const char *name, double density) {
    pl_material_def m = pl_default_material_def();
    m.name = name;
    m.density = density;
    m.kn = 1e6;
    m.friction = 0.5;
    m.restitution = 0.5;
    return pl_world_add_material(w, &m);
}

static void add_wall(pl_world *w, int mat, double ax, double ay, double bx, double by) {
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_SEGMENT;
    b.motion = PL_MOTION_FIXED;
    b.material = mat;
    b.a = (pl_vec2){ax, ay};
    b.b = (pl_vec2){bx, by};
    pl_world_add_body(w, &b);
}

static void add_disc(pl_world *w, int mat, double x, double y, double r, double omega) {
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_DISC;
    b.material = mat;
    b.position = (pl_vec2){x, y};
    b.radius = r;
    b.omega = omega;
    b.angle = 0.7 * x + 1.3 * y; /* varied rotation marks */
    pl_world_add_body(w, &b);
}

static void add_polygon(pl_world *w, int mat, const pl_vec2 *v, int n) {
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_POLYGON;
    b.material = mat;
    b.vertices = v;
    b.vertex_count = n;
    pl_world_add_body(w, &b);
}

static pl_world *pile(double spin) {
    pl_world_def wd = pl_default_world_def();
    wd.dt = 1e-5;
    pl_world *w = pl_world_create(&wd);
    if (!w) return NULL;
    int sand = add_material(w, "sand", 2600.0);
    int glass = add_material(w, "glass", 2500.0);
    int granite = add_material(w, "granite", 2700.0);
    int steel = add_material(w, "steel", 7800.0);
    add_wall(w, steel, -0.6, 0.0, 0.6, 0.0);
    add_wall(w, steel, -0.55, 0.0, -0.55, 1.0);
    add_wall(w, steel, 0.55, 0.0, 0.55, 1.0);
    const double r = 0.1;
    double y = r - 0.0025; /* row 0 presses 2.5 mm into the floor */
    for (int k = 0; k < 4; k++) {
        int n = 5 - k;
        double x0 = -0.4 + k * 0.1;
        for (int i = 0; i < n; i++)
            add_disc(w, (k % 2) ? glass : sand, x0 + 0.2 * i, y, r, spin);
        double d = 2.0 * r - 0.0005 * (4 - k); /* overlap to the next row: 2, 1.5, 1, 0.5 mm */
        y += sqrt(d * d - r * r);
    }
    /* a square on top of the right disc of the top row (0.5 mm overlap) */
    double top = y - sqrt(pow(2.0 * r - 0.0005, 2) - r * r) + r - 0.0005;
    pl_vec2 sq[4] = {{0.02, top}, {0.18, top}, {0.18, top + 0.16}, {0.02, top + 0.16}};
    add_polygon(w, granite, sq, 4);
    /* a hexagon resting on the right end of the bottom row */
    pl_vec2 hex[6];
    double cx = 0.465, cy = 0.2491, hr = 0.07;
    for (int i = 0; i < 6; i++) {
        double a = i * 3.14159265358979323846 / 3.0;
        hex[i] = (pl_vec2){cx + hr * cos(a), cy + hr * sin(a)};
    }
    add_polygon(w, granite, hex, 6);
    /* a fixed obstacle disc */
    pl_body_def ob = pl_default_body_def();
    ob.shape = PL_SHAPE_DISC;
    ob.motion = PL_MOTION_FIXED;
    ob.material = steel;
    ob.position = (pl_vec2){-0.43, 0.62};
    ob.radius = 0.06;
    pl_world_add_body(w, &ob);
    if (pl_world_step(w, 2) != PL_OK) {
        fprintf(stderr, "pile world: %s\n", pl_world_last_error(w));
        pl_world_destroy(&w);
        return NULL;
    }
    return w;
}

pl_world *make_pile_world(void) { return pile(0.0); }

pl_world *make_moving_world(void) {
    pl_world_def wd = pl_default_world_def();
    wd.dt = 1e-5;
    pl_world *w = pl_world_create(&wd);
    if (!w) return NULL;
    int sand = add_material(w, "sand", 2600.0);
    int steel = add_material(w, "steel", 7800.0);
    add_wall(w, steel, -0.6, 0.0, 0.6, 0.0);
    for (int i = 0; i < 12; i++) {
        double x = -0.5 + 0.09 * i, yy = 0.15 + 0.05 * (i % 3) + 0.02 * i;
        pl_body_def b = pl_default_body_def();
        b.shape = PL_SHAPE_DISC;
        b.material = sand;
        b.position = (pl_vec2){x, yy};
        b.radius = 0.035 + 0.004 * (i % 4);
        b.velocity = (pl_vec2){0.25 * i * cos(0.5 * i), 0.25 * i * sin(0.5 * i)};
        b.angle = 0.4 * i;
        pl_world_add_body(w, &b);
    }
    if (pl_world_step(w, 2) != PL_OK) {
        pl_world_destroy(&w);
        return NULL;
    }
    return w;
}

/* Synthetic pore pressure on a structured mesh over the pile's box: hydrostatic for a water
 * table at y = 0.9 m plus a positive bump and a negative dip of excess pressure; Darcy
 * velocity v = -(k / (rho g)) grad p_excess with k = 1e-3 m/s (per triangle, analytic). */
static double excess(double x, double y) {
    return 1800.0 * exp(-((x - 0.15) * (x - 0.15) + (y - 0.35) * (y - 0.35)) / 0.05) -
           1200.0 * exp(-((x + 0.3) * (x + 0.3) + (y - 0.6) * (y - 0.6)) / 0.03);
}

int set_synthetic_fluid(pl_render_scene *s, int field) {
    enum { NX = 22, NY = 18 };
    static pl_vec2 nodes[(NX + 1) * (NY + 1)];
    static double values[(NX + 1) * (NY + 1)];
    static int tris[NX * NY * 2 * 3];
    static pl_vec2 vel[NX * NY * 2];
    const double x0 = -0.55, x1 = 0.55, y0 = 0.0, y1 = 0.9, rho_g = 1000.0 * 9.81;
    for (int j = 0; j <= NY; j++)
        for (int i = 0; i <= NX; i++) {
            int n = j * (NX + 1) + i;
            double x = x0 + (x1 - x0) * i / NX, y = y0 + (y1 - y0) * j / NY;
            nodes[n] = (pl_vec2){x, y};
            values[n] = field == 3 ? excess(x, y) : rho_g * (0.9 - y) + excess(x, y);
        }
    int t = 0;
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            int a = j * (NX + 1) + i, b = a + 1, c = a + NX + 1, d = c + 1;
            int q[2][3];
            if ((i + j) % 2 == 0) {
                int q0[3] = {a, b, d}, q1[3] = {a, d, c};
                memcpy(q[0], q0, sizeof q0);
                memcpy(q[1], q1, sizeof q1);
            } else {
                int q0[3] = {a, b, c}, q1[3] = {b, d, c};
                memcpy(q[0], q0, sizeof q0);
                memcpy(q[1], q1, sizeof q1);
            }
            for (int k = 0; k < 2; k++) {
                memcpy(&tris[3 * t], q[k], sizeof q[k]);
                double cx = (nodes[q[k][0]].x + nodes[q[k][1]].x + nodes[q[k][2]].x) / 3.0;
                double cy = (nodes[q[k][0]].y + nodes[q[k][1]].y + nodes[q[k][2]].y) / 3.0;
                const double h = 1e-6, kk = 1e-3 / rho_g;
                vel[t].x = -kk * (excess(cx + h, cy) - excess(cx - h, cy)) / (2 * h);
                vel[t].y = -kk * (excess(cx, cy + h) - excess(cx, cy - h)) / (2 * h);
                t++;
            }
        }
    return pl_render_scene_set_fluid(s, nodes, values, (NX + 1) * (NY + 1), tris, vel, t, field);
}

/* ------------------------------------------------------------------ cases */

enum { W_PILE, W_SPIN, W_MOVING };

typedef struct case_def {
    render_case_info info;
    int world;
    unsigned layers;
    int coloring;
    int fluid_field; /* -1 none */
    const char *title;
} case_def;

static const case_def cases[] = {
    {{"bodies", "discs, polygons, fixed disc and walls coloured by material"}, W_PILE,
     PL_LAYER_BODIES, PL_COLOR_BY_MATERIAL, -1, NULL},
    {{"forces", "normal-force chains over the bodies"}, W_PILE, PL_LAYER_BODIES | PL_LAYER_FORCES,
     PL_COLOR_BY_MATERIAL, -1, NULL},
    {{"tangential", "tangential contact forces of spinning discs"}, W_SPIN,
     PL_LAYER_BODIES | PL_LAYER_FORCES | PL_LAYER_TANGENTIAL, PL_COLOR_BY_MATERIAL, -1, NULL},
    {{"colorbar_speed", "bodies coloured by speed with the colour bar"}, W_MOVING,
     PL_LAYER_BODIES | PL_LAYER_COLORBAR, PL_COLOR_BY_SPEED, -1, NULL},
    {{"stress", "bodies coloured by mean stress from contact forces"}, W_PILE,
     PL_LAYER_BODIES | PL_LAYER_FORCES | PL_LAYER_COLORBAR, PL_COLOR_BY_STRESS, -1, NULL},
    {{"annotations", "time stamp, title, scale bar and material legend"}, W_PILE,
     PL_LAYER_BODIES | PL_LAYER_TIME | PL_LAYER_TITLE | PL_LAYER_SCALEBAR | PL_LAYER_COLORBAR,
     PL_COLOR_BY_MATERIAL, -1, "A pile of grains"},
    {{"pressure", "excess pore pressure (diverging map) on Gouraud triangles"}, W_PILE,
     PL_LAYER_PRESSURE | PL_LAYER_COLORBAR, PL_COLOR_BY_MATERIAL, 3, NULL},
    {{"isolines", "labelled pressure isolines over the mesh"}, W_PILE,
     PL_LAYER_ISOLINES | PL_LAYER_MESH, PL_COLOR_BY_MATERIAL, 2, NULL},
    {{"velocity", "Darcy velocity arrows with a reference arrow"}, W_PILE,
     PL_LAYER_VELOCITY | PL_LAYER_MESH | PL_LAYER_SCALEBAR, PL_COLOR_BY_MATERIAL, 3, NULL},
    {{"combined", "pressure, isolines, bodies, force chains, overlay and all annotations"}, W_PILE,
     PL_LAYER_PRESSURE | PL_LAYER_ISOLINES | PL_LAYER_BODIES | PL_LAYER_FORCES | PL_LAYER_TIME |
         PL_LAYER_TITLE | PL_LAYER_SCALEBAR | PL_LAYER_COLORBAR | PL_LAYER_OVERLAY,
     PL_COLOR_BY_MATERIAL, 2, "Grains in water"},
};

int render_case_count(void) { return (int)(sizeof cases / sizeof cases[0]); }

const render_case_info *render_case_at(int i) { return &cases[i].info; }

int render_case(int i, const render_tweak *tw, pl_draw_list *dl, char *err, size_t errlen) {
    const case_def *c = &cases[i];
    render_tweak none = {0, 0, 0};
    if (!tw) tw = &none;
    pl_world *w = c->world == W_MOVING ? make_moving_world() : pile(c->world == W_SPIN ? 300.0 : 0.0);
    if (!w) {
        snprintf(err, errlen, "could not build the test world");
        return -1;
    }
    pl_render_options o = pl_default_render_options();
    o.width = 480;
    o.height = 360;
    o.layers = c->layers & ~tw->drop_layers;
    o.coloring = (pl_body_coloring)c->coloring;
    if (c->title) snprintf(o.title, sizeof o.title, "%s", c->title);
    if (tw->colour_shift) {
        o.material_color_count = 4;
        for (int m = 0; m < 4; m++) o.material_colors[m] = pl_material_palette(m);
        o.material_colors[0].g += 0.08f; /* 20 of 255 greener sand */
    }
    if (c->fluid_field >= 0) o.fluid_field = c->fluid_field;
    pl_draw_list overlay;
    pl_draw_list_init(&overlay);
    pl_vec2 water[2] = {{-0.55, 0.9}, {0.55, 0.9}};
    pl_dl_polyline(&overlay, PL_SPACE_WORLD, water, 2, pl_rgb_hex(0x1F5FA8), 2.0f);
    pl_dl_text(&overlay, PL_SPACE_WORLD, (pl_vec2){0.53, 0.91}, "water table", 12.0f,
               PL_ANCHOR_RIGHT | PL_ANCHOR_BOTTOM, 0.0f, pl_rgb_hex(0x1F5FA8), NULL);
    o.overlay = &overlay;
    pl_render_scene s;
    pl_render_scene_init(&s);
    int rc = pl_render_scene_capture(&s, w);
    if (rc == 0 && tw->shift_body) s.bodies[3 + 3].position.x += s.bodies[3 + 3].radius / 3.0;
    if (rc == 0 && c->fluid_field >= 0) rc = set_synthetic_fluid(&s, c->fluid_field);
    if (rc) snprintf(err, errlen, "out of memory");
    else rc = pl_render_build_scene(dl, &s, &o, err, errlen);
    pl_render_scene_free(&s);
    pl_draw_list_free(&overlay);
    pl_world_destroy(&w);
    return rc;
}

int set_grid_field(pl_render_scene *s, int gx, int gy, double kx, double ky, double vscale)
{
    int nn = (gx + 1) * (gy + 1), nt = 2 * gx * gy;
    pl_vec2 *nodes = malloc((size_t)nn * sizeof *nodes);
    double *val = malloc((size_t)nn * sizeof *val);
    int *tris = malloc((size_t)nt * 3 * sizeof *tris);
    pl_vec2 *vel = malloc((size_t)nt * sizeof *vel);
    int rc = -1;
    if (nodes && val && tris && vel) {
        for (int j = 0; j <= gy; j++)
            for (int i = 0; i <= gx; i++) {
                int n = j * (gx + 1) + i;
                nodes[n] = (pl_vec2){s->hi.x * i / gx, s->hi.y * j / gy};
                val[n] = 9810.0 * (s->hi.y - nodes[n].y) + 3000.0 * sin(kx * i) * cos(ky * j);
            }
        int t = 0;
        for (int j = 0; j < gy; j++)
            for (int i = 0; i < gx; i++) {
                int a = j * (gx + 1) + i, b = a + 1, c = a + gx + 1, d = c + 1;
                int q[6] = {a, b, d, a, d, c};
                memcpy(tris + 3 * t, q, sizeof q);
                vel[t] = vscale == 0 ? (pl_vec2){0, 0} : (pl_vec2){vscale * cos(kx * i), vscale * sin(ky * j)};
                vel[t + 1] = vel[t];
                t += 2;
            }
        pl_render_scene_set_fluid(s, nodes, val, nn, tris, vel, nt, 2);
        rc = 0;
    }
    free(nodes);
    free(val);
    free(tris);
    free(vel);
    return rc;
}
