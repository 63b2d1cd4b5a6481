/* OpenGL backend: draw list -> vertices (CPU) -> a few indexed draws (one per run of
 * primitives sharing a program, clip and depth state) into an offscreen framebuffer ->
 * resolve. See backend_gl.h for how each primitive is drawn. */
#include "backend_gl.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_text.h"

/* Programs: PROG_SHAPE draws every untextured primitive with one branch-free distance
 * formula (see fs_shape); PROG_GLYPH samples the glyph atlas; PROG_SOLID only passes the
 * vertex colour on (field meshes, which cover the plot area, and fills without an
 * antialiased edge: the cheapest possible pixels). */
enum { PROG_SHAPE = 0, PROG_GLYPH = 1, PROG_SOLID = 2, PROG_COUNT = 3 };

/* Half-width of the "band" that makes the shape shader paint solid geometry (coverage 1)
 * and one-sided edge ramps of antialiased convex fills (see add_fill_aa). */
#define HUGE_HW 16384.0f

typedef struct gv {
    float x, y, z;     /* pixels (y down), depth in NDC */
    uint8_t c0[4];     /* circle fill colour, straight alpha (0 for everything else) */
    uint8_t c1[4];     /* stroke / solid colour; glyph colour */
    float p[4];        /* shape: u, v, L or -r, half-width; glyph: atlas u, v, size */
} gv;

/* A run of indices drawn with one program, clip and depth state. */
typedef struct gl_batch {
    long first, count;
    uint8_t prog, clip, depth;
} gl_batch;

struct pl_gl {
    pl_gl_funcs f;
    GLuint prog[PROG_COUNT], vbo, ibo, tex, vao;
    GLint u_size[PROG_COUNT], u_clip[PROG_COUNT], u_tex, u_core;
    long vbo_bytes, ibo_bytes; /* allocated sizes: reused while large enough */
    GLuint fbo_ms, rb_color_ms, rb_depth_ms, fbo_res, rb_color_res;
    /* the window's scene without its overlay, kept while the scene's draw list is unchanged */
    GLuint fbo_cache, rb_cache;
    int cache_ok;
    pl_draw_list last; /* the draw list in fbo_cache */
    int nb_scene;      /* batches of the scene (the overlay's follow) */
    int fresh;         /* 1: the next primitive starts a new batch */
    int fb_w, fb_h, samples, max_size;
    int width, height; /* size of the last render */
    pl_glyph_atlas atlas;
    /* frame geometry, reused between frames */
    gv *v; long nv, cv;
    uint32_t *ix; long ni, ci;
    gl_batch *bt; int nb, cb;
    int failed;
    float z;
    int clip; /* 1 when the current primitive is clipped to dl->clip */
    char renderer[128], version[128];
};

/* ------------------------------------------------------------------ shaders */

static const char *vs_src =
    "#version 120\n"
    "attribute vec3 a_pos;\n"
    "attribute vec4 a_c0;\n"
    "attribute vec4 a_c1;\n"
    "attribute vec4 a_p;\n"
    "uniform vec2 u_size;\n"
    "varying vec4 v_c0;\n"
    "varying vec4 v_c1;\n"
    "varying vec4 v_p;\n"
    "void main() {\n"
    "  gl_Position = vec4(2.0 * a_pos.x / u_size.x - 1.0, 1.0 - 2.0 * a_pos.y / u_size.y,\n"
    "                     a_pos.z, 1.0);\n"
    "  v_c0 = a_c0; v_c1 = a_c1; v_p = a_p;\n"
    "}\n";

/* The glyph program needs no fill colour. */
static const char *vs_glyph_src =
    "#version 120\n"
    "attribute vec3 a_pos;\n"
    "attribute vec4 a_c1;\n"
    "attribute vec4 a_p;\n"
    "uniform vec2 u_size;\n"
    "varying vec4 v_c1;\n"
    "varying vec4 v_p;\n"
    "void main() {\n"
    "  gl_Position = vec4(2.0 * a_pos.x / u_size.x - 1.0, 1.0 - 2.0 * a_pos.y / u_size.y,\n"
    "                     a_pos.z, 1.0);\n"
    "  v_c1 = a_c1; v_p = a_p;\n"
    "}\n";

/* The plot-area clip: a pixel is kept when its centre lies in u_clip = [x0, x1) x [y0, y1)
 * in GL window coordinates (y up), as cairo clips at pixel centres; unclipped batches get
 * a rectangle larger than the frame. (A scissor box would be cheaper, but llvmpipe applies
 * it per sample when multisampling, which leaves half-covered pixels at the clip edge.) */
#define CLIP_TEST                                                                            \
    "  if (gl_FragCoord.x < u_clip.x || gl_FragCoord.x >= u_clip.z ||\n"                      \
    "      gl_FragCoord.y < u_clip.y || gl_FragCoord.y >= u_clip.w) discard;\n"

/* Output is premultiplied (blend ONE, ONE_MINUS_SRC_ALPHA). Coverage of a band of
 * half-width h at distance d from its centre line, box-filtered over one pixel:
 * clamp(h - d + 0.5) - clamp(-h - d + 0.5); exact for straight edges.
 *
 * One formula for every untextured primitive, without branches (llvmpipe runs every branch
 * of a fragment shader on all pixels of a block, so an "uber-shader" costs the sum of its
 * modes): d = distance from (u, v) to the segment [0, L] x {0}; a disc of radius r filled
 * with c0 (coverage clamp(r - d + 0.5)), under a band of half-width hw around the circle
 * of radius r in c1.
 * - circle:  (u, v) relative to the centre, L = 0 (p.z = -r), hw = half the stroke width;
 * - capsule: (u, v) along/across the segment, p.z = L, r = 0: the band is the capsule;
 *   p.w < 0 = butt ends (arrow shafts): band across times the clamped ends;
 * - solid geometry: (0, 0), L = r = 0, hw = HUGE_HW: coverage 1, colour c1 per vertex;
 * - edge ramp of an antialiased convex fill: v = HUGE_HW - s (s = signed distance inside
 *   the edge, interpolated exactly since it is affine), hw = HUGE_HW: coverage
 *   clamp(s + 0.5). */
static const char *fs_shape_src =
    "#version 120\n"
    "uniform float u_core;\n"
    "uniform vec4 u_clip;\n"
    "varying vec4 v_c0;\n"
    "varying vec4 v_c1;\n"
    "varying vec4 v_p;\n"
    "float band(float h, float d) {\n"
    "  return clamp(h - d + 0.5, 0.0, 1.0) - clamp(-h - d + 0.5, 0.0, 1.0);\n"
    "}\n"
    "void main() {\n"
    CLIP_TEST
    "  float u = v_p.x, hw = abs(v_p.w);\n"
    "  float L = max(v_p.z, 0.0), r = max(-v_p.z, 0.0);\n"
    "  float d = length(vec2(u - clamp(u, 0.0, L), v_p.y));\n"
    "  float cf = clamp(r - d + 0.5, 0.0, 1.0) * min(2.0 * r, 1.0);\n" /* sub-pixel discs keep their area */
    "  float cs = v_p.w >= 0.0 ? band(hw, abs(d - r))\n"
    "                          : band(hw, abs(v_p.y)) * clamp(min(u, L - u) + 0.5, 0.0, 1.0);\n"
    "  if (cs < u_core) discard;\n"
    "  float fa = v_c0.a * cf, sa = v_c1.a * cs;\n"
    "  vec4 c = vec4(v_c1.rgb * sa + v_c0.rgb * fa * (1.0 - sa), sa + fa * (1.0 - sa));\n"
    "  if (c.a <= 0.0) discard;\n"
    "  gl_FragColor = c;\n"
    "}\n";

