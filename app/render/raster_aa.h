/// Antialiased rasterizer for small primitives on image surfaces (discs, rings, capsules,
/// small convex polygons and their outlines, arrows, segments), used by the cairo backend
/// where cairo's per-path cost dominates: thousands of small bodies, force-chain and mesh
/// segments, arrows. Shapes built of edges get their exact area per pixel (signed-area
/// accumulation over the bounding box, or over the whole image in sum batches); segments get
/// the coverage of a band at the pixel's distance. The shapes of one batch combine by the
/// per-pixel maximum (the union where shapes meet or nest) or, in sum batches, by their sum
/// clamped to 1; compositing is OVER with pixman's 8-bit premultiplied arithmetic. How far the
/// pictures are from cairo's is measured in docs/rendering.md (Performance). Pixels, y down.
#ifndef PORELAB_RASTER_AA_H
#define PORELAB_RASTER_AA_H

#include <stdint.h>
#include "drawlist.h"

typedef struct pl_aa pl_aa;

/// A rasterizer for images of width x height pixels (NULL when out of memory).
pl_aa *pl_aa_create(int width, int height);
void pl_aa_destroy(pl_aa *aa);

/// Starts a batch drawn inside the clip rectangle [x0, x1) x [y0, y1) (pixels).
void pl_aa_begin(pl_aa *aa, double x0, double y0, double x1, double y1);
/// Starts a sum batch in the clip rectangle: the coverages of its shapes (polygons, arrows;
/// give them one orientation) add up, clamped to 1 — their union inside, nearly cairo's
/// one-over-the-other at overlapping antialiased edges — in one buffer over the whole image,
/// composited by pl_aa_fill in one pass (no per-shape buffers: for thousands of small
/// overlapping shapes). Returns -1 when out of memory (the batch is then an ordinary one).
int pl_aa_begin_sum(pl_aa *aa, double x0, double y0, double x1, double y1);
/// Makes the current batch immediate: each shape is composited with the colour as soon as it
/// is added (for batches of one shape, or of shapes drawn one over the other); pl_aa_fill
/// then only ends the batch.
void pl_aa_immediate(pl_aa *aa, uint8_t *data, int stride, pl_rgba color);
/// Makes the current batch incremental: each pixel is composited as soon as a shape raises its
/// coverage (by the amount that brings it from the previous maximum to the new one, so the
/// result is that of compositing the per-pixel maximum once, up to 8-bit rounding), no
/// compositing pass at the end; pl_aa_fill then only clears. For pl_aa_thin_segment only.
void pl_aa_incremental(pl_aa *aa, uint8_t *data, int stride, pl_rgba color);
/// Adds a filled simple polygon (n >= 3 points, either orientation).
void pl_aa_polygon(pl_aa *aa, const pl_vec2 *p, int n);
/// Adds a filled circle, flattened within a fraction of cairo's 0.1 px tolerance.
void pl_aa_circle(pl_aa *aa, pl_vec2 c, double r);
/// Adds the ring r0 < |x - c| < r1 (a stroked circle: r0 = r - w/2, r1 = r + w/2).
void pl_aa_ring(pl_aa *aa, pl_vec2 c, double r0, double r1);
/// Adds the outline of a convex polygon stroked with width w and round joins (the ring between
/// the polygon grown by w/2 with round corners and the polygon shrunk by w/2). Returns -1 when
/// the polygon is not convex or too small (nothing added; draw it otherwise).
int pl_aa_convex_outline(pl_aa *aa, const pl_vec2 *p, int n, double w);
/// 0 when pl_aa_convex_outline would draw this outline, -1 when not.
int pl_aa_convex_outline_check(const pl_vec2 *p, int n, double w);
/// Adds a segment stroked with round caps, width w (a capsule).
void pl_aa_capsule(pl_aa *aa, pl_vec2 a, pl_vec2 b, double w);
/// Adds a segment stroked with butt caps, width w.
void pl_aa_bar(pl_aa *aa, pl_vec2 a, pl_vec2 b, double w);
/// Adds a segment (round caps, width w: force chains and mesh lines, any length): the coverage of
/// each pixel is that of the straight band of width w at the pixel centre's distance from the
/// segment (exact along the band for any direction, the same formula around the caps), so the
/// per-pixel maximum of a batch is the coverage by the distance to the union of its segments:
/// lines meeting at a node join without gaps and without doubly blended pixels.
void pl_aa_thin_segment(pl_aa *aa, pl_vec2 a, pl_vec2 b, double w);
/// Adds an arrow as one shape: the shaft from a to shaft_end (butt caps, width w) and the head
/// triangle, same orientation, so that their coverages add (clamped to 1) where they overlap,
/// as cairo's shaft-then-head compositing nearly does.
void pl_aa_arrow(pl_aa *aa, pl_vec2 a, pl_vec2 shaft_end, double w, const pl_vec2 head[3]);
/// Composites the batch with the colour (non-premultiplied) over a premultiplied ARGB32
/// image (data, stride in bytes) and clears it. Returns -1 when memory ran out while the
/// batch was built (shapes are missing), else 0.
int pl_aa_fill(pl_aa *aa, uint8_t *data, int stride, pl_rgba color);

#endif
