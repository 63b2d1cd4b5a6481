/* Restart files of `porelab run`: --save-every T and --save-at T,T,... write the world's state
 * (pl_world_save_state) as DIR/state_<t>.plstate, whole files only (a temporary name in the same
 * folder, then a rename); --resume FILE loads one into the world the scene built and the run
 * goes on to the scene's end, frames numbered as in the run that never stopped. */
#ifndef PL_APP_RESTART_H
#define PL_APP_RESTART_H

#include "options.h"
#include "run_plan.h"
#include "porelab/world.h"

#include <stddef.h>

typedef struct pl_restart pl_restart;

/* The option rows (for a command's option table). */
#define PL_RESTART_OPTION_ROWS                                                                      \
    {"--save-every", NULL, "T", "write a restart file DIR/state_<t>.plstate every T simulated seconds"}, \
    {"--save-at", NULL, "LIST", "write restart files at these times, s (comma list; 'end': at the end)"}, \
    {"--resume", NULL, "FILE", "load a restart file into the scene's world and run on to its end"}

/* Reads the options; with --resume loads the file into w (built by the scene, plan made from it
   before the load). start_step: the world's step count when the run started. Returns 0 with
   *r (NULL when no restart option was given), or an exit code after printing the error. */
int pl_restart_open(pl_restart **r, const pl_opts *o, const pl_run_plan *p, pl_world *w, const char *out_dir,
                    long long start_step);

/* Frames of a resumed run: *k the index of the first frame after the start, *draw_first 1 when
   the start is itself a frame step (drawn with index *k - 1), *first the index the frame writer
   starts numbering at. Without a resume: k = 1, draw_first = 1, first = 0. */
void pl_restart_frames(const pl_restart *r, const pl_run_plan *p, long long *k, int *draw_first, int *first);

/* The step (counted from the run's start) to stop at before `target`: the next save. */
long long pl_restart_clip(const pl_restart *r, long long target, long long done);

/* Writes the restart files due at `done` steps. 0, or -1 with the message in pl_restart_error. */
int pl_restart_after_steps(pl_restart *r, const pl_world *w, long long done);
const char *pl_restart_error(const pl_restart *r);

void pl_restart_close(pl_restart **r);

/* Reads a whole file into a new buffer (free it); NULL with a message in err. */
void *pl_restart_read_file(const char *path, size_t *len, char *err, size_t errlen);
/* Writes bytes as path, whole or not at all (path.tmp then rename). 0, or -1 with err. */
int pl_restart_write_file(const char *path, const void *bytes, size_t len, char *err, size_t errlen);

#endif

/* porelab still --from-state DIR: loads the restart file of DIR with the latest step at or
   before `target` steps after the run's start (start_step: the world's step count then) into
   w. 0 with *loaded 1 (and the file's name in used) or 0 (no such file: w is left alone), or -1
   after printing the error. */
int pl_restart_load_nearest(const char *dir, pl_world *w, long long start_step, long long target, int *loaded,
                            char *used, size_t n);

/* The first frame at or after `done` steps: its index and its step. */
void pl_restart_frame_at(const pl_run_plan *p, long long done, long long *index, long long *step);
