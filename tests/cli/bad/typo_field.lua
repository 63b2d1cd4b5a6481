-- bad input: a misspelt field
local w = porelab.world {}
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0 }, radious = 0.1, material = m }
return w
