/* OpenGL backend: draw list -> vertices (CPU) -> one indexed draw into a multisampled
 * offscreen framebuffer -> resolve. See backend_gl.h for how each primitive is drawn. */
#include "backend_gl.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_text.h"

enum { MODE_SOLID = 0, MODE_GLYPH = 1, MODE_CIRCLE = 2, MODE_CAPSULE = 3 };

typedef struct gv {
    float x, y, z;     /* pixels (y down), depth in NDC */
    uint8_t c0[4];     /* fill / primary colour, straight alpha */
    uint8_t c1[4];     /* circle stroke colour */
    float p[4];        /* per-mode parameters (see the fragment shader) */
    float mode;
} gv;

struct pl_gl {
    pl_gl_funcs f;
    GLuint prog, vbo, ibo, tex, vao;
    GLint u_size, u_tex, u_clip, u_fsize;
    GLuint fbo_ms, rb_color_ms, rb_depth_ms, fbo_res, rb_color_res;
    int fb_w, fb_h, samples, max_size;
    int width, height; /* size of the last render */
    pl_glyph_atlas atlas;
    /* frame geometry, reused between frames */
    gv *v; long nv, cv;
    uint32_t *ix; long ni, ci;
    int failed;
    float z;
    float clip_mode; /* 8 when the current primitive is clipped to dl->clip, else 0 */
    char renderer[128], version[128];
};

/* ------------------------------------------------------------------ shaders */

static const char *vs_src =
    "#version 120\n"
    "attribute vec3 a_pos;\n"
    "attribute vec4 a_c0;\n"
    "attribute vec4 a_c1;\n"
    "attribute vec4 a_p;\n"
    "attribute float a_mode;\n"
    "uniform vec2 u_size;\n"
    "varying vec4 v_c0;\n"
    "varying vec4 v_c1;\n"
    "varying vec4 v_p;\n"
    "varying float v_mode;\n"
    "void main() {\n"
    "  gl_Position = vec4(2.0 * a_pos.x / u_size.x - 1.0, 1.0 - 2.0 * a_pos.y / u_size.y,\n"
    "                     a_pos.z, 1.0);\n"
    "  v_c0 = a_c0; v_c1 = a_c1; v_p = a_p; v_mode = a_mode;\n"
    "}\n";

/* Output is premultiplied (blend ONE, ONE_MINUS_SRC_ALPHA). Coverage of a band of
 * half-width h at distance d from its centre line, box-filtered over one pixel:
 * clamp(h - d + 0.5) - clamp(-h - d + 0.5); exact for straight edges. */
