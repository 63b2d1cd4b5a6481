-- a run that goes unstable: the fixed time step is several times the critical step
-- (about 0.016 s here); the engine's guards stop it with a diagnosis
local w = porelab.world { gravity = { 0, -9.81 }, dt = 0.055 }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
w:wall { from = { -1, 0 }, to = { 1, 0 }, material = m }
for i = 0, 4 do
  w:disc { center = { -0.4 + 0.2 * i, 0.1 }, radius = 0.1, material = m }
  w:disc { center = { -0.4 + 0.2 * i, 0.3 }, radius = 0.1, material = m }
end
return { world = w, run = { steps = 2000, every = 10 } }
