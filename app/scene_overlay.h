/* Scene-drawn overlays: render.overlay in a scene is a list of items, or a function
 * (world) -> list called before each frame, turned into draw-list primitives drawn with the
 * `overlay` layer (e.g. the analytic water line, a settlement gauge, labels). */
#ifndef PL_APP_SCENE_OVERLAY_H
#define PL_APP_SCENE_OVERLAY_H

#include "render/drawlist.h"
#include "scene.h"

/* Clears dl and fills it from render.overlay. Returns 1 when the scene has an overlay, 0
 * when it has none, -1 on error (message in pl_scene_error). */
int pl_scene_overlay(pl_scene *s, pl_draw_list *dl);

#endif
