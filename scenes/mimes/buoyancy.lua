-- Seed 000 (Klosek 1997) Appendix C.2, buoyancy.tcl, line for line through porelab.mimes:
-- a superquadric falls into standing fluid (§4.2, Figs. 4-4 to 4-8). Material 2 is the
-- particle; the thesis changed density(2) between runs (rho_particle = 1/2, 1, > 1 times
-- FLUID_DENSITY = 1); the listing's 0.001 is kept below and `ratio` picks a case.
-- Transcription notes (the text extraction damaged two lines):
--  * add_rectangle_ui for id 187 lost one coordinate; restored as the left wall
--    (100,80) (80,80) (80,300) (100,300), mirroring id 189;
--  * '$' comment markers of the listing are Tcl comments ('#').
--  * add_superquad_ui's signature is not printed in the thesis; porelab.mimes reads it as
--    bounding-box corners (131, 396)-(250, 321), id 42, material 2, exponent 2 (an ellipse),
--    angle 0, -, 16 vertices, velocity (0, 0) (see lua/lib/porelab/mimes.lua).
--   porelab run scenes/mimes/buoyancy.lua
local ratio = 0.5 -- rho_particle / rho_fluid for this run (thesis: 1/2, 1, > 1)

local M = require("porelab.mimes").session()
M.install(_ENV)

--#-- set up the material; change the density here as required.
-- also add the free-falling particle
set("matnum", 2)
global("E(2)")
global("nu(2)")
global("density(2)")
create_material_list_ui(2)
set("E(1)", 200)
set("nu(1)", 0.3)
set("density(1)", 1.5)
set("E(2)", 200)
set("nu(2)", 0.3)
set("density(2)", 0.001)
set("density(2)", ratio * 1.0) -- porelab: the case chosen above (FLUID_DENSITY = 1)
apply_material_list(2)
set("fric(1,1)", 0.1)
set("fric(2,1)", 0.1)
set("fric(2,2)", 0.1)
apply_fric(2)
set("k_normal(1,1)", 400000)
set("k_normal(2,1)", 400000)
set("k_normal(2,2)", 400000)
apply_kn(2)
set("k_shear(1,1)", 600000)
set("k_shear(2,1)", 600000)
set("k_shear(2,2)", 600000)
apply_ks(2)
add_superquad_ui(131, 396, 250, 321, 42, 2, 2, 0, 1, 16, 0, 0)
--
--#-- add a fluid mesh and some boundary conditions
add_fluid_mesh_ui(100, 100, 300, 100, 300, 300, 100, 300, 4, 4, 10)
add_fluid_bc_ui(100, 100, 300, 100, 200)
add_fluid_bc_ui(100, 300, 300, 300, 0)
--
--#-- put the fluid in a box
add_rectangle_ui(100, 80, 80, 80, 80, 300, 100, 300, 187, 2)
add_rectangle_ui(100, 80, 100, 100, 320, 100, 320, 80, 188, 2)
add_rectangle_ui(300, 100, 300, 300, 320, 300, 320, 100, 189, 2)
set_velocity(1, 1, 1, 0, 0, 0, 187)
set_velocity(1, 1, 1, 0, 0, 0, 188)
set_velocity(1, 1, 1, 0, 0, 0, 189)
--
--#-- set up MIMES for a fluid solution
set("GRAVITY_Y", -9.81)
set("FLUIDS_ON", 1)
set("PRINT_INT", 10)
set("PRINT_INT", 400)                   -- porelab: 100 frames instead of 4000
set("TIMESTEPS", 40000)
set("RAYLEIGH_FACTOR", 1.0)
set("MAX_DT_CR", 0.005)
set("FIRST_STEP_STATIC", 1)
set("FLUID_SOLVE_TIMESTEPS", 10000)
set("FLUID_PERM", 0)
set("FLUID_GEOMETRY_FLAG", 0)
set("FLUID_PRESSES_FLAG", 0)
set("FLUID_PERM_LOW", 0.0001)
set("FLUID_DENSITY", 1)
set("FLUID_PERM_HIGH", 4.0)
set("EXODUSWRITEFILE", "buoyancy.exe")
set("EXODUSFLAG", 0)
set("EXODUSOUTPUTSTEP", 10)
apply_mimes_params()

return M.scene { render = { title = string.format("Particle in water, ρp/ρf = %g (Klosek 1997 §4.2)", ratio),
                            layers = "bodies,mesh,pressure,colorbar,title,time" } }
