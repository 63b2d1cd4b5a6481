-- nasty: a table of a million entries as a field
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
local t = {}
for i = 1, 1000000 do t[i] = i end
w:disc { center = t, radius = 0.1, material = m }
return { world = w }
