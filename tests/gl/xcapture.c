/* gl_xcapture WINDOW_ID OUT.png: captures an X11 window's pixels (XGetImage) into a PNG, to
 * check what the window really shows (test_window_xvfb.sh). */
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <stdlib.h>

#include "backend_cairo.h"

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: gl_xcapture WINDOW_ID OUT.png\n");
        return 2;
    }
    Display *d = XOpenDisplay(NULL);
    if (!d) {
        fprintf(stderr, "gl_xcapture: cannot open the display\n");
        return 1;
    }
    Window win = (Window)strtoul(argv[1], NULL, 0);
    XWindowAttributes wa;
    if (!XGetWindowAttributes(d, win, &wa)) {
        fprintf(stderr, "gl_xcapture: no window %s\n", argv[1]);
        return 1;
    }
    XImage *im = XGetImage(d, win, 0, 0, (unsigned)wa.width, (unsigned)wa.height, AllPlanes, ZPixmap);
    if (!im) {
        fprintf(stderr, "gl_xcapture: XGetImage failed\n");
        return 1;
    }
    pl_image img = {wa.width, wa.height, malloc((size_t)wa.width * (size_t)wa.height * 4)};
    for (int y = 0; y < wa.height; y++)
        for (int x = 0; x < wa.width; x++) {
            unsigned long p = XGetPixel(im, x, y);
            uint8_t *o = img.rgba + 4 * ((size_t)y * (size_t)wa.width + (size_t)x);
            o[0] = (uint8_t)((p & im->red_mask) >> 16);
            o[1] = (uint8_t)((p & im->green_mask) >> 8);
            o[2] = (uint8_t)(p & im->blue_mask);
            o[3] = 255;
        }
    char err[256];
    int rc = pl_png_write(argv[2], &img, 6, 1, err, sizeof err);
    if (rc) fprintf(stderr, "gl_xcapture: %s\n", err);
    XDestroyImage(im);
    XCloseDisplay(d);
    pl_image_free(&img);
    return rc ? 1 : 0;
}
