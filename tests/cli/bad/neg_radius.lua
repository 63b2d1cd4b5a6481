-- bad input: a negative radius
local w = porelab.world {}
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0 }, radius = -1, material = m }
return w
