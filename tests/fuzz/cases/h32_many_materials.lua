-- nasty: 1000 materials (issue 13 item 12: pair table N^3)
-- fuzz-set: long
local w = porelab.world {}
for i = 1, 1000 do w:material { name = "m" .. i, density = 2650, kn = 1e6 } end
return { world = w }
