/* Render benchmark (not a test): time per frame at 1280x720 for 20,000 bodies, 40,000
 * contacts and 40,000 fluid triangles, split into draw-list build, rasterization (cairo) and
 * PNG encoding (libpng, zlib level 1, no filters). Also times reading the state of a real
 * engine world of 20,000 discs (pl_render_scene_capture).
 *   bench_render [frames] [outdir] [config]   (defaults: 5 frames, the build's render-out
 *                                             folder, every configuration)
 * Prints one line per configuration and a CSV block. Times are CPU time of the rendering
 * thread (the same as wall time on an idle machine). Set PORELAB_CAIRO_ONLY=1 to time cairo
 * alone (no direct rasterization of small primitives). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "backend_cairo.h"
#include "draw_world.h"
#include "render_scenes.h"

/* CPU time of this (single) thread: the machine running the benchmark is often shared, and
 * wall-clock time then measures the neighbours as much as the renderer. */
static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

enum { NX = 200, NY = 100 }; /* 20,000 bodies */

static void build_scene(pl_render_scene *s) {
    const double r = 0.5;
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            pl_body_info b;
            memset(&b, 0, sizeof b);
            int poly = (i * 7 + j * 3) % 10 == 0; /* one body in ten is a hexagon */
            b.shape = poly ? PL_SHAPE_POLYGON : PL_SHAPE_DISC;
            b.material = (i / 10 + j / 10) % 3;
            b.position = (pl_vec2){(2.0 * r - 0.01) * i + r * (j % 2), (2.0 * r - 0.01) * 0.866 * j};
            b.radius = r * (0.9 + 0.1 * sin(i * 0.37 + j));
            b.area = 3.14159 * b.radius * b.radius;
            b.angle = 0.1 * i + 0.2 * j;
            b.velocity = (pl_vec2){sin(0.05 * i), cos(0.07 * j)};
            pl_vec2 v[6];
            int nv = 0;
            if (poly) {
                for (int k = 0; k < 6; k++)
                    v[k] = (pl_vec2){b.position.x + b.radius * cos(b.angle + k * 1.0471975512),
                                     b.position.y + b.radius * sin(b.angle + k * 1.0471975512)};
                nv = 6;
                b.vertex_count = 6;
            }
            pl_render_scene_add_body(s, &b, v, nv);
        }
    /* 40,000 contacts: each body with its right and upper neighbour */
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            int a = j * NX + i;
            int nb[2] = {i + 1 < NX ? a + 1 : a - NX + 1, j + 1 < NY ? a + NX : a - NX * (NY - 1) + 1};
            for (int k = 0; k < 2; k++) {
                int b = nb[k];
                if (b < 0 || b >= NX * NY || b == a) b = (a + 7) % (NX * NY);
                pl_contact_info c;
                memset(&c, 0, sizeof c);
                c.a = a < b ? a : b;
                c.b = a < b ? b : a;
                pl_vec2 pa = s->bodies[c.a].position, pb = s->bodies[c.b].position;
                c.point = (pl_vec2){0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y)};
                double d = hypot(pb.x - pa.x, pb.y - pa.y);
                c.normal = (pl_vec2){(pb.x - pa.x) / d, (pb.y - pa.y) / d};
                c.fn = 1000.0 * (1.0 + sin(0.13 * i + 0.29 * j + k)) * (1.0 + j / (double)NY);
                c.ft = 200.0 * sin(0.7 * i + k);
                pl_render_scene_add_contact(s, &c);
            }
        }
    s->lo = (pl_vec2){-1.0, -1.0};
    s->hi = (pl_vec2){NX * 1.0 + 1.0, NY * 0.866 + 1.0};
    s->time = 12.345;
    /* 40,000 fluid triangles on a 200 x 100 grid over the packing */
    set_grid_field(s, NX, NY, 0.05, 0.08, 1e-4);
    s->material_count = 0;
}

static const char *only; /* optional third argument: run only this configuration */