static const char *fs_src =
    "#version 120\n"
    "uniform sampler2D u_tex;\n"
    "uniform vec4 u_clip;\n"   /* x0, y0, x1, y1 in pixels, y down */
    "uniform vec2 u_fsize;\n"
    "varying vec4 v_c0;\n"
    "varying vec4 v_c1;\n"
    "varying vec4 v_p;\n"
    "varying float v_mode;\n"
    "float band(float h, float d) {\n"
    "  return clamp(h - d + 0.5, 0.0, 1.0) - clamp(-h - d + 0.5, 0.0, 1.0);\n"
    "}\n"
    "void main() {\n"
    "  vec4 c;\n"
    "  float mode = v_mode;\n"
    "  if (mode > 7.5) {\n" /* world-space primitive clipped to the plot area */
    "    vec2 q = vec2(gl_FragCoord.x, u_fsize.y - gl_FragCoord.y);\n"
    "    if (q.x < u_clip.x || q.x >= u_clip.z || q.y < u_clip.y || q.y >= u_clip.w) discard;\n"
    "    mode -= 8.0;\n"
    "  }\n"
    "  if (mode < 0.5) {\n"
    "    c = vec4(v_c0.rgb * v_c0.a, v_c0.a);\n"
    "  } else if (mode < 1.5) {\n"
    /* unrotated glyphs (p.z = atlas size) sample exact texel centres, so the picture does
     * not depend on where the glyph sits in the atlas; rotated ones (p.z = 0) filter */
    "    vec2 uv = v_p.z > 0.0 ? (floor(v_p.xy * v_p.z) + 0.5) / v_p.z : v_p.xy;\n"
    "    float a = texture2D(u_tex, uv).r * v_c0.a;\n"
    "    c = vec4(v_c0.rgb * a, a);\n"
    "  } else if (mode < 2.5) {\n"
    "    float d = length(v_p.xy);\n"
    "    float r = v_p.z, hw = 0.5 * v_p.w;\n"
    "    float cf = clamp(r - d + 0.5, 0.0, 1.0);\n"
    "    if (r < 0.5) cf *= 2.0 * r;\n" /* sub-pixel discs: keep their area */
    "    float cs = hw > 0.0 ? band(hw, abs(d - r)) : 0.0;\n"
    "    float fa = v_c0.a * cf, sa = v_c1.a * cs;\n"
    "    c = vec4(v_c1.rgb * sa + v_c0.rgb * fa * (1.0 - sa), sa + fa * (1.0 - sa));\n"
    "  } else {\n"
    "    float u = v_p.x, L = v_p.z, hw = abs(v_p.w);\n"
    "    float cv;\n"
    "    if (v_p.w >= 0.0) {\n"
    "      float d = length(vec2(u - clamp(u, 0.0, L), v_p.y));\n"
    "      cv = band(hw, d);\n"
    "    } else {\n"
    "      cv = band(hw, abs(v_p.y)) * clamp(min(u, L - u) + 0.5, 0.0, 1.0);\n"
    "    }\n"
    "    float a = v_c0.a * cv;\n"
    "    c = vec4(v_c0.rgb * a, a);\n"
    "  }\n"
    "  if (c.a <= 0.0) discard;\n"
    "  gl_FragColor = c;\n"
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
    g->fbo_ms = g->fbo_res = g->rb_color_ms = g->rb_depth_ms = g->rb_color_res = 0;
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
    GLuint vs = compile(g, GL_VERTEX_SHADER, vs_src, err, errlen);
    GLuint fs = vs ? compile(g, GL_FRAGMENT_SHADER, fs_src, err, errlen) : 0;
    if (!fs) {
        if (vs) g->f.DeleteShader(vs);
        pl_glyph_atlas_free(&g->atlas);
        free(g);
        return NULL;
    }
    g->prog = g->f.CreateProgram();
    g->f.AttachShader(g->prog, vs);
    g->f.AttachShader(g->prog, fs);
    g->f.BindAttribLocation(g->prog, 0, "a_pos");
    g->f.BindAttribLocation(g->prog, 1, "a_c0");
    g->f.BindAttribLocation(g->prog, 2, "a_c1");
    g->f.BindAttribLocation(g->prog, 3, "a_p");
    g->f.BindAttribLocation(g->prog, 4, "a_mode");
    g->f.LinkProgram(g->prog);
    g->f.DeleteShader(vs);
    g->f.DeleteShader(fs);
    GLint ok = 0;
    g->f.GetProgramiv(g->prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[512] = "";
        g->f.GetProgramInfoLog(g->prog, sizeof log, NULL, log);
        snprintf(err, errlen, "GL program link failed: %s", log);
        g->f.DeleteProgram(g->prog);
        pl_glyph_atlas_free(&g->atlas);
        free(g);
        return NULL;
    }
    g->u_size = g->f.GetUniformLocation(g->prog, "u_size");
    g->u_tex = g->f.GetUniformLocation(g->prog, "u_tex");
    g->u_clip = g->f.GetUniformLocation(g->prog, "u_clip");
    g->u_fsize = g->f.GetUniformLocation(g->prog, "u_fsize");
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
    if (samples <= 0) { /* default 4; PORELAB_GL_SAMPLES=1 trades polygon edges for speed */
        const char *env = getenv("PORELAB_GL_SAMPLES");
        samples = env && atoi(env) > 0 ? atoi(env) : 4;
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
    g->f.DeleteProgram(g->prog);
    if (g->vao && g->f.DeleteVertexArrays) g->f.DeleteVertexArrays(1, &g->vao);
    pl_glyph_atlas_free(&g->atlas);
    free(g->v);
    free(g->ix);
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

static gv *vert(pl_gl *g, double x, double y, const uint8_t c0[4], float mode)
{
    gv *v = &g->v[g->nv++];
    v->x = (float)x;
    v->y = (float)y;
    v->z = g->z;
    memcpy(v->c0, c0, 4);
    memset(v->c1, 0, 4);
    v->p[0] = v->p[1] = v->p[2] = v->p[3] = 0.0f;
    v->mode = mode + g->clip_mode;
    return v;
}

static void quad_idx(pl_gl *g, uint32_t b)
{
    uint32_t *i = g->ix + g->ni;
    i[0] = b; i[1] = b + 1; i[2] = b + 2;
    i[3] = b; i[4] = b + 2; i[5] = b + 3;
    g->ni += 6;
}

static int circle_segments(double r)
{
    const double tol = 0.12; /* px: largest distance between the chord and the arc */
    if (r <= tol * 2.0) return 8;
    double a = 2.0 * acos(1.0 - tol / r);
    int n = (int)ceil(6.283185307179586 / a);
    return n < 8 ? 8 : n > 720 ? 720 : n;
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
    next_depth(g);
    double e = r + 0.5 * w + 0.75; /* coverage is zero beyond r + w/2 + 0.5 */
    uint32_t b = (uint32_t)g->nv;
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; k++) {
        gv *v = vert(g, c.x + sx[k] * e, c.y + sy[k] * e, f, MODE_CIRCLE);
        memcpy(v->c1, s, 4);
        v->p[0] = (float)(sx[k] * e);
        v->p[1] = (float)(sy[k] * e);
        v->p[2] = (float)r;
        v->p[3] = (float)w;
    }
    quad_idx(g, b);
}

