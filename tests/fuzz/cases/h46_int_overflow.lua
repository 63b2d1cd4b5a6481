-- nasty: integers at the edge
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
w:disc { center = { math.maxinteger, math.mininteger }, radius = 0.1, material = m }
return { world = w, run = { steps = math.maxinteger } }