static const char *fs_solid_src =
    "#version 120\n"
    "uniform vec4 u_clip;\n"
    "varying vec4 v_c1;\n"
    "void main() {\n"
    CLIP_TEST
    "  gl_FragColor = vec4(v_c1.rgb * v_c1.a, v_c1.a);\n"
    "}\n";

/* Unrotated glyphs (p.z = atlas size) sample exact texel centres, so the picture does not
 * depend on where the glyph sits in the atlas; rotated ones (p.z = 0) filter. */
static const char *fs_glyph_src =
    "#version 120\n"
    "uniform sampler2D u_tex;\n"
    "uniform vec4 u_clip;\n"
    "varying vec4 v_c1;\n"
    "varying vec4 v_p;\n"
    "void main() {\n"
    CLIP_TEST
    "  vec2 uv = v_p.z > 0.0 ? (floor(v_p.xy * v_p.z) + 0.5) / v_p.z : v_p.xy;\n"
    "  float a = texture2D(u_tex, uv).r * v_c1.a;\n"
    "  if (a <= 0.0) discard;\n"
    "  gl_FragColor = vec4(v_c1.rgb * a, a);\n"
    "}\n";

static GLuint compile(pl_gl *g, GLenum kind, const char *src, char *err, size_t errlen)
{
    GLuint s = g->f.CreateShader(kind);
    g->f.ShaderSource(s, 1, &src, NULL);
    g->f.CompileShader(s);
    GLint ok = 0;
    g->f.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[512] = "";
        g->f.GetShaderInfoLog(s, sizeof log, NULL, log);
        snprintf(err, errlen, "GL shader compile failed: %s", log);
        g->f.DeleteShader(s);
        return 0;
    }
    return s;
}

/* ------------------------------------------------------------- framebuffers */

static void free_fbos(pl_gl *g)
{
    GLuint fb[2] = {g->fbo_ms, g->fbo_res};
    GLuint rb[3] = {g->rb_color_ms, g->rb_depth_ms, g->rb_color_res};
    if (g->fbo_ms) g->f.DeleteFramebuffers(2, fb);
    if (g->rb_color_ms) g->f.DeleteRenderbuffers(3, rb);
    if (g->fbo_cache) g->f.DeleteFramebuffers(1, &g->fbo_cache);
    if (g->rb_cache) g->f.DeleteRenderbuffers(1, &g->rb_cache);
    g->fbo_ms = g->fbo_res = g->rb_color_ms = g->rb_depth_ms = g->rb_color_res = 0;
    g->fbo_cache = g->rb_cache = 0;
    g->cache_ok = 0;
    g->fb_w = g->fb_h = 0;
}

static void storage(pl_gl *g, GLenum fmt, int w, int h)
{
    if (g->samples > 1)
        g->f.RenderbufferStorageMultisample(GL_RENDERBUFFER, g->samples, fmt, w, h);
    else
        g->f.RenderbufferStorage(GL_RENDERBUFFER, fmt, w, h);
}

static int ensure_fbos(pl_gl *g, int w, int h, char *err, size_t errlen)
{
    if (g->fbo_ms && g->fb_w == w && g->fb_h == h) return 0;
    free_fbos(g);
    if (w > g->max_size || h > g->max_size) {
        snprintf(err, errlen, "image size %dx%d exceeds the GL limit of %d pixels per side", w, h,
                 g->max_size);
        return -1;
    }
    GLuint fb[2], rb[3];
    g->f.GenFramebuffers(2, fb);
    g->f.GenRenderbuffers(3, rb);
    g->fbo_ms = fb[0];
    g->fbo_res = fb[1];
    g->rb_color_ms = rb[0];
    g->rb_depth_ms = rb[1];
    g->rb_color_res = rb[2];
    g->f.BindRenderbuffer(GL_RENDERBUFFER, g->rb_color_ms);
    storage(g, GL_RGBA8, w, h);
    g->f.BindRenderbuffer(GL_RENDERBUFFER, g->rb_depth_ms);
    storage(g, GL_DEPTH_COMPONENT24, w, h);
    g->f.BindFramebuffer(GL_FRAMEBUFFER, g->fbo_ms);
    g->f.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                 g->rb_color_ms);
    g->f.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                 g->rb_depth_ms);
    GLenum st1 = g->f.CheckFramebufferStatus(GL_FRAMEBUFFER);
    g->f.BindRenderbuffer(GL_RENDERBUFFER, g->rb_color_res);
    g->f.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
    g->f.BindFramebuffer(GL_FRAMEBUFFER, g->fbo_res);
    g->f.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                 g->rb_color_res);
    GLenum st2 = g->f.CheckFramebufferStatus(GL_FRAMEBUFFER);
    g->f.BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (st1 != GL_FRAMEBUFFER_COMPLETE || st2 != GL_FRAMEBUFFER_COMPLETE) {
        snprintf(err, errlen, "GL framebuffer %dx%d (%d samples) incomplete (status 0x%x, 0x%x)",
                 w, h, g->samples, st1, st2);
        free_fbos(g);
        return -1;
    }
    g->fb_w = w;
    g->fb_h = h;
    return 0;
}

/* The scene cache: a colour buffer like the drawing one (same size and samples). */
static int ensure_cache(pl_gl *g)
{
    if (g->fbo_cache) return 0;
    g->f.GenFramebuffers(1, &g->fbo_cache);
    g->f.GenRenderbuffers(1, &g->rb_cache);
    g->f.BindRenderbuffer(GL_RENDERBUFFER, g->rb_cache);
    storage(g, GL_RGBA8, g->fb_w, g->fb_h);
    g->f.BindFramebuffer(GL_FRAMEBUFFER, g->fbo_cache);
    g->f.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                 g->rb_cache);
    GLenum st = g->f.CheckFramebufferStatus(GL_FRAMEBUFFER);
    g->f.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return st == GL_FRAMEBUFFER_COMPLETE ? 0 : -1;
}

static int prim_equal(const pl_prim *a, const pl_prim *b)
{
    return a->kind == b->kind && a->space == b->space && a->anchor == b->anchor &&
           a->has_fill == b->has_fill && a->has_stroke == b->has_stroke &&
           a->has_halo == b->has_halo && a->width == b->width && a->size == b->size &&
           a->angle == b->angle && a->radius == b->radius &&
           !memcmp(&a->fill, &b->fill, sizeof a->fill) &&
           !memcmp(&a->stroke, &b->stroke, sizeof a->stroke) && a->first == b->first &&
           a->count == b->count && a->color_first == b->color_first && a->text == b->text;
}

/* 1 when b draws exactly what a does (same primitives, points, colours, text, camera, clip
 * and background). */
static int dl_equal(const pl_draw_list *a, const pl_draw_list *b)
{
    if (a->prim_count != b->prim_count || a->point_count != b->point_count ||
        a->color_count != b->color_count || a->text_size != b->text_size ||
        a->has_clip != b->has_clip || memcmp(&a->camera, &b->camera, sizeof a->camera) ||
        memcmp(&a->clip, &b->clip, sizeof a->clip) ||
        memcmp(&a->background, &b->background, sizeof a->background))
        return 0;
    if (memcmp(a->points, b->points, (size_t)a->point_count * sizeof *a->points) ||
        memcmp(a->colors, b->colors, (size_t)a->color_count * sizeof *a->colors) ||
        memcmp(a->text, b->text, (size_t)a->text_size))
        return 0;
    for (int i = 0; i < a->prim_count; i++)
        if (!prim_equal(&a->prims[i], &b->prims[i])) return 0;
    return 1;
}

