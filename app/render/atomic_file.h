/* Whole-file output: every file porelab writes in one go (PNG frames and stills, SVG/PDF
 * stills, charts, videos) is written under a hidden temporary name in the same folder and
 * renamed over its final name only once it is complete, so a kill, a crash or a full disk
 * never leaves a half-written file under the final name (rename() within a folder is
 * atomic). A kill may leave the hidden temporary (".frame_000003.tmp-1234.png") behind.
 *
 *     pl_atomic_file a;
 *     if (pl_atomic_file_begin(&a, path, err, errlen)) return -1;
 *     int ok = write_whole_file(a.tmp_path) == 0;
 *     return pl_atomic_file_end(&a, ok, err, errlen);  // rename on success, else unlink
 *
 * The temporary keeps the final extension, so writers that choose the format from the file
 * name (cairo, ffmpeg) write the same format. Header-only so that the renderer and the
 * program share it without a new source file. No fsync: this protects against
 * the process dying, not against a power cut. */
#ifndef PL_RENDER_ATOMIC_FILE_H
#define PL_RENDER_ATOMIC_FILE_H

#include <errno.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define PL_ATOMIC_PATH_MAX 4096

typedef struct pl_atomic_file {
    char final_path[PL_ATOMIC_PATH_MAX];
    char tmp_path[PL_ATOMIC_PATH_MAX + 64];
} pl_atomic_file;

/* Chooses the temporary name for `path`: DIR/.NAME.tmp-PID.EXT (NAME without the extension).
 * Returns 0, or -1 with a message when the name is empty or too long. */
static inline int pl_atomic_file_begin(pl_atomic_file *a, const char *path, char *err,
                                       size_t errlen)
{
    size_t n = path ? strlen(path) : 0;
    const char *slash = path ? strrchr(path, '/') : NULL;
    const char *base = slash ? slash + 1 : path;
    if (n == 0 || n >= sizeof a->final_path || !*base) {
        snprintf(err, errlen, "cannot write '%s': the file name is empty or too long",
                 path ? path : "");
        return -1;
    }
    memcpy(a->final_path, path, n + 1);
    const char *dot = strrchr(base, '.');
    if (!dot || dot == base) dot = base + strlen(base);
    int dir_len = (int)(base - path), stem_len = (int)(dot - base);
    snprintf(a->tmp_path, sizeof a->tmp_path, "%.*s.%.*s.tmp-%ld%s", dir_len, path, stem_len,
             base, (long)getpid(), dot);
    return 0;
}

/* Finishes: ok != 0 renames the temporary over the final name (0, or -1 with a message);
 * ok == 0 removes the temporary and returns -1 (the caller's message stands). */
static inline int pl_atomic_file_end(pl_atomic_file *a, int ok, char *err, size_t errlen)
{
    if (ok && rename(a->tmp_path, a->final_path) == 0) return 0;
    if (ok)
        snprintf(err, errlen, "cannot write %s: renaming %s into place failed: %s",
                 a->final_path, a->tmp_path, strerror(errno));
    int keep = errno;
    unlink(a->tmp_path);
    errno = keep;
    return -1;
}

#endif
