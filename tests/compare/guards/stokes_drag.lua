-- Past the Stokes drag limit: a disc (r = 5 mm, 2000 kg/m^3) in a box of liquid (mu = 5 Pa s)
-- with dt = 3e-3 s, above the model's stable step 2 min(m/K, I/K_rot) = 2.49e-3 s. The model
-- (engine/src/fluid/stokes_bem) refuses at the first solve and names the safe step.
local R, B, H = 0.005, 0.025, 0.10
local w = porelab.world { gravity = { 0, -9.81 }, dt = 3e-3 }
local m = w:material { name = "disc", density = 2000, kn = 1e6, friction = 0.3 }
w:wall { from = { -B - 0.001, -H / 2 }, to = { B + 0.001, -H / 2 }, material = m }
w:wall { from = { B, -H / 2 - 0.001 }, to = { B, H / 2 + 0.001 }, material = m }
w:wall { from = { B + 0.001, H / 2 }, to = { -B - 0.001, H / 2 }, material = m }
w:wall { from = { -B, H / 2 + 0.001 }, to = { -B, -H / 2 - 0.001 }, material = m }
w:disc { center = { 0, 0 }, radius = R, material = m }
w:stokes { viscosity = 5.0, density = 1000, disc_elements = 16, element_length = 0.005 }
return { world = w, run = { steps = 20, every = 1000 } }
