/* DIR/manifest.json: what one run was (scene and its content hash, parameters, seed, porelab
 * build), how it ended (state hash, wall and CPU time, exit status) and the values the scene
 * reported (docs/scene-reference.md, "Run manifest"). Written atomically (temporary file, then
 * rename), so a reader (porelab collect, a resumed sweep) sees a whole manifest or none. Also a
 * small reader of the JSON it writes, for collect and for skipping runs already done. */
#ifndef PL_APP_MANIFEST_H
#define PL_APP_MANIFEST_H

#include <stddef.h>
#include <stdint.h>
#include "scene.h"

#define PL_MANIFEST_FORMAT "porelab-manifest-1"
#define PL_MANIFEST_MAX_OVER 32

typedef struct pl_manifest {
    char scene_path[4096];     /* absolute */
    uint64_t scene_hash;       /* FNV-1a 64 of the scene file's bytes */
    long long scene_bytes;
    char out_dir[4096];
    long long seed;
    int nover;                 /* --param as given */
    char over_name[PL_MANIFEST_MAX_OVER][48];
    double over_value[PL_MANIFEST_MAX_OVER];
    const char *until, *steps; /* --until / --steps as given, or NULL */
    uint64_t inputs;           /* key of the inputs (pl_manifest_inputs_key) */
    /* filled after the run */
    int nparams;
    pl_scene_param params[2 * PL_SCENE_MAX_PARAMS];
    int overridden[2 * PL_SCENE_MAX_PARAMS];
    int nresults;
    pl_scene_result results[PL_SCENE_MAX_RESULTS];
    int has_state;
    uint64_t state_hash;
    long long step_count;
    double t_end;
    double wall_s, cpu_s;
    int exit_status;
    char error[1024];
    char started_utc[32];
} pl_manifest;

/* Hashes the scene file (0 or -1 with err when unreadable) and computes the inputs key: scene
 * hash, the --param overrides (sorted by name), seed, --until, --steps and the porelab build. */
int pl_manifest_prepare(pl_manifest *m, const char *scene_path, char *err, size_t errlen);
/* Writes DIR/manifest.json atomically. 0, or -1 with err. */
int pl_manifest_write(const pl_manifest *m, const char *dir, char *err, size_t errlen);
/* 1 when DIR/manifest.json exists, ended with exit status 0 and has the same inputs key. */
int pl_manifest_done(const char *dir, uint64_t inputs);
/* "Release, GCC 12.2.0, gmsh 1, asserts 0": the build options recorded in manifests. */
const char *pl_manifest_build(void);

/* ---- reader: a JSON document flattened into dotted paths ("params.amp.value") */
typedef struct pl_json_item {
    char path[160];
    int type;            /* 0 null, 1 bool, 2 number, 3 string */
    double num;
    char str[512];
} pl_json_item;
typedef struct pl_json_doc {
    pl_json_item *items;
    int n, cap;
} pl_json_doc;
/* Reads and flattens a JSON file (arrays index as "a.0"). 0, or -1 with err (file:offset). */
int pl_json_read(const char *path, pl_json_doc *doc, char *err, size_t errlen);
const pl_json_item *pl_json_get(const pl_json_doc *doc, const char *path);
void pl_json_free(pl_json_doc *doc);

/* FNV-1a 64 of a file's bytes; -1 when unreadable. */
int pl_file_hash(const char *path, uint64_t *hash, long long *bytes);

#endif
