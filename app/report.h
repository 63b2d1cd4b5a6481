/* Text descriptions of a world shared by `porelab info` and the run summary. Each writes
 * one or more lines "  label        text". */
#ifndef PL_APP_REPORT_H
#define PL_APP_REPORT_H

#include <stdio.h>
#include "porelab/world.h"
#include "scene.h"

void pl_report_bodies(FILE *f, const pl_world *w);
void pl_report_materials(FILE *f, const pl_world *w);
void pl_report_contact_law(FILE *f, const pl_world *w);
void pl_report_damping(FILE *f, const pl_world *w);
void pl_report_time_step(FILE *f, pl_world *w);
void pl_report_fluid(FILE *f, const pl_world *w);
void pl_report_flags(FILE *f, pl_scene *s);
void pl_report_energy(FILE *f, const pl_world *w);

#endif
