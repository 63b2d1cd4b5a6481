/// Builders that turn the world's state into draw-list primitives. The state is first copied
/// into a pl_render_scene through the engine's read-only queries (bodies, outlines,
/// contacts, time, bounds); building from a scene touches no engine internals, so the same
/// code serves live worlds, tests and benchmarks.
#ifndef PORELAB_DRAW_WORLD_H
#define PORELAB_DRAW_WORLD_H

#include "drawlist.h"
#include "colormap.h"
#include "porelab/bonds.h"

#ifdef __cplusplus
extern "C" {
#endif

/// A snapshot of what the renderer needs. Reuse across frames: capture keeps the memory.
typedef struct pl_render_scene {
    pl_body_info *bodies;   int body_count, body_cap;
    int *vert_first;        ///< body i's outline: verts[vert_first[i] .. vert_first[i+1])
    pl_vec2 *verts;         int vert_count, vert_cap;
    pl_contact_info *contacts; int contact_count, contact_cap;
    double *stress;         ///< mean stress per body, Pa (filled by pl_render_scene_stress)
    double *values;         ///< scratch: the colouring quantity per body
    double time;            ///< s
    pl_vec2 lo, hi;         ///< bounds of all bodies, m
    int material_count;
    char (*material_names)[48];
    int material_cap;
    /* fluid (filled by pl_render_scene_capture_fluid; node_count 0 without a fluid model) */
    pl_vec2 *fluid_nodes;   int fluid_node_count, fluid_node_cap;
    double *fluid_values;   ///< the chosen node field per node
    int *fluid_tris;        int fluid_tri_count, fluid_tri_cap; ///< 3 node indices per triangle
    pl_vec2 *fluid_velocity;///< Darcy velocity per triangle, m/s
    int fluid_field;        ///< which node field fluid_values holds (pl_fluid_node_field)
    pl_vec2 *mesh_nodes;    int mesh_node_count; ///< the model's own elements for the mesh layer
    int *mesh_tris;         int mesh_tri_count;  ///< (PL_FLUID_ELEMENT_MESH); 0: fluid_tris
    double fluid_conductivity; ///< largest element conductivity, m/s (0 = unknown); Darcy
                            ///< velocities below 1e-9 of it (gradients < 1e-9) are not drawn
    double *temperature;    ///< per body, K (NaN without heat; porelab/bonds.h)
    unsigned char *hidden;  ///< per body: 1 when worn away (not drawn)
    pl_bond_info *bonds;    int bond_count, bond_cap; ///< every bond, intact and broken
} pl_render_scene;

/// Bonds: intact ones as thin lines between the centres, broken ones as crack segments across
/// the bond (tension red, shear and combined blue).
void pl_draw_bonds(pl_draw_list *dl, const pl_render_scene *s);

void pl_render_scene_init(pl_render_scene *s);
void pl_render_scene_free(pl_render_scene *s);
/// Copies the world's state. Returns 0, or -1 when out of memory.
int pl_render_scene_capture(pl_render_scene *s, const pl_world *w);
/// Copies the fluid mesh, the node field `field` (pl_fluid_node_field) and the element
/// velocities. The fluid queries mesh on demand, hence the non-const world. Returns 0, or -1
/// when out of memory.
int pl_render_scene_capture_fluid(pl_render_scene *s, const pl_world *w, int field);
/// Sets a synthetic fluid field (tests, benchmarks): copies nodes, triangles, node values
/// and optional per-triangle velocities (NULL = zero).
int pl_render_scene_set_fluid(pl_render_scene *s, const pl_vec2 *nodes, const double *values,
                              int node_count, const int *tris, const pl_vec2 *velocity,
                              int tri_count, int field);

/// Appends a body (for synthetic scenes in tests and benchmarks). verts may be NULL.
int pl_render_scene_add_body(pl_render_scene *s, const pl_body_info *b, const pl_vec2 *verts,
                             int nverts);
int pl_render_scene_add_contact(pl_render_scene *s, const pl_contact_info *c);

/// Mean stress of each body (compression positive), Pa per unit thickness:
/// sigma = (1 / (2 A)) sum over contacts c of (-f_c . l_c), with f_c the contact force on the
/// body and l_c the branch vector from its centroid to the contact point (the trace of the
/// Love-Weber average stress tensor, divided by 2 in 2D). Bodies without area get 0.
/// Returns 0, or -1 when out of memory.
int pl_render_scene_stress(pl_render_scene *s);

/// Builds the complete frame (all layers selected in opt) into dl (cleared first).
/// Returns 0, or -1 with a message.
int pl_render_build_scene(pl_draw_list *dl, pl_render_scene *s,
                          const pl_render_options *opt, char *err, size_t errlen);

/* Individual layers (dl->camera set). Used by pl_render_build_scene and by tests. */

/// Bodies: fills by colouring, outlines, rotation marks, kinematic bodies and walls in
/// opt->wall_color. values/map/vmin/vmax are used when opt->coloring is not by material.
void pl_draw_bodies(pl_draw_list *dl, const pl_render_scene *s, const pl_render_options *opt,
                    const double *values, pl_colormap map, double vmin, double vmax);

/// Force chains: segment between the two centres (the contact point for walls), width and
/// colour proportional to the normal force; strongest drawn last. Returns the force scale
/// used (N), 0 when nothing was drawn.
double pl_draw_force_chains(pl_draw_list *dl, const pl_render_scene *s,
                            const pl_render_options *opt);

/// Tangential forces: arrows at the contact points along the tangent, length proportional to
/// |ft| (force_scale as for chains).
void pl_draw_tangential(pl_draw_list *dl, const pl_render_scene *s, const pl_render_options *opt,
                        double force_scale);

/* Fluid layers (draw_fluid.c) */

/// Range and colour map of the fluid field for the options (automatic or fixed), with the
/// display label and unit factor; returns 0 when there is no fluid field.
int pl_fluid_field_range(const pl_render_scene *s, const pl_render_options *opt, double *vmin,
                         double *vmax, pl_colormap *map, char *label, size_t labellen,
                         double *unit_factor);
/// Round-off in the fluid field (|value| below 0.01 Pa, or 1e-6 m for heads) set to zero.
void pl_render_scene_denoise_fluid(pl_render_scene *s);
/// pl_render_scene_capture_fluid for the options' field, with the options' excess-pressure
/// reference head applied. Returns 0, or -1 when out of memory.
int pl_render_scene_capture_fluid_opt(pl_render_scene *s, const pl_world *w,
                                      const pl_render_options *opt);
struct pl_obstacles;
/// The obstacles isoline labels avoid (label_place.h): walls, non-disc and large bodies,
/// overlay text.
void pl_fluid_label_obstacles(struct pl_obstacles *o, const pl_draw_list *dl,
                              const pl_render_scene *s, const pl_render_options *opt);
/// Draws the selected fluid layers (pressure, mesh, isolines, velocity) of the scene.
/// Returns the velocity scale used (m per m/s), 0 when no arrows were drawn.
double pl_draw_fluid(pl_draw_list *dl, const pl_render_scene *s, const pl_render_options *opt,
                     unsigned layers);
/// A reference arrow of a round velocity at pixel point at (tail), with its label.
void pl_draw_velocity_key(pl_draw_list *dl, pl_vec2 at, double velocity_scale, float fs);

/* Annotations (draw_annot.c); fs is the base font size in px. */

void pl_draw_time_stamp(pl_draw_list *dl, pl_vec2 at, double t, float fs);
void pl_draw_title(pl_draw_list *dl, pl_vec2 at, const char *title, float fs);
/// A scale bar of a round length (1, 2, 5 x 10^k m, shown in mm, cm or m) about a fifth of
/// max_px long, starting at left (px), baseline y.
void pl_draw_scale_bar(pl_draw_list *dl, pl_vec2 left, double max_px, float fs);
/// Vertical colour bar in the pixel rectangle r with nice ticks; label like "speed (m/s)".
void pl_draw_colorbar(pl_draw_list *dl, pl_px_rect r, pl_colormap map, double vmin, double vmax,
                      const char *label, float fs);
/// Legend of material colours at top-left point at.
void pl_draw_material_legend(pl_draw_list *dl, pl_vec2 at, const char (*names)[48],
                             const pl_rgba *colors, int n, float fs);

/// Base font size for an image: max(min(width, height) / 38, max(width, height) / 80),
/// between 11 and 30 px.
float pl_render_font_size(int width, int height);
/// Overlay text of a scene is drawn at least this fraction of the base font size (a scene's
/// 12 px label on a 1720 x 860 frame, whose base font is 22.6 px, is drawn at 17 px).
#define PL_OVERLAY_TEXT_MIN 0.75f

#ifdef __cplusplus
}
#endif
#endif
