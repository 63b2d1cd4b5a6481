/* The window's scene picker: the shipped scenes (the scenes/ folder: $PORELAB_SCENES, else the
 * scenes/ folder the open scene lies in, else ./scenes) with a one-line description each,
 * read from the scene file without running it: a comment line "-- Description: ..." when the
 * scene declares one, else the first sentence of its opening comment (references in
 * parentheses left out). Imperative scripts (no top-level `return`) are not listed: the window
 * runs declarative scenes only. */
#ifndef PL_APP_WINDOW_PICKER_H
#define PL_APP_WINDOW_PICKER_H

#include <limits.h>

#define PL_PICKER_MAX 96

typedef struct pl_picker_entry {
    char path[PATH_MAX]; /* as passed to the loader */
    char name[96];       /* relative to the scenes folder, without .lua: "soil/liquefaction" */
    char desc[200];
} pl_picker_entry;

typedef struct pl_picker {
    char dir[PATH_MAX];
    int n;
    pl_picker_entry e[PL_PICKER_MAX];
} pl_picker;

/* Finds the scenes folder and lists it (sorted by name). Returns the count (0 when no folder). */
int pl_picker_scan(pl_picker *pk, const char *open_scene);
/* The description of one scene file ("" when it has no opening comment). */
void pl_picker_describe(const char *path, char *out, int n);

#endif
