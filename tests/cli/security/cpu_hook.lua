-- security: an endless loop in a hook is stopped by the CPU-time budget
local w = porelab.world { dt = 1e-3 }
w:disc { center = { 0, 0 }, radius = 0.1,
         material = w:material { name = "m", density = 1000, kn = 1e5 } }
return {
  world = w,
  run = { steps = 10, every = 5 },
  on_frame = function(world, i)
    if i == 1 then
      while true do end
    end
  end,
}
