/// OpenGL backend: rasterizes a draw list (app/render/drawlist.h) with OpenGL 2.1 + framebuffer
/// objects, the same list the cairo backend rasterizes. Used by the window (SDL2) and, through
/// OSMesa, headless (`--renderer gl`).
///
/// How each primitive is drawn (painter's order kept; a few draw calls per frame, one per run
/// of primitives sharing a program, clip and depth state; vertex and index buffers keep
/// their storage between frames). Every edge is antialiased in the fragment shaders, so no
/// multisampling is needed (software GL spends its time per primitive and per pixel, and
/// 4x multisampling cost twice the frame time):
/// - circles: a quad per disc; the shader computes the exact distance to the centre and the
///   fill and stroke coverage (fill then stroke like cairo);
/// - lines and strokes: capsules (quad per segment, distance to the segment in the shader)
///   = round caps and joins; a translucent stroke is drawn in two passes under one depth
///   value (fully covered cores, then the rims) so its overlapping pieces blend once;
/// - convex filled polygons (bodies, arrow heads, label boxes): per edge, a triangle to the
///   edge and a 1 px strip across it carrying the distance to the edge (coverage ramp, exact
///   for straight edges); concave ones by ear clipping (edges not antialiased without
///   multisampling); Gouraud triangles: vertex colours, each grown by 0.3 px so T-junctions
///   of adaptively refined field meshes leave no seams (one depth value: overlaps drawn once);
/// - arrows: butt shaft + filled head, as in the cairo backend;
/// - text: textured quads from a FreeType glyph atlas (gl_text.h); with a halo, on a box of
///   the halo colour (as the cairo backend).
/// World-space primitives are clipped to dl->clip when dl->has_clip (per pixel centre, in the
/// fragment shader). Rendering goes to an offscreen framebuffer (multisampled when asked),
/// resolved into a single-sample one that is read back or shown in the window.
#ifndef PORELAB_BACKEND_GL_H
#define PORELAB_BACKEND_GL_H

#include <stddef.h>
#include "backend_cairo.h" /* pl_image */
#include "drawlist.h"
#include "gl_funcs.h"

typedef struct pl_gl pl_gl;

/// Creates the renderer in the current GL context. samples = multisample count wanted
/// (0 = the environment variable PORELAB_GL_SAMPLES, else 1 = none; clamped to what the
/// driver offers; more samples also smooth the edges of concave fills and of field meshes).
/// The goldens and the GL-vs-cairo threshold are for 1. NULL with a message.
pl_gl *pl_gl_create(pl_gl_get_proc get_proc, int samples, char *err, size_t errlen);
void pl_gl_destroy(pl_gl **g);

/// Draws the list into the offscreen framebuffer (sized dl->camera.width x height) and
/// resolves it. Returns 0, or -1 with a message.
int pl_gl_render(pl_gl *g, const pl_draw_list *dl, char *err, size_t errlen);
/// As pl_gl_render, with a second list drawn on top of the first (the window's on-screen
/// text): same camera, background and clip as dl, without copying the lists into one.
/// When dl draws exactly what the previous call's dl drew (same primitives, points, colours,
/// text, camera, clip, background: a paused window), its picture is copied from a cache of
/// the last frame and only `over` is drawn: the same pixels at a fraction of the cost.
int pl_gl_render_over(pl_gl *g, const pl_draw_list *dl, const pl_draw_list *over, char *err,
                      size_t errlen);
/// Reads the last render into img (8-bit RGBA, not premultiplied, rows top to bottom).
int pl_gl_read(pl_gl *g, pl_image *img, char *err, size_t errlen);
/// Copies the last render into the default framebuffer (a window of win_w x win_h pixels),
/// at the top-left corner.
void pl_gl_present(pl_gl *g, int win_w, int win_h);

/// Advance width of a string in the backend's font at size px (what the text will occupy).
double pl_gl_text_width(pl_gl *g, const char *s, float size);

/// GL_RENDERER and GL_VERSION strings, and the multisample count in use.
const char *pl_gl_renderer_name(const pl_gl *g);
const char *pl_gl_version(const pl_gl *g);
int pl_gl_samples(const pl_gl *g);
/// Vertices and indices of the last frame (for benchmarks).
void pl_gl_last_counts(const pl_gl *g, long *vertices, long *indices);

#endif
