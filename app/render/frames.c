/* Frame writer: numbered PNG frames, optionally streamed to ffmpeg for a video.
 *
 * MP4: raw RGBA frames go to ffmpeg's stdin as they are rendered (libx264, yuv420p, padded to
 * even dimensions). The stream is a socketpair rather than a pipe so a crashed ffmpeg gives
 * an error code (send with MSG_NOSIGNAL) instead of a SIGPIPE that would kill porelab.
 * GIF: made at close from the PNG frames in two ffmpeg filter passes (palettegen, paletteuse
 * in one filter graph), which needs every frame anyway. ffmpeg's messages go to
 * DIR/ffmpeg.log.
 * Every file is whole under its final name (atomic_file.h): a frame is written under a hidden
 * temporary name and renamed when complete (pl_png_write), and ffmpeg writes the video under
 * a temporary name that is renamed at close when ffmpeg succeeded. */
#define _POSIX_C_SOURCE 200809L
#include "render.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <dirent.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "atomic_file.h"
#include "backend_cairo.h"
#include "draw_world.h"

enum { VIDEO_NONE = 0, VIDEO_MP4 = 1, VIDEO_GIF = 2 };

struct pl_frame_writer {
    char dir[4096];
    char video[4096];
    pl_atomic_file video_file; /* ffmpeg writes video_file.tmp_path */
    char log[4200];
    int video_kind;   /* VIDEO_* (NONE also when ffmpeg is missing) */
    int fps;
    int count;
    int width, height;
    int sock;         /* write end to ffmpeg (mp4), -1 when closed */
    pid_t pid;        /* ffmpeg process (mp4), 0 when none */
    int video_failed; /* ffmpeg stopped accepting frames */
    pl_render_scene scene;
    pl_draw_list dl;
    pl_image img;
    pl_render_ranges ranges; /* fixed colour ranges and arrow scale across the run */
    int started;      /* stale frames of an earlier run removed */
};

static int make_dirs(const char *path, char *err, size_t errlen) {
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
                snprintf(err, errlen, "cannot create the output folder %s: %s", buf, strerror(errno));
                return -1;
            }
            buf[i] = c;
        }
    }
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISDIR(st.st_mode)) {
        snprintf(err, errlen, "%s exists and is not a folder", path);
        return -1;
    }
    return 0;
}

/* 1 when an executable named ffmpeg is on PATH. */
static int ffmpeg_on_path(void) {
    const char *path = getenv("PATH");
    if (!path) return 0;
    char buf[4096];
    while (*path) {
        const char *end = strchr(path, ':');
        size_t len = end ? (size_t)(end - path) : strlen(path);
        if (len > 0 && len + 8 < sizeof buf) {
            memcpy(buf, path, len);
            memcpy(buf + len, "/ffmpeg", 8);
            if (access(buf, X_OK) == 0) return 1;
        }
        if (!end) break;
        path = end + 1;
    }
    return 0;
}

/* Starts ffmpeg with argv; stdin from in_fd (or /dev/null when < 0), output to the log. */
static pid_t spawn_ffmpeg(char *const argv[], int in_fd, const char *log) {
    pid_t pid = fork();
    if (pid != 0) return pid;
    int fd = in_fd >= 0 ? in_fd : open("/dev/null", O_RDONLY);
    if (fd >= 0 && fd != 0) {
        dup2(fd, 0);
        close(fd);
    }
    int lf = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0666);
    if (lf >= 0) {
        dup2(lf, 1);
        dup2(lf, 2);
        close(lf);
    }
    execvp("ffmpeg", argv);
    _exit(127);
}

