-- fluid = "auto" (docs/compare.md): the flow between light grains in a viscous liquid (Re_p << 1): Stokes by boundary elements is the model, which auto does not set up yet, so Darcy with a note.
-- A tank 0.4 m wide with water to 0.3 m; a bed of 1100 discs of radius 0.01 m, 2 rows.
-- porelab chooses the fluid model from the question; `porelab info` explains the choice.
local w = porelab.world { gravity = { 0, -9.81 }, fluid = "auto", needs = "flow_between_grains",
  water = { x_min = 0, x_max = 0.4, bottom = 0, level = 0.3, viscosity = 1.0, density = 1000 } }
local wall = w:material { name = "tank", density = 2500, kn = 2e5, friction = 0.4, restitution = 0.2 }
w:wall { from = { -0.02, 0 }, to = { 0.42, 0 }, material = wall }
w:wall { from = { 0, 0 }, to = { 0, 0.45 }, material = wall }
w:wall { from = { 0.4, 0 }, to = { 0.4, 0.45 }, material = wall }
local R = 0.01
local sand = w:material { name = "grains", density = 1100, kn = 2e5, friction = 0.5, restitution = 0.2 }
for j = 0, 2 - 1 do
  for i = 0, math.floor(0.4 / (2 * R)) - 2 do
    w:disc { center = { R * (2 * i + 2 + (j % 2)), R * (1 + 2 * j) }, radius = R, material = sand }
  end
end
return { world = w, run = { t_end = 2.0, fps = 10 } }
