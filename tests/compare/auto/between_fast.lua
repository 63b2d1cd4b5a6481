-- fluid = "auto" (docs/compare.md): the flow around three glass discs (d = 1 cm, 2500 kg/m^3) settling in water: Re_p in the hundreds, inertia matters, so Navier-Stokes.
-- A tank 0.2 m wide with water to 0.3 m, open at the top.
-- porelab chooses the fluid model from the question; `porelab info` explains the choice.
local w = porelab.world { gravity = { 0, -9.81 }, fluid = "auto", needs = "flow_between_grains",
  water = { x_min = 0, x_max = 0.2, bottom = 0, level = 0.3 } }
local wall = w:material { name = "tank", density = 2500, kn = 2e5, friction = 0.4, restitution = 0.2 }
w:wall { from = { -0.01, 0 }, to = { 0.21, 0 }, material = wall }
w:wall { from = { 0, 0 }, to = { 0, 0.35 }, material = wall }
w:wall { from = { 0.2, 0 }, to = { 0.2, 0.35 }, material = wall }
local glass = w:material { name = "glass", density = 2500, kn = 2e5, friction = 0.3, restitution = 0.3 }
for i = 1, 3 do w:disc { center = { 0.05 * i, 0.25 }, radius = 0.005, material = glass } end
return { world = w, run = { t_end = 0.5, fps = 20 } }
