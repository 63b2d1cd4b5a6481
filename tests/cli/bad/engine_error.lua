-- bad input caught by the engine: a polygon given clockwise (not counter-clockwise)
local w = porelab.world {}
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:polygon { vertices = { { 0, 0 }, { 0, 1 }, { 1, 1 }, { 1, 0 } }, material = m }
return w
