/* Meshes of the solid's parts by gmsh's C API (Debian libgmsh-dev): structured (transfinite)
 * four-sided patches and annular sectors, unstructured triangles in a polygon. Without gmsh
 * (PL_HAVE_GMSH = 0) every function refuses with a message naming the package.
 *
 * gmsh keeps global state: each call initialises it if needed (a second initialisation is a
 * no-op in gmsh 4), silences its terminal, meshes in one thread in a model of its own name and
 * removes that model afterwards; gmsh is not finalised here because another room of the engine
 * may hold models of its own in the same process. Same input -> same mesh (single thread, no
 * random perturbation). */
#include "solid/fic/solid_mesh.h"
#include "core/alloc.h"
#include "mesh/gmsh_session.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#if PL_HAVE_GMSH
#include <gmshc.h>
#endif

void pl_sf_mesh_free(pl_sf_mesh *m) {
    pl_free(m->xy);
    pl_free(m->conn);
    m->xy = NULL;
    m->conn = NULL;
    m->nn = m->ne = 0;
}

#if !PL_HAVE_GMSH
static pl_status no_gmsh(char *msg, size_t len, const char *what) {
    snprintf(msg, len,
             "solid: meshing a %s needs gmsh's C API, which this build lacks (install the Debian package "
             "libgmsh-dev and reconfigure with cmake)",
             what);
    return PL_ERR_NOT_BUILT;
}
pl_status pl_sf_mesh_quad(const pl_vec2 c[4], int nx, int ny, int quads, pl_sf_mesh *out, char *msg, size_t len) {
    (void)c; (void)nx; (void)ny; (void)quads; (void)out;
    return no_gmsh(msg, len, "four-sided part");
}
pl_status pl_sf_mesh_annulus(double cx, double cy, double ri, double ro, double a0, double a1, int nr, int nt,
                             int quads, pl_sf_mesh *out, char *msg, size_t len) {
    (void)cx; (void)cy; (void)ri; (void)ro; (void)a0; (void)a1; (void)nr; (void)nt; (void)quads; (void)out;
    return no_gmsh(msg, len, "ring");
}
pl_status pl_sf_mesh_polygon(const pl_vec2 *v, int n, double h, pl_sf_mesh *out, char *msg, size_t len) {
    (void)v; (void)n; (void)h; (void)out;
    return no_gmsh(msg, len, "polygon");
}
pl_status pl_sf_mesh_read(const char *path, int quads, pl_sf_mesh *out, char *msg, size_t len) {
    (void)path; (void)quads; (void)out;
    return no_gmsh(msg, len, ".msh file");
}
#else

static int begin(void) {
    int ierr = 0;
    ierr = pl__gmsh_initialize(); /* not gmshInitialize: keeps gmsh (FLTK) out of $HOME */
    gmshOptionSetNumber("General.Terminal", 0, &ierr);
    gmshOptionSetNumber("General.Verbosity", 0, &ierr);
    gmshOptionSetNumber("General.NumThreads", 1, &ierr);
    gmshOptionSetNumber("Mesh.RandomFactor", 1e-9, &ierr);
    gmshOptionSetNumber("Mesh.Algorithm", 6, &ierr);
    gmshOptionSetNumber("Mesh.RecombineAll", 0, &ierr);
    gmshOptionSetNumber("Mesh.SaveAll", 0, &ierr);
    gmshModelAdd("porelab_solid_part", &ierr);
    return ierr;
}

static void end(void) {
    int ierr = 0;
    gmshModelRemove(&ierr);
}

static pl_status copy_mesh(int quads, pl_sf_mesh *out, char *msg, size_t len);

/* Generates the 2D mesh and copies nodes and elements of type 2 (3-node triangles) or 3 (4-node
   quadrilaterals). */
static pl_status extract(int quads, pl_sf_mesh *out, char *msg, size_t len) {
    int ierr = 0;
    gmshModelMeshGenerate(2, &ierr);
    if (ierr) {
        snprintf(msg, len, "solid: gmsh could not mesh the part (error %d)", ierr);
        return PL_ERR_NUMERIC;
    }
    return copy_mesh(quads, out, msg, len);
}

