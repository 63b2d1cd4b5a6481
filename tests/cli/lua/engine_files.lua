-- The engine opens no files: the MIMES output files (FLUID_GEOMETRY_FLAG, FLUID_PRESSURES_FLAG,
-- default names geometry.flu and pressures.flu) reach the disk through the scene's file writer,
-- which puts a relative name inside the output folder (before, they landed in the current
-- folder, outside the sandbox). ctest cli_engine_files checks where they are.
local w = porelab.world {}
local m = w:material { name = "m", density = 2000, kn = 1e5 }
w:disc { center = { 0.5, 0.5 }, radius = 0.05, material = m }
w:fluid_quad { corners = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }, ndivx = 4, ndivy = 4 }
w:fluid_bc { from = { 0, 1 }, to = { 1, 1 }, head = 0 }
w:set_flag("FLUIDS_ON", 1)
w:set_flag("FLUID_GEOMETRY_FLAG", 1)
w:set_flag("FLUID_PRESSURES_FLAG", 1)
w:step(3)
