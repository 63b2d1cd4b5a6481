-- A short busy run for the kill test: large frames (so a kill often lands in a PNG write),
-- a row per frame in energy.csv and a row per step in steps.csv (the hook steps the world
-- itself between frames, as a per-step logger would). Killed long before its end.
local w = porelab.world { gravity = { 0, -10 }, dt = 1e-4 }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.3 }
w:wall { from = { -0.5, 0 }, to = { 0.5, 0 }, material = m }
for i = 0, 9 do
  w:disc { center = { -0.45 + 0.1 * i, 0.05 + 0.03 * (i % 3) }, radius = 0.04, material = m }
end
local energy = porelab.csv("energy.csv", { "frame", "t", "kinetic", "note" })
local steps = porelab.csv("steps.csv", { "t", "x", "y", "vx", "vy", "note" })
local probe = w:disc { center = { 0, 0.3 }, radius = 0.04, material = m }
return {
  world = w,
  run = { steps = 100000000, every = 2 },
  render = { size = { 1600, 1200 } },
  on_frame = function(world, k)
    energy:row(k, world:time(), world:energy().kinetic, "a row per frame")
    for _ = 1, 20 do
      world:step(1)
      local x, y = probe:position()
      local vx, vy = probe:velocity()
      steps:row(world:time(), x, y, vx, vy, "a row per step long enough to span buffers")
    end
  end,
}
