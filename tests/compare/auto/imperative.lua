-- fluid = "auto" in an imperative script: the model is chosen at the first step. A disc
-- floats (600 kg/m^3): hydrostatic water is chosen, so w:water_level() answers.
local w = porelab.world { gravity = { 0, -9.81 }, fluid = "auto", needs = "buoyancy",
  water = { x_min = 0, x_max = 0.4, bottom = 0, level = 0.3 } }
local wall = w:material { name = "tank", density = 2500, kn = 2e5, friction = 0.4, restitution = 0.2 }
w:wall { from = { -0.02, 0 }, to = { 0.42, 0 }, material = wall }
local wood = w:material { name = "wood", density = 600, kn = 2e5, friction = 0.4, restitution = 0.2 }
local d = w:disc { center = { 0.2, 0.3 }, radius = 0.02, material = wood }
w:step(10)
assert(math.abs(w:water_level() - 0.3) < 1e-12, "the hydrostatic water was not attached")
print("imperative auto: water level " .. w:water_level() .. " m")