static void bench(const char *name, pl_render_scene *s, unsigned layers, int frames,
                  const char *outdir, FILE *csv) {
    if (only && strcmp(only, name) != 0) return;
    pl_render_options o = pl_default_render_options();
    o.width = 1280;
    o.height = 720;
    o.layers = layers;
    snprintf(o.title, sizeof o.title, "benchmark");
    pl_draw_list dl;
    pl_draw_list_init(&dl);
    pl_image img = {0, 0, NULL};
    char err[512], path[1024];
    double tb = 0, tr = 0, te = 0;
    for (int f = 0; f < frames + 1; f++) { /* frame 0 warms up (allocations, font) */
        double t0 = now();
        if (pl_render_build_scene(&dl, s, &o, err, sizeof err)) { fprintf(stderr, "%s\n", err); exit(1); }
        double t1 = now();
        if (pl_cairo_rasterize(&dl, &img, err, sizeof err)) { fprintf(stderr, "%s\n", err); exit(1); }
        double t2 = now();
        snprintf(path, sizeof path, "%s/bench_%s.png", outdir, name);
        if (pl_png_write(path, &img, 1, 0, err, sizeof err)) { fprintf(stderr, "%s\n", err); exit(1); }
        double t3 = now();
        if (f > 0) {
            tb += t1 - t0;
            tr += t2 - t1;
            te += t3 - t2;
        }
    }
    tb /= frames; tr /= frames; te /= frames;
    printf("%-22s %6d prims  build %7.1f ms  raster %7.1f ms  encode %6.1f ms  total %7.1f ms\n",
           name, dl.prim_count, 1e3 * tb, 1e3 * tr, 1e3 * te, 1e3 * (tb + tr + te));
    fprintf(csv, "%s,%d,%.2f,%.2f,%.2f,%.2f\n", name, dl.prim_count, 1e3 * tb, 1e3 * tr, 1e3 * te,
            1e3 * (tb + tr + te));
    pl_draw_list_free(&dl);
    pl_image_free(&img);
}

int main(int argc, char **argv) {
    int frames = argc > 1 ? atoi(argv[1]) : 5;
    const char *outdir = argc > 2 ? argv[2] : PL_RENDER_OUT_DIR;
    if (frames < 1) frames = 1;
    only = argc > 3 ? argv[3] : NULL;
    pl_render_scene s;
    pl_render_scene_init(&s);
    build_scene(&s);
    printf("1280x720, %d bodies, %d contacts, %d fluid triangles, mean of %d frames\n",
           s.body_count, s.contact_count, s.fluid_tri_count, frames);
    char csvbuf[8192];
    FILE *csv = fmemopen(csvbuf, sizeof csvbuf, "w");
    fprintf(csv, "config,primitives,build_ms,raster_ms,encode_ms,total_ms\n");
    bench("bodies", &s, PL_LAYER_BODIES, frames, outdir, csv);
    bench("bodies+forces+time", &s, PL_LAYERS_DEFAULT, frames, outdir, csv);
    bench("forces", &s, PL_LAYER_FORCES, frames, outdir, csv);
    bench("tangential", &s, PL_LAYER_TANGENTIAL, frames, outdir, csv);
    bench("mesh", &s, PL_LAYER_MESH, frames, outdir, csv);
    bench("pressure", &s, PL_LAYER_PRESSURE, frames, outdir, csv);
    bench("isolines+velocity", &s, PL_LAYER_ISOLINES | PL_LAYER_VELOCITY, frames, outdir, csv);
    bench("all layers", &s, 0xFFFu, frames, outdir, csv);
    fclose(csv);
    printf("\n%s", csvbuf);

    /* reading a real world: 20,000 discs through the engine's queries */
    pl_world_def wd = pl_default_world_def();
    wd.dt = 1e-5;
    pl_world *w = pl_world_create(&wd);
    pl_material_def m = pl_default_material_def();
    m.name = "sand";
    m.density = 2600;
    m.kn = 1e6;
    int mat = pl_world_add_material(w, &m);
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            pl_body_def b = pl_default_body_def();
            b.shape = PL_SHAPE_DISC;
            b.material = mat;
            b.position = (pl_vec2){0.999 * i + 0.5 * (j % 2), 0.866 * 0.999 * j};
            b.radius = 0.5;
            pl_world_add_body(w, &b);
        }
    pl_world_step(w, 1);
    pl_render_scene rs;
    pl_render_scene_init(&rs);
    pl_render_scene_capture(&rs, w);
    double t0 = now();
    for (int f = 0; f < frames; f++) pl_render_scene_capture(&rs, w);
    double tc = (now() - t0) / frames;
    printf("\ncapture from a world of %d discs with %d contacts: %.1f ms per frame\n",
           rs.body_count, rs.contact_count, 1e3 * tc);
    pl_render_scene_free(&rs);
    pl_world_destroy(&w);
    pl_render_scene_free(&s);
    return 0;
}
