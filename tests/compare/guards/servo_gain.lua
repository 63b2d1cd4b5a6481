-- Past the servo limit: a servo lid (gain 200 m/s, force 100 N) on a disc resting on a floor,
-- kn = 1e6 N/m, dt = 1e-5 s: G k dt / F = 200 x 1e6 x 1e-5 / 100 = 20 > 2 once the lid touches.
-- The guard (engine/src/dem/guards.c) stops the run and names the safe gain F / (k dt) = 10 m/s.
local GAIN = GAIN or 200
local w = porelab.world { gravity = { 0, 0 }, dt = 1e-5 }
local m = w:material { name = "steel", density = 7800, kn = 1e6, friction = 0, restitution = 0.3 }
w:wall { from = { -0.02, -0.01 }, to = { 0.02, -0.01 }, material = m }
w:disc { center = { 0, 0 }, radius = 0.01, material = m }
local lid = w:rectangle { center = { 0, 0.0151 }, width = 0.04, height = 0.01, material = m }
lid:servo { direction = { 0, -1 }, force = 100, gain = GAIN, vmax = 1 }
return { world = w, run = { steps = 400, every = 1000 } }
