/// porelab scene loader: runs a Lua scene file in a (sandboxed) Lua state and hands its
/// world, run settings and hooks to the program. The host (app/) reads render options from
/// the result itself, so this library never includes the renderer.
#ifndef PORELAB_LUA_SCENE_H
#define PORELAB_LUA_SCENE_H

#include <lua.h>
#include "porelab/world.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pl_scene pl_scene;

typedef struct pl_scene_options {
    const char *path;    ///< scene file (.lua); required
    const char *out_dir; ///< output folder for frames and CSV (created on first write); required
    int trust;           ///< 1 lifts the sandbox (--trust)
    long long seed;      ///< run seed (--seed); 0 keeps the scene's own seeds as written
    int nparams;         ///< parameter overrides (--param name=value), at most 32
    const char *const *param_names;
    const double *param_values;
} pl_scene_options;

/// Limits on the scene's code. A sandboxed scene starts with the defaults below, a trusted
/// one with none. max_cpu: CPU time (s) the scene's code may take in one go: running the
/// scene file, or one call from porelab into the scene (a hook, params.set, reading
/// render/run); the Lua code and the porelab functions it calls count. max_memory_mb: the
/// Lua data the scene may hold, MB. For each: > 0 sets it, < 0 removes it, 0 keeps it.
/// Exceeding either stops the scene with "scene.lua:LINE: ..." naming the option.
void pl_scene_set_limits(pl_scene *s, double max_cpu, double max_memory_mb);

#define PL_SCENE_DEFAULT_MAX_CPU 300.0     ///< s, sandboxed scenes
#define PL_SCENE_DEFAULT_MAX_MEMORY 1024.0 ///< MB, sandboxed scenes
#define PL_SCENE_MAX_CPU_LIMIT 1e7         ///< largest --max-cpu, s
#define PL_SCENE_MIN_MEMORY 16.0           ///< smallest --max-memory, MB
#define PL_SCENE_MAX_MEMORY_LIMIT 1048576.0 ///< largest --max-memory, MB (1 TB)

/// Run settings the scene asked for in its `run` table; 0 = not given.
typedef struct pl_scene_run {
    double t_end;        ///< simulated end time, s
    long long steps;     ///< number of steps
    double fps;          ///< frames per simulated second
    long long every;     ///< one frame every N steps
} pl_scene_run;

/// Creates the Lua state with the porelab module and the sandbox. NULL when out of memory.
pl_scene *pl_scene_create(const pl_scene_options *opt);
/// Runs the scene file. Returns 0, or -1 with a one-line message in pl_scene_error
/// ("scenes/x.lua:12: disc: radius must be > 0 (got -1)").
int pl_scene_load(pl_scene *s);
/// The last error message ("" when none) and its Lua traceback ("" when none).
const char *pl_scene_error(const pl_scene *s);
const char *pl_scene_traceback(const pl_scene *s);

/// The world the scene returned, or else the last world it created (imperative scripts);
/// NULL when it created none. Owned by the scene.
pl_world *pl_scene_world(pl_scene *s);
/// 1 when the scene returned a world (declarative), 0 for imperative scripts.
int pl_scene_declarative(const pl_scene *s);
/// Reads the scene's `run` table. Returns 0, or -1 with a message.
int pl_scene_run_settings(pl_scene *s, pl_scene_run *out);
/// 1 when the scene set the flag (in world{flags=...} or world:set_flag), with its value.
int pl_scene_flag_was_set(pl_scene *s, const char *name, double *value);
/// Calls result.<name>(world, arg) when the scene defined that hook. Returns 0 (also when
/// there is no such hook) or -1 with a message.
int pl_scene_call_hook(pl_scene *s, const char *name, long long arg);

