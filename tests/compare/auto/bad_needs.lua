-- bad input: needs must name one of the four questions
local w = porelab.world { fluid = "auto", needs = "everything", water = { x_min = 0, x_max = 1, bottom = 0, level = 1 } }
return w
