-- 20,000 discs created at one point (a loop that never moves the centre): refused at the
-- first step with the bodies and the place named, instead of a first step that computes all
-- 2e8 contacts among them (205 s before the check).
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
for i = 1, 20000 do w:disc { center = { 0, 0 }, radius = 0.01, material = m } end
return { world = w, render = { size = { 64, 48 }, camera = { -1, -1, 1, 0.5 } } }
