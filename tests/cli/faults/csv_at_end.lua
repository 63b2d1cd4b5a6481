-- Writes about 40 KB of rows into log.csv only in on_finish and never closes it: the rows
-- reach the disk when the program closes the file after the run. A failed write there
-- must still be reported (non-zero exit), not "finished".
local w = porelab.world { gravity = { 0, -10 }, dt = 1e-3 }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.2 }, radius = 0.1, material = m }
local log = porelab.csv("log.csv", { "t", "i", "note" })
return {
  world = w,
  run = { steps = 10, every = 10 },
  render = { size = { 32, 24 } },
  on_finish = function(world)
    for i = 1, 1000 do log:row(world:time(), i, "forty bytes of text in every row") end
  end,
}
