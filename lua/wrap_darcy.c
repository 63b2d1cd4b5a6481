/* The Darcy model's parameters in Lua: w:darcy{...} sets any of the fields of pl_darcy_def
 * (porelab/darcy.h; names, units and ranges from its parameter table, which also defines the
 * MIMES flags FLUIDS_ON, FLUID_PERM, ...: setting one sets the other), w:darcy() returns them.
 * The mesh and boundary lines are given with w:fluid_quad, w:fluid_bc, ... (wrap_fluid.c). */
#include "lua_params.h"
#include "lua_util.h"
#include "porelab/darcy.h"
#include "wrap.h"

static int d_darcy(lua_State *L) {
    pl_lua_world *lw = pl_lua_check_world(L, 1);
    int n = 0;
    const pl_param *t = pl_darcy_param_table(&n);
    pl_darcy_def d;
    pl_world_get_darcy(lw->w, &d);
    if (!lua_isnoneornil(L, 2)) {
        pl_lua_check_def(L, 2, "darcy");
        pl_lua_read_params(L, 2, "darcy", t, n, &d);
        pl_lua_check_status(L, lw->w, pl_world_set_darcy(lw->w, &d), "darcy");
        for (int k = 0; k < n; k++) { /* porelab info lists what the scene set */
            lua_getfield(L, 2, t[k].name);
            if (!lua_isnil(L, -1) && t[k].flag) pl_lua_mark_flag(lw, t[k].flag);
            lua_pop(L, 1);
        }
    }
    pl_lua_push_params(L, t, n, &d);
    return 1;
}

const luaL_Reg pl_lua_darcy_methods[] = {{"darcy", d_darcy}, {NULL, NULL}};
