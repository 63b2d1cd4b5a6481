-- A fluid boundary line but no fluid mesh: the set-up error comes at the first fluid update
-- (step 0) and names the line of the return that handed the world over.
local w = porelab.world { gravity = { 0, -9.81 }, flags = { FLUIDS_ON = 1 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.1 }, radius = 0.01, material = m }
w:fluid_bc { from = { -1, 1 }, to = { 1, 1 }, head = 0 }
return { world = w, run = { steps = 10 } }