pl_frame_writer *pl_frame_writer_open(const char *dir, const char *video_path, int fps,
                                      char *err, size_t errlen) {
    if (!dir || !*dir) dir = ".";
    if (fps <= 0 || fps > 1000) {
        snprintf(err, errlen, "frames per second %d is out of range (1..1000)", fps);
        return NULL;
    }
    int kind = VIDEO_NONE;
    if (video_path && *video_path) {
        const char *dot = strrchr(video_path, '.');
        if (dot && strcasecmp(dot, ".mp4") == 0) kind = VIDEO_MP4;
        else if (dot && strcasecmp(dot, ".gif") == 0) kind = VIDEO_GIF;
        else {
            snprintf(err, errlen, "%s: unknown video format (valid extensions: .mp4, .gif)", video_path);
            return NULL;
        }
        if (strlen(video_path) >= 4096) {
            snprintf(err, errlen, "video file name is too long");
            return NULL;
        }
    }
    if (strlen(dir) >= 4096) {
        snprintf(err, errlen, "output folder name is too long");
        return NULL;
    }
    if (make_dirs(dir, err, errlen)) return NULL;
    pl_frame_writer *fw = calloc(1, sizeof *fw);
    if (!fw) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    snprintf(fw->dir, sizeof fw->dir, "%s", dir);
    snprintf(fw->log, sizeof fw->log, "%s/ffmpeg.log", dir);
    fw->fps = fps;
    fw->sock = -1;
    pl_render_scene_init(&fw->scene);
    pl_draw_list_init(&fw->dl);
    if (kind != VIDEO_NONE) {
        snprintf(fw->video, sizeof fw->video, "%s", video_path);
        if (pl_atomic_file_begin(&fw->video_file, video_path, err, errlen)) {
            free(fw);
            return NULL;
        }
        if (ffmpeg_on_path()) {
            fw->video_kind = kind;
        } else {
            fprintf(stderr, "porelab: ffmpeg is not installed (not found on PATH), so no video "
                            "%s is made; the PNG frames are in %s\n", video_path, dir);
        }
    }
    return fw;
}

static int start_mp4(pl_frame_writer *fw, char *err, size_t errlen) {
    int sv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM, 0, sv) != 0) {
        snprintf(err, errlen, "cannot start ffmpeg: %s", strerror(errno));
        return -1;
    }
    /* our end must not stay open in ffmpeg, or it would never see the end of the stream */
    fcntl(sv[1], F_SETFD, FD_CLOEXEC);
    char size[64], rate[32];
    snprintf(size, sizeof size, "%dx%d", fw->width, fw->height);
    snprintf(rate, sizeof rate, "%d", fw->fps);
    char *argv[] = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo",
                    "-pix_fmt", "rgba", "-s", size, "-r", rate, "-i", "-",
                    "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-preset", "veryfast",
                    "-crf", "20", "-pix_fmt", "yuv420p", "-movflags", "+faststart",
                    fw->video_file.tmp_path, NULL};
    pid_t pid = spawn_ffmpeg(argv, sv[0], fw->log);
    close(sv[0]);
    if (pid < 0) {
        close(sv[1]);
        snprintf(err, errlen, "cannot start ffmpeg: %s", strerror(errno));
        return -1;
    }
    fw->pid = pid;
    fw->sock = sv[1];
    return 0;
}

static int send_all(int fd, const unsigned char *p, size_t n) {
    while (n > 0) {
        ssize_t k = send(fd, p, n, MSG_NOSIGNAL);
        if (k < 0) {
            if (errno == EINTR) continue;
            return -1;
        }
        p += k;
        n -= (size_t)k;
    }
    return 0;
}

int pl_frames_remove_stale(const char *dir, int from, FILE *note) {
    DIR *d = opendir(dir);
    if (!d) return 0;
    int removed = 0;
    struct dirent *e;
    char path[4200];
    while ((e = readdir(d)) != NULL) {
        int idx = -1, len = 0;
        if (sscanf(e->d_name, "frame_%6d.png%n", &idx, &len) == 1 && len == 16 &&
            e->d_name[16] == 0 && idx >= from) {
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            if (unlink(path) == 0) removed++;
        }
    }
    closedir(d);
    if (removed > 0 && note)
        fprintf(note, "porelab: removed %d frame%s of an earlier run from %s/ (frame_%06d.png "
                      "and later)\n", removed, removed == 1 ? "" : "s", dir, from);
    return removed;
}

