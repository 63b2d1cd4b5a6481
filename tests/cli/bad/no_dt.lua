-- Nothing moves and no dt is given: no automatic time step; the message names the return.
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "steel", density = 7800, kn = 1e7 }
w:wall { from = { -1, 0 }, to = { 1, 0 }, material = m }
return { world = w }