/// The Lua state (for the host reading result fields) and result[field] pushed on its
/// stack (returns the Lua type; LUA_TNIL when absent). The caller pops it.
lua_State *pl_scene_lua(pl_scene *s);
int pl_scene_push_result_field(pl_scene *s, const char *field);
/// Calls reader(ud, result[field]) protected: the reader gets a light userdata at index 1
/// and the field (possibly nil) at index 2 and may raise Lua errors (the lua/ helpers in
/// lua_util.h). Returns 0, or -1 with "scene.lua: <message>" in pl_scene_error.
int pl_scene_read_field(pl_scene *s, const char *field, lua_CFunction reader, void *ud);
/// A parameter the scene lets the user change while it runs (the live window): the result
/// table's `params` list, or else the global PARAMS, each entry { name = "wood block",
/// unit = "kg/m3", value = 600, min = 100, max = 3000, step = 100,
/// set = function(world, value) ... end }. value, min, max and set are required, min < max,
/// value in [min, max], step in (0, max - min] (default (max - min) / 20).
#define PL_SCENE_MAX_PARAMS 16
typedef struct pl_scene_param {
    char name[48];
    char unit[24];
    double value, min, max, step;
} pl_scene_param;
/// Reads and checks the parameter list (result.params, else the global PARAMS; the loader
/// already checked result.params). Returns the count (0 when the scene declares none), or
/// -1 with "scene.lua: params[2] (name): max must be > min (...)" in pl_scene_error.
int pl_scene_params(pl_scene *s, pl_scene_param out[PL_SCENE_MAX_PARAMS]);
/// Calls params[i + 1].set(world, value) (between steps). Returns 0, or -1 with a message.
int pl_scene_set_param(pl_scene *s, int i, double value);

/// What porelab chose for world{fluid = "auto"} and why (the rejected models too), and warnings
/// about a fixed model used past its assumptions: lines ending in '\n', "" when none.
const char *pl_scene_fluid_notes(pl_scene *s);
/// After pl_scene_load: applies the --param overrides that porelab.params did not take to the
/// result's params list (calling set(world, value) before the first step), checking each
/// against its range. Returns 0, or -1 with "--param x=1: ..." (unknown name: the message lists
/// the declared parameters with their ranges) in pl_scene_error.
int pl_scene_apply_params(pl_scene *s);
/// The declared parameters (porelab.params, then the result's params list) with the values
/// the run uses; overridden[i] = 1 when --param set it. Returns the count (<= cap).
int pl_scene_declared_params(pl_scene *s, pl_scene_param *out, int *overridden, int cap);
/// The run seed (0: the scene's own seeds).
long long pl_scene_seed(const pl_scene *s);

/// One value the scene reports as its result (docs/scene-reference.md, "Results").
typedef struct pl_scene_result {
    char name[48];
    char unit[24];
    int kind;       ///< 0 number, 1 boolean (value 0/1), 2 string (text)
    double value;
    char text[128];
} pl_scene_result;
#define PL_SCENE_MAX_RESULTS 64
/// Reads the scene's results: the result table's `results` (a table, or a function(world)
/// returning one, called now), else the global RESULTS; each entry name = number | boolean |
/// string | {value = number, unit = "mm"}; sorted by name. Returns the count (0 when none), or
/// -1 with "scene.lua:LINE: results.x: ..." in pl_scene_error.
int pl_scene_results(pl_scene *s, pl_scene_result out[PL_SCENE_MAX_RESULTS]);

/// The scene path as given (for messages).
const char *pl_scene_path(const pl_scene *s);
/// "scene.lua:LINE" of the scene's final `return` (the statement that returned the result
/// table), or the scene path alone when not known: for messages about the result table
/// written outside the Lua reader (e.g. "no usable time step").
const char *pl_scene_result_location(const pl_scene *s);
/// Sets the error message (used by the host when it rejects a result field).
void pl_scene_set_error(pl_scene *s, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/// Closes the Lua state (flushing CSV files), frees the world, nulls the pointer.
void pl_scene_destroy(pl_scene **s);

#ifdef __cplusplus
}
#endif
#endif
