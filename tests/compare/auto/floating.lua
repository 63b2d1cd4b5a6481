-- fluid = "auto" (docs/compare.md): a floating block asks for buoyancy only: no head difference, so hydrostatic water.
-- A tank 0.4 m wide with water to 0.3 m; a wooden block floats in it.
-- porelab chooses the fluid model from the question; `porelab info` explains the choice.
local w = porelab.world { gravity = { 0, -9.81 }, fluid = "auto", needs = "buoyancy",
  water = { x_min = 0, x_max = 0.4, bottom = 0, level = 0.3 } }
local wall = w:material { name = "tank", density = 2500, kn = 2e5, friction = 0.4, restitution = 0.2 }
w:wall { from = { -0.02, 0 }, to = { 0.42, 0 }, material = wall }
w:wall { from = { 0, 0 }, to = { 0, 0.45 }, material = wall }
w:wall { from = { 0.4, 0 }, to = { 0.4, 0.45 }, material = wall }
local wood = w:material { name = "wood", density = 600, kn = 2e5, friction = 0.4, restitution = 0.2 }
w:rectangle { center = { 0.2, 0.29 }, width = 0.1, height = 0.05, material = wood }
return { world = w, run = { t_end = 2.0, fps = 10 } }
