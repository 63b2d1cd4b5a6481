-- a declarative scene whose on_frame hook fails on the third frame
local w = porelab.world { gravity = { 0, -10 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:wall { from = { -1, 0 }, to = { 1, 0 }, material = m }
w:disc { center = { 0, 0.2 }, radius = 0.1, material = m }
return {
  world = w,
  run = { steps = 100, every = 10 },
  on_frame = function(world, frame)
    if frame == 2 then error("hook failed at frame " .. frame) end
  end,
}