/* A capsule (round caps) or, with butt = 1, a plain bar from a to b, full width w. */
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
                     col, MODE_CAPSULE);
        v->p[0] = (float)along[k];
        v->p[1] = (float)across[k];
        v->p[2] = (float)L;
        v->p[3] = (float)(butt ? -hw : hw);
    }
    quad_idx(g, base);
}

static void add_disc_fan(pl_gl *g, pl_vec2 c, double r, const uint8_t col[4])
{
    int n = circle_segments(r);
    if (reserve(g, n + 1, 3 * n)) return;
    uint32_t b = (uint32_t)g->nv;
    vert(g, c.x, c.y, col, MODE_SOLID);
    for (int k = 0; k < n; k++) {
        double t = 6.283185307179586 * k / n;
        vert(g, c.x + r * cos(t), c.y + r * sin(t), col, MODE_SOLID);
    }
    for (int k = 0; k < n; k++) {
        uint32_t *i = g->ix + g->ni;
        i[0] = b;
        i[1] = b + 1 + (uint32_t)k;
        i[2] = b + 1 + (uint32_t)((k + 1) % n);
        g->ni += 3;
    }
}

/* Stroke of a path with round joins and caps. Opaque strokes: capsules (analytic edges);
 * translucent strokes: multisampled quads and join fans under one depth value. */
