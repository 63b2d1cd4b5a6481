-- nasty: a camera with NaN and inf
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
w:disc { center = { 0, 0 }, radius = 0.1, material = m }
return { world = w, render = { camera = { 0/0, 1/0, -1/0, 0 } } }
