/* The grain store's section of a state image (world/snapshot.c, next to the list of state
 * arrays it is made from) and the file format around the sections (world/snapshot_file.c). */
#ifndef PL_STATE_IMAGE_H
#define PL_STATE_IMAGE_H
#include "world/world_layer.h"

/* Folds the layout of everything the grains section holds (struct sizes, the offsets and
   element sizes of the state arrays, the flag table, byte order) into h. */
uint64_t pl__grains_layout(uint64_t h);
/* Writes the grains section: the world's scalars and every state array. */
pl_status pl__grains_save(const pl_world *w, pl_image *img);
/* Reads a grains section written for a world like w (same bodies, vertices, materials) into a
   new snapshot without models (*out); an error status with w's message set when it does not fit. */
pl_status pl__grains_decode(pl_world *w, pl_image *img, pl_snapshot **out);
/* Puts a snapshot's grain store into w (the models are left alone). */
pl_status pl__grains_restore(pl_world *w, const pl_snapshot *s);
#endif