/* Copies the current model's nodes and elements of type 2 or 3 (the nodes they use only). */
static pl_status copy_mesh(int quads, pl_sf_mesh *out, char *msg, size_t len) {
    int ierr = 0;
    size_t *tags = NULL, ntags = 0, npc = 0, ncoord = 0;
    double *coord = NULL, *pc = NULL;
    gmshModelMeshGetNodes(&tags, &ntags, &coord, &ncoord, &pc, &npc, -1, -1, 0, 0, &ierr);
    size_t *et = NULL, net = 0, *en = NULL, nen = 0;
    gmshModelMeshGetElementsByType(quads ? 3 : 2, &et, &net, &en, &nen, -1, 0, 1, &ierr);
    pl_status st = PL_OK;
    size_t maxtag = 0;
    for (size_t k = 0; k < ntags; k++)
        if (tags[k] > maxtag) maxtag = tags[k];
    int32_t *map = pl_malloc(sizeof *map * (maxtag + 1));
    const int nv = quads ? 4 : 3;
    if (ierr || net == 0) {
        snprintf(msg, len, "solid: gmsh made no %s for the part", quads ? "quadrilaterals" : "triangles");
        st = PL_ERR_NUMERIC;
    } else if (!map) {
        st = PL_ERR_NOMEM;
    } else {
        for (size_t k = 0; k <= maxtag; k++) map[k] = -1;
        /* nodes that elements use, numbered in the order gmsh lists them */
        out->nn = 0;
        uint8_t *used = pl_calloc(maxtag + 1, 1);
        out->xy = pl_malloc(sizeof *out->xy * 2 * (ntags > 0 ? ntags : 1));
        out->conn = pl_malloc(sizeof *out->conn * nv * net);
        if (!used || !out->xy || !out->conn) {
            st = PL_ERR_NOMEM;
        } else {
            for (size_t k = 0; k < nen; k++) used[en[k]] = 1;
            for (size_t k = 0; k < ntags; k++) {
                if (!used[tags[k]]) continue;
                map[tags[k]] = out->nn;
                out->xy[2 * out->nn] = coord[3 * k];
                out->xy[2 * out->nn + 1] = coord[3 * k + 1];
                out->nn++;
            }
            out->ne = (int)net;
            out->nen = nv;
            for (size_t k = 0; k < nen; k++) out->conn[k] = map[en[k]];
        }
        pl_free(used);
    }
    pl_free(map);
    gmshFree(tags); gmshFree(coord); gmshFree(pc); gmshFree(et); gmshFree(en);
    if (st != PL_OK) pl_sf_mesh_free(out);
    return st;
}

pl_status pl_sf_mesh_read(const char *path, int quads, pl_sf_mesh *out, char *msg, size_t len) {
    memset(out, 0, sizeof *out);
    const size_t n = strlen(path);
    if (n < 5 || strcmp(path + n - 4, ".msh") != 0) {
        snprintf(msg, len, "solid_mesh: '%s' is not a gmsh mesh file: the name must end in .msh (gmsh would run "
                 "any other file as a script)", path);
        return PL_ERR_ARG;
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(msg, len, "solid_mesh: cannot read '%s': %s", path, strerror(errno));
        return PL_ERR_IO;
    }
    char head[16] = {0};
    const size_t got = fread(head, 1, 11, f);
    fclose(f);
    if (got < 11 || strncmp(head, "$MeshFormat", 11) != 0) {
        snprintf(msg, len, "solid_mesh: '%s' is not a gmsh .msh file (it does not begin with $MeshFormat)", path);
        return PL_ERR_ARG;
    }
    int ierr = begin();
    gmshMerge(path, &ierr); /* into the model begin() made current (gmshOpen would replace models) */
    if (ierr) {
        snprintf(msg, len, "solid_mesh: gmsh could not read '%s' (gmsh error %d: a damaged or unsupported .msh "
                 "file)", path, ierr);
        end();
        return PL_ERR_ARG;
    }
    /* 2D only: every node in the plane z = 0 */
    size_t *tags = NULL, ntags = 0, npc = 0, ncoord = 0;
    double *coord = NULL, *pc = NULL;
    gmshModelMeshGetNodes(&tags, &ntags, &coord, &ncoord, &pc, &npc, -1, -1, 0, 0, &ierr);
    double zmax = 0;
    for (size_t k = 0; k < ntags; k++) zmax = fmax(zmax, fabs(coord[3 * k + 2]));
    gmshFree(tags); gmshFree(coord); gmshFree(pc);
    if (ierr || ntags == 0) {
        snprintf(msg, len, "solid_mesh: '%s' holds no mesh nodes", path);
        end();
        return PL_ERR_ARG;
    }
    if (zmax > 0) {
        snprintf(msg, len, "solid_mesh: '%s' is not a plane mesh: a node lies at z = %g (porelab is 2D: z must be 0)",
                 path, zmax);
        end();
        return PL_ERR_ARG;
    }
    pl_status st = copy_mesh(quads, out, msg, len);
    if (st != PL_OK)
        snprintf(msg, len, "solid_mesh: '%s' has no %s (gmsh element type %d)%s", path,
                 quads ? "4-node quadrilaterals" : "3-node triangles", quads ? 3 : 2,
                 quads ? " for the Q1/P0 formulation" : ": mesh the surface with first-order triangles");
    end();
    return st;
}

