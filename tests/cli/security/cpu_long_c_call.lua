-- security: one porelab call that would run for days (a huge step count) is stopped too
local w = porelab.world { dt = 1e-3 }
w:disc { center = { 0, 0 }, radius = 0.1,
         material = w:material { name = "m", density = 1000, kn = 1e5 } }
w:step(1e15)