/* Compiles and links the shape and glyph programs. */
static GLuint link_one(pl_gl *g, const char *vsrc, const char *fsrc, char *err, size_t errlen)
{
    GLuint vs = compile(g, GL_VERTEX_SHADER, vsrc, err, errlen);
    GLuint fs = vs ? compile(g, GL_FRAGMENT_SHADER, fsrc, err, errlen) : 0;
    if (!fs) {
        if (vs) g->f.DeleteShader(vs);
        return 0;
    }
    GLuint prog = g->f.CreateProgram();
    g->f.AttachShader(prog, vs);
    g->f.AttachShader(prog, fs);
    g->f.BindAttribLocation(prog, 0, "a_pos");
    g->f.BindAttribLocation(prog, 1, "a_c0");
    g->f.BindAttribLocation(prog, 2, "a_c1");
    g->f.BindAttribLocation(prog, 3, "a_p");
    g->f.LinkProgram(prog);
    g->f.DeleteShader(vs);
    g->f.DeleteShader(fs);
    GLint ok = 0;
    g->f.GetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[512] = "";
        g->f.GetProgramInfoLog(prog, sizeof log, NULL, log);
        snprintf(err, errlen, "GL program link failed: %s", log);
        g->f.DeleteProgram(prog);
        return 0;
    }
    return prog;
}

static int link_programs(pl_gl *g, char *err, size_t errlen)
{
    g->prog[PROG_SHAPE] = link_one(g, vs_src, fs_shape_src, err, errlen);
    if (!g->prog[PROG_SHAPE]) return -1;
    g->prog[PROG_GLYPH] = link_one(g, vs_glyph_src, fs_glyph_src, err, errlen);
    g->prog[PROG_SOLID] = g->prog[PROG_GLYPH] ? link_one(g, vs_glyph_src, fs_solid_src, err, errlen) : 0;
    if (!g->prog[PROG_SOLID]) {
        g->f.DeleteProgram(g->prog[PROG_SHAPE]);
        if (g->prog[PROG_GLYPH]) g->f.DeleteProgram(g->prog[PROG_GLYPH]);
        return -1;
    }
    for (int k = 0; k < PROG_COUNT; k++) {
        g->u_size[k] = g->f.GetUniformLocation(g->prog[k], "u_size");
        g->u_clip[k] = g->f.GetUniformLocation(g->prog[k], "u_clip");
    }
    g->u_tex = g->f.GetUniformLocation(g->prog[PROG_GLYPH], "u_tex");
    g->u_core = g->f.GetUniformLocation(g->prog[PROG_SHAPE], "u_core");
    return 0;
}

/* ------------------------------------------------------------------ create */

pl_gl *pl_gl_create(pl_gl_get_proc get_proc, int samples, char *err, size_t errlen)
{
    pl_gl *g = calloc(1, sizeof *g);
    if (!g) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    if (pl_gl_funcs_load(&g->f, get_proc, err, (unsigned)errlen) != 0) {
        free(g);
        return NULL;
    }
    const char *rn = (const char *)g->f.GetString(GL_RENDERER);
    const char *vn = (const char *)g->f.GetString(GL_VERSION);
    snprintf(g->renderer, sizeof g->renderer, "%s", rn ? rn : "?");
    snprintf(g->version, sizeof g->version, "%s", vn ? vn : "?");
    if (pl_glyph_atlas_init(&g->atlas, err, errlen) != 0) {
        free(g);
        return NULL;
    }
    if (link_programs(g, err, errlen) != 0) {
        pl_glyph_atlas_free(&g->atlas);
        free(g);
        return NULL;
    }
    if (g->f.GenVertexArrays && g->f.BindVertexArray) {
        g->f.GenVertexArrays(1, &g->vao);
        g->f.BindVertexArray(g->vao);
    }
    GLuint bufs[2];
    g->f.GenBuffers(2, bufs);
    g->vbo = bufs[0];
    g->ibo = bufs[1];
    g->f.GenTextures(1, &g->tex);
    g->f.BindTexture(GL_TEXTURE_2D, g->tex);
    g->f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    g->f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    g->f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    g->f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    GLint max_samples = 0, max_rb = 0;
    if (g->f.RenderbufferStorageMultisample) g->f.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
    g->f.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_rb);
    g->max_size = max_rb > 0 ? max_rb : 4096;
    if (samples <= 0) { /* default 1: every edge is antialiased in the shaders */
        const char *env = getenv("PORELAB_GL_SAMPLES");
        samples = env && atoi(env) > 0 ? atoi(env) : 1;
    }
    if (samples > max_samples) samples = max_samples;
    if (samples < 2) samples = 1;
    /* llvmpipe and most drivers support 4 or 8; a count they reject falls back to 4, then 1 */
    g->samples = samples;
    g->f.GetError();
    return g;
}

void pl_gl_destroy(pl_gl **gp)
{
    if (!gp || !*gp) return;
    pl_gl *g = *gp;
    free_fbos(g);
    GLuint bufs[2] = {g->vbo, g->ibo};
    g->f.DeleteBuffers(2, bufs);
    g->f.DeleteTextures(1, &g->tex);
    for (int k = 0; k < PROG_COUNT; k++) g->f.DeleteProgram(g->prog[k]);
    if (g->vao && g->f.DeleteVertexArrays) g->f.DeleteVertexArrays(1, &g->vao);
    pl_glyph_atlas_free(&g->atlas);
    free(g->v);
    free(g->ix);
    free(g->bt);
    pl_draw_list_free(&g->last);
    free(g);
    *gp = NULL;
}

double pl_gl_text_width(pl_gl *g, const char *s, float size)
{
    return pl_text_advance(&g->atlas, s, size);
}

const char *pl_gl_renderer_name(const pl_gl *g) { return g->renderer; }
const char *pl_gl_version(const pl_gl *g) { return g->version; }
int pl_gl_samples(const pl_gl *g) { return g->samples; }
void pl_gl_last_counts(const pl_gl *g, long *vertices, long *indices)
{
    *vertices = g->nv;
    *indices = g->ni;
}

/* ------------------------------------------------------------- geometry */

static int reserve(pl_gl *g, long nv, long ni)
{
    if (g->failed) return -1;
    if (g->nv + nv > g->cv) {
        long c = g->cv ? g->cv : 4096;
        while (c < g->nv + nv) c *= 2;
        gv *p = realloc(g->v, (size_t)c * sizeof *p);
        if (!p) { g->failed = 1; return -1; }
        g->v = p;
        g->cv = c;
    }
    if (g->ni + ni > g->ci) {
        long c = g->ci ? g->ci : 8192;
        while (c < g->ni + ni) c *= 2;
        uint32_t *p = realloc(g->ix, (size_t)c * sizeof *p);
        if (!p) { g->failed = 1; return -1; }
        g->ix = p;
        g->ci = c;
    }
    return 0;
}

/* Call before adding the indices of a primitive: starts a new batch when the program, the
 * clip or the depth test changes (painter's order is the order of the batches). Depth is
 * tested only where a primitive is drawn in overlapping pieces that must blend once
 * (translucent strokes, the grown Gouraud triangles); everything else needs no test. */
