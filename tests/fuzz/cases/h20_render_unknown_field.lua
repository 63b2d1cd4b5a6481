-- nasty: an unknown render field
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
w:disc { center = { 0, 0 }, radius = 0.1, material = m }
return { world = w, render = { sise = { 10, 10 }, title = string.rep("t", 100000) } }
