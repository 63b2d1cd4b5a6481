-- nasty: wrong types everywhere
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
w:disc { center = "origin", radius = { 1 }, material = 5 }
return { world = w }
