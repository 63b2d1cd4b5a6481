-- nasty: params with NaN bounds and a non-function set
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
w:disc { center = { 0, 0 }, radius = 0.1, material = m }
return { world = w, params = { { name = 'x', value = 0/0, min = 0/0, max = 1/0, set = 5 } } }
