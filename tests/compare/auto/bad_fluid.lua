-- bad input: fluid must be "auto"
local w = porelab.world { fluid = "magic", needs = "buoyancy", water = { x_min = 0, x_max = 1, bottom = 0, level = 1 } }
return w
