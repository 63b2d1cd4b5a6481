-- Restart test scene (tests/cli/restart.cmake): one column of scenes/soil/consolidation.lua
-- with FLUID_CONSOLIDATION 1 from the start and the piston loaded from the start, so that a
-- short run already has a skeleton compressing against its pore water (excess pressure,
-- consolidation source and reference positions in the state). No hook keeps Lua state, so a
-- run resumed from a restart file is the same run.
local packing = require "porelab.packing"
local W, HMESH, PH = 0.04, 0.080, 0.03
local w = porelab.world { gravity = { 0, -9.81 }, rayleigh_alpha = 20, dt_safety = 0.05, local_damping = 0.3 }
local sand = w:material { name = "sand", density = 2650, kn = 2e5, friction = 0.3, restitution = 0.2 }
local wall = w:material { name = "wall", density = 2650, kn = 2e5, friction = 0.0, restitution = 0.2 }
local pmat = w:material { name = "piston", density = 1000, kn = 2e5, friction = 0.3, restitution = 0.2 }
w:wall { from = { -0.005, 0 }, to = { W + 0.005, 0 }, material = sand }
w:wall { from = { 0, 0 }, to = { 0, 0.3 }, material = wall }
w:wall { from = { W, 0 }, to = { W, 0.3 }, material = wall }
packing.rain(w, { lo = { 0.001, 0.002 }, hi = { W - 0.001, 0.058 }, radii = { 0.0020, 0.0026 },
                  count = 50, material = sand, seed = 5 })
local piston = w:rectangle { center = { W / 2, 0.075 }, width = W - 0.0006, height = PH, material = pmat }
piston:set_load(0, -(6000 * W - piston:mass() * 9.81))
w:fluid_quad { corners = { { 0, 0 }, { W, 0 }, { W, HMESH }, { 0, HMESH } }, ndivx = 4, ndivy = 13 }
w:fluid_bc { from = { 0, 0 }, to = { W, 0 }, head = HMESH }
w:set_flag("FLUIDS_ON", 1)
w:set_flag("FIRST_STEP_STATIC", 1)
w:set_flag("FLUID_PERM", 1)
w:set_flag("FLUID_PERM_LOW", 1e-4)
w:set_flag("FLUID_PERM_HIGH", 1e-3)
w:set_flag("FLUID_STORAGE", 0)
w:set_flag("FLUID_CONSOLIDATION", 1)
w:set_flag("FLUID_BULK_MODULUS", 1e6)
w:set_flag("FLUID_SOLVE_TIMESTEPS", 2)
return { world = w, run = { t_end = 0.2, fps = 50 } }
