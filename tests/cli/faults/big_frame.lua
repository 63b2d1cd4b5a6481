-- One large first frame (1600 x 1200, well above a few KB): under a small file size limit
-- its write fails, and no truncated frame_000000.png may be left under its final name.
local w = porelab.world { gravity = { 0, -10 }, dt = 1e-3 }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
for i = 0, 20 do
  w:disc { center = { -1 + 0.1 * i, 0.2 + 0.05 * (i % 4) }, radius = 0.04, material = m }
end
return { world = w, run = { steps = 10, every = 5 }, render = { size = { 1600, 1200 } } }