pl_status pl_sf_mesh_quad(const pl_vec2 c[4], int nx, int ny, int quads, pl_sf_mesh *out, char *msg, size_t len) {
    memset(out, 0, sizeof *out);
    if (nx < 1 || ny < 1 || nx > 4000 || ny > 4000) {
        snprintf(msg, len, "solid: divisions nx = %d, ny = %d must be in [1, 4000]", nx, ny);
        return PL_ERR_ARG;
    }
    int ierr = begin();
    int p[4], l[4];
    for (int k = 0; k < 4; k++) p[k] = gmshModelGeoAddPoint(c[k].x, c[k].y, 0, 0, -1, &ierr);
    for (int k = 0; k < 4; k++) l[k] = gmshModelGeoAddLine(p[k], p[(k + 1) % 4], -1, &ierr);
    int loop = gmshModelGeoAddCurveLoop(l, 4, -1, 0, &ierr);
    int surf = gmshModelGeoAddPlaneSurface(&loop, 1, -1, &ierr);
    for (int k = 0; k < 4; k++) gmshModelGeoMeshSetTransfiniteCurve(l[k], (k % 2 == 0 ? nx : ny) + 1, "Progression", 1, &ierr);
    gmshModelGeoMeshSetTransfiniteSurface(surf, quads == PL_SF_TRI_RIGHT ? "Right" : "Alternate", p, 4, &ierr);
    if (quads == PL_SF_QUADS) gmshModelGeoMeshSetRecombine(2, surf, 45, &ierr);
    gmshModelGeoSynchronize(&ierr);
    pl_status st = extract(quads == PL_SF_QUADS, out, msg, len);
    end();
    return st;
}