int pl_frame_writer_add(pl_frame_writer *fw, const pl_world *w, const pl_render_options *in_opt,
                        char *err, size_t errlen) {
    if (!fw->started) { /* a rerun into the same folder leaves no frames of the old run */
        pl_frames_remove_stale(fw->dir, fw->count, stderr);
        fw->started = 1;
    }
    /* a scene's preparation (before render.record_from) is run but not recorded */
    if (in_opt->record_from > 0.0 && pl_world_time(w) < in_opt->record_from - 1e-9) return 0;
    pl_render_options fixed;
    pl_render_ranges_apply(&fw->ranges, in_opt, &fixed);
    const pl_render_options *opt = &fixed;
    if (fw->count > 0 && fw->width > 0 && (opt->width != fw->width || opt->height != fw->height)) {
        snprintf(err, errlen, "frame size changed from %dx%d to %dx%d during the run",
                 fw->width, fw->height, opt->width, opt->height);
        return -1;
    }
    fw->width = opt->width;
    fw->height = opt->height;
    unsigned fluid = PL_LAYER_MESH | PL_LAYER_PRESSURE | PL_LAYER_ISOLINES | PL_LAYER_VELOCITY;
    if (pl_render_scene_capture(&fw->scene, w) ||
        ((opt->layers & fluid) &&
         pl_render_scene_capture_fluid_opt(&fw->scene, w, opt))) {
        snprintf(err, errlen, "out of memory while reading the world");
        return -1;
    }
    if (pl_render_build_scene(&fw->dl, &fw->scene, opt, err, errlen)) return -1;
    pl_render_ranges_update(&fw->ranges, &fw->dl);
    if (pl_cairo_rasterize(&fw->dl, &fw->img, err, errlen)) return -1;
    char path[4200];
    snprintf(path, sizeof path, "%s/frame_%06d.png", fw->dir, fw->count);
    if (pl_png_write(path, &fw->img, 1, 0, err, errlen)) return -1;
    fw->count++;
    if (fw->video_kind == VIDEO_MP4 && !fw->video_failed) {
        if (fw->sock < 0 && fw->pid == 0 && start_mp4(fw, err, errlen)) {
            fw->video_failed = 1;
            return -1;
        }
        size_t n = (size_t)fw->width * (size_t)fw->height * 4u;
        if (send_all(fw->sock, fw->img.rgba, n)) {
            fw->video_failed = 1;
            snprintf(err, errlen, "ffmpeg stopped accepting frames (see %s); the PNG frames go on",
                     fw->log);
            return -1;
        }
    }
    return 0;
}

int pl_frame_writer_count(const pl_frame_writer *fw) { return fw ? fw->count : 0; }
void pl_frame_writer_start_at(pl_frame_writer *fw, int index) { if (fw && fw->count == 0 && index > 0) fw->count = index; }

static int wait_ffmpeg(pid_t pid, const char *what, const char *log, char *err, size_t errlen) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            snprintf(err, errlen, "lost track of ffmpeg while making %s", what);
            return -1;
        }
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return 0;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
        snprintf(err, errlen, "ffmpeg could not be started for %s", what);
    else
        snprintf(err, errlen, "ffmpeg failed making %s (status %d); see %s", what,
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1, log);
    return -1;
}

int pl_frame_writer_close(pl_frame_writer **pfw, char *err, size_t errlen) {
    if (!pfw || !*pfw) return 0;
    pl_frame_writer *fw = *pfw;
    int rc = 0;
    if (fw->sock >= 0) close(fw->sock);
    if (fw->pid > 0) rc = wait_ffmpeg(fw->pid, fw->video, fw->log, err, errlen);
    if (rc == 0 && fw->video_failed) {
        snprintf(err, errlen, "the video %s was not made: ffmpeg stopped accepting frames (see %s)",
                 fw->video, fw->log);
        rc = -1;
    }
    if (rc == 0 && fw->video_kind == VIDEO_GIF && fw->count > 0) {
        char pattern[4200], rate[32], frames[32];
        snprintf(pattern, sizeof pattern, "%s/frame_%%06d.png", fw->dir);
        snprintf(rate, sizeof rate, "%d", fw->fps);
        snprintf(frames, sizeof frames, "%d", fw->count);
        char *argv[] = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-framerate", rate,
                        "-start_number", "0", "-i", pattern, "-frames:v", frames, "-vf",
                        "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer",
                        "-loop", "0", fw->video_file.tmp_path, NULL};
        pid_t pid = spawn_ffmpeg(argv, -1, fw->log);
        if (pid < 0) {
            snprintf(err, errlen, "cannot start ffmpeg: %s", strerror(errno));
            rc = -1;
        } else {
            rc = wait_ffmpeg(pid, fw->video, fw->log, err, errlen);
        }
    }
    if (fw->video_kind == VIDEO_MP4 ? fw->pid > 0 : fw->video_kind == VIDEO_GIF && fw->count > 0) {
        /* the video is whole under its final name, or not there */
        if (pl_atomic_file_end(&fw->video_file, rc == 0, err, errlen)) rc = -1;
    }
    pl_render_ranges_note(&fw->ranges, stderr);
    pl_render_scene_free(&fw->scene);
    pl_draw_list_free(&fw->dl);
    pl_image_free(&fw->img);
    free(fw);
    *pfw = NULL;
    return rc;
}