static void state(pl_gl *g, int prog, int depth)
{
    if (g->failed) return;
    if (g->nb > 0 && !g->fresh) {
        gl_batch *b = &g->bt[g->nb - 1];
        if (b->prog == prog && b->clip == g->clip && b->depth == depth) return;
        b->count = g->ni - b->first;
        if (b->count == 0) {
            b->prog = (uint8_t)prog;
            b->clip = (uint8_t)g->clip;
            b->depth = (uint8_t)depth;
            return;
        }
    }
    if (g->nb == g->cb) {
        int c = g->cb ? 2 * g->cb : 64;
        gl_batch *p = realloc(g->bt, (size_t)c * sizeof *p);
        if (!p) { g->failed = 1; return; }
        g->bt = p;
        g->cb = c;
    }
    g->fresh = 0;
    gl_batch *b = &g->bt[g->nb++];
    b->first = g->ni;
    b->count = 0;
    b->prog = (uint8_t)prog;
    b->clip = (uint8_t)g->clip;
    b->depth = (uint8_t)depth;
}

/* Each primitive gets a depth just in front of all earlier ones: later primitives always
 * pass GL_LESS, and pieces of the same primitive never draw twice on one sample. */
static void next_depth(pl_gl *g)
{
    const float step = 1.0f / 2097152.0f; /* 2^-21: distinct in a 24-bit depth buffer */
    if (g->z > -1.0f + step) g->z -= step;
}

static void to_u8(uint8_t out[4], pl_rgba c)
{
    float k[4] = {c.r, c.g, c.b, c.a};
    for (int i = 0; i < 4; i++) {
        float x = k[i] < 0.0f ? 0.0f : k[i] > 1.0f ? 1.0f : k[i];
        out[i] = (uint8_t)lrintf(x * 255.0f);
    }
}

/* A vertex of solid geometry in colour col (coverage 1 in the shape shader). */
static gv *vert(pl_gl *g, double x, double y, const uint8_t col[4])
{
    gv *v = &g->v[g->nv++];
    v->x = (float)x;
    v->y = (float)y;
    v->z = g->z;
    memset(v->c0, 0, 4);
    memcpy(v->c1, col, 4);
    v->p[0] = v->p[1] = v->p[2] = 0.0f;
    v->p[3] = HUGE_HW;
    return v;
}

static void quad_idx(pl_gl *g, uint32_t b)
{
    uint32_t *i = g->ix + g->ni;
    i[0] = b; i[1] = b + 1; i[2] = b + 2;
    i[3] = b; i[4] = b + 2; i[5] = b + 3;
    g->ni += 6;
}

static void add_circle(pl_gl *g, pl_vec2 c, double r, const pl_prim *p)
{
    if (!(r > 0.0) || !isfinite(r)) return;
    uint8_t f[4] = {0, 0, 0, 0}, s[4] = {0, 0, 0, 0};
    double w = 0.0;
    if (p->has_fill) to_u8(f, p->fill);
    if (p->has_stroke && p->width > 0.0f) {
        to_u8(s, p->stroke);
        w = p->width;
    }
    if (reserve(g, 4, 6)) return;
    state(g, PROG_SHAPE, 0);
    next_depth(g);
    double e = r + 0.5 * w + 0.75; /* coverage is zero beyond r + w/2 + 0.5 */
    uint32_t b = (uint32_t)g->nv;
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; k++) {
        gv *v = vert(g, c.x + sx[k] * e, c.y + sy[k] * e, s);
        memcpy(v->c0, f, 4);
        v->p[0] = (float)(sx[k] * e);
        v->p[1] = (float)(sy[k] * e);
        v->p[2] = (float)-r;
        v->p[3] = (float)(0.5 * w);
    }
    quad_idx(g, b);
}

/* A capsule (round caps) or, with butt = 1, a plain bar from a to b, full width w. The
 * caller sets the state. */
static void add_capsule(pl_gl *g, pl_vec2 a, pl_vec2 b, double w, const uint8_t col[4], int butt)
{
    if (!(w > 0.0)) return;
    double dx = b.x - a.x, dy = b.y - a.y, L = sqrt(dx * dx + dy * dy);
    double ux = 1.0, uy = 0.0;
    if (L > 1e-9) { ux = dx / L; uy = dy / L; }
    else L = 0.0;
    if (butt && L == 0.0) return;
    double nx = -uy, ny = ux, hw = 0.5 * w, e = hw + 0.75; /* zero coverage beyond hw + 0.5 */
    if (reserve(g, 4, 6)) return;
    uint32_t base = (uint32_t)g->nv;
    const double along[4] = {-e, L + e, L + e, -e}, across[4] = {-e, -e, e, e};
    for (int k = 0; k < 4; k++) {
        gv *v = vert(g, a.x + ux * along[k] + nx * across[k], a.y + uy * along[k] + ny * across[k],
                     col);
        v->p[0] = (float)along[k];
        v->p[1] = (float)across[k];
        v->p[2] = (float)L;
        v->p[3] = (float)(butt ? -hw : hw);
    }
    quad_idx(g, base);
}

/* Stroke of a path: capsules (round caps and joins, analytic edges). An opaque stroke
 * gives each capsule its own depth (overlaps need no single coverage); a translucent one
 * shares one depth and is drawn in two passes (batch depth 2, see pl_gl_render): first the
 * fully covered cores, which write depth, then the antialiased rims where no core was
 * drawn, so the overlapping pieces of one stroke blend once (as cairo strokes one path);
 * only the thin rims of two pieces that overlap outside every core blend twice. */
static void add_stroke(pl_gl *g, const pl_draw_list *dl, const pl_prim *p, int closed,
                       int pairs)
{
    int n = p->count;
    if (n < 2 || !(p->width > 0.0f)) return;
    uint8_t col[4];
    to_u8(col, p->stroke);
    const pl_vec2 *pts = dl->points + p->first;
    int opaque = col[3] == 255;
    state(g, PROG_SHAPE, opaque ? 0 : 2);
    next_depth(g);
    int nseg = pairs ? n / 2 : (closed ? n : n - 1);
    for (int s = 0; s < nseg; s++) {
        int i0 = pairs ? 2 * s : s, i1 = pairs ? 2 * s + 1 : (s + 1) % n;
        if (opaque && s > 0) next_depth(g);
        add_capsule(g, pl_dl_px(dl, p, pts[i0]), pl_dl_px(dl, p, pts[i1]), p->width, col, 0);
    }
}

