-- A run table with a misspelt field: `porelab info` printed the error and exited 0.
local w = porelab.world { gravity = { 0, -10 }, dt = 1e-3 }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.2 }, radius = 0.1, material = m }
return { world = w, run = { stepz = 10 } }
