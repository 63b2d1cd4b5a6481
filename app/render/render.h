/// porelab renderer: reads a world through read-only engine queries, builds a draw list of
/// primitives (independent of any backend), and rasterizes it with a backend (cairo now:
/// PNG, SVG, PDF; OpenGL later). Depends on the engine only, never on Lua.
#ifndef PORELAB_RENDER_H
#define PORELAB_RENDER_H

#include <stddef.h>
#include <stdio.h>
#include "porelab/world.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Layers, combinable as a bit mask.
enum {
    PL_LAYER_BODIES = 1u << 0,  ///< filled bodies with outline and rotation mark; walls
    PL_LAYER_FORCES = 1u << 1,  ///< contact-force chains (normal force)
    PL_LAYER_TIME = 1u << 2,    ///< time stamp
    PL_LAYER_MESH = 1u << 3,    ///< fluid mesh wireframe
    PL_LAYER_PRESSURE = 1u << 4,///< pressure field (filled)
    PL_LAYER_ISOLINES = 1u << 5,///< isolines of the pressure field
    PL_LAYER_VELOCITY = 1u << 6,///< Darcy velocity arrows
    PL_LAYER_COLORBAR = 1u << 7,///< colour bar of the coloured quantity
    PL_LAYER_SCALEBAR = 1u << 8,///< length scale bar
    PL_LAYER_TITLE = 1u << 9,   ///< title text
    PL_LAYER_OVERLAY = 1u << 10,///< scene-drawn overlays
    PL_LAYER_TANGENTIAL = 1u << 11,///< tangential contact forces
    PL_LAYER_BONDS = 1u << 12   ///< bonds (porelab/bonds.h): intact thin, broken ones as cracks
};
#define PL_LAYERS_DEFAULT (PL_LAYER_BODIES | PL_LAYER_FORCES | PL_LAYER_TIME)

/// fluid_field value: the speed |u| (m/s) from the node velocities PL_FLUID_VELOCITY_NODE_X/Y
/// of a resolved model (Stokes, Navier-Stokes).
#define PL_RENDER_FLUID_SPEED 6

typedef struct pl_rgba {
    float r, g, b, a; ///< 0..1
} pl_rgba;

/// How bodies are coloured.
typedef enum pl_body_coloring {
    PL_COLOR_BY_MATERIAL = 0,
    PL_COLOR_BY_SPEED = 1,
    PL_COLOR_BY_STRESS = 2,
    PL_COLOR_BY_TEMPERATURE = 3 ///< grain temperature (porelab/bonds.h heat), K
} pl_body_coloring;

#define PL_RENDER_MAX_MATERIAL_COLORS 16

typedef struct pl_render_options {
    int width, height;        ///< pixels; default 800 x 600
    unsigned layers;          ///< PL_LAYER_* mask; default PL_LAYERS_DEFAULT
    int auto_camera;          ///< 1: fit the world's bounds (default); 0: use view_lo/view_hi
    pl_vec2 view_lo, view_hi; ///< world rectangle to show when auto_camera = 0 (aspect preserved)
    double margin;            ///< fraction of the view added around auto-fitted bounds; default 0.05
    pl_rgba background;       ///< default white
    pl_rgba material_colors[PL_RENDER_MAX_MATERIAL_COLORS]; ///< fill per material index (cycled)
    int material_color_count; ///< how many of material_colors are set (0 = built-in palette)
    pl_rgba wall_color;       ///< walls and fixed bodies
    pl_rgba force_color;      ///< force-chain colour
    double force_scale;       ///< force (N) drawn at the maximum width; 0 = the largest force in frame
    double force_threshold;   ///< forces below this fraction of force_scale are not drawn; default 0.02
    double force_max_width;   ///< line width (pixels) at force_scale; default 6
    pl_body_coloring coloring;
    char title[128];          ///< used by PL_LAYER_TITLE
    /* ---- added by the renderer (keep new fields at the end) ---- */
    double color_min, color_max; ///< range of the body colouring quantity (m/s or Pa);
                              ///< color_max <= color_min = automatic from the frame (default)
    const struct pl_draw_list *overlay; ///< scene-drawn primitives (world or pixel space) drawn
                              ///< with PL_LAYER_OVERLAY; not owned; default NULL
    double time_offset;       ///< added to the world time in the time stamp, s; default 0
    int fluid_field;          ///< node field for PL_LAYER_PRESSURE / ISOLINES: a pl_fluid_node_field
                              ///< (porelab/fluid.h) or PL_RENDER_FLUID_SPEED; default PL_FLUID_PRESSURE (Pa)
    int isoline_count;        ///< about this many nice isoline levels; default 10
    double fluid_min, fluid_max; ///< range of the fluid field; fluid_max <= fluid_min = automatic
    double velocity_scale;    ///< arrow length per unit Darcy velocity, m per (m/s); 0 = automatic
    int has_excess_reference; ///< 1: excess pore pressure is rho_f g (h - excess_reference)
    double excess_reference;  ///< head h0 (m) of the hydrostatic state the excess pressure is
                              ///< measured from (e.g. the outlet's); default: the engine's
                              ///< (mean prescribed head)
    double record_from;       ///< frames before this world time (s) are not written (a run's
                              ///< preparation); the scene's hooks still run; default 0
    int reserve_right;        ///< px at the right edge left to the host (a window's control panel):
                              ///< the scene and its annotations stay left of it; default 0
    unsigned hidden_materials;///< bit m set: bodies of material m (< 32) are not drawn (numerical
                              ///< helpers such as mesh-confining slabs); default 0
} pl_render_options;