static void add_stroke(pl_gl *g, const pl_draw_list *dl, const pl_prim *p, int closed,
                       int pairs)
{
    int n = p->count;
    if (n < 2 || !(p->width > 0.0f)) return;
    uint8_t col[4];
    to_u8(col, p->stroke);
    const pl_vec2 *pts = dl->points + p->first;
    double w = p->width, hw = 0.5 * w;
    next_depth(g);
    int opaque = col[3] == 255;
    int nseg = pairs ? n / 2 : (closed ? n : n - 1);
    for (int s = 0; s < nseg; s++) {
        int i0 = pairs ? 2 * s : s, i1 = pairs ? 2 * s + 1 : (s + 1) % n;
        pl_vec2 a = pl_dl_px(dl, p, pts[i0]), b = pl_dl_px(dl, p, pts[i1]);
        if (opaque) { /* own depth: opaque overlaps need no single coverage, and sharing
                       * one would let a capsule's antialiased rim block its neighbour */
            if (s > 0) next_depth(g);
            add_capsule(g, a, b, w, col, 0);
            continue;
        }
        double dx = b.x - a.x, dy = b.y - a.y, L = sqrt(dx * dx + dy * dy);
        if (L > 1e-9) {
            double nx = -dy / L * hw, ny = dx / L * hw;
            if (reserve(g, 4, 6)) return;
            uint32_t base = (uint32_t)g->nv;
            vert(g, a.x + nx, a.y + ny, col, MODE_SOLID);
            vert(g, b.x + nx, b.y + ny, col, MODE_SOLID);
            vert(g, b.x - nx, b.y - ny, col, MODE_SOLID);
            vert(g, a.x - nx, a.y - ny, col, MODE_SOLID);
            quad_idx(g, base);
        }
        /* round joins and caps: a disc at the start of every piece, and at the end of the
         * last one of an open path (or of every independent segment) */
        add_disc_fan(g, a, hw, col);
        if (pairs || (!closed && s == nseg - 1)) add_disc_fan(g, b, hw, col);
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

static void add_fill(pl_gl *g, const pl_draw_list *dl, const pl_prim *p)
{
    int n = p->count;
    if (n < 3) return;
    uint8_t col[4];
    to_u8(col, p->fill);
    if (reserve(g, n, 3 * (n - 2))) return;
    next_depth(g);
    const pl_vec2 *pts = dl->points + p->first;
    uint32_t b = (uint32_t)g->nv;
    double area = 0.0;
    int pos = 0, neg = 0;
    for (int i = 0; i < n; i++) {
        pl_vec2 q = pl_dl_px(dl, p, pts[i]);
        vert(g, q.x, q.y, col, MODE_SOLID);
    }
    gv *v = g->v + b;
    for (int i = 0; i < n; i++) {
        pl_vec2 a = {v[i].x, v[i].y}, c = {v[(i + 1) % n].x, v[(i + 1) % n].y},
                d = {v[(i + 2) % n].x, v[(i + 2) % n].y};
        area += a.x * c.y - c.x * a.y;
        double cr = cross3(a, c, d);
        if (cr > 1e-12) pos++;
        else if (cr < -1e-12) neg++;
    }
    if (pos == 0 || neg == 0) { /* convex: fan */
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
    next_depth(g);
    const pl_vec2 *pts = dl->points + p->first;
    const pl_rgba *cols = dl->colors + p->color_first;
    /* Each triangle is grown by 0.3 px (edges moved outward, mitred corners, capped): field
     * meshes refined adaptively have T-junctions, whose rounding gaps multisampling would
     * show as thin light seams. The batch shares one depth value, so the overlaps are drawn
     * once and colours are continuous across edges. */
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
            vert(g, x, y, c, MODE_SOLID);
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
    next_depth(g);
    add_capsule(g, a, (pl_vec2){bx + ux * 0.5, by + uy * 0.5}, p->width, sc, 1);
    if (reserve(g, 3, 3)) return;
    next_depth(g);
    uint32_t base = (uint32_t)g->nv;
    vert(g, b.x, b.y, fc, MODE_SOLID);
    vert(g, bx - uy * half, by + ux * half, fc, MODE_SOLID);
    vert(g, bx + uy * half, by - ux * half, fc, MODE_SOLID);
    for (int k = 0; k < 3; k++) g->ix[g->ni++] = base + (uint32_t)k;
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
        if (reserve(g, 4, 6)) return;
        next_depth(g);
        uint32_t base = (uint32_t)g->nv;
        for (int k = 0; k < 4; k++)
            vert(g, at.x + lx[k] * ca - ly[k] * sa, at.y + lx[k] * sa + ly[k] * ca, bc, MODE_SOLID);
        quad_idx(g, base);
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
                    gv *v = vert(g, at.x + px * ca - py * sa, at.y + px * sa + py * ca, col,
                                 MODE_GLYPH);
                    v->p[0] = (float)(u[k] * inv);
                    v->p[1] = (float)(vv[k] * inv);
                    v->p[2] = rotated ? 0.0f : (float)PL_ATLAS_SIZE;
                }
                quad_idx(g, base);
            }
            pen += gl->advance;
        }
    }
}

