-- nasty: an overlay text placed at NaN (found by the long fuzz run, m2484: cairo's matrix
-- became singular, "cairo: invalid matrix" with no line); now refused with the return line
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.1 }, radius = 0.05, material = m }
return { world = w, render = { overlay = function(world)
  return { { text = "x", at = { 0, 0 / 0 } }, { circle = { 1 / 0, 0 }, radius = 1 } }
end } }
