-- Below the servo limit: the same lid with gain 5 m/s (G k dt / F = 0.5) holds its force and
-- runs to the end (tests/compare/guards/servo_gain.lua is the one past the limit).
local GAIN = 5
local w = porelab.world { gravity = { 0, 0 }, dt = 1e-5 }
local m = w:material { name = "steel", density = 7800, kn = 1e6, friction = 0, restitution = 0.3 }
w:wall { from = { -0.02, -0.01 }, to = { 0.02, -0.01 }, material = m }
w:disc { center = { 0, 0 }, radius = 0.01, material = m }
local lid = w:rectangle { center = { 0, 0.0151 }, width = 0.04, height = 0.01, material = m }
lid:servo { direction = { 0, -1 }, force = 100, gain = GAIN, vmax = 1 }
return { world = w, run = { steps = 400, every = 1000 } }
