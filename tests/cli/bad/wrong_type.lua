-- bad input: a string where a number is expected
local w = porelab.world {}
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0 }, radius = "big", material = m }
return w
