-- nasty: an imperative script stepping until t = 1e9 s (found by the long fuzz run, m1027: it
-- ran past the fuzz budget); porelab's --max-cpu stops it with the scene's line
-- fuzz-set: long
local w = porelab.world { gravity = { 0, -9.81 }, dt = 1e-3 }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.1 }, radius = 0.05, material = m }
while w:time() < 1e9 do w:step(100) end
