-- nasty: gravity 1e308
local w = porelab.world { gravity = { 0, -1e308 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0 }, radius = 0.1, material = m }
return { world = w }
