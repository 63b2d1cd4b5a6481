/* On-screen text of the window (status line, help, values under the cursor, parameters,
 * errors), drawn as a pixel-space draw list on top of the scene. Screenshots leave it out. */
#ifndef PL_APP_WINDOW_HUD_H
#define PL_APP_WINDOW_HUD_H

#include "render/drawlist.h"

/* Appends lines of text in a translucent panel; corner 0 top-left, 1 top-right,
 * 2 bottom-left, 3 bottom-right; shift moves it away from its edge (px). */
typedef double (*pl_hud_measure)(void *ud, const char *s, float size); /* text width, px */
void pl_hud_panel(pl_draw_list *dl, int corner, double shift, const char *const *lines, int n,
                  float size, pl_rgba ink, pl_hud_measure measure, void *ud);
/* The key list shown by 'h'. */
extern const char *const pl_hud_help[];
extern const int pl_hud_help_count;

#endif
