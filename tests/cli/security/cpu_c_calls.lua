-- security: a loop that spends its time in porelab's C functions is stopped too
local w = porelab.world { dt = 1e-3 }
w:disc { center = { 0, 0 }, radius = 0.1,
         material = w:material { name = "m", density = 1000, kn = 1e5 } }
while true do w:step(1000) end
