-- nasty: a wall from -1e308 to 1e308
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
w:wall { from = { -1e308, 0 }, to = { 1e308, 0 }, material = m }
w:disc { center = { 0, 0.2 }, radius = 0.1, material = m }
return { world = w }
