-- A time step of 1e-22 s: one simulated second would take 1e22 steps, more than a step
-- counter holds (the frame plan overflowed and the run ended at once with exit 0).
local w = porelab.world { gravity = { 0, -10 }, dt = 1e-22 }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.2 }, radius = 0.1, material = m }
return { world = w, run = { t_end = 1 } }
