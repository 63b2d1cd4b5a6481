-- nasty: a packing lattice of tiny radius (issue 13 item 12: 3 GB, no capacity check)
-- fuzz-set: long
local packing = require 'porelab.packing'
local w = porelab.world {}
local m = w:material { name = 'sand', density = 2650, kn = 1e6 }
packing.lattice(w, { box = { 0, 0, 1, 1 }, radius = 1e-6, material = m })
return { world = w }
