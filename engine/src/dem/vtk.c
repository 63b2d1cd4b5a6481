/* VTK XML export of bodies and contacts for ParaView (ASCII .vtu; an index .pvd is written by
 * the caller that numbers the frames). Discs are written as 24-gons so ParaView shows shapes. */
#include "dem/world_internal.h"
#include "core/out.h"
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
    pl_out o = {0}, *f = &o;
    long npts = 0;
    pl_vec2 v[PL_MAX_POLY_VERTICES > 24 ? PL_MAX_POLY_VERTICES : 24];
    for (int i = 0; i < w->n; i++) npts += outline(w, i, v);
    pl_out_printf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%ld\" NumberOfCells=\"%d\">\n<Points>\n"
               "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n", npts, w->n);
    for (int i = 0; i < w->n; i++) {
        const int n = outline(w, i, v);
        for (int k = 0; k < n; k++) pl_out_printf(f, "%.9g %.9g 0\n", v[k].x, v[k].y);
    }
    pl_out_printf(f, "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    long off = 0;
    for (int i = 0; i < w->n; i++) {
        const int n = outline(w, i, v);
        for (int k = 0; k < n; k++) pl_out_printf(f, "%ld ", off + k);
        pl_out_printf(f, "\n");
        off += n;
    }
    pl_out_printf(f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    off = 0;
    for (int i = 0; i < w->n; i++) {
        off += outline(w, i, v);
        pl_out_printf(f, "%ld\n", off);
    }
    pl_out_printf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) pl_out_printf(f, "%d\n", w->shape[i] == PL_SHAPE_SEGMENT ? 3 : 7); /* line, polygon */
    pl_out_printf(f, "</DataArray>\n</Cells>\n<CellData>\n");
    pl_out_printf(f, "<DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) pl_out_printf(f, "%.9g %.9g 0\n", w->vel[i].x, w->vel[i].y);
    pl_out_printf(f, "</DataArray>\n<DataArray type=\"Float64\" Name=\"angle\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) pl_out_printf(f, "%.9g\n", w->angle[i]);
    pl_out_printf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"material\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) pl_out_printf(f, "%d\n", w->material[i]);
    pl_out_printf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"id\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) pl_out_printf(f, "%d\n", i);
    /* disc radius (polygons and segments: bounding radius about the centroid), m */
    pl_out_printf(f, "</DataArray>\n<DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) pl_out_printf(f, "%.9g\n", w->radius[i]);
    /* material names: a VTK string array (ASCII: each string's byte codes, then 0) */
    pl_out_printf(f, "</DataArray>\n<DataArray type=\"String\" Name=\"material_name\" format=\"ascii\">\n");
    for (int i = 0; i < w->n; i++) {
        const int m = w->material[i];
        const char *nm = m >= 0 && m < w->material_count ? w->materials[m].name : "";
        for (const unsigned char *c = (const unsigned char *)nm; *c; c++) pl_out_printf(f, "%u ", (unsigned)*c);
        pl_out_printf(f, "0\n");
    }
    pl_out_printf(f, "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    char msg[1024];
    const pl_status st = pl_out_write(f, &w->writer, path, 0, msg, sizeof msg);
    return st == PL_OK ? PL_OK : pl__error(w, st, "vtk: %s", msg);
}

static pl_status write_contacts(const pl_world *w, const char *path) {
    pl_out o = {0}, *f = &o;
    const int nc = pl_world_contact_count(w);
    pl_out_printf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n<Points>\n"
               "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n", 2 * nc, nc);
    for (int k = 0; k < w->pair_n; k++) {
        const pl_pair *p = &w->pairs[k];
        if (!p->touching) continue;
        /* a line from a's centroid to b's (walls: from the contact point) */
        const pl_vec2 pa = w->shape[p->a] == PL_SHAPE_SEGMENT ? p->point : w->pos[p->a];
        const pl_vec2 pb = w->shape[p->b] == PL_SHAPE_SEGMENT ? p->point : w->pos[p->b];
        pl_out_printf(f, "%.9g %.9g 0\n%.9g %.9g 0\n", pa.x, pa.y, pb.x, pb.y);
    }
    pl_out_printf(f, "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for (int c = 0; c < nc; c++) pl_out_printf(f, "%d %d\n", 2 * c, 2 * c + 1);
    pl_out_printf(f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for (int c = 0; c < nc; c++) pl_out_printf(f, "%d\n", 2 * c + 2);
    pl_out_printf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (int c = 0; c < nc; c++) pl_out_printf(f, "3\n");
    pl_out_printf(f, "</DataArray>\n</Cells>\n<CellData>\n<DataArray type=\"Float64\" Name=\"normal_force\" format=\"ascii\">\n");
    for (int k = 0; k < w->pair_n; k++)
        if (w->pairs[k].touching) pl_out_printf(f, "%.9g\n", w->pairs[k].fn);
    pl_out_printf(f, "</DataArray>\n<DataArray type=\"Float64\" Name=\"tangential_force\" format=\"ascii\">\n");
    for (int k = 0; k < w->pair_n; k++)
        if (w->pairs[k].touching) pl_out_printf(f, "%.9g\n", w->pairs[k].ft);
    pl_out_printf(f, "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    char msg[1024];
    const pl_status st = pl_out_write(f, &w->writer, path, 0, msg, sizeof msg);
    return st == PL_OK ? PL_OK : pl__error(w, st, "vtk: %s", msg);
}

pl_status pl_world_write_vtk(const pl_world *w, const char *prefix) {
    char path[4096];
    snprintf(path, sizeof path, "%s_bodies.vtu", prefix);
    pl_status s = write_bodies(w, path);
    if (s != PL_OK) return s;
    snprintf(path, sizeof path, "%s_contacts.vtu", prefix);
    return write_contacts(w, path);
}
