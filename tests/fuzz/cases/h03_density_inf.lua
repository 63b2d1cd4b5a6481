-- nasty: infinite density and velocity
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
w:disc { center = { 0, 0 }, radius = 0.1, material = w:material { name = "x", density = 1/0, kn = 1e6 }, velocity = { 1e308, -1e308 } }
return { world = w }
