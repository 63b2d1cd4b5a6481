-- fluid = "auto" (docs/compare.md): pore pressure from loading in a silty bed (conductivity 1e-7 m/s, cf. scenes/soil/liquefaction.lua): t_c far above the 2 s run, so Darcy with consolidation.
-- A tank 0.4 m wide with water to 0.3 m; a bed of 2650 discs of radius 0.005 m, 6 rows.
-- porelab chooses the fluid model from the question; `porelab info` explains the choice.
local w = porelab.world { gravity = { 0, -9.81 }, fluid = "auto", needs = "pore_pressure",
  water = { x_min = 0, x_max = 0.4, bottom = 0, level = 0.3, conductivity = 1e-7, bulk_modulus = 3e5 } }
local wall = w:material { name = "tank", density = 2500, kn = 2e5, friction = 0.4, restitution = 0.2 }
w:wall { from = { -0.02, 0 }, to = { 0.42, 0 }, material = wall }
w:wall { from = { 0, 0 }, to = { 0, 0.45 }, material = wall }
w:wall { from = { 0.4, 0 }, to = { 0.4, 0.45 }, material = wall }
local R = 0.005
local sand = w:material { name = "grains", density = 2650, kn = 2e5, friction = 0.5, restitution = 0.2 }
for j = 0, 6 - 1 do
  for i = 0, math.floor(0.4 / (2 * R)) - 2 do
    w:disc { center = { R * (2 * i + 2 + (j % 2)), R * (1 + 2 * j) }, radius = R, material = sand }
  end
end
return { world = w, run = { t_end = 2.0, fps = 10 } }
