/* Triangle meshes of fluid (and later solid) domains: the MIMES quad mesher (seed 000 §3.5)
 * and point location on a uniform grid (seed 000 §3.13.1). Plain structs, no world. */
#ifndef PL_MESH_H
#define PL_MESH_H

#include "porelab/core.h"
#include <stdint.h>

typedef struct pl_mesh_quad {
    pl_vec2 c[4];       /* counter-clockwise corners */
    int ndivx, ndivy;
    int id;
    double anisotropy;  /* D_y / D_x */
} pl_mesh_quad;

/* --------------------------------------------------------------------- mesh */

typedef struct pl_mesh {
    int nn, ne;
    pl_vec2 *xy;        /* nn node coordinates */
    int32_t *tri;       /* 3 * ne node indices, counter-clockwise */
    int32_t *tri_quad;  /* quad index of each triangle */
    double *area;       /* ne */
    double *bc;         /* 6 * ne: b_i b_j b_k c_i c_j c_k of eq. 3.12 */
    double scale;       /* bounding-box diagonal (tolerances) */
    pl_vec2 lo, hi;     /* bounding box */
    /* point-location grid (seed 000 §3.13.1) */
    double cell;
    int gx, gy;
    int32_t *cell_start, *cell_items;
    /* per-triangle geometry kept for the per-grain loops (built with the grid): bounding box
       (lo.x, lo.y, hi.x, hi.y), the first grid cell the box overlaps (i, j), and for each edge
       k = 0..2 (from vertex k to k+1) its direction angle atan2(ey, ex) and length */
    double *tri_box;    /* 4 * ne */
    int32_t *tri_cell0; /* 2 * ne */
    double *edge_ang;   /* 3 * ne */
    double *edge_len;   /* 3 * ne */
    /* boundary edges (used once) */
    int nbe;
    int32_t *bedge;     /* 2 * nbe, oriented as in their triangle (counter-clockwise) */
    /* statistics of the meshing */
    int merged_nodes, split_triangles;
} pl_mesh;

/* Meshes the quads into mesh (allocates). On error returns a status and writes msg. */
pl_status pl_mesh_build(pl_mesh *m, const pl_mesh_quad *quads, int nq, char *msg, int msglen);
void pl_mesh_free(pl_mesh *m);
/* Builds the point-location grid (called by pl_mesh_build). */
pl_status pl_mesh_build_grid(pl_mesh *m);
/* Triangle containing p (barycentric tolerance relative), or -1. */
int pl_mesh_locate(const pl_mesh *m, pl_vec2 p);
/* Barycentric coordinates of p in triangle e. */
void pl_mesh_barycentric(const pl_mesh *m, int e, pl_vec2 p, double l[3]);
/* Grid cell range covering a box (clamped); returns 0 if the box misses the grid. */
int pl_mesh_grid_range(const pl_mesh *m, pl_vec2 lo, pl_vec2 hi, int *i0, int *j0, int *i1, int *j1);

#endif
