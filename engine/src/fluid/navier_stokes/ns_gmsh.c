/* Meshing the pore space with gmsh's C API (Debian libgmsh-dev).
 *
 * gmsh keeps global state (options, models). Each call initialises gmsh, sets every option the
 * result depends on (terminal silenced, one thread, Frontal-Delaunay, the size field), meshes one
 * model and finalises gmsh again, so two calls with the same input give the same mesh and nothing
 * leaks from one call into the next. The engine steps single-threaded, so calls never nest. */
#include "fluid/navier_stokes/ns_internal.h"
#include "core/alloc.h"
#include "mesh/gmsh_session.h"
#include <stdio.h>
#include <string.h>

#if PL_HAVE_GMSH
#include <gmshc.h>

int ns_have_gmsh(void) { return 1; }

#define GCHK(what)                                                                                 \
    do {                                                                                           \
        if (ierr) {                                                                                \
            snprintf(msg, msg_size, "gmsh failed in %s (error %d)", what, ierr);                    \
            goto fail;                                                                             \
        }                                                                                          \
    } while (0)

static int sorted_find(const size_t *keys, size_t n, size_t key) {
    size_t lo = 0, hi = n;
    while (lo < hi) {
        const size_t mid = (lo + hi) / 2;
        if (keys[mid] < key) lo = mid + 1;
        else hi = mid;
    }
    return lo < n && keys[lo] == key ? (int)lo : -1;
}

