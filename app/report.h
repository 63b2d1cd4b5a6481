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
/* The attached models (fluid ladder) and, with trial_steps > 0, the CPU cost per step of the
 * grains and of each model, measured on trial_steps steps from a snapshot that is restored. */
void pl_report_models(FILE *f, pl_world *w, int trial_steps);
void pl_report_flags(FILE *f, pl_scene *s);
void pl_report_energy(FILE *f, const pl_world *w);

/* The scene's CSV files (porelab.csv): pl_report_flush_csv writes their whole lines (after
 * each frame, when a run stops); pl_report_close_csv flushes and closes them all, also those
 * the scene never closed (before the scene is destroyed). A failed write is printed to f as
 * "porelab: writing the CSV file '...' failed: <reason> ..."; both return 0 or -1. */
int pl_report_flush_csv(FILE *f, pl_scene *s);
int pl_report_close_csv(FILE *f, pl_scene *s);

/* Makes a write past the file size limit (ulimit -f) fail with EFBIG, reported like a full
 * disk, instead of killing porelab with SIGXFSZ. */
void pl_report_ignore_file_size_signal(void);

#endif
