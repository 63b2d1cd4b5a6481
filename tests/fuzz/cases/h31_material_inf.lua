-- nasty: material parameters 1/0 (issue 13 item 13)
local w = porelab.world {}
local m = w:material { name = "sand", density = 2650, kn = 1/0, ks = 1/0, cn = 1/0, friction = 0/0, cohesion = 1/0 }
w:disc { center = { 0, 0 }, radius = 0.1, material = m }
return { world = w }
