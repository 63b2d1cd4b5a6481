/* VTK XML export of bodies and contacts for ParaView (ASCII .vtu; an index .pvd is written by
 * the caller that numbers the frames). Discs are written as 24-gons so ParaView shows shapes. */
#include "dem/world_internal.h"
#include <math.h>
#include <stdio.h>

static int outline(const pl_world *w, int i, pl_vec2 *v) {
    if (w->shape[i] == PL_SHAPE_DISC) {
        for (int k = 0; k < 24; k++) {
            const double a = 2 * M_PI * k / 24;
            v[k] = (pl_vec2){w->pos[i].x + w->radius[i] * cos(a), w->pos[i].y + w->radius[i] * sin(a)};
        }
        return 24;
    }
    const int n = w->vert_count[i];
    for (int k = 0; k < n; k++) v[k] = w->verts_world[w->vert_offset[i] + k];
    return n;
}

static pl_status write_bodies(const pl_world *w, const char *path) {
    FILE *f = fopen(path, "w");
    if (!f) return pl__error(w, PL_ERR_IO, "vtk: cannot write '%s'", path);
    long npts = 0;
    pl_vec2 v[PL_MAX_POLY_VERTICES > 24 ? PL_MAX_POLY_VERTICES : 24];
    for (int i = 0; i < w->n; i++) npts += outline(w, i, v);
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%ld\" NumberOfCells=\"%d\">\n<Points>\n"
               "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n", npts, w->n);
    for (int i = 0; i < w->n; i++) {
        const int n = outline(w, i, v);
        for (int k = 0; k < n; k++) fprintf(f, "%.9g %.9g 0\n", v[k].x, v[k].y);
    }
    fprintf(f, "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    long off = 0;
    for (int i = 0; i < w->n; i++) {
        const int n = outline(w, i, v);
        for (int k = 0; k < n; k++) fprintf(f, "%ld ", off + k);
        fputc('\n', f);
        off += n;
    }
    fprintf(f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    off = 0;
    for (int i = 0; i < w->n; i++) {
        off += outline(w, i, v);
        fprintf(f, "%ld\n", off);
    }
    fprintf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) fprintf(f, "%d\n", w->shape[i] == PL_SHAPE_SEGMENT ? 3 : 7); /* line, polygon */
    fprintf(f, "</DataArray>\n</Cells>\n<CellData>\n");
    fprintf(f, "<DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) fprintf(f, "%.9g %.9g 0\n", w->vel[i].x, w->vel[i].y);
    fprintf(f, "</DataArray>\n<DataArray type=\"Float64\" Name=\"angle\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) fprintf(f, "%.9g\n", w->angle[i]);
    fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"material\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) fprintf(f, "%d\n", w->material[i]);
    fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"id\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) fprintf(f, "%d\n", i);
    fprintf(f, "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    const int bad = ferror(f);
    if (fclose(f) != 0 || bad) return pl__error(w, PL_ERR_IO, "vtk: error writing '%s'", path);
    return PL_OK;
}

static pl_status write_contacts(const pl_world *w, const char *path) {
    FILE *f = fopen(path, "w");
    if (!f) return pl__error(w, PL_ERR_IO, "vtk: cannot write '%s'", path);
    const int nc = pl_world_contact_count(w);
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n<Points>\n"
               "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n", 2 * nc, nc);
    for (int k = 0; k < w->pair_n; k++) {
        const pl_pair *p = &w->pairs[k];
        if (!p->touching) continue;
        /* a line from a's centroid to b's (walls: from the contact point) */
        const pl_vec2 pa = w->shape[p->a] == PL_SHAPE_SEGMENT ? p->point : w->pos[p->a];
        const pl_vec2 pb = w->shape[p->b] == PL_SHAPE_SEGMENT ? p->point : w->pos[p->b];
        fprintf(f, "%.9g %.9g 0\n%.9g %.9g 0\n", pa.x, pa.y, pb.x, pb.y);
    }
    fprintf(f, "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for (int c = 0; c < nc; c++) fprintf(f, "%d %d\n", 2 * c, 2 * c + 1);
    fprintf(f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for (int c = 0; c < nc; c++) fprintf(f, "%d\n", 2 * c + 2);
    fprintf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (int c = 0; c < nc; c++) fprintf(f, "3\n");
    fprintf(f, "</DataArray>\n</Cells>\n<CellData>\n<DataArray type=\"Float64\" Name=\"normal_force\" format=\"ascii\">\n");
    for (int k = 0; k < w->pair_n; k++)
        if (w->pairs[k].touching) fprintf(f, "%.9g\n", w->pairs[k].fn);
    fprintf(f, "</DataArray>\n<DataArray type=\"Float64\" Name=\"tangential_force\" format=\"ascii\">\n");
    for (int k = 0; k < w->pair_n; k++)
        if (w->pairs[k].touching) fprintf(f, "%.9g\n", w->pairs[k].ft);
    fprintf(f, "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    const int bad = ferror(f);
    if (fclose(f) != 0 || bad) return pl__error(w, PL_ERR_IO, "vtk: error writing '%s'", path);
    return PL_OK;
}

pl_status pl_world_write_vtk(const pl_world *w, const char *prefix) {
    char path[4096];
    snprintf(path, sizeof path, "%s_bodies.vtu", prefix);
    pl_status s = write_bodies(w, path);
    if (s != PL_OK) return s;
    snprintf(path, sizeof path, "%s_contacts.vtu", prefix);
    return write_contacts(w, path);
}
