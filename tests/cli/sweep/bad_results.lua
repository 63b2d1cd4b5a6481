-- A declarative scene whose results table holds a value that is not a number: the run fails
-- with the result's name, and its manifest records exit status 1.
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "m", density = 1000, kn = 1e5 }
w:disc { center = { 0, 0.1 }, radius = 0.01, material = m }
return { world = w, run = { steps = 5 }, results = { ru = { 1, 2 } } }
