/* HUD panels: dark translucent boxes with light text, sized from the text advance widths
 * measured by the renderer's font. */
#include "window_hud.h"

#include <string.h>

const char *const pl_hud_help[] = {
    "space  play / pause            s  one frame     .  one step",
    "+ / -  faster / slower         r  restart (keeps parameters)   R  restart with scene values",
    "left / backspace  rewind one frame      pgdown  rewind 1 s      home  back to start",
    "1 bodies  2 forces  3 pressure  4 isolines  5 velocity  6 mesh  7 labels  8 tangential",
    "c  colour by material / speed / stress     f  pressure / excess / head     a  auto range",
    "[ ]  narrower / wider colour range   wheel  zoom   drag empty space or middle button  pan",
    "z  fit view    drag a grain  spring grab    right click / x  fix or release the grain",
    "tab  next parameter   up / down  change it    p  screenshot (= headless render)",
    "i  hide / show all text    h  this help    q / esc  quit    (saving the scene reloads it)",
};
const int pl_hud_help_count = (int)(sizeof pl_hud_help / sizeof pl_hud_help[0]);

void pl_hud_panel(pl_draw_list *dl, int corner, double shift, const char *const *lines, int n,
                  float size, pl_rgba ink, pl_hud_measure measure, void *ud)
{
    if (n <= 0) return;
    double W = dl->camera.width, H = dl->camera.height;
    double lh = 1.35 * size, pad = 0.5 * size, wmax = 0.0;
    for (int i = 0; i < n; i++) {
        double w = measure(ud, lines[i], size);
        if (w > wmax) wmax = w;
    }
    double bw = wmax + 2.0 * pad, bh = n * lh + 2.0 * pad;
    double x0 = (corner & 1) ? W - bw - 4.0 : 4.0;
    double y0 = (corner & 2) ? H - bh - 4.0 - shift : 4.0 + shift;
    pl_vec2 box[4] = {{x0, y0}, {x0 + bw, y0}, {x0 + bw, y0 + bh}, {x0, y0 + bh}};
    pl_style st = pl_style_fill((pl_rgba){0.08f, 0.08f, 0.10f, 0.72f});
    pl_dl_polygon(dl, PL_SPACE_PIXEL, box, 4, &st);
    for (int i = 0; i < n; i++)
        pl_dl_text(dl, PL_SPACE_PIXEL, (pl_vec2){x0 + pad, y0 + pad + (i + 0.5) * lh}, lines[i],
                   size, PL_ANCHOR_LEFT | PL_ANCHOR_MIDDLE, 0.0f, ink, NULL);
}
