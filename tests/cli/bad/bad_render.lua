-- bad input: an unknown layer name in the render table
local w = porelab.world {}
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0 }, radius = 0.1, material = m }
return { world = w, render = { layers = { "bodies", "force" } } }
