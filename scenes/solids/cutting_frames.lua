-- Frames of the cutting scene (seed 002 §7.2, docs/solids.md): the same elasto-plastic tool at
-- 4 m/s through bonded rock as cutting.lua (whose set-up it requires), drawn with a field
-- layer of the tool: von Mises stress by default, or the equivalent plastic strain with
-- --param field=2. Broken bonds are drawn as cracks.
--   porelab run scenes/solids/cutting_frames.lua --out out/cutting_mises
--   porelab run scenes/solids/cutting_frames.lua --param field=2 --out out/cutting_plastic
local P = porelab.params {
  { name = "field", unit = "1", value = 1, min = 1, max = 2,
    doc = "field drawn in the tool: 1 von Mises stress, 2 equivalent plastic strain" },
}
local w, _, _, camera = require("cutting")()
local t0 = w:time()

local plastic = P.field >= 2
return {
  world = w,
  run = { t_end = t0 + 3e-3, fps = 2000 },
  render = {
    size = { 960, 640 }, camera = camera, time_offset = -t0,
    layers = "bodies,bonds,pressure,colorbar,scalebar,title,time",
    fluid_field = plastic and "plastic_strain" or "mises",
    fluid_range = plastic and { 0, 0.03 } or { 0, 1e8 },   -- Mises up to the yield stress
    colors = { granite = "#c9c2b6", steel = "#3a3a3a" },
    title = plastic and "Cutting tool at 4 m/s in bonded rock: equivalent plastic strain"
                    or "Cutting tool at 4 m/s in bonded rock: von Mises stress",
  },
}
