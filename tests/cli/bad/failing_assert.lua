-- an imperative script whose check fails: porelab run must exit non-zero
local w = porelab.world { gravity = { 0, -10 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
local d = w:disc { center = { 0, 1 }, radius = 0.1, material = m }
w:step(100)
local _, y = d:position()
assert(y > 1, "the disc fell (y = " .. y .. ")")
