-- fluid = "auto" (docs/compare.md): seepage through coarse gravel (conductivity 0.5 m/s): Re_p past Darcy's range; Darcy is still the only averaged model (Navier-Stokes would resolve every pore), so Darcy with a note.
-- A tank 0.4 m wide with water to 0.3 m; a bed of 2650 discs of radius 0.01 m, 3 rows.
-- porelab chooses the fluid model from the question; `porelab info` explains the choice.
local w = porelab.world { gravity = { 0, -9.81 }, fluid = "auto", needs = "seepage",
  water = { x_min = 0, x_max = 0.4, bottom = 0, level = 0.3, head_difference = 0.2, conductivity = 0.5 } }
local wall = w:material { name = "tank", density = 2500, kn = 2e5, friction = 0.4, restitution = 0.2 }
w:wall { from = { -0.02, 0 }, to = { 0.42, 0 }, material = wall }
w:wall { from = { 0, 0 }, to = { 0, 0.45 }, material = wall }
w:wall { from = { 0.4, 0 }, to = { 0.4, 0.45 }, material = wall }
local R = 0.01
local sand = w:material { name = "grains", density = 2650, kn = 2e5, friction = 0.5, restitution = 0.2 }
for j = 0, 3 - 1 do
  for i = 0, math.floor(0.4 / (2 * R)) - 2 do
    w:disc { center = { R * (2 * i + 2 + (j % 2)), R * (1 + 2 * j) }, radius = R, material = sand }
  end
end
return { world = w, run = { t_end = 2.0, fps = 10 } }
