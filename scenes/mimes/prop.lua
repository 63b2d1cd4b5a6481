-- Seed 000 (Klosek 1997) Appendix C.3, prop.tcl, line for line through porelab.mimes: the
-- fluid pressure wave (§4.3, Figs. 4-9 to 4-12). The thesis varied the mesh (1 x 16 here)
-- and wrote geometry.flu / pressures.flu for MATLAB. The listing gives no boundary lines
-- (they were in the text: head phi0 at the bottom, 0 at the top); they are added below, with
-- FLUID_STORAGE 1 so that "all the constants are 1" (eq. 4.1) and gravity 0. Comparison with
-- phi0 erfc(x / 2 sqrt(t)) and the error against the mesh: tests/fluid/test_fluid_wave.c.
--   porelab run scenes/mimes/prop.lua
local M = require("porelab.mimes").session()
M.install(_ENV)

--#-- add a fluid mesh and some boundary conditions.
set_scales_ui(0, 0, 150.1, 150.1)
add_fluid_mesh_ui(1, 1, 150, 1, 150, 150, 1, 150, 1, 16, 1000)
add_fluid_bc_ui(1, 1, 150, 1, 1.0)      -- porelab: phi0 = 1 at the bottom (Fig. 4-9)
add_fluid_bc_ui(1, 150, 150, 150, 0.0)  -- porelab: 0 at the top
--
--#-- this particle is required to force MIMES to run the experiment.
--   (if there are no particles, it won't execute)
add_rectangle_ui(0, 0, 0, 150, 1, 150, 1, 0, 100, 1)
set_velocity(1, 1, 1, 0, 0, 0, 100)
--
--#-- force MIMES to create a fluid solution; EXODUS output also.
set("FLUIDS_ON", 1)
set("FIRST_STEP_STATIC", 0)
set("PRINT_INT", 1)
set("PRINT_INT", 2000)                  -- porelab: 40 frames instead of 80000
set("MAX_DT_CR", 0.01)
set("TIMESTEPS", 80000)
set("FLUID_PERM", 0)
set("FLUID_SOLVE_TIMESTEPS", 1)
set("FLUID_SOLVE_TIMESTEPS", 100)       -- porelab: 1 s fluid steps (implicit, stable), 800 rows of pressures
set("FLUID_PERM_LOW", 1.0)
set("FLUID_PERM_HIGH", 1.0)
set("FLUID_DENSITY", 1.0)
set("FLUID_STORAGE", 1.0)               -- porelab: rho c = 1 of eq. 3.17 (eq. 4.1)
set("DT", 0.01)                         -- porelab: the MAX_DT_CR step, fixed (no moving body)
set("EXODUSFLAG", 0)
set("EXODUSOUTPUTSTEP", 1)
set("EXODUSWRITEFILE", "prop.exe")
set("FLUID_PRESSES_FLAG", 1)
set("FLUID_GEOMETRY_FLAG", 1)
set("FLUID_GEOMETRY_FILENAME", "geometry.flu")
set("FLUID_PRESSURES_FILENAME", "pressures.flu")
apply_mines_params()

return M.scene { render = { title = "A pressure wave diffusing into a fluid column (Klosek 1997, §4.3)",
                            layers = "bodies,mesh,pressure,isolines,colorbar,title,time" } }
