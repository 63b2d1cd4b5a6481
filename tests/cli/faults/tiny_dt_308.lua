-- A time step of 1e-308 s: `porelab info` looped forever counting frames.
local w = porelab.world { gravity = { 0, -10 }, dt = 1e-308 }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.2 }, radius = 0.1, material = m }
return { world = w }