pl_status pl_sf_mesh_annulus(double cx, double cy, double ri, double ro, double a0, double a1, int nr, int nt,
                             int quads, pl_sf_mesh *out, char *msg, size_t len) {
    memset(out, 0, sizeof *out);
    const double span = a1 - a0;
    if (!(ri > 0 && ro > ri) || !(span > 0 && span <= 2 * M_PI + 1e-12) || nr < 1 || nt < 1 || nr > 4000 ||
        nt > 4000) {
        snprintf(msg, len,
                 "solid: annulus needs 0 < ri < ro (got %g, %g), 0 < a1 - a0 <= 2 pi (got %g) and divisions in "
                 "[1, 4000] (got %d, %d)",
                 ri, ro, span, nr, nt);
        return PL_ERR_ARG;
    }
    const int full = span > 2 * M_PI - 1e-9;
    int pieces = (int)ceil(span / (0.5 * M_PI) - 1e-9);
    if (pieces < 1) pieces = 1;
    if (full && pieces < 4) pieces = 4;
    if (nt % pieces != 0) {
        snprintf(msg, len, "solid: the circumferential divisions nt = %d must be a multiple of %d for this sector",
                 nt, pieces);
        return PL_ERR_ARG;
    }
    int ierr = begin();
    int ctr = gmshModelGeoAddPoint(cx, cy, 0, 0, -1, &ierr);
    int pin[17], pout[17], radial[17], ain[16], aout[16];
    const int npt = full ? pieces : pieces + 1;
    for (int k = 0; k < npt; k++) {
        const double a = a0 + span * k / pieces;
        pin[k] = gmshModelGeoAddPoint(cx + ri * cos(a), cy + ri * sin(a), 0, 0, -1, &ierr);
        pout[k] = gmshModelGeoAddPoint(cx + ro * cos(a), cy + ro * sin(a), 0, 0, -1, &ierr);
        radial[k] = gmshModelGeoAddLine(pin[k], pout[k], -1, &ierr);
        gmshModelGeoMeshSetTransfiniteCurve(radial[k], nr + 1, "Progression", 1, &ierr);
    }
    for (int k = 0; k < pieces; k++) {
        const int k1 = (k + 1) % npt;
        ain[k] = gmshModelGeoAddCircleArc(pin[k], ctr, pin[k1], -1, 0, 0, 0, &ierr);
        aout[k] = gmshModelGeoAddCircleArc(pout[k], ctr, pout[k1], -1, 0, 0, 0, &ierr);
        gmshModelGeoMeshSetTransfiniteCurve(ain[k], nt / pieces + 1, "Progression", 1, &ierr);
        gmshModelGeoMeshSetTransfiniteCurve(aout[k], nt / pieces + 1, "Progression", 1, &ierr);
        int loopc[4] = {radial[k], aout[k], -radial[k1], -ain[k]};
        int loop = gmshModelGeoAddCurveLoop(loopc, 4, -1, 0, &ierr);
        int surf = gmshModelGeoAddPlaneSurface(&loop, 1, -1, &ierr);
        int corners[4] = {pin[k], pout[k], pout[k1], pin[k1]};
        gmshModelGeoMeshSetTransfiniteSurface(surf, quads == PL_SF_TRI_RIGHT ? "Right" : "Alternate", corners, 4, &ierr);
        if (quads == PL_SF_QUADS) gmshModelGeoMeshSetRecombine(2, surf, 45, &ierr);
    }
    gmshModelGeoSynchronize(&ierr);
    pl_status st = ierr ? PL_ERR_NUMERIC : extract(quads == PL_SF_QUADS, out, msg, len);
    if (ierr && st == PL_ERR_NUMERIC) snprintf(msg, len, "solid: gmsh refused the annulus geometry (error %d)", ierr);
    end();
    return st;
}

pl_status pl_sf_mesh_polygon(const pl_vec2 *v, int n, double h, pl_sf_mesh *out, char *msg, size_t len) {
    memset(out, 0, sizeof *out);
    if (n < 3 || n > 10000 || !(h > 0)) {
        snprintf(msg, len, "solid: a polygon needs 3 to 10000 vertices (got %d) and an element size h > 0 (got %g)", n, h);
        return PL_ERR_ARG;
    }
    int ierr = begin();
    int *p = pl_malloc(sizeof *p * 2 * (size_t)n);
    if (!p) {
        end();
        return PL_ERR_NOMEM;
    }
    int *l = p + n;
    for (int k = 0; k < n; k++) p[k] = gmshModelGeoAddPoint(v[k].x, v[k].y, 0, h, -1, &ierr);
    for (int k = 0; k < n; k++) l[k] = gmshModelGeoAddLine(p[k], p[(k + 1) % n], -1, &ierr);
    int loop = gmshModelGeoAddCurveLoop(l, (size_t)n, -1, 0, &ierr);
    gmshModelGeoAddPlaneSurface(&loop, 1, -1, &ierr);
    gmshModelGeoSynchronize(&ierr);
    pl_free(p);
    pl_status st = ierr ? PL_ERR_ARG : extract(0, out, msg, len);
    if (ierr) snprintf(msg, len, "solid: gmsh refused the polygon (error %d): it must be simple", ierr);
    end();
    return st;
}
#endif
