-- nasty: dt = 1e-300 (issue 13 item 12: the frame plan hangs)
-- fuzz-set: long
local w = porelab.world { dt = 1e-300 }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0 }, radius = 0.1, material = m }
return { world = w }
