-- A shaking table whose ramp is longer than half the shaking: refused with the argument and its range.
local w = porelab.world {}
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
local floor = w:wall { from = { 0, 0 }, to = { 1, 0 }, material = m }
floor:shake { amplitude = { 0.01, 0 }, frequency = 2, start = 0, stop = 1, ramp = 0.8 }
return { world = w }
