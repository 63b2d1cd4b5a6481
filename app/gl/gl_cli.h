/* The command line's side of the OpenGL renderer: `--renderer gl` for `porelab still` and
 * `porelab run` (headless through OSMesa). Compiled into the program whether or not the GL
 * backend was built; without it, the functions explain how to get it. */
#ifndef PL_APP_GL_CLI_H
#define PL_APP_GL_CLI_H

#include <stddef.h>
#include "porelab/world.h"
#include "render/render.h"

/* 1 when this build has the OpenGL renderer (OSMesa found at build time). */
int pl_gl_cli_available(void);

/* Checks a --renderer value: 0 = cairo, 1 = gl; -1 after printing the error (unknown name,
 * or gl asked for but not built). cmd names the command for the message. */
int pl_gl_cli_parse_renderer(const char *value, const char *cmd);

/* Renders the world's current state through headless GL into a PNG. 0 or -1 with err. */
int pl_gl_cli_still(const pl_world *w, const pl_render_options *opt, const char *path,
                    char *err, size_t errlen);

/* Frame writer for `run --renderer gl`: DIR/frame_000000.png ... rendered by GL; a video
 * (.mp4 or .gif) is encoded from the PNG frames by ffmpeg when the writer closes. */
typedef struct pl_gl_frames pl_gl_frames;
pl_gl_frames *pl_gl_frames_open(const char *dir, const char *video, int fps, char *err,
                                size_t errlen);
int pl_gl_frames_add(pl_gl_frames *fw, const pl_world *w, const pl_render_options *opt,
                     char *err, size_t errlen);
int pl_gl_frames_count(const pl_gl_frames *fw);
int pl_gl_frames_close(pl_gl_frames **fw, char *err, size_t errlen);

#endif
