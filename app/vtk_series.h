/* VTK time series for ParaView (porelab run --vtk): per frame, DIR/vtk/frame_NNNNNN_bodies.vtu,
 * _contacts.vtu and (with a fluid model) _fluid.vtu, indexed by one collection DIR/run.pvd
 * (rewritten after every frame, whole, so it stays valid if a run stops). */
#ifndef PL_APP_VTK_SERIES_H
#define PL_APP_VTK_SERIES_H
#include "porelab/world.h"
#include <stddef.h>

typedef struct pl_vtk_series pl_vtk_series;

pl_vtk_series *pl_vtk_series_open(const char *dir, char *err, size_t errlen);
int pl_vtk_series_add(pl_vtk_series *s, pl_world *w, char *err, size_t errlen);
void pl_vtk_series_close(pl_vtk_series **s);
#endif
