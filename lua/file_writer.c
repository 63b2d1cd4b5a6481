/* The engine's file writer for scenes (porelab/core.h pl_file_writer): every file the engine
 * makes (VTK, the MIMES geometry and pressure files) arrives here whole. A relative path is
 * taken inside the output folder; in the sandbox the file must lie inside it, symbolic links are
 * never followed, and a replaced file is written under a temporary name and renamed (a kill
 * never leaves half a file). Nothing here raises a Lua error: the engine may call it while it
 * steps. */
#include "file_writer.h"
#include "context.h"
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static int write_all(int fd, const void *data, size_t len) {
    const char *p = data;
    while (len > 0) {
        ssize_t k = write(fd, p, len);
        if (k < 0) {
            if (errno == EINTR) continue;
            return -1;
        }
        p += k;
        len -= (size_t)k;
    }
    return 0;
}

static int scene_write(void *ctx_, const char *path, int append, const void *data, size_t len, char *msg,
                       size_t msglen) {
    const pl_lua_context *ctx = ctx_;
    char full[PATH_MAX], real[PATH_MAX], out_real[PATH_MAX];
    if (!path || !path[0]) {
        snprintf(msg, msglen, "no file name given");
        return -1;
    }
    pl_path_join(full, sizeof full, ctx->out_dir, path);
    if (pl_path_mkdirs(ctx->out_dir) != 0) {
        snprintf(msg, msglen, "cannot create the output folder '%s': %s", ctx->out_dir, strerror(errno));
        return -1;
    }
    if (!ctx->trust) {
        if (pl_path_resolve(full, real, sizeof real) != 0 || pl_path_resolve(ctx->out_dir, out_real, sizeof out_real) != 0 ||
            !pl_path_inside(real, out_real)) {
            snprintf(msg, msglen, "'%s' is outside the output folder %s (scenes write only there; --trust lifts this)",
                     path, ctx->out_dir);
            return -1;
        }
    }
    const int flags = O_WRONLY | O_CREAT | O_NOFOLLOW | O_CLOEXEC;
    if (append) {
        int fd = open(full, flags | O_APPEND, 0644);
        if (fd < 0 || write_all(fd, data, len) != 0) {
            snprintf(msg, msglen, "cannot write '%s': %s", full, strerror(errno));
            if (fd >= 0) close(fd);
            return -1;
        }
        if (close(fd) != 0) {
            snprintf(msg, msglen, "cannot write '%s': %s", full, strerror(errno));
            return -1;
        }
        return 0;
    }
    char tmp[PATH_MAX + 32];
    snprintf(tmp, sizeof tmp, "%s.tmp-%ld", full, (long)getpid());
    int fd = open(tmp, flags | O_EXCL | O_TRUNC, 0644);
    if (fd < 0) {
        snprintf(msg, msglen, "cannot write '%s': %s", full, strerror(errno));
        return -1;
    }
    int bad = write_all(fd, data, len) != 0;
    bad |= close(fd) != 0;
    if (bad || rename(tmp, full) != 0) {
        snprintf(msg, msglen, "cannot write '%s': %s", full, strerror(errno));
        unlink(tmp);
        return -1;
    }
    return 0;
}

pl_file_writer pl_lua_file_writer(pl_lua_context *ctx) { return (pl_file_writer){scene_write, ctx}; }
