-- fluid = "auto" (docs/compare.md): the flow between light grains in a viscous liquid (Re_p << 1): Stokes flow by boundary elements, the open tank closed by a lid at the water level, the grain step capped below the drag limit.
-- A tank 0.12 m wide with water to 0.1 m (viscosity 1 Pa s); a bed of 1100 kg/m^3 discs of radius 0.01 m, 2 rows.
-- porelab chooses the fluid model from the question; `porelab info` explains the choice.
local w = porelab.world { gravity = { 0, -9.81 }, fluid = "auto", needs = "flow_between_grains",
  water = { x_min = 0, x_max = 0.12, bottom = 0, level = 0.1, viscosity = 1.0, density = 1000 } }
local wall = w:material { name = "tank", density = 2500, kn = 2e5, friction = 0.4, restitution = 0.2 }
w:wall { from = { -0.01, 0 }, to = { 0.13, 0 }, material = wall }
w:wall { from = { 0, 0 }, to = { 0, 0.15 }, material = wall }
w:wall { from = { 0.12, 0 }, to = { 0.12, 0.15 }, material = wall }
local R = 0.01
local sand = w:material { name = "grains", density = 1100, kn = 2e5, friction = 0.5, restitution = 0.2 }
for j = 0, 1 do
  for i = 0, 4 do
    w:disc { center = { R * (2.1 * i + 1.2 + 1.05 * (j % 2)), R * (1.05 + 2.1 * j) }, radius = R, material = sand }
  end
end
return { world = w, run = { t_end = 0.05, fps = 100 } }
