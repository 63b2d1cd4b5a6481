-- Seed 000 (Klosek 1997) Appendix C.1, dam-flow.tcl, line for line through porelab.mimes:
-- flow under a dam (§4.1, Figs. 4-1 to 4-3). Three fluid quads of different sizes (regions A,
-- B, C) mesh together (incompatible faces re-meshed), pressure head 40 on top of A and 0 on
-- top of C, all other boundaries impermeable; fixed rectangles form the channel. One step:
-- the static solution (FIRST_STEP_STATIC 1). Inflow equals outflow (checked by
-- tests/fluid/test_fluid_static.c); EXODUS output becomes dam-flow.vtu (ParaView).
--   porelab run scenes/mimes/dam_flow.lua
local M = require("porelab.mimes").session()
M.install(_ENV)

-- set_scales_ui 0 0 600 600
set_scales_ui(0, 0, 600, 600)
--
--#-- add a fluid mesh and some boundary conditions.
add_fluid_mesh_ui(50, 50, 250, 50, 250, 300, 50, 300, 4, 4, 1000)
add_fluid_mesh_ui(250, 50, 350, 50, 350, 100, 250, 100, 4, 4, 1001)
add_fluid_mesh_ui(350, 50, 480, 50, 480, 300, 350, 300, 4, 4, 1002)
add_fluid_bc_ui(50, 300, 250, 300, 40)
add_fluid_bc_ui(350, 300, 480, 300, 0)
--
--#-- create the "dam" or channel for particles to flow through.
add_rectangle_ui(30, 300, 50, 300, 50, 30, 30, 30, 100, 1)
set_velocity(1, 1, 1, 0, 0, 0, 100)
add_rectangle_ui(30, 50, 500, 50, 500, 30, 30, 30, 101, 1)
set_velocity(1, 1, 1, 0, 0, 0, 101)
add_rectangle_ui(480, 30, 480, 300, 500, 300, 500, 30, 102, 1)
set_velocity(1, 1, 1, 0, 0, 0, 102)
add_rectangle_ui(250, 100, 250, 310, 350, 310, 350, 100, 103, 1)
set_velocity(1, 1, 1, 0, 0, 0, 103)
--
--#-- force MIMES to create a fluid solution; EXODUS output also.
set("FLUIDS_ON", 1)
set("FIRST_STEP_STATIC", 1)
set("PRINT_INT", 5)
set("MAX_DT_CR", 0.001)
set("TIMESTEPS", 1)
set("FLUID_PERM", 0)
set("FLUID_SOLVE_TIMESTEPS", 2000)
set("FLUID_PERM_LOW", 0.001)
set("FLUID_PERM_HIGH", 5.0)
set("FLUID_DENSITY", 0.1)
set("EXODUSFLAG", 1)
set("EXODUSOUTPUTSTEP", 1)
set("EXODUSWRITEFILE", "dam-flow.exe")
apply_mines_params()

return M.scene { render = { title = "Flow under a dam: pore pressure and Darcy velocity (Klosek 1997, §4.1)",
                            layers = "bodies,mesh,pressure,isolines,velocity,colorbar,title" } }