static double cross3(pl_vec2 a, pl_vec2 b, pl_vec2 c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

static int point_in_tri(pl_vec2 p, pl_vec2 a, pl_vec2 b, pl_vec2 c, double sign)
{
    return sign * cross3(a, b, p) >= 0 && sign * cross3(b, c, p) >= 0 &&
           sign * cross3(c, a, p) >= 0;
}

/* Antialiased fill of a convex polygon (pixel coordinates, either orientation, n >= 3):
 * for each edge, the triangle from an inner point to the edge and the strip from the edge
 * to the edge moved 0.5 px outward (mitred corners, so neighbouring strips meet on the
 * corner's bisector), carrying the signed distance to that edge; the shape shader turns it
 * into the coverage clamp(s + 0.5), exact along straight edges. Returns 0 when drawn (or
 * nothing to draw), 1 when the polygon is too large for the distance encoding (the caller
 * then fills it without the ramp). */
static int add_fill_aa(pl_gl *g, const pl_vec2 *pts, int n, const uint8_t col[4])
{
    pl_vec2 sbuf[64], *q = n <= 64 ? sbuf : malloc((size_t)n * sizeof *q);
    pl_vec2 nbuf[64], *nn = n <= 64 ? nbuf : malloc((size_t)n * sizeof *nn);
    int rc = 0;
    if (!q || !nn) { g->failed = 1; goto done; }
    int m = 0; /* drop repeated points */
    for (int i = 0; i < n; i++) {
        pl_vec2 a = pts[i];
        if (m > 0 && fabs(a.x - q[m - 1].x) < 1e-9 && fabs(a.y - q[m - 1].y) < 1e-9) continue;
        q[m++] = a;
    }
    while (m > 1 && fabs(q[0].x - q[m - 1].x) < 1e-9 && fabs(q[0].y - q[m - 1].y) < 1e-9) m--;
    if (m < 3) goto done;
    double area2 = 0.0, cx = 0.0, cy = 0.0;
    for (int i = 0; i < m; i++) {
        pl_vec2 a = q[i], b = q[(i + 1) % m];
        area2 += a.x * b.y - b.x * a.y;
        cx += a.x;
        cy += a.y;
    }
    if (!(fabs(area2) > 1e-12)) goto done;
    cx /= m;
    cy /= m;
    double sgn = area2 > 0 ? 1.0 : -1.0;
    for (int i = 0; i < m; i++) { /* outward unit normal of edge i (q[i] -> q[i+1]) */
        pl_vec2 a = q[i], b = q[(i + 1) % m];
        double ex = b.x - a.x, ey = b.y - a.y, l = sqrt(ex * ex + ey * ey);
        nn[i] = (pl_vec2){sgn * ey / l, -sgn * ex / l};
        double s = (a.x - cx) * nn[i].x + (a.y - cy) * nn[i].y; /* inner point's distance */
        if (!(s < 0.45 * HUGE_HW)) { rc = 1; goto done; }
    }
    if (reserve(g, 5L * m, 9L * m)) goto done;
    state(g, PROG_SHAPE, 0);
    next_depth(g);
    const double d = 0.5;
    for (int i = 0; i < m; i++) {
        pl_vec2 a = q[i], b = q[(i + 1) % m], ni = nn[i];
        pl_vec2 o[2];
        for (int k = 0; k < 2; k++) { /* mitred offsets of a (edges i-1, i) and b (i, i+1) */
            pl_vec2 n1 = k == 0 ? nn[(i + m - 1) % m] : ni, n2 = k == 0 ? ni : nn[(i + 1) % m];
            double dot = n1.x * n2.x + n1.y * n2.y;
            double f = d / (1.0 + dot > 1e-6 ? 1.0 + dot : 1e-6);
            double ox = (n1.x + n2.x) * f, oy = (n1.y + n2.y) * f, len = sqrt(ox * ox + oy * oy);
            if (len > 4.0 * d) { ox *= 4.0 * d / len; oy *= 4.0 * d / len; }
            o[k] = (pl_vec2){ox, oy};
        }
        const double px[5] = {cx, a.x, b.x, a.x + o[0].x, b.x + o[1].x};
        const double py[5] = {cy, a.y, b.y, a.y + o[0].y, b.y + o[1].y};
        uint32_t base = (uint32_t)g->nv;
        for (int k = 0; k < 5; k++) {
            double s = (a.x - px[k]) * ni.x + (a.y - py[k]) * ni.y; /* > 0 inside */
            gv *v = vert(g, px[k], py[k], col);
            v->p[1] = (float)(HUGE_HW - s);
        }
        uint32_t *ix = g->ix + g->ni;
        ix[0] = base; ix[1] = base + 1; ix[2] = base + 2;
        ix[3] = base + 1; ix[4] = base + 2; ix[5] = base + 4;
        ix[6] = base + 1; ix[7] = base + 4; ix[8] = base + 3;
        g->ni += 9;
    }
done:
    if (q && q != sbuf) free(q);
    if (nn && nn != nbuf) free(nn);
    return rc;
}

static void add_fill(pl_gl *g, const pl_draw_list *dl, const pl_prim *p)
{
    int n = p->count;
    if (n < 3) return;
    uint8_t col[4];
    to_u8(col, p->fill);
    const pl_vec2 *pts = dl->points + p->first;
    /* convex (all turns one way): antialiased fill */
    int pos = 0, neg = 0;
    {
        pl_vec2 a = pl_dl_px(dl, p, pts[0]), b = pl_dl_px(dl, p, pts[1 % n]);
        pl_vec2 a0 = a, b0 = b;
        for (int i = 0; i < n; i++) {
            pl_vec2 c = i + 2 < n ? pl_dl_px(dl, p, pts[i + 2]) : (i + 2 == n ? a0 : b0);
            double cr = cross3(a, b, c);
            if (cr > 1e-12) pos++;
            else if (cr < -1e-12) neg++;
            a = b;
            b = c;
        }
    }
    if (pos == 0 || neg == 0) {
        pl_vec2 sbuf[64], *q = n <= 64 ? sbuf : malloc((size_t)n * sizeof *q);
        if (!q) { g->failed = 1; return; }
        for (int i = 0; i < n; i++) q[i] = pl_dl_px(dl, p, pts[i]);
        int rc = add_fill_aa(g, q, n, col);
        if (q != sbuf) free(q);
        if (rc == 0) return;
    }
    if (reserve(g, n, 3 * (n - 2))) return;
    state(g, PROG_SOLID, 0);
    next_depth(g);
    uint32_t b = (uint32_t)g->nv;
    double area = 0.0;
    for (int i = 0; i < n; i++) {
        pl_vec2 q = pl_dl_px(dl, p, pts[i]);
        vert(g, q.x, q.y, col);
    }
    gv *v = g->v + b;
    for (int i = 0; i < n; i++) {
        pl_vec2 a = {v[i].x, v[i].y}, c = {v[(i + 1) % n].x, v[(i + 1) % n].y};
        area += a.x * c.y - c.x * a.y;
    }
    if (pos == 0 || neg == 0) { /* convex but huge: fan */
        for (int i = 1; i + 1 < n; i++) {
            uint32_t *ix = g->ix + g->ni;
            ix[0] = b; ix[1] = b + (uint32_t)i; ix[2] = b + (uint32_t)i + 1;
            g->ni += 3;
        }
        return;
    }
    /* concave: ear clipping, O(n^2), on a scratch index list kept in the index buffer tail */
    double sign = area > 0 ? 1.0 : -1.0;
    int *idx = malloc((size_t)n * sizeof *idx);
    if (!idx) { g->failed = 1; return; }
    for (int i = 0; i < n; i++) idx[i] = i;
    int m = n, guard = 0;
    while (m > 3 && guard < 2 * n * n) {
        int found = 0;
        for (int k = 0; k < m && !found; k++) {
            int i0 = idx[(k + m - 1) % m], i1 = idx[k], i2 = idx[(k + 1) % m];
            pl_vec2 a = {v[i0].x, v[i0].y}, c = {v[i1].x, v[i1].y}, d = {v[i2].x, v[i2].y};
            if (sign * cross3(a, c, d) <= 0) continue;
            int inside = 0;
            for (int j = 0; j < m && !inside; j++) {
                int t = idx[j];
                if (t == i0 || t == i1 || t == i2) continue;
                inside = point_in_tri((pl_vec2){v[t].x, v[t].y}, a, c, d, sign);
            }
            if (inside) continue;
            uint32_t *ix = g->ix + g->ni;
            ix[0] = b + (uint32_t)i0; ix[1] = b + (uint32_t)i1; ix[2] = b + (uint32_t)i2;
            g->ni += 3;
            memmove(idx + k, idx + k + 1, (size_t)(m - k - 1) * sizeof *idx);
            m--;
            found = 1;
        }
        if (!found) break; /* self-intersecting outline: fan the rest */
        guard++;
    }
    for (int i = 1; i + 1 < m; i++) {
        uint32_t *ix = g->ix + g->ni;
        ix[0] = b + (uint32_t)idx[0]; ix[1] = b + (uint32_t)idx[i]; ix[2] = b + (uint32_t)idx[i + 1];
        g->ni += 3;
    }
    free(idx);
}

static void add_triangles(pl_gl *g, const pl_draw_list *dl, const pl_prim *p)
{
    int nt = p->count / 3;
    if (nt <= 0 || reserve(g, 3L * nt, 3L * nt)) return;
    state(g, PROG_SOLID, 1);
    next_depth(g);
    const pl_vec2 *pts = dl->points + p->first;
    const pl_rgba *cols = dl->colors + p->color_first;
    /* Each triangle is grown by 0.3 px (edges moved outward, mitred corners, capped): field
     * meshes refined adaptively have T-junctions, whose rounding gaps would show as thin
     * light seams. The batch shares one depth value, so the overlaps are drawn once and
     * colours are continuous across edges. */
    const double d = 0.3;
    for (int t = 0; t < nt; t++) {
        pl_vec2 q[3];
        for (int k = 0; k < 3; k++) q[k] = pl_dl_px(dl, p, pts[3 * t + k]);
        double area2 = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
        double sgn = area2 > 0 ? 1.0 : -1.0;
        pl_vec2 n[3]; /* outward unit normal of edge k (from q[k] to q[k+1]) */
        int ok = area2 != 0.0;
        for (int k = 0; k < 3 && ok; k++) {
            pl_vec2 a = q[k], b = q[(k + 1) % 3];
            double ex = b.x - a.x, ey = b.y - a.y, l = sqrt(ex * ex + ey * ey);
            if (!(l > 1e-9)) { ok = 0; break; }
            n[k] = (pl_vec2){sgn * ey / l, -sgn * ex / l};
        }
        for (int k = 0; k < 3; k++) {
            uint8_t c[4];
            to_u8(c, cols[3 * t + k]);
            double x = q[k].x, y = q[k].y;
            if (ok) {
                pl_vec2 n1 = n[(k + 2) % 3], n2 = n[k]; /* the two edges meeting at q[k] */
                double dot = n1.x * n2.x + n1.y * n2.y;
                double ox = (n1.x + n2.x), oy = (n1.y + n2.y);
                double f = d / (1.0 + dot > 1e-6 ? 1.0 + dot : 1e-6);
                ox *= f;
                oy *= f;
                double len = sqrt(ox * ox + oy * oy);
                if (len > 4.0 * d) { ox *= 4.0 * d / len; oy *= 4.0 * d / len; }
                x += ox;
                y += oy;
            }
            g->ix[g->ni++] = (uint32_t)g->nv;
            vert(g, x, y, c);
        }
    }
}

static void add_arrow(pl_gl *g, const pl_draw_list *dl, const pl_prim *p)
{
    pl_vec2 a = pl_dl_px(dl, p, dl->points[p->first]);
    pl_vec2 b = pl_dl_px(dl, p, dl->points[p->first + 1]);
    double dx = b.x - a.x, dy = b.y - a.y, len = sqrt(dx * dx + dy * dy);
    if (!(len > 0.0)) return;
    double ux = dx / len, uy = dy / len;
    double head = p->size;
    if (head > 0.6 * len) head = 0.6 * len;
    double half = 0.42 * head;
    if (half < 0.5 * p->width) half = 0.5 * p->width;
    double bx = b.x - ux * head, by = b.y - uy * head;
    uint8_t sc[4], fc[4];
    to_u8(sc, p->stroke);
    to_u8(fc, p->fill);
    state(g, PROG_SHAPE, 0);
    next_depth(g);
    add_capsule(g, a, (pl_vec2){bx + ux * 0.5, by + uy * 0.5}, p->width, sc, 1);
    const pl_vec2 tri[3] = {b, {bx - uy * half, by + ux * half}, {bx + uy * half, by - ux * half}};
    add_fill_aa(g, tri, 3, fc);
}

/* Text as in the cairo backend: horizontal anchor from the advance width, vertical anchor
 * from the cap height (0.729 em) or the descent; glyphs at whole pixels when unrotated; a
 * halo is a background box (padding 0.18 em) in the halo colour. */
static void add_text(pl_gl *g, const pl_draw_list *dl, const pl_prim *p)
{
    const char *s = dl->text + p->text;
    pl_vec2 at = pl_dl_px(dl, p, dl->points[p->first]);
    float size = p->size;
    if (!(size > 0.0f)) return;
    double adv = pl_text_advance(&g->atlas, s, size);
    double x = 0.0, y = 0.0;
    switch (PL_ANCHOR_H(p->anchor)) {
    case PL_ANCHOR_CENTER: x = -0.5 * adv; break;
    case PL_ANCHOR_RIGHT: x = -adv; break;
    default: break;
    }
    double cap = 0.729 * size;
    switch (PL_ANCHOR_V(p->anchor)) {
    case PL_ANCHOR_TOP: y = cap; break;
    case PL_ANCHOR_MIDDLE: y = 0.5 * cap; break;
    case PL_ANCHOR_BOTTOM: y = g->atlas.descender * size; break;
    default: break;
    }
    double ca = cos(-p->angle), sa = sin(-p->angle);
    int rotated = p->angle != 0.0f;
    const double inv = 1.0 / PL_ATLAS_SIZE;
    if (p->has_halo) { /* a background box a little larger than the text, as cairo */
        double pad = 0.18 * size;
        double bx0 = x - pad, by0 = y - cap - pad, bx1 = x + adv + pad, by1 = y + pad;
        const double lx[4] = {bx0, bx1, bx1, bx0}, ly[4] = {by0, by0, by1, by1};
        uint8_t bc[4];
        to_u8(bc, p->stroke);
        pl_vec2 box[4];
        for (int k = 0; k < 4; k++)
            box[k] = (pl_vec2){at.x + lx[k] * ca - ly[k] * sa, at.y + lx[k] * sa + ly[k] * ca};
        add_fill_aa(g, box, 4, bc);
    }
    {
        uint8_t col[4];
        to_u8(col, p->fill);
        double pen = x;
        for (const char *q = s; *q;) {
            uint32_t c = pl_utf8_next(&q);
            const pl_glyph *gl = pl_glyph_get(&g->atlas, c, size, 0);
            if (!gl) continue;
            if (gl->w > 0 && gl->h > 0) {
                if (reserve(g, 4, 6)) return;
                state(g, PROG_GLYPH, 0);
                next_depth(g);
                double lx[4], ly[4];
                double x0 = pen + gl->left, y0 = y - gl->top;
                lx[0] = x0; ly[0] = y0;
                lx[1] = x0 + gl->w; ly[1] = y0;
                lx[2] = x0 + gl->w; ly[2] = y0 + gl->h;
                lx[3] = x0; ly[3] = y0 + gl->h;
                double ox = 0.0, oy = 0.0;
                if (!rotated) { /* whole-pixel glyph origin, as cairo's image backend */
                    ox = floor(at.x + pen + 0.5) - (at.x + pen);
                    oy = floor(at.y + y + 0.5) - (at.y + y);
                }
                const double u[4] = {gl->x, gl->x + gl->w, gl->x + gl->w, gl->x};
                const double vv[4] = {gl->y, gl->y, gl->y + gl->h, gl->y + gl->h};
                uint32_t base = (uint32_t)g->nv;
                for (int k = 0; k < 4; k++) {
                    double px = lx[k] + ox, py = ly[k] + oy;
                    gv *v = vert(g, at.x + px * ca - py * sa, at.y + px * sa + py * ca, col);
                    v->p[0] = (float)(u[k] * inv);
                    v->p[1] = (float)(vv[k] * inv);
                    v->p[2] = rotated ? 0.0f : (float)PL_ATLAS_SIZE;
                    v->p[3] = 0.0f;
                }
                quad_idx(g, base);
            }
            pen += gl->advance;
        }
    }
}

/* Adds the primitives of dl; world-space ones are clipped when has_clip (the frame's). */
static void build_list(pl_gl *g, const pl_draw_list *dl, int has_clip)
{
    for (int i = 0; i < dl->prim_count; i++) {
        const pl_prim *p = &dl->prims[i];
        g->clip = has_clip && p->space == PL_SPACE_WORLD;
        switch (p->kind) {
        case PL_PRIM_CIRCLE:
            add_circle(g, pl_dl_px(dl, p, dl->points[p->first]), pl_dl_px_radius(dl, p), p);
            break;
        case PL_PRIM_POLYGON:
            if (p->has_fill) add_fill(g, dl, p);
            if (p->has_stroke) add_stroke(g, dl, p, 1, 0);
            break;
        case PL_PRIM_POLYLINE:
            if (p->count == 2) { /* the common single line: one capsule */
                uint8_t col[4];
                to_u8(col, p->stroke);
                state(g, PROG_SHAPE, 0);
                next_depth(g);
                add_capsule(g, pl_dl_px(dl, p, dl->points[p->first]),
                            pl_dl_px(dl, p, dl->points[p->first + 1]), p->width, col, 0);
            } else {
                add_stroke(g, dl, p, 0, 0);
            }
            break;
        case PL_PRIM_SEGMENTS: add_stroke(g, dl, p, 0, 1); break;
        case PL_PRIM_TRIANGLES: add_triangles(g, dl, p); break;
        case PL_PRIM_ARROW: add_arrow(g, dl, p); break;
        case PL_PRIM_TEXT: add_text(g, dl, p); break;
        default: break;
        }
    }
}

/* Vertices of dl (unless scene = 0: only its clip is used) and then of over; the overlay
 * starts a new batch (g->nb_scene = batches of the scene). */
static void build(pl_gl *g, const pl_draw_list *dl, const pl_draw_list *over, int scene)
{
    g->nv = g->ni = 0;
    g->nb = 0;
    g->failed = 0;
    g->fresh = 0;
    g->z = 1.0f;
    if (scene) build_list(g, dl, dl->has_clip);
    if (g->nb > 0) g->bt[g->nb - 1].count = g->ni - g->bt[g->nb - 1].first;
    while (g->nb > 0 && g->bt[g->nb - 1].count == 0) g->nb--;
    g->nb_scene = g->nb;
    if (over) {
        g->fresh = 1; /* the overlay opens a batch of its own */
        build_list(g, over, dl->has_clip);
    }
    if (g->nb > 0) g->bt[g->nb - 1].count = g->ni - g->bt[g->nb - 1].first;
}

/* ------------------------------------------------------------------ render */

/* Copies the scene drawn so far into the cache (and remembers its draw list). */
static void store_scene(pl_gl *g, const pl_draw_list *dl)
{
    const pl_gl_funcs *f = &g->f;
    int w = g->fb_w, h = g->fb_h;
    f->BindFramebuffer(GL_READ_FRAMEBUFFER, g->fbo_ms);
    f->BindFramebuffer(GL_DRAW_FRAMEBUFFER, g->fbo_cache);
    f->BlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    f->BindFramebuffer(GL_FRAMEBUFFER, g->fbo_ms);
    pl_draw_list_clear(&g->last);
    pl_draw_list_append(&g->last, dl);
    g->last.camera = dl->camera;
    g->last.clip = dl->clip;
    g->last.has_clip = dl->has_clip;
    g->last.background = dl->background;
    g->cache_ok = !g->last.failed;
}

int pl_gl_render(pl_gl *g, const pl_draw_list *dl, char *err, size_t errlen)
{
    return pl_gl_render_over(g, dl, NULL, err, errlen);
}

int pl_gl_render_over(pl_gl *g, const pl_draw_list *dl, const pl_draw_list *over, char *err,
                      size_t errlen)
{
    if (dl->failed || (over && over->failed)) {
        snprintf(err, errlen, "the draw list is incomplete (out of memory while building it)");
        return -1;
    }
    int w = dl->camera.width, h = dl->camera.height;
    if (w <= 0 || h <= 0) {
        snprintf(err, errlen, "image size %dx%d is out of range", w, h);
        return -1;
    }
    /* with an overlay (the window), an unchanged scene is copied from the cache and only the
     * overlay is drawn: the same pixels, since the overlay is painted after the scene */
    int cached = over && g->cache_ok && g->fb_w == w && g->fb_h == h && dl_equal(&g->last, dl);
    int gen = g->atlas.generation;
    build(g, dl, over, !cached);
    if (g->atlas.generation != gen) build(g, dl, over, !cached); /* atlas cleared mid-frame */
    if (g->failed) {
        snprintf(err, errlen, "out of memory while building the GL frame");
        return -1;
    }
    if (ensure_fbos(g, w, h, err, errlen) != 0) {
        if (g->samples > 4) { /* some drivers refuse 8 samples: retry with 4, then none */
            g->samples = 4;
            if (ensure_fbos(g, w, h, err, errlen) == 0) goto ok;
        }
        if (g->samples > 1) {
            g->samples = 1;
            if (ensure_fbos(g, w, h, err, errlen) == 0) goto ok;
        }
        return -1;
    }
ok:
    g->width = w;
    g->height = h;
    const pl_gl_funcs *f = &g->f;
    if (over && ensure_cache(g) != 0) {
        snprintf(err, errlen, "GL framebuffer %dx%d for the scene cache incomplete", w, h);
        return -1;
    }
    f->Disable(GL_SCISSOR_TEST);
    if (cached) {
        f->BindFramebuffer(GL_READ_FRAMEBUFFER, g->fbo_cache);
        f->BindFramebuffer(GL_DRAW_FRAMEBUFFER, g->fbo_ms);
        f->BlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    f->BindFramebuffer(GL_FRAMEBUFFER, g->fbo_ms);
    f->Viewport(0, 0, w, h);
    pl_rgba bg = dl->background;
    f->ClearColor(bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a);
    f->ClearDepth(1.0);
    f->DepthMask(GL_TRUE);
    f->Clear(cached ? GL_DEPTH_BUFFER_BIT : GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (over && !cached) g->cache_ok = 0;
    if (g->ni > 0) {
        f->ActiveTexture(GL_TEXTURE0);
        f->BindTexture(GL_TEXTURE_2D, g->tex);
        if (g->atlas.dirty) {
            f->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
            f->TexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, PL_ATLAS_SIZE, PL_ATLAS_SIZE, 0,
                          GL_LUMINANCE, GL_UNSIGNED_BYTE, g->atlas.pixels);
            g->atlas.dirty = 0;
        }
        f->Enable(GL_BLEND);
        f->BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        f->DepthFunc(GL_LESS);
        if (g->samples > 1) f->Enable(GL_MULTISAMPLE);
        /* the buffers keep their storage between frames (reallocated only to grow): a new
         * allocation per frame costs page faults on the whole vertex array in llvmpipe */
        long vb = g->nv * (long)sizeof(gv), ib = g->ni * (long)sizeof(uint32_t);
        f->BindBuffer(GL_ARRAY_BUFFER, g->vbo);
        if (vb > g->vbo_bytes) {
            g->vbo_bytes = vb + vb / 4;
            f->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)g->vbo_bytes, NULL, GL_DYNAMIC_DRAW);
        }
        f->BufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)vb, g->v);
        f->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, g->ibo);
        if (ib > g->ibo_bytes) {
            g->ibo_bytes = ib + ib / 4;
            f->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)g->ibo_bytes, NULL, GL_DYNAMIC_DRAW);
        }
        f->BufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, (GLsizeiptr)ib, g->ix);
        const GLsizei st = (GLsizei)sizeof(gv);
        for (GLuint a = 0; a < 4; a++) f->EnableVertexAttribArray(a);
        f->VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, st, (const void *)offsetof(gv, x));
        f->VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, st, (const void *)offsetof(gv, c0));
        f->VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, st, (const void *)offsetof(gv, c1));
        f->VertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, st, (const void *)offsetof(gv, p));
        /* the clip rectangle in GL window coordinates (y up) */
        const float cx0 = (float)dl->clip.x0, cx1 = (float)dl->clip.x1;
        const float cy0 = (float)(h - dl->clip.y1), cy1 = (float)(h - dl->clip.y0);
        int cur_prog = -1, cur_clip = -1, cur_depth = -1;
        for (int i = 0; i < g->nb; i++) {
            const gl_batch *bt = &g->bt[i];
            if (over && !cached && i == g->nb_scene) store_scene(g, dl);
            if (bt->count <= 0) continue;
            if (bt->prog != cur_prog) {
                cur_prog = bt->prog;
                cur_clip = -1;
                f->UseProgram(g->prog[cur_prog]);
                f->Uniform2f(g->u_size[cur_prog], (float)w, (float)h);
                if (cur_prog == PROG_SHAPE) f->Uniform1f(g->u_core, 0.0f);
                if (cur_prog == PROG_GLYPH) f->Uniform1i(g->u_tex, 0);
            }
            if (bt->clip != cur_clip) {
                cur_clip = bt->clip;
                if (cur_clip) f->Uniform4f(g->u_clip[cur_prog], cx0, cy0, cx1, cy1);
                else f->Uniform4f(g->u_clip[cur_prog], -1e9f, -1e9f, 1e9f, 1e9f);
            }
            if (bt->depth != cur_depth) {
                cur_depth = bt->depth;
                if (cur_depth) f->Enable(GL_DEPTH_TEST);
                else f->Disable(GL_DEPTH_TEST);
            }
            const void *off = (const void *)(bt->first * (long)sizeof(uint32_t));
            if (bt->depth == 2) { /* translucent stroke: cores (writing depth), then rims */
                f->Uniform1f(g->u_core, 0.999f);
                f->DrawElements(GL_TRIANGLES, (GLsizei)bt->count, GL_UNSIGNED_INT, off);
                f->Uniform1f(g->u_core, 0.0f);
                f->DepthMask(GL_FALSE);
                f->DrawElements(GL_TRIANGLES, (GLsizei)bt->count, GL_UNSIGNED_INT, off);
                f->DepthMask(GL_TRUE);
                continue;
            }
            f->DrawElements(GL_TRIANGLES, (GLsizei)bt->count, GL_UNSIGNED_INT,
                            (const void *)(bt->first * (long)sizeof(uint32_t)));
        }
        f->Disable(GL_DEPTH_TEST);
        f->Disable(GL_BLEND);
    }
    if (over && !cached && !g->cache_ok) store_scene(g, dl); /* an overlay without batches */
    f->BindFramebuffer(GL_READ_FRAMEBUFFER, g->fbo_ms);
    f->BindFramebuffer(GL_DRAW_FRAMEBUFFER, g->fbo_res);
    f->BlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    f->BindFramebuffer(GL_FRAMEBUFFER, 0);
    GLenum e = f->GetError();
    if (e != GL_NO_ERROR) {
        snprintf(err, errlen, "OpenGL error 0x%x while drawing a %dx%d frame", e, w, h);
        return -1;
    }
    return 0;
}

