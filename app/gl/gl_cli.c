/* `--renderer gl`: headless OpenGL stills and frames (see gl_cli.h). */
#include "gl_cli.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include <fcntl.h>

#include "render/drawlist.h"

#ifdef PL_HAVE_GL
#include "osmesa_context.h"
#endif

int pl_gl_cli_available(void)
{
#ifdef PL_HAVE_GL
    return 1;
#else
    return 0;
#endif
}

int pl_gl_cli_parse_renderer(const char *value, const char *cmd)
{
    if (!value || strcmp(value, "cairo") == 0) return 0;
    if (strcmp(value, "gl") == 0) {
        if (pl_gl_cli_available()) return 1;
        fprintf(stderr, "porelab %s: --renderer gl: this porelab was built without the OpenGL "
                        "renderer; install OSMesa (Debian: apt-get install libosmesa6-dev) and "
                        "rebuild\n", cmd);
        return -1;
    }
    fprintf(stderr, "porelab %s: --renderer must be cairo or gl (got '%s')\n", cmd, value);
    return -1;
}

#ifdef PL_HAVE_GL

int pl_gl_cli_still(const pl_world *w, const pl_render_options *opt, const char *path,
                    char *err, size_t errlen)
{
    const char *dot = strrchr(path, '.');
    if (!dot || strcasecmp(dot, ".png") != 0) {
        snprintf(err, errlen, "%s: the GL renderer writes PNG only (use --renderer cairo for "
                 "SVG or PDF)", path);
        return -1;
    }
    pl_osmesa *o = pl_osmesa_shared(err, errlen);
    if (!o) return -1;
    pl_draw_list dl;
    pl_draw_list_init(&dl);
    int rc = pl_render_build(w, opt, &dl, err, errlen);
    if (rc == 0) rc = pl_osmesa_write_png(o, &dl, path, 6, err, errlen);
    pl_draw_list_free(&dl);
    return rc;
}

struct pl_gl_frames {
    char dir[4096];
    char video[4096];
    int fps, count;
    pl_draw_list dl;
    pl_osmesa *o;
    pl_render_ranges ranges; /* fixed colour ranges and arrow scale across the run */
    int started;             /* stale frames of an earlier run removed */
};

static int make_dirs(const char *path, char *err, size_t errlen)
{
    char buf[4096];
    size_t n = strlen(path);
    if (n == 0 || n >= sizeof buf) {
        snprintf(err, errlen, "output folder name is empty or too long");
        return -1;
    }
    memcpy(buf, path, n + 1);
    for (size_t i = 1; i <= n; i++) {
        if (buf[i] == '/' || buf[i] == 0) {
            char c = buf[i];
            buf[i] = 0;
            if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
                snprintf(err, errlen, "cannot create the output folder %s: %s", buf,
                         strerror(errno));
                return -1;
            }
            buf[i] = c;
        }
    }
    return 0;
}

pl_gl_frames *pl_gl_frames_open(const char *dir, const char *video, int fps, char *err,
                                size_t errlen)
{
    if (make_dirs(dir, err, errlen) != 0) return NULL;
    if (video) {
        const char *dot = strrchr(video, '.');
        if (!dot || (strcasecmp(dot, ".mp4") != 0 && strcasecmp(dot, ".gif") != 0)) {
            snprintf(err, errlen, "--video %s: the video must end in .mp4 or .gif", video);
            return NULL;
        }
    }
    pl_osmesa *o = pl_osmesa_shared(err, errlen);
    if (!o) return NULL;
    pl_gl_frames *fw = calloc(1, sizeof *fw);
    if (!fw) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    snprintf(fw->dir, sizeof fw->dir, "%s", dir);
    if (video) snprintf(fw->video, sizeof fw->video, "%s", video);
    fw->fps = fps > 0 ? fps : 30;
    fw->o = o;
    pl_draw_list_init(&fw->dl);
    return fw;
}

