-- Description: Dry grains pour from a hopper into a box and build a heap.
-- porelab demo: about 330 grains of two sizes rest in a hopper on a closed gate; at
-- t = 0.6 s the gate slides away and the grains pour into a box, where they build a heap.
-- Force chains (dark lines, width proportional to the normal contact force) show how the
-- weight is carried: arches over the gate, then a network under the heap. 4 s simulated;
-- the grains' kinetic energy goes to out/demo/energy.csv through the on_frame hook.
--   porelab run scenes/demo.lua            (frames in out/demo/)
local packing = require "porelab.packing"

local w = porelab.world {
  gravity = { 0, -9.81 },  -- m/s^2
  dt_safety = 0.2,         -- fraction of the critical time step 2 sqrt(m/k)
}

-- Same mechanics, two colours. Stiffness per unit thickness (2D), N/m.
local function grain(name)
  return w:material { name = name, density = 2650, kn = 1e6, friction = 0.5,
                      restitution = 0.3 }
end
local small, large = grain("small"), grain("large")
local steel = w:material { name = "steel", density = 7800, kn = 1e6, friction = 0.5,
                           restitution = 0.3 }

-- The box (open at the top), a hopper with a 0.2 m outlet, and the gate closing it.
packing.box(w, { lo = { 0.25, 0 }, hi = { 0.95, 0.5 }, material = steel })
w:wall { from = { 0.15, 1.0 }, to = { 0.5, 0.6 }, material = steel }
w:wall { from = { 0.7, 0.6 }, to = { 1.05, 1.0 }, material = steel }
local gate = w:wall { from = { 0.45, 0.59 }, to = { 0.75, 0.59 }, material = steel }

packing.rain(w, {
  lo = { 0.28, 0.9 }, hi = { 0.92, 1.45 },
  radii = { 0.009, 0.014 },       -- m
  weights = { 0.6, 0.4 },         -- number fractions
  materials = { small, large },
  count = 330,
  seed = 7,
})

local energy = porelab.csv("energy.csv", { "t", "kinetic", "contacts" }, { "s", "J", "" })
local fps = 30

return {
  world = w,
  run = { t_end = 4.0, fps = fps },
  render = {
    size = { 640, 960 },
    camera = { 0.1, -0.03, 1.1, 1.47 },    -- m; the gate slides out of view
    colors = { small = "#f2cf6b", large = "#9dbbdc", steel = "#3a3a3a" },
    force_color = "#7a1010",
    force_scale = 200,       -- N drawn at the full width (the heavier contacts near the floor)
    force_max_width = 4.5,   -- pixels: thinner than a small grain, so the chains do not hide it
    force_threshold = 0.02,  -- contacts under 4 N are not drawn
    layers = { "bodies", "forces", "time", "title" },
    title = "Grains through a hopper: force chains",
  },
  on_frame = function(world, frame)
    energy:row(world:time(), world:energy().kinetic, world:contact_count())
    if frame == math.floor(0.6 * fps) then gate:set_velocity(3, 0) end   -- open
    if frame == math.floor(1.0 * fps) then gate:set_velocity(0, 0) end   -- park
  end,
}
