/* porelab.params, porelab.seed and the seed mix of the random helpers (run_inputs.h). */
#include "run_inputs.h"
#include "context.h"
#include "lua_util.h"

#include <lauxlib.h>
#include <stdio.h>
#include <string.h>

pl_lua_run_inputs *pl_lua_run_inputs_of(lua_State *L)
{
    return pl_lua_get_context(L)->run;
}

static uint64_t splitmix(uint64_t x)
{
    uint64_t z = x + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

uint64_t pl_lua_mix_seed(lua_State *L, uint64_t s)
{
    const pl_lua_run_inputs *r = pl_lua_run_inputs_of(L);
    if (!r || r->seed == 0) return s;
    return splitmix(s ^ splitmix((uint64_t)r->seed));
}

int pl_lua_p_seed(lua_State *L)
{
    const pl_lua_run_inputs *r = pl_lua_run_inputs_of(L);
    lua_pushinteger(L, r ? (lua_Integer)r->seed : 0);
    return 1;
}

int pl_lua_p_mix_seed(lua_State *L)
{
    lua_Integer s = luaL_checkinteger(L, 1);
    lua_pushinteger(L, (lua_Integer)pl_lua_mix_seed(L, (uint64_t)s));
    return 1;
}

/* local P = porelab.params { {name = "amp", unit = "m", value = 0.0035, min = 0.001,
 * max = 0.006, doc = "..."}, ... }  ->  P.amp is --param amp=VALUE, else value. */
int pl_lua_p_params(lua_State *L)
{
    pl_lua_run_inputs *r = pl_lua_run_inputs_of(L);
    if (r->declared_called) return pl_lua_error(L, "porelab.params: called twice (declare every parameter in one list)");
    pl_scene_param p[PL_SCENE_MAX_PARAMS];
    int n = pl_lua_check_param_list(L, 1, p, 0);
    r->declared_called = 1;
    lua_createtable(L, 0, n);
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < i; j++)
            if (strcmp(p[i].name, p[j].name) == 0)
                return pl_lua_error(L, "porelab.params: parameter '%s' declared twice", p[i].name);
        int over = 0;
        for (int k = 0; k < r->n_over; k++) {
            if (strcmp(r->over_name[k], p[i].name) != 0) continue;
            double v = r->over_value[k];
            if (!(v >= p[i].min && v <= p[i].max)) {
                char msg[4096]; /* lua_pushfstring knows no %g */
                snprintf(msg, sizeof msg, "--param %s=%g: %s must be in [%g, %g]%s%s", p[i].name, v, p[i].name,
                         p[i].min, p[i].max, p[i].unit[0] ? " " : "", p[i].unit);
                return pl_lua_error(L, "%s", msg);
            }
            p[i].value = v;
            r->over_used[k] = 1;
            over = 1;
        }
        r->declared[r->ndeclared] = p[i];
        r->overridden[r->ndeclared++] = over;
        lua_pushnumber(L, p[i].value);
        lua_setfield(L, -2, p[i].name);
    }
    return 1;
}