int pl_gl_read(pl_gl *g, pl_image *img, char *err, size_t errlen)
{
    int w = g->width, h = g->height;
    if (w <= 0 || h <= 0) {
        snprintf(err, errlen, "nothing rendered yet");
        return -1;
    }
    if (!img->rgba || img->width != w || img->height != h) {
        uint8_t *buf = realloc(img->rgba, (size_t)w * (size_t)h * 4u);
        if (!buf) {
            snprintf(err, errlen, "out of memory for a %dx%d image", w, h);
            return -1;
        }
        img->rgba = buf;
        img->width = w;
        img->height = h;
    }
    const pl_gl_funcs *f = &g->f;
    f->BindFramebuffer(GL_READ_FRAMEBUFFER, g->fbo_res);
    f->PixelStorei(GL_PACK_ALIGNMENT, 1);
    f->ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, img->rgba);
    f->BindFramebuffer(GL_FRAMEBUFFER, 0);
    /* GL rows go bottom to top: flip; un-premultiply like the cairo backend */
    size_t row = (size_t)w * 4u;
    uint8_t tmp[4 * 4096];
    for (int y = 0; y < h / 2; y++) {
        uint8_t *a = img->rgba + (size_t)y * row, *b = img->rgba + (size_t)(h - 1 - y) * row;
        for (size_t off = 0; off < row; off += sizeof tmp) {
            size_t n = row - off < sizeof tmp ? row - off : sizeof tmp;
            memcpy(tmp, a + off, n);
            memcpy(a + off, b + off, n);
            memcpy(b + off, tmp, n);
        }
    }
    size_t npx = (size_t)w * (size_t)h;
    for (size_t i = 0; i < npx; i++) {
        uint8_t *px = img->rgba + 4 * i;
        unsigned a = px[3];
        if (a != 255u && a != 0u)
            for (int k = 0; k < 3; k++) {
                unsigned v = (px[k] * 255u + a / 2u) / a;
                px[k] = (uint8_t)(v > 255u ? 255u : v);
            }
    }
    GLenum e = f->GetError();
    if (e != GL_NO_ERROR) {
        snprintf(err, errlen, "OpenGL error 0x%x while reading the frame", e);
        return -1;
    }
    return 0;
}

void pl_gl_present(pl_gl *g, int win_w, int win_h)
{
    const pl_gl_funcs *f = &g->f;
    f->BindFramebuffer(GL_READ_FRAMEBUFFER, g->fbo_res);
    f->BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    f->Viewport(0, 0, win_w, win_h);
    f->ClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    f->Clear(GL_COLOR_BUFFER_BIT);
    int w = g->width < win_w ? g->width : win_w, h = g->height < win_h ? g->height : win_h;
    /* top-left corner of the image at the top-left of the window */
    f->BlitFramebuffer(0, g->height - h, w, g->height, 0, win_h - h, w, win_h,
                       GL_COLOR_BUFFER_BIT, GL_NEAREST);
    f->BindFramebuffer(GL_FRAMEBUFFER, 0);
}
