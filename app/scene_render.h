/* Translates the scene's `render` table into pl_render_options. This is the one place
 * where Lua and the renderer meet (lua/ never includes render.h). */
#ifndef PL_APP_SCENE_RENDER_H
#define PL_APP_SCENE_RENDER_H

#include "render/render.h"
#include "scene.h"

/* Applies the fields of result.render over *opt. Returns 0, or -1 with a message in
 * pl_scene_error ("scenes/x.lua: render: size must be ..."). */
int pl_scene_render_options(pl_scene *s, pl_world *w, pl_render_options *opt);

/* A colour at stack index idx: "#rrggbb", "#rrggbbaa" or {r, g, b [, a]} in 0..1. Raises
 * "<what> must be a colour ..." otherwise (call only inside a protected reader). */
pl_rgba pl_scene_render_color(lua_State *L, int idx, const char *what);

#endif
