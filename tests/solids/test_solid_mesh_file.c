/* Reading a solid part from a gmsh .msh file (solid_mesh_gmsh.c, pl_sf_mesh_read; w:solid_mesh).
 * - a plate 2 x 1 with a hole of radius 0.25 meshed by gmsh and written as .msh 4.1 (gmsh's own
 *   writer), read back: the same node and triangle counts gmsh reports, the area within 1 % of
 *   2 - pi 0.25^2 (polygonal hole), every triangle positive;
 * - bad files: missing, not named .msh, not a gmsh file, damaged after the header, not plane:
 *   each refused with the file's name and the reason.
 * Writes plate_hole.msh into the folder given as the first argument (default: current). */
#include "harness.h"
#include "solid_test_util.h"
#include "mesh/gmsh_session.h"
#include <gmshc.h>
#include <stdlib.h>
#include <string.h>

static char dir[1024] = ".";

static int write_plate(const char *path, size_t *nn, size_t *ne) {
    const double z = 0;
    int ierr = 0;
    ierr = pl__gmsh_initialize(); /* gmshInitialize kept out of $HOME */
    gmshOptionSetNumber("General.Terminal", 0, &ierr);
    gmshModelAdd("plate", &ierr);
    const int r = gmshModelOccAddRectangle(0, 0, z, 2, 1, -1, 0, &ierr);
    const int d = gmshModelOccAddDisk(1, 0.5, z, 0.25, 0.25, -1, &ierr);
    int a[2] = {2, r}, b[2] = {2, d}, *o = NULL, **om = NULL;
    size_t no = 0, nom = 0, *omn = NULL;
    gmshModelOccCut(a, 2, b, 2, &o, &no, &om, &omn, &nom, -1, 1, 1, &ierr);
    gmshModelOccSynchronize(&ierr);
    gmshOptionSetNumber("Mesh.MeshSizeMax", 0.1, &ierr);
    gmshModelMeshGenerate(2, &ierr);
    size_t *et = NULL, net = 0, *en = NULL, nen = 0, *tags = NULL, nt = 0, nc = 0, npc = 0;
    double *c = NULL, *pc = NULL;
    gmshModelMeshGetElementsByType(2, &et, &net, &en, &nen, -1, 0, 1, &ierr);
    gmshModelMeshGetNodes(&tags, &nt, &c, &nc, &pc, &npc, 2, -1, 1, 0, &ierr);
    *ne = net;
    *nn = nt;
    gmshWrite(path, &ierr);
    gmshFree(et); gmshFree(en); gmshFree(tags); gmshFree(c); gmshFree(pc); gmshFree(o);
    for (size_t k = 0; k < nom; k++) gmshFree(om[k]);
    gmshFree(om); gmshFree(omn);
    gmshModelRemove(&ierr);
    return ierr;
}

static int test_read_plate(void) {
    char path[1200];
    snprintf(path, sizeof path, "%s/plate_hole.msh", dir);
    size_t nn = 0, ne = 0;
    ENSURE(write_plate(path, &nn, &ne) == 0);
    pl_sf_mesh m;
    char msg[320];
    ENSURE(pl_sf_mesh_read(path, 0, &m, msg, sizeof msg) == PL_OK);
    pl_solid_def d = pl_default_solid_def();
    d.young = 1000;
    d.poisson = 0.3;
    d.density = 1;
    d.damping = 20;
    pl_sf *s = pl_sf_create(&d, &m, msg, sizeof msg);
    pl_sf_mesh_free(&m);
    ENSURE(s);
    double area = 0;
    for (int i = 0; i < s->nn; i++) area += s->mp[i];
    const double aref = 2 - M_PI * 0.25 * 0.25;
    fprintf(stderr, "read %s: %d nodes (gmsh %zu), %d triangles (gmsh %zu), area %.5f (plate minus hole %.5f)\n", path,
            s->nn, nn, s->ne, ne, area, aref);
    ENSURE(s->ne == (int)ne && s->nn == (int)nn);
    ENSURE_REL(area, aref, 0.01);
    pl_sf_destroy(s);
    return 0;
}

static int refused(const char *path, const char *expect) {
    pl_sf_mesh m;
    char msg[320] = "";
    const pl_status st = pl_sf_mesh_read(path, 0, &m, msg, sizeof msg);
    fprintf(stderr, "  %s -> %s\n", path, msg);
    ENSURE(st != PL_OK);
    ENSURE(strstr(msg, path) != NULL);
    ENSURE(strstr(msg, expect) != NULL);
    return 0;
}

static int test_bad_files(void) {
    char p[1200];
    snprintf(p, sizeof p, "%s/no_such_part.msh", dir);
    ENSURE(refused(p, "No such file") == 0);
    snprintf(p, sizeof p, "%s/part.geo", dir);
    ENSURE(refused(p, "must end in .msh") == 0);
    snprintf(p, sizeof p, "%s/not_gmsh.msh", dir);
    FILE *f = fopen(p, "w");
    ENSURE(f);
    fputs("hello, this is not a mesh\n", f);
    fclose(f);
    ENSURE(refused(p, "does not begin with $MeshFormat") == 0);
    snprintf(p, sizeof p, "%s/lifted.msh", dir); /* one triangle at z = 0.5 (msh 2.2) */
    f = fopen(p, "w");
    ENSURE(f);
    fputs("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0.5\n2 1 0 0.5\n3 0 1 0.5\n$EndNodes\n"
          "$Elements\n1\n1 2 2 0 1 1 2 3\n$EndElements\n", f);
    fclose(f);
    ENSURE(refused(p, "z = 0") == 0);
    snprintf(p, sizeof p, "%s/damaged.msh", dir);
    f = fopen(p, "w");
    ENSURE(f);
    fputs("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n", f);
    fclose(f);
    ENSURE(refused(p, "") == 0);
    /* and gmsh is still usable after a file it refused */
    snprintf(p, sizeof p, "%s/plate_hole.msh", dir);
    pl_sf_mesh m;
    char msg[320];
    if (pl_sf_mesh_read(p, 0, &m, msg, sizeof msg) != PL_OK) fprintf(stderr, "after: %s\n", msg);
    ENSURE(m.ne > 0);
    pl_sf_mesh_free(&m);
    return 0;
}

int main(int argc, char **argv) {
    if (argc > 1) snprintf(dir, sizeof dir, "%s", argv[1]);
    RUN(test_read_plate);
    RUN(test_bad_files);
    return pl_test_report();
}
