#include "vtk_series.h"
#include "porelab/fluid.h"
#include "render/atomic_file.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

struct pl_vtk_series {
    char dir[PATH_MAX];
    double *times;
    int n, cap;
    int fluid;
};

pl_vtk_series *pl_vtk_series_open(const char *dir, char *err, size_t errlen) {
    char sub[PATH_MAX];
    snprintf(sub, sizeof sub, "%s/vtk", dir);
    if (mkdir(sub, 0777) != 0 && errno != EEXIST) {
        snprintf(err, errlen, "cannot create %s: %s", sub, strerror(errno));
        return NULL;
    }
    pl_vtk_series *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    snprintf(s->dir, sizeof s->dir, "%s", dir);
    return s;
}

/* Writes DIR/run.pvd: one collection for the whole run, each frame's bodies (part 0),
 * contacts (part 1) and fluid (part 2, when there is a fluid mesh) at its time (under a
 * temporary name, renamed into place when whole: render/atomic_file.h). */
static int write_pvd(const pl_vtk_series *s, char *err, size_t errlen) {
    char path[PATH_MAX + 32];
    snprintf(path, sizeof path, "%s/run.pvd", s->dir);
    pl_atomic_file a;
    if (pl_atomic_file_begin(&a, path, err, errlen)) return -1;
    FILE *f = fopen(a.tmp_path, "w");
    if (!f) {
        snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    static const char *const parts[] = {"bodies", "contacts", "fluid"};
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n");
    for (int k = 0; k < s->n; k++)
        for (int p = 0; p < (s->fluid ? 3 : 2); p++)
            fprintf(f, "<DataSet timestep=\"%.9g\" part=\"%d\" name=\"%s\" file=\"vtk/frame_%06d_%s.vtu\"/>\n",
                    s->times[k], p, parts[p], k, parts[p]);
    fprintf(f, "</Collection>\n</VTKFile>\n");
    errno = 0;
    int ok = !ferror(f);
    int e = errno;
    if (fclose(f) != 0) {
        ok = 0;
        if (!e) e = errno;
    }
    if (!ok) snprintf(err, errlen, "cannot write %s: %s", path, e ? strerror(e) : "write error");
    return pl_atomic_file_end(&a, ok, err, errlen);
}

/* The frame's .vtu files come whole from the engine's file writer (a temporary name renamed
   into place: lua/file_writer.c); the .pvd collections are rewritten at every frame here, the
   same way (write_pvd). */
int pl_vtk_series_add(pl_vtk_series *s, pl_world *w, char *err, size_t errlen) {
    char prefix[PATH_MAX + 32];
    snprintf(prefix, sizeof prefix, "%s/vtk/frame_%06d", s->dir, s->n);
    if (pl_world_write_vtk(w, prefix) != PL_OK) {
        snprintf(err, errlen, "%s", pl_world_last_error(w));
        return -1;
    }
    if (pl_world_fluid_node_count(w) > 0) {
        char path[PATH_MAX + 48];
        snprintf(path, sizeof path, "%s_fluid.vtu", prefix);
        if (pl_world_fluid_write_vtu(w, path) != PL_OK) {
            snprintf(err, errlen, "%s", pl_world_last_error(w));
            return -1;
        }
        s->fluid = 1;
    }
    if (s->n == s->cap) {
        int cap = s->cap ? 2 * s->cap : 64;
        double *t = realloc(s->times, (size_t)cap * sizeof *t);
        if (!t) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        s->times = t;
        s->cap = cap;
    }
    s->times[s->n++] = pl_world_time(w);
    if (write_pvd(s, err, errlen)) return -1;
    return 0;
}

void pl_vtk_series_close(pl_vtk_series **s) {
    if (!s || !*s) return;
    free((*s)->times);
    free(*s);
    *s = NULL;
}
