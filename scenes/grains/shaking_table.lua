-- Shaking table: a layer of grains in an open box on a table that shakes sideways. Small and
-- large grains segregate slowly (the "Brazil nut" effect) and the force network rebuilds
-- itself every cycle. The box moves with the table (all its walls shake together).
-- Parameters (porelab run --param NAME=VALUE, porelab sweep --grid) and results (in the run's
-- manifest.json, docs/scene-reference.md): the nut's rise, the layer's coordination number.
--   porelab run scenes/grains/shaking_table.lua
--   porelab run scenes/grains/shaking_table.lua --param amp=0.012 --param freq=5 --seed 3
local packing = require "porelab.packing"

local P = porelab.params {
  { name = "amp", unit = "m", value = 0.008, min = 0.001, max = 0.02,
    doc = "horizontal shaking amplitude (the vertical one is half of it)" },
  { name = "freq", unit = "Hz", value = 6, min = 1, max = 15, doc = "shaking frequency" },
}

local w = porelab.world { gravity = { 0, -9.81 }, dt_safety = 0.2 }
local sand = w:material { name = "sand", density = 2650, kn = 2e6, friction = 0.5, restitution = 0.4 }
local pebble = w:material { name = "pebble", density = 2650, kn = 2e6, friction = 0.5, restitution = 0.4 }
local steel = w:material { name = "steel", density = 7800, kn = 2e6, friction = 0.5, restitution = 0.4 }

local box = packing.box(w, { lo = { 0, 0 }, hi = { 0.5, 0.2 }, material = steel })
packing.rain(w, { lo = { 0.01, 0.05 }, hi = { 0.49, 0.45 }, radii = { 0.006, 0.009 },
                  weights = { 0.7, 0.3 }, materials = { sand, pebble }, count = 330, seed = 11 })
-- one big "nut" at the bottom
local nut = w:disc { center = { 0.25, 0.025 }, radius = 0.022, material = pebble }
local nut_y0 -- the nut's height once the grains have settled (at the first frame after it)

-- the box shakes 8 mm at 6 Hz (peak acceleration 1.2 g) after the grains have settled
local settle = 0.5
for _, wall in pairs(box) do
  wall:shake { amplitude = { P.amp, P.amp / 2 }, frequency = P.freq, start = settle }
end

local csv = porelab.csv("table.csv", { "t", "table_x", "kinetic", "coordination" }, { "s", "m", "J", "" })
return {
  world = w,
  run = { t_end = 4.0, fps = 30 },
  render = {
    size = { 960, 480 },
    camera = { -0.03, -0.02, 0.53, 0.24 },
    colors = { sand = "#e9c46a", pebble = "#8ab17d", steel = "#3a3a3a" },
    force_color = "#7a1f1f",
    force_max_width = 5,
    layers = { "bodies", "forces", "time", "title", "scalebar" },
    title = "Shaking table: 6 Hz, 8 mm, force chains",
  },
  on_frame = function(world)
    local x = box.bottom:position()
    if not nut_y0 and world:time() >= settle then nut_y0 = select(2, nut:position()) end
    csv:row(world:time(), x - 0.25, world:energy().kinetic, world:coordination())
  end,
  results = function(world)
    local _, y = nut:position()
    return {
      nut_rise_mm = { value = 1000 * (y - (nut_y0 or y)), unit = "mm" },
      coordination = world:coordination(),
      peak_accel_g = { value = P.amp * (2 * math.pi * P.freq) ^ 2 / 9.81, unit = "g" },
    }
  end,
}
