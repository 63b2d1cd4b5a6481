-- Writes about 40 KB of rows into log.csv from its on_frame hook (the program flushes them
-- after each frame) and never closes the file. Under a 4-8 KB file size limit the write
-- fails: the run must stop with a message and a non-zero exit, log.csv ending in a whole line.
local w = porelab.world { gravity = { 0, -10 }, dt = 1e-3 }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.2 }, radius = 0.1, material = m }
local log = porelab.csv("log.csv", { "t", "i", "note" })
return {
  world = w,
  run = { steps = 100, every = 10 },
  render = { size = { 32, 24 } },
  on_frame = function(world, k)
    for i = 1, 100 do log:row(world:time(), i, "forty bytes of text in every row") end
  end,
}
