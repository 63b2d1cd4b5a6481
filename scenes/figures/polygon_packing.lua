-- A settled packing of random convex polygons (the grains of seed 004 §2.1: 5-9 corners on
-- ellipses with half axes 5-7.5 mm, aspect 0.6-1) in a box 0.32 m wide, for the force-chain
-- figure of tools/figures.sh. 400 grains start on a loose lattice, fall under gravity and
-- settle (local damping 0.3, area-based contacts of seed 004 §3, friction 0.5); by t = 1.5 s
-- the packing is at rest and carries its weight through chains of contacts.
--   porelab still scenes/figures/polygon_packing.lua --at 1.5 -o chains.png
local random = require "porelab.random"

local w = porelab.world { gravity = { 0, -9.81 }, local_damping = 0.3 }
local grain = w:material { name = "grain", density = 2650, kn = 1e6, friction = 0.5,
                           restitution = 0.2 }
local steel = w:material { name = "steel", density = 7800, kn = 1e6, friction = 0.5,
                           restitution = 0.2 }
local x0, x1 = -0.16, 0.16
w:wall { from = { x0, 0 }, to = { x1, 0 }, material = steel }
w:wall { from = { x0, 0.5 }, to = { x0, 0 }, material = steel }
w:wall { from = { x1, 0 }, to = { x1, 0.5 }, material = steel }

local rng = random.new(4)
local cols, rows, pitch = 20, 20, 0.016
local seed = 0
for j = 0, rows - 1 do
  for i = 0, cols - 1 do
    seed = seed + 1
    local x = x0 + pitch * (i + 0.5) + 0.0005 * (j % 2) + rng:uniform(-0.0005, 0.0005)
    local y = 0.01 + pitch * (j + 0.5)
    w:random_polygon { center = { x, y }, seed = seed, corners = { 5, 9 },
                       axis = { 0.005, 0.0075 }, aspect = { 0.6, 1.0 }, material = grain }
  end
end

return {
  world = w,
  run = { t_end = 1.5, fps = 20 },
  render = {
    size = { 1000, 560 },
    camera = { x0 - 0.008, -0.012, x1 + 0.008, 0.158 },
    colors = { grain = "#e3cfa6", steel = "#3a3a3a" },
    layers = "bodies,forces,title,scalebar",
    force_max_width = 6,
    force_scale = 40, -- N per metre of thickness at full width (the weight of ~15 grains)
    force_threshold = 0.04,
    title = "Force chains in a settled packing of 400 polygons",
  },
}
