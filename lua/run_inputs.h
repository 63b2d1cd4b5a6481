/* The inputs of one run that the command line hands to a scene (porelab run --param, --seed)
 * and what the scene declares about them: its parameters (porelab.params{...} while it
 * builds, the result's params list of live sliders) and its seed. */
#ifndef PL_LUA_RUN_INPUTS_H
#define PL_LUA_RUN_INPUTS_H

#include <lua.h>
#include <stdint.h>
#include "scene.h"

#define PL_RUN_MAX_OVERRIDES 32

typedef struct pl_lua_run_inputs {
    long long seed;                 /* run seed; 0: the scene's own seeds as written */
    int n_over;                     /* --param name=value given */
    char over_name[PL_RUN_MAX_OVERRIDES][48];
    double over_value[PL_RUN_MAX_OVERRIDES];
    int over_used[PL_RUN_MAX_OVERRIDES];
    int declared_called;            /* porelab.params was called */
    int ndeclared;                  /* declared parameters (porelab.params, then result.params) */
    pl_scene_param declared[2 * PL_SCENE_MAX_PARAMS];
    int overridden[2 * PL_SCENE_MAX_PARAMS];
} pl_lua_run_inputs;

/* The inputs of the scene in L (never NULL once the scene is created). */
pl_lua_run_inputs *pl_lua_run_inputs_of(lua_State *L);

/* The seed a random helper uses for the scene's stream seed s: s itself for run seed 0,
 * else a SplitMix64 mix of both (every helper's stream changes with --seed). */
uint64_t pl_lua_mix_seed(lua_State *L, uint64_t s);

/* porelab.params{...}, porelab.seed(), porelab.mix_seed(s) */
int pl_lua_p_params(lua_State *L);
int pl_lua_p_seed(lua_State *L);
int pl_lua_p_mix_seed(lua_State *L);

/* Validates a parameter list at index t ({name, unit, value, min, max, step, doc, set}; set
 * required when need_set) and copies it into out (when not NULL); raises Lua errors naming the
 * entry and the field; returns the count (scene.c). */
int pl_lua_check_param_list(lua_State *L, int t, pl_scene_param *out, int need_set);

#endif
