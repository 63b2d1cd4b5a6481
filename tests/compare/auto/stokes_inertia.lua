-- A scene that fixes Stokes flow (w:stokes) where inertia matters: glass discs settling in water
-- (Re_p in the hundreds). porelab info and run warn with the number and suggest Navier-Stokes.
local w = porelab.world { gravity = { 0, -9.81 } }
local wall = w:material { name = "tank", density = 2500, kn = 2e5, friction = 0.4, restitution = 0.2 }
w:wall { from = { -0.01, 0 }, to = { 0.21, 0 }, material = wall }
w:wall { from = { 0.2, -0.01 }, to = { 0.2, 0.31 }, material = wall }
w:wall { from = { 0.21, 0.3 }, to = { -0.01, 0.3 }, material = wall }
w:wall { from = { 0, 0.31 }, to = { 0, -0.01 }, material = wall }
local glass = w:material { name = "glass", density = 2500, kn = 2e5, friction = 0.3, restitution = 0.3 }
for i = 1, 3 do w:disc { center = { 0.05 * i, 0.25 }, radius = 0.005, material = glass } end
w:stokes { viscosity = 1e-3, density = 1000 }
return { world = w, run = { t_end = 0.5, fps = 20 } }
