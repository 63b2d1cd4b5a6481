-- errors in the returned table name the line of the return
local w = porelab.world { dt = 1e-3 }
w:disc { center = { 0, 0 }, radius = 0.1,
         material = w:material { name = "m", density = 1000, kn = 1e5 } }

return {
  world = w,
  run = { steps = 10, fps = -3 },
}
