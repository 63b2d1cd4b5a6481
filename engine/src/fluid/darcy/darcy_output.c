/* Output of the fluid field: VTK unstructured grid (.vtu, ASCII) and ParaView collection
 * (.pvd); the thesis's MATLAB-readable text files (Appendix B: FLUID_GEOMETRY_FILENAME,
 * FLUID_PRESSURES_FILENAME). */
#include "world/model.h"
#include "core/alloc.h"
#include "fluid/darcy/darcy_internal.h"
#include "fluid/darcy/darcy_world.h"
#include "core/out.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Hands a formatted file to the host's writer (the engine opens no files). */
static pl_status write_out(pl_world *w, pl_out *o, const char *path, int append, const char *fn) {
    char msg[1024];
    const pl_status st = pl_out_write(o, pl__world_file_writer(w), path, append, msg, sizeof msg);
    return st == PL_OK ? PL_OK : pl__world_error(w, st, "%s: %s", fn, msg);
}

pl_status pl_world_fluid_append_pressures_header(pl_world *w, const char *path) {
    pl_out o = {0};
    pl_out_printf(&o, "%% porelab fluid pressures: each row is t (s) then the pressure head (m) of every node\n");
    return write_out(w, &o, path, 0, "fluid");
}

pl_status pl_world_fluid_write_vtu(pl_world *w, const char *path) {
    pl_status st = pl_world_prepare(w); /* an action, not a query: the field it writes is built */
    if (st != PL_OK) return st;
    int nn = pl_world_fluid_node_count(w), ne = pl_world_fluid_triangle_count(w);
    if (nn <= 0) return pl__world_error(w, PL_ERR_STATE, "fluid_write_vtu: no fluid mesh");
    struct pl_fluid *f = pl__darcy(w);
    pl_out o = {0}, *fp = &o;
    double *buf = pl_malloc(sizeof(double) * (size_t)(nn > ne ? nn : ne));
    double *buf2 = pl_malloc(sizeof(double) * (size_t)ne);
    if (!buf || !buf2) {
        pl_out_free(fp); pl_free(buf); pl_free(buf2);
        return pl__world_error(w, PL_ERR_NOMEM, "fluid_write_vtu: out of memory");
    }
    pl_out_printf(fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n");
    pl_out_printf(fp, "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n", nn, ne);
    pl_out_printf(fp, "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for (int i = 0; i < nn; i++) pl_out_printf(fp, "%.17g %.17g 0\n", f->mesh.xy[i].x, f->mesh.xy[i].y);
    pl_out_printf(fp, "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n");
    for (int e = 0; e < ne; e++) pl_out_printf(fp, "%d %d %d\n", f->mesh.tri[3 * e], f->mesh.tri[3 * e + 1], f->mesh.tri[3 * e + 2]);
    pl_out_printf(fp, "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n");
    for (int e = 0; e < ne; e++) pl_out_printf(fp, "%d\n", 3 * (e + 1));
    pl_out_printf(fp, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (int e = 0; e < ne; e++) pl_out_printf(fp, "5\n");
    pl_out_printf(fp, "</DataArray>\n</Cells>\n<PointData Scalars=\"head\">\n");
    static const char *nnames[] = {"head", "pressure_head", "pressure", "excess_pressure"};
    for (int k = 0; k < 4; k++) {
        pl_world_fluid_copy_node_field(w, (pl_fluid_node_field)k, buf, nn);
        pl_out_printf(fp, "<DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n", nnames[k]);
        for (int i = 0; i < nn; i++) pl_out_printf(fp, "%.10g\n", buf[i]);
        pl_out_printf(fp, "</DataArray>\n");
    }
    pl_out_printf(fp, "</PointData>\n<CellData Vectors=\"darcy_velocity\">\n");
    pl_world_fluid_copy_element_field(w, PL_FLUID_VELOCITY_X, buf, ne);
    pl_world_fluid_copy_element_field(w, PL_FLUID_VELOCITY_Y, buf2, ne);
    pl_out_printf(fp, "<DataArray type=\"Float64\" Name=\"darcy_velocity\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for (int e = 0; e < ne; e++) pl_out_printf(fp, "%.10g %.10g 0\n", buf[e], buf2[e]);
    pl_out_printf(fp, "</DataArray>\n");
    static const char *enames[] = {"porosity", "void_ratio", "perm_x", "perm_y", "solid_area"};
    static const pl_fluid_element_field efields[] = {PL_FLUID_POROSITY, PL_FLUID_VOID_RATIO, PL_FLUID_PERM_X,
                                                     PL_FLUID_PERM_Y, PL_FLUID_SOLID_AREA};
    for (int k = 0; k < 5; k++) {
        pl_world_fluid_copy_element_field(w, efields[k], buf, ne);
        pl_out_printf(fp, "<DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n", enames[k]);
        for (int e = 0; e < ne; e++) pl_out_printf(fp, "%.10g\n", buf[e]);
        pl_out_printf(fp, "</DataArray>\n");
    }
    pl_out_printf(fp, "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    pl_free(buf); pl_free(buf2);
    return write_out(w, fp, path, 0, "fluid_write_vtu");
}

pl_status pl_world_fluid_write_pvd(pl_world *w, const char *path, const char *const *files, const double *times,
                                   int n) {
    pl_out o = {0}, *fp = &o;
    pl_out_printf(fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n");
    for (int i = 0; i < n; i++)
        pl_out_printf(fp, "<DataSet timestep=\"%.10g\" group=\"\" part=\"0\" file=\"%s\"/>\n", times[i], files[i]);
    pl_out_printf(fp, "</Collection>\n</VTKFile>\n");
    return write_out(w, fp, path, 0, "fluid_write_pvd");
}

pl_status pl_world_fluid_set_output_file(pl_world *w, const char *which, const char *path) {
    if (!which || !path || !path[0]) return pl__world_error(w, PL_ERR_ARG, "fluid_set_output_file: give which and a path");
    struct pl_fluid *f = pl__darcy(w);
    if (!f) return pl__world_error(w, PL_ERR_STATE, "fluid_set_output_file: add a fluid quad first");
    if (strlen(path) >= sizeof f->geometry_file)
        return pl__world_error(w, PL_ERR_ARG, "fluid_set_output_file: path longer than %zu characters", sizeof f->geometry_file - 1);
    if (!strcmp(which, "geometry")) {
        snprintf(f->geometry_file, sizeof f->geometry_file, "%s", path);
        f->geometry_written = 0;
    } else if (!strcmp(which, "pressures")) {
        snprintf(f->pressures_file, sizeof f->pressures_file, "%s", path);
        f->pressures_started = 0;
    } else
        return pl__world_error(w, PL_ERR_ARG, "fluid_set_output_file: which must be 'geometry' or 'pressures' (got '%s')", which);
    return PL_OK;
}

pl_status pl_world_fluid_write_geometry(pl_world *w, const char *path) {
    int nn = pl_world_fluid_node_count(w);
    if (nn <= 0) return pl__world_error(w, PL_ERR_STATE, "fluid_write_geometry: no fluid mesh");
    struct pl_fluid *f = pl__darcy(w);
    pl_out o = {0}, *fp = &o;
    pl_out_printf(fp, "%% porelab fluid geometry: one row per node: x y (m); triangles in %s.tri\n", path);
    for (int i = 0; i < nn; i++) pl_out_printf(fp, "%.17g %.17g\n", f->mesh.xy[i].x, f->mesh.xy[i].y);
    pl_status st = write_out(w, fp, path, 0, "fluid_write_geometry");
    if (st != PL_OK) return st;
    char tri[300];
    snprintf(tri, sizeof tri, "%s.tri", path);
    pl_out_printf(fp, "%% porelab fluid triangles: node numbers i j k (1-based, counter-clockwise)\n");
    for (int e = 0; e < f->mesh.ne; e++)
        pl_out_printf(fp, "%d %d %d\n", f->mesh.tri[3 * e] + 1, f->mesh.tri[3 * e + 1] + 1, f->mesh.tri[3 * e + 2] + 1);
    return write_out(w, fp, tri, 0, "fluid_write_geometry");
}

pl_status pl_world_fluid_append_pressures(pl_world *w, const char *path) {
    int nn = pl_world_fluid_node_count(w);
    if (nn <= 0) return pl__world_error(w, PL_ERR_STATE, "fluid_append_pressures: no fluid mesh");
    struct pl_fluid *f = pl__darcy(w);
    pl_out o = {0}, *fp = &o;
    const double t = pl__world_time(w);
    pl_out_printf(fp, "%.10g", f->out_time > t ? f->out_time : t);
    for (int i = 0; i < nn; i++) pl_out_printf(fp, " %.10g", f->head[i] - pl_fl_z(f, f->mesh.xy[i]));
    pl_out_printf(fp, "\n");
    return write_out(w, fp, path, 1, "fluid_append_pressures");
}
