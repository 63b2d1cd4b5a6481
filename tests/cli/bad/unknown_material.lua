-- bad input: a material name that was never defined
local w = porelab.world {}
w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0 }, radius = 0.1, material = "snad" }
return w
