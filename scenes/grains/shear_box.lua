-- Cyclic simple shear at constant volume (seed 003 §5.4-5.6): grains between a bottom plate,
-- a top plate that moves back and forth at a fixed height, and two side walls hinged at the
-- bottom that turn with it. The shear force on the top plate against the shear strain traces a
-- hysteresis loop; the contact forces line up along the compressed diagonal each half cycle.
--   porelab run scenes/grains/shear_box.lua      (loop data in out/shear_box/shear.csv)
local packing = require "porelab.packing"

local w = porelab.world { gravity = { 0, 0 }, dt_safety = 0.2 }
local grain = w:material { name = "grain", density = 2650, kn = 5e6, friction = 0.5, restitution = 0.3 }
local steel = w:material { name = "steel", density = 7800, kn = 5e6, friction = 0.5, restitution = 0.3 }

local W, H = 0.2, 0.1
local box = packing.box(w, { lo = { 0, 0 }, hi = { W, H }, material = steel, open_top = false })
-- longer side walls so that grains cannot escape past their ends while they turn
local grains = packing.fill(w, { lo = { 0.002, 0.002 }, hi = { W - 0.002, H - 0.002 },
                                 radius_range = { 0.0035, 0.0055 }, porosity = 0.56,
                                 material = grain, seed = 5 })
-- consolidate to 50 kPa with servo walls, then fix the box
local t_c, err = packing.compress(w, { walls = box, pressure = 5e4, t_max = 2 })
local _, y_top = box.top:position()
print(string.format("shear_box: %d grains consolidated in %.2f s (wall error %.3f), height %.4f m",
                    #grains, t_c, err, y_top))

-- cyclic shear: the top plate moves +-4 mm (strain +-4 %) at 1 Hz; the sides follow on hinges
box.top:shake { amplitude = { 0.004, 0 }, frequency = 1 }
box.left:hinge { pivot = box.left:vertices()[2], follow = box.top, height = y_top }
box.right:hinge { pivot = box.right:vertices()[1], follow = box.top, height = y_top }

local csv = porelab.csv("shear.csv", { "t", "strain", "shear_force", "normal_force" }, { "s", "", "N/m", "N/m" })
local x0 = box.top:position()
return {
  world = w,
  run = { t_end = w:time() + 2.0, fps = 40 },
  render = {
    size = { 900, 560 },
    colors = { grain = "#b8c4d6", steel = "#2f2f2f" },
    force_color = "#9b2226",
    force_max_width = 6,
    layers = { "bodies", "forces", "time", "title" },
    title = "Cyclic simple shear at constant volume (hinged walls)",
  },
  on_frame = function(world)
    local x = box.top:position()
    local fx, fy = box.top:force()
    csv:row(world:time(), (x - x0) / y_top, fx, fy)
  end,
}