static void build(pl_gl *g, const pl_draw_list *dl)
{
    g->nv = g->ni = 0;
    g->failed = 0;
    g->z = 1.0f;
    for (int i = 0; i < dl->prim_count; i++) {
        const pl_prim *p = &dl->prims[i];
        g->clip_mode = dl->has_clip && p->space == PL_SPACE_WORLD ? 8.0f : 0.0f;
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

/* ------------------------------------------------------------------ render */

int pl_gl_render(pl_gl *g, const pl_draw_list *dl, char *err, size_t errlen)
{
    if (dl->failed) {
        snprintf(err, errlen, "the draw list is incomplete (out of memory while building it)");
        return -1;
    }
    int w = dl->camera.width, h = dl->camera.height;
    if (w <= 0 || h <= 0) {
        snprintf(err, errlen, "image size %dx%d is out of range", w, h);
        return -1;
    }
    int gen = g->atlas.generation;
    build(g, dl);
    if (g->atlas.generation != gen) build(g, dl); /* atlas was cleared mid-frame */
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
    f->BindFramebuffer(GL_FRAMEBUFFER, g->fbo_ms);
    f->Viewport(0, 0, w, h);
    f->Disable(GL_SCISSOR_TEST);
    pl_rgba bg = dl->background;
    f->ClearColor(bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a);
    f->ClearDepth(1.0);
    f->DepthMask(GL_TRUE);
    f->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (g->ni > 0) {
        f->UseProgram(g->prog);
        f->Uniform2f(g->u_size, (float)w, (float)h);
        f->Uniform2f(g->u_fsize, (float)w, (float)h);
        f->Uniform4f(g->u_clip, (float)dl->clip.x0, (float)dl->clip.y0, (float)dl->clip.x1,
                     (float)dl->clip.y1);
        f->Uniform1i(g->u_tex, 0);
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
        f->Enable(GL_DEPTH_TEST);
        f->DepthFunc(GL_LESS);
        if (g->samples > 1) f->Enable(GL_MULTISAMPLE);
        f->BindBuffer(GL_ARRAY_BUFFER, g->vbo);
        f->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(g->nv * (long)sizeof(gv)), g->v,
                      GL_STREAM_DRAW);
        f->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, g->ibo);
        f->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(g->ni * (long)sizeof(uint32_t)), g->ix,
                      GL_STREAM_DRAW);
        const GLsizei st = (GLsizei)sizeof(gv);
        for (GLuint a = 0; a < 5; a++) f->EnableVertexAttribArray(a);
        f->VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, st, (const void *)offsetof(gv, x));
        f->VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, st, (const void *)offsetof(gv, c0));
        f->VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, st, (const void *)offsetof(gv, c1));
        f->VertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, st, (const void *)offsetof(gv, p));
        f->VertexAttribPointer(4, 1, GL_FLOAT, GL_FALSE, st, (const void *)offsetof(gv, mode));
        f->DrawElements(GL_TRIANGLES, (GLsizei)g->ni, GL_UNSIGNED_INT, NULL);
        f->Disable(GL_DEPTH_TEST);
        f->Disable(GL_BLEND);
    }
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
