-- A plain falling disc, for command-line arguments at the edge of their range.
local w = porelab.world { gravity = { 0, -10 }, dt = 1e-3 }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.2 }, radius = 0.1, material = m }
return { world = w, render = { size = { 64, 48 } } }