/// Fixed ranges across a run (house style: never re-fitted per frame). A run keeps one of
/// these: after each frame it takes in the frame's automatic ranges (the fluid field and body
/// colouring grow to the union of all frames so far, the velocity arrow scale shrinks to fit
/// the fastest flow so far), and before each frame it fills the options' automatic ranges
/// from it. A range that still changed after the first frame is reported at the end with the
/// setting that fixes it from the start (pl_render_ranges_note).
typedef struct pl_render_ranges {
    int field_set, color_set, vscale_set;
    double field_lo, field_hi;   ///< fluid field, SI units
    double color_lo, color_hi;   ///< body colouring quantity, SI units
    double vscale;               ///< m per (m/s)
    int field_changed, color_changed, vscale_changed;
    int field_fixed, color_fixed, vscale_fixed; ///< the scene's own options fix them (no note)
    int frames;
} pl_render_ranges;

/// Copies opt into out with the automatic ranges replaced by the run's so far, and notes which
/// ranges opt (the scene's options) fixes itself, so that they are not reported as grown.
void pl_render_ranges_apply(pl_render_ranges *r, const pl_render_options *opt,
                            pl_render_options *out);
/// Takes in the automatic ranges of the frame just built into dl.
struct pl_draw_list;
void pl_render_ranges_update(pl_render_ranges *r, const struct pl_draw_list *dl);
/// Writes a note (one line each) for ranges that changed during the run, with the render
/// setting that would have fixed them; nothing when all stayed fixed.
void pl_render_ranges_note(const pl_render_ranges *r, FILE *out);

pl_render_options pl_default_render_options(void);

/// Parses a comma-separated layer list ("bodies,forces,time", "all", "none", "+mesh,-time"
/// relative to the current mask). Returns 0 on success; on failure writes a message listing
/// the valid names into err and returns -1.
int pl_render_parse_layers(const char *list, unsigned *layers, char *err, size_t errlen);

/// Renders the world's current state to a file; the format follows the extension
/// (.png, .svg, .pdf). Returns 0 on success, else -1 with a message in err.
int pl_render_to_file(const pl_world *w, const pl_render_options *opt, const char *path,
                      char *err, size_t errlen);

/* ---- added by the renderer ---- */
struct pl_draw_list;

/// Builds the draw list of the world's current state (clears dl first; dl is reused so no
/// allocation happens in steady state). Returns 0, or -1 with a message in err.
/* The layers that read a fluid model's field. */
#define PL_RENDER_FLUID_LAYERS \
    (PL_LAYER_MESH | PL_LAYER_PRESSURE | PL_LAYER_ISOLINES | PL_LAYER_VELOCITY)
/* The engine's queries only read: before drawing a fluid layer (or writing VTK, vtk = 1) the
 * host prepares the world's models (pl_world_prepare) so that a changed mesh or boundary line
 * and the initial field show. Returns the engine status (the message in pl_world_last_error). */
pl_status pl_render_prepare(pl_world *w, const pl_render_options *opt, int vtk);
int pl_render_build(const pl_world *w, const pl_render_options *opt, struct pl_draw_list *dl,
                    char *err, size_t errlen);

/// Renders the world into an RGBA buffer (8 bits per channel, not premultiplied, rows top to
/// bottom, 4 x width bytes per row). *rgba is allocated (or reused when *rgba is not NULL and
/// the caller passes the same size). Returns 0, or -1 with a message.
int pl_render_to_rgba(const pl_world *w, const pl_render_options *opt, unsigned char **rgba,
                      char *err, size_t errlen);

/// Names of the layers, in bit order (PL_LAYER_BODIES is "bodies"); NULL past the end.
const char *pl_render_layer_name(int bit);

/// Frame writer for animations: numbered PNG frames DIR/frame_000000.png ..., optionally
/// piped to ffmpeg for a video (.mp4 or .gif). Frames are written as they come so nothing
/// already written is lost when a run stops.
typedef struct pl_frame_writer pl_frame_writer;

/// Creates the output directory if needed. video_path may be NULL. When ffmpeg is missing
/// and a video was requested, a one-line note is printed (to stderr) and frames still go on.
pl_frame_writer *pl_frame_writer_open(const char *dir, const char *video_path, int fps,
                                      char *err, size_t errlen);
/// Renders and writes the next frame; returns 0 or -1 with a message.
int pl_frame_writer_add(pl_frame_writer *fw, const pl_world *w, const pl_render_options *opt,
                        char *err, size_t errlen);
int pl_frame_writer_count(const pl_frame_writer *fw);
/// Numbers the next frame `index` (a run resumed from a restart file goes on numbering where
/// the run that never stopped would be). Call before the first frame.
void pl_frame_writer_start_at(pl_frame_writer *fw, int index);
/// Removes DIR/frame_NNNNNN.png with NNNNNN >= from (the frames of an earlier run into the
/// same folder); prints one note to `note` (may be NULL) when any were removed. Returns the
/// count. The frame writers call it before their first frame.
int pl_frames_remove_stale(const char *dir, int from, FILE *note);
/// Finishes (closes the video pipe, waits for ffmpeg) and frees; nulls the pointer.
/// Returns 0 or -1 with a message (for example when ffmpeg failed).
int pl_frame_writer_close(pl_frame_writer **fw, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
