-- Past the polygons' grain-step limit: the square of tests/compare/stability/polygon_area.lua
-- (face down on a floor, undamped, kn = 1e6 N/m), let go touching, at dt = 1.2 of the computed
-- critical step 2 / omega of the area law's face spring kn L / h (docs/stability.md). The
-- guards stop the run and name the time step, the critical step and a safe step.
local S = 0.02
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "grain", density = 2650, kn = 1e6, friction = 0, restitution = 1 }
w:wall { from = { -0.1, 0 }, to = { 0.1, 0 }, material = m }
w:rectangle { center = { 0, S / 2 }, width = S, height = S, material = m, fixed_rotation = true }
w:set_flag("DT", 1.2 * w:dt_report().dt_critical)
return { world = w, run = { steps = 2000, every = 100000 } }
