/* Meshes of the solid's parts (solid_mesh_gmsh.c): gmsh's C API, or a refusal naming
 * libgmsh-dev when the engine is built without it. Each returns a mesh the caller frees with
 * pl_sf_mesh_free. */
#ifndef PL_SOLID_MESH_H
#define PL_SOLID_MESH_H

#include "solid/fic/solid_internal.h"

/* Element kinds of the structured meshes (the `quads` argument). */
enum { PL_SF_TRI_ALTERNATE = 0, PL_SF_QUADS = 1, PL_SF_TRI_RIGHT = 2 };

/* Transfinite four-sided patch with corners c[0..3] (CCW): nx divisions along c0-c1 and
   c2-c3, ny along c1-c2 and c3-c0; quads: PL_SF_TRI_ALTERNATE (alternating diagonals),
   PL_SF_QUADS or PL_SF_TRI_RIGHT (every diagonal the same way: the mesh on which plain
   triangles lock worst). */
pl_status pl_sf_mesh_quad(const pl_vec2 c[4], int nx, int ny, int quads, pl_sf_mesh *out, char *msg, size_t len);
/* Annular sector (a full ring when a1 - a0 = 2 pi), transfinite, nr radial by nt around. */
pl_status pl_sf_mesh_annulus(double cx, double cy, double ri, double ro, double a0, double a1, int nr, int nt,
                             int quads, pl_sf_mesh *out, char *msg, size_t len);
/* Unstructured triangles of size h in a simple polygon. */
pl_status pl_sf_mesh_polygon(const pl_vec2 *v, int n, double h, pl_sf_mesh *out, char *msg, size_t len);
/* Reads a gmsh .msh file (gmshMerge into a model of its own, gmshModelMeshGetNodes /
   GetElementsByType; gmshOpen left gmsh unable to read a second file after a damaged one): its 3-node
   triangles (quads = 0) or 4-node quadrilaterals (quads = 1); plane (z = 0) meshes only. */
pl_status pl_sf_mesh_read(const char *path, int quads, pl_sf_mesh *out, char *msg, size_t len);
void pl_sf_mesh_free(pl_sf_mesh *m);

#endif
