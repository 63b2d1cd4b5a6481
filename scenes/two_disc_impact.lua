-- Seed 003 (Tan 1990) §2.2.5.3, Table 2.4: disc 1 moving up at 6 m/s strikes disc 2 at rest
-- (equal radius 1 m and mass pi kg) along a line of centres 30 degrees from the vertical.
-- No damping, no friction, no gravity, k_N = 1e7 N/m, dt = 1e-5 s; impact at about
-- 44-46 ms. Theory (momentum and e = 1): v1 = (2.598, 1.500), v2 = (-2.598, 4.500) m/s.
local w = porelab.world { gravity = { 0, 0 }, dt = 1e-5 }
local m = w:material { name = "disc", density = 1, kn = 1e7, ks = 0, friction = 0, cn = 0,
                       cs = 0 }

-- Disc 2 sits so that the discs touch after disc 1 has moved 0.264 m (t = 44 ms).
local gap = 0.264
local d1 = w:disc { center = { 0, 0 }, radius = 1, material = m, velocity = { 0, 6 } }
local d2 = w:disc { center = { -1, math.sqrt(3) + gap }, radius = 1, material = m }

return {
  world = w,
  run = { t_end = 0.1, fps = 200 },
  render = { size = { 480, 480 }, camera = { -3.5, -1.5, 1.5, 4 },
             title = "Impact of two discs" },
  on_finish = function(world)
    local v1x, v1y = d1:velocity()
    local v2x, v2y = d2:velocity()
    local theory = { 3 * math.sqrt(3) / 2, 1.5, -3 * math.sqrt(3) / 2, 4.5 }
    local got = { v1x, v1y, v2x, v2y }
    local names = { "v1x", "v1y", "v2x", "v2y" }
    for i = 1, 4 do
      print(string.format("%s  predicted %8.4f  theory %8.4f m/s  error %.3f %%", names[i],
                          got[i], theory[i], 100 * math.abs(got[i] - theory[i]) / math.abs(theory[i])))
    end
  end,
}
