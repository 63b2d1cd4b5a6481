-- nasty: 20000 discs in one place
-- fuzz-set: long
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
for i = 1, 20000 do w:disc { center = { 0, 0 }, radius = 0.01, material = m } end
return { world = w }