int pl_gl_frames_add(pl_gl_frames *fw, const pl_world *w, const pl_render_options *opt,
                     char *err, size_t errlen)
{
    if (!fw->started) { /* a rerun into the same folder leaves no frames of the old run */
        pl_frames_remove_stale(fw->dir, fw->count, stderr);
        fw->started = 1;
    }
    if (opt->record_from > 0.0 && pl_world_time(w) < opt->record_from - 1e-9) return 0;
    pl_render_options fixed;
    pl_render_ranges_apply(&fw->ranges, opt, &fixed);
    if (pl_render_build(w, &fixed, &fw->dl, err, errlen) != 0) return -1;
    pl_render_ranges_update(&fw->ranges, &fw->dl);
    char path[4200];
    snprintf(path, sizeof path, "%s/frame_%06d.png", fw->dir, fw->count);
    /* level 1: frames are many and temporary; stills use 6 */
    if (pl_osmesa_write_png(fw->o, &fw->dl, path, 1, err, errlen) != 0) return -1;
    fw->count++;
    return 0;
}

int pl_gl_frames_count(const pl_gl_frames *fw) { return fw ? fw->count : 0; }

/* Encodes the PNG frames with ffmpeg; its messages go to DIR/ffmpeg.log. */
static int encode(pl_gl_frames *fw, char *err, size_t errlen)
{
    char pattern[4200], log[4200], rate[32];
    snprintf(pattern, sizeof pattern, "%s/frame_%%06d.png", fw->dir);
    snprintf(log, sizeof log, "%s/ffmpeg.log", fw->dir);
    snprintf(rate, sizeof rate, "%d", fw->fps);
    int gif = strcasecmp(strrchr(fw->video, '.'), ".gif") == 0;
    char *mp4[] = {"ffmpeg", "-y", "-loglevel", "error", "-framerate", rate, "-i", pattern,
                   "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt",
                   "yuv420p", fw->video, NULL};
    char *gifv[] = {"ffmpeg", "-y", "-loglevel", "error", "-framerate", rate, "-i", pattern,
                    "-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse", fw->video, NULL};
    pid_t pid = fork();
    if (pid < 0) {
        snprintf(err, errlen, "cannot start ffmpeg: %s", strerror(errno));
        return -1;
    }
    if (pid == 0) {
        int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
        }
        execvp("ffmpeg", gif ? gifv : mp4);
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
            snprintf(err, errlen, "ffmpeg is not installed (Debian package ffmpeg)");
        else
            snprintf(err, errlen, "ffmpeg failed (see %s)", log);
        return -1;
    }
    return 0;
}

int pl_gl_frames_close(pl_gl_frames **fwp, char *err, size_t errlen)
{
    if (!fwp || !*fwp) return 0;
    pl_gl_frames *fw = *fwp;
    int rc = 0;
    if (fw->video[0] && fw->count > 0) rc = encode(fw, err, errlen);
    pl_render_ranges_note(&fw->ranges, stderr);
    pl_draw_list_free(&fw->dl);
    free(fw);
    *fwp = NULL;
    return rc;
}

#else /* no GL backend in this build */

static int missing(char *err, size_t errlen)
{
    snprintf(err, errlen, "this porelab was built without the OpenGL renderer (install "
             "libosmesa6-dev and rebuild)");
    return -1;
}
int pl_gl_cli_still(const pl_world *w, const pl_render_options *opt, const char *path,
                    char *err, size_t errlen)
{
    return missing(err, errlen);
}
pl_gl_frames *pl_gl_frames_open(const char *dir, const char *video, int fps, char *err,
                                size_t errlen)
{
    missing(err, errlen);
    return NULL;
}
int pl_gl_frames_add(pl_gl_frames *fw, const pl_world *w, const pl_render_options *opt,
                     char *err, size_t errlen)
{
    return missing(err, errlen);
}
int pl_gl_frames_count(const pl_gl_frames *fw) { return 0; }
int pl_gl_frames_close(pl_gl_frames **fw, char *err, size_t errlen) { return 0; }

#endif