int ns_mesh_domain(const ns_domain *d, ns_mesh *out, char *msg, size_t msg_size) {
    int ierr = 0, ok = -1;
    memset(out, 0, sizeof *out);
    if (!(d->x1 > d->x0 && d->y1 > d->y0 && d->h_far > 0 && ((d->nholes == 0 && !d->refine_corners) || d->h_near > 0))) {
        snprintf(msg, msg_size, "mesh domain: need x1 > x0, y1 > y0, h_far > 0 and h_near > 0");
        return -1;
    }
    int ncurve_max = 4;
    for (int k = 0; k < d->nholes; k++) ncurve_max += d->hole_offset[k + 1] - d->hole_offset[k];
    int *curve_tag = pl_malloc(sizeof(int) * (size_t)ncurve_max); /* bc tag of curve i */
    int *curve_gmsh = pl_malloc(sizeof(int) * (size_t)ncurve_max); /* gmsh tag of curve i */
    int *loops = pl_malloc(sizeof(int) * (size_t)(d->nholes + 1));
    int *lines = pl_malloc(sizeof(int) * (size_t)ncurve_max);
    double *hole_curves = pl_malloc(sizeof(double) * (size_t)ncurve_max);
    size_t *ntags = NULL, *etags = NULL, *enodes = NULL;
    double *coord = NULL, *pc = NULL;
    size_t ntags_n = 0, coord_n = 0, pc_n = 0, etags_n = 0, enodes_n = 0;
    size_t *order = NULL;
    if (!curve_tag || !curve_gmsh || !loops || !lines || !hole_curves) {
        snprintf(msg, msg_size, "mesh domain: out of memory");
        goto done_nogmsh;
    }
    ierr = pl__gmsh_initialize(); /* not gmshInitialize: keeps gmsh (FLTK) out of $HOME */
    if (ierr) {
        snprintf(msg, msg_size, "gmsh could not be initialised (error %d)", ierr);
        goto done_nogmsh;
    }
    gmshOptionSetNumber("General.Terminal", 0, &ierr);
    gmshOptionSetNumber("General.Verbosity", 0, &ierr);
    gmshOptionSetNumber("General.AbortOnError", 0, &ierr);
    gmshOptionSetNumber("General.NumThreads", 1, &ierr);
    gmshOptionSetNumber("Mesh.MaxNumThreads2D", 1, &ierr);
    gmshOptionSetNumber("Mesh.Algorithm", 6, &ierr); /* Frontal-Delaunay */
    gmshOptionSetNumber("Mesh.RandomFactor", 1e-9, &ierr);
    gmshOptionSetNumber("Mesh.MeshSizeExtendFromBoundary", d->nholes || d->refine_corners ? 0 : 1, &ierr);
    gmshOptionSetNumber("Mesh.MeshSizeFromCurvature", 0, &ierr);
    gmshOptionSetNumber("Mesh.MeshSizeFromPoints", 1, &ierr);
    gmshOptionSetNumber("Mesh.ElementOrder", 1, &ierr);
    GCHK("setting options");
    gmshModelAdd("porelab_pore_space", &ierr);
    GCHK("model add");
    /* outer box, counter-clockwise: bottom, right, top, left */
    const double bx[4] = {d->x0, d->x1, d->x1, d->x0}, by[4] = {d->y0, d->y0, d->y1, d->y1};
    int pts[4];
    for (int i = 0; i < 4; i++) pts[i] = gmshModelGeoAddPoint(bx[i], by[i], 0, d->h_far, -1, &ierr);
    GCHK("outer points");
    int nc = 0;
    for (int i = 0; i < 4; i++) {
        lines[i] = gmshModelGeoAddLine(pts[i], pts[(i + 1) % 4], -1, &ierr);
        curve_gmsh[nc] = lines[i];
        curve_tag[nc++] = NS_TAG_BOTTOM + i;
    }
    GCHK("outer lines");
    loops[0] = gmshModelGeoAddCurveLoop(lines, 4, -1, 0, &ierr);
    GCHK("outer loop");
    int nhc = 0;
    for (int k = 0; k < d->nholes; k++) {
        const int o = d->hole_offset[k], m = d->hole_offset[k + 1] - o;
        int first = -1, prev = -1, nl = 0;
        for (int i = 0; i < m; i++) {
            const int p = gmshModelGeoAddPoint(d->hole_xy[2 * (o + i)], d->hole_xy[2 * (o + i) + 1], 0, d->h_near, -1,
                                               &ierr);
            if (i == 0) first = p;
            else lines[nl++] = gmshModelGeoAddLine(prev, p, -1, &ierr);
            prev = p;
        }
        lines[nl++] = gmshModelGeoAddLine(prev, first, -1, &ierr);
        GCHK("hole outline");
        for (int i = 0; i < nl; i++) {
            curve_gmsh[nc] = lines[i];
            curve_tag[nc++] = NS_TAG_HOLE0 + k;
            hole_curves[nhc++] = lines[i];
        }
        loops[k + 1] = gmshModelGeoAddCurveLoop(lines, (size_t)nl, -1, 0, &ierr);
        GCHK("hole loop");
    }
    gmshModelGeoAddPlaneSurface(loops, (size_t)(d->nholes + 1), -1, &ierr);
    GCHK("plane surface");
    gmshModelGeoSynchronize(&ierr);
    GCHK("synchronize");
    if (d->nholes > 0 || d->refine_corners) {
        const int fd = gmshModelMeshFieldAdd("Distance", -1, &ierr);
        GCHK("distance field");
        if (nhc > 0) {
            gmshModelMeshFieldSetNumbers(fd, "CurvesList", hole_curves, (size_t)nhc, &ierr);
            if (ierr) {
                ierr = 0;
                gmshModelMeshFieldSetNumbers(fd, "EdgesList", hole_curves, (size_t)nhc, &ierr);
            }
            GCHK("distance curves");
        }
        if (d->refine_corners) {
            double rp[4];
            int nr = 0;
            for (int i = 0; i < 4; i++)
                if (d->refine_corners & (1 << i)) rp[nr++] = pts[i];
            gmshModelMeshFieldSetNumbers(fd, "PointsList", rp, (size_t)nr, &ierr);
            if (ierr) {
                ierr = 0;
                gmshModelMeshFieldSetNumbers(fd, "NodesList", rp, (size_t)nr, &ierr);
            }
            GCHK("distance points");
        }
        gmshModelMeshFieldSetNumber(fd, "NumPointsPerCurve", 20, &ierr);
        ierr = 0; /* named Sampling in later gmsh: the default sampling is fine too */
        const int ft = gmshModelMeshFieldAdd("Threshold", -1, &ierr);
        gmshModelMeshFieldSetNumber(ft, "InField", fd, &ierr);
        gmshModelMeshFieldSetNumber(ft, "SizeMin", d->h_near, &ierr);
        gmshModelMeshFieldSetNumber(ft, "SizeMax", d->h_far, &ierr);
        gmshModelMeshFieldSetNumber(ft, "DistMin", d->d_min, &ierr);
        gmshModelMeshFieldSetNumber(ft, "DistMax", d->d_max > d->d_min ? d->d_max : d->d_min + d->h_far, &ierr);
        GCHK("threshold field");
        gmshModelMeshFieldSetAsBackgroundMesh(ft, &ierr);
        GCHK("background field");
    }
    gmshModelMeshGenerate(2, &ierr);
    GCHK("mesh generate");
    gmshModelMeshGetNodes(&ntags, &ntags_n, &coord, &coord_n, &pc, &pc_n, -1, -1, 0, 0, &ierr);
    GCHK("get nodes");
    gmshModelMeshGetElementsByType(2, &etags, &etags_n, &enodes, &enodes_n, -1, 0, 1, &ierr);
    GCHK("get triangles");
    if (ntags_n == 0 || etags_n == 0) {
        snprintf(msg, msg_size, "gmsh produced an empty mesh");
        goto fail;
    }
    /* node tags sorted with their index (tags need not be dense) */
    order = pl_malloc(sizeof(size_t) * ntags_n * 2);
    if (!order) goto fail;
    {
        /* insertion by counting: tags are unique; sort (tag, index) pairs by tag */
        size_t *keys = order, *idx = order + ntags_n;
        for (size_t i = 0; i < ntags_n; i++) {
            keys[i] = ntags[i];
            idx[i] = i;
        }
        /* shell sort on pairs: deterministic, no allocation */
        for (size_t gap = ntags_n / 2; gap > 0; gap /= 2)
            for (size_t i = gap; i < ntags_n; i++) {
                const size_t kt = keys[i], it = idx[i];
                size_t j = i;
                for (; j >= gap && keys[j - gap] > kt; j -= gap) {
                    keys[j] = keys[j - gap];
                    idx[j] = idx[j - gap];
                }
                keys[j] = kt;
                idx[j] = it;
            }
        out->nv = (int)ntags_n;
        out->nt = (int)etags_n;
        out->xy = pl_malloc(sizeof(double) * 2 * ntags_n);
        out->tri = pl_malloc(sizeof(int32_t) * 3 * etags_n);
        if (!out->xy || !out->tri) goto fail;
        for (size_t i = 0; i < ntags_n; i++) {
            /* vertex numbering: the order of the sorted tags */
            out->xy[2 * i] = coord[3 * idx[i]];
            out->xy[2 * i + 1] = coord[3 * idx[i] + 1];
        }
        for (size_t t = 0; t < 3 * etags_n; t++) {
            const int at = sorted_find(keys, ntags_n, enodes[t]);
            if (at < 0) {
                snprintf(msg, msg_size, "gmsh triangle refers to an unknown node");
                goto fail;
            }
            out->tri[t] = at;
        }
        if (ns_mesh_build_edges(out)) goto fail;
        /* boundary tags from the 1D elements of each curve */
        for (int c = 0; c < nc; c++) {
            size_t *lt = NULL, *ln = NULL, lt_n = 0, ln_n = 0;
            gmshModelMeshGetElementsByType(1, &lt, &lt_n, &ln, &ln_n, curve_gmsh[c], 0, 1, &ierr);
            if (ierr) {
                gmshFree(lt);
                gmshFree(ln);
                GCHK("get boundary lines");
            }
            for (size_t l = 0; l < lt_n; l++) {
                const int a = sorted_find(keys, ntags_n, ln[2 * l]), b = sorted_find(keys, ntags_n, ln[2 * l + 1]);
                if (a < 0 || b < 0) continue;
                /* find the edge (a, b): scan the triangles' edges at vertex a is costly; use the
                   edge list, sorted by (min, max) by construction */
                const int32_t lo = a < b ? a : b, hi = a < b ? b : a;
                int e0 = 0, e1 = out->ne;
                while (e0 < e1) {
                    const int mid = (e0 + e1) / 2;
                    const int32_t *em = out->edge + 2 * mid;
                    if (em[0] < lo || (em[0] == lo && em[1] < hi)) e0 = mid + 1;
                    else e1 = mid;
                }
                if (e0 < out->ne && out->edge[2 * e0] == lo && out->edge[2 * e0 + 1] == hi)
                    out->edge_tag[e0] = curve_tag[c];
            }
            gmshFree(lt);
            gmshFree(ln);
        }
        for (int e = 0; e < out->ne; e++)
            if (out->edge_tri[2 * e + 1] < 0 && out->edge_tag[e] == 0) {
                snprintf(msg, msg_size, "gmsh mesh has a boundary edge on no curve (overlapping holes?)");
                goto fail;
            }
    }
    ok = 0;
fail:
    if (ok && out->xy == NULL && msg[0] == 0) snprintf(msg, msg_size, "mesh domain: out of memory");
    gmshFree(ntags);
    gmshFree(coord);
    gmshFree(pc);
    gmshFree(etags);
    gmshFree(enodes);
    gmshFinalize(&ierr);
done_nogmsh:
    pl_free(order);
    pl_free(curve_tag);
    pl_free(curve_gmsh);
    pl_free(loops);
    pl_free(lines);
    pl_free(hole_curves);
    if (ok) ns_mesh_free(out);
    return ok;
}

#else

int ns_have_gmsh(void) { return 0; }

int ns_mesh_domain(const ns_domain *d, ns_mesh *out, char *msg, size_t msg_size) {
    (void)d;
    memset(out, 0, sizeof *out);
    snprintf(msg, msg_size,
             "this build has no gmsh: the Navier-Stokes model meshes with gmsh's C API (install the Debian "
             "package libgmsh-dev and rebuild)");
    return -1;
}

#endif
