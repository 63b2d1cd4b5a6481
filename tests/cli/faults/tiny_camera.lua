-- A camera 1e-300 m wide: a 0.1 m disc becomes an arc 1e302 pixels across and cairo never
-- finishes drawing it.
local w = porelab.world { gravity = { 0, -10 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.2 }, radius = 0.1, material = m }
return { world = w, run = { steps = 10, every = 5 },
         render = { camera = { 0, 0, 1e-300, 1e-300 } } }
