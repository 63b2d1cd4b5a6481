-- Strip punch on confined rock (seed 002 §7.3, docs/rock.md): a square specimen of bonded discs
-- rests on a smooth fixed base; servo plates on both sides hold a confining stress; a rigid
-- steel punch a quarter of the specimen wide is pushed into the top at a constant speed. Under
-- the punch the rock is crushed into a wedge; below the wedge an axial splitting crack opens.
-- Broken bonds are drawn (red tension, blue shear); the punch force against its penetration
-- goes to out/punch/punch.csv and punch_curve.png.
--   porelab run scenes/rock/punch.lua                  (a quick small specimen)
--   porelab run scenes/rock/punch.lua --param size=80 --param depth=0.6   (docs/rock.md)
local rock = require "porelab.rock"

local P = porelab.params {
  { name = "size", unit = "mm", value = 30, min = 20, max = 200, doc = "side of the box the discs are compacted in (the specimen comes out about 3/4 of it)" },
  { name = "confining", unit = "MPa", value = 1, min = 0, max = 50, doc = "confining stress of the side plates" },
  { name = "speed", unit = "m/s", value = 0.05, min = 0.001, max = 2, doc = "punch speed" },
  { name = "depth", unit = "mm", value = 0.4, min = 0.01, max = 10, doc = "punch penetration at the end of the run" },
}
local S = P.size * 1e-3
local w = porelab.world { gravity = { 0, 0 }, dt_safety = 0.2, local_damping = 0.7 }
local granite, steel = rock.lab_materials(w)
w:pair(granite, steel, { friction = 0.1 }) -- smooth base and plates

local s = rock.specimen(w, { lo = { 0, 0 }, hi = { S, S }, material = granite, wall_material = steel })
print("punch: specimen " .. s.report)
local box = s.box
local xl = box.left:position()
local xr = box.right:position()
local _, yt = box.top:position()
local width, height = xr - xl, yt
local xc = 0.5 * (xl + xr)
box.top:set_state { position = { xc, yt + S } } -- the top plate leaves
-- the side plates hold the confining stress on the specimen's height
if P.confining > 0 then
  local F = P.confining * 1e6 * height
  local n = math.ceil(height / 2e-3) + 4 -- grains along a side, an upper bound of its contacts
  local g = 0.5 * F / (n * 2e10 * w:dt())
  box.left:servo { direction = { 1, 0 }, force = F, gain = g, vmax = 0.05 }
  box.right:servo { direction = { -1, 0 }, force = F, gain = g, vmax = 0.05 }
end
local intact0 = w:bond_count()
rock.rest(w, 1e-5, 10000)
local intact1 = w:bond_count()
-- the punch: a steel block just above the highest grain in the middle quarter
local top = 0
for _, d in ipairs(s.discs) do
  local x, y = d:position()
  if math.abs(x - xc) < 0.125 * width then top = math.max(top, y + d:radius()) end
end
local b = 0.25 * width
local punch = w:rectangle { center = { xc, top + 0.5 * b }, width = b, height = b, material = steel,
                            motion = "prescribed", velocity = { 0, -P.speed } }
print(string.format("punch: %.0f x %.0f mm, confining %.3g MPa, punch %.1f mm wide, %d bonds intact (%d broke at rest)",
                    width * 1e3, height * 1e3, P.confining, b * 1e3, intact1, intact0 - intact1))
local _, y0 = punch:position()
local t0 = w:time()
local csv = porelab.csv("punch.csv", { "t", "penetration", "force", "bonds_broken" }, { "s", "m", "N/m", "" })
local pen, force = {}, {}
local peak = 0
local t_end = t0 + P.depth * 1e-3 / P.speed
return {
  world = w,
  run = { t_end = t_end, every = math.max(1, math.floor((t_end - t0) / w:dt() / 150)) },
  render = {
    size = { 800, 760 },
    camera = { xl - 0.1 * width, -0.08 * height, xr + 0.1 * width, top + 0.35 * width },
    time_offset = -t0,
    colors = { granite = "#c9c2b6", steel = "#3a3a3a" },
    layers = { "bodies", "bonds", "time", "title", "overlay" },
    title = "Strip punch on confined rock",
    overlay = function(world)
      local k = #force
      return { { text = string.format("punch force %.3g kN/m   cracks: red tension, blue shear",
                                      k > 0 and force[k] / 1e3 or 0),
                 at = { 400, 740 }, space = "pixel", anchor = "center" } }
    end,
  },
  on_frame = function(world)
    local _, y = punch:position()
    local _, fy = punch:force()
    local k = #force + 1
    pen[k], force[k] = y0 - y, fy
    peak = math.max(peak, fy)
    csv:row(world:time() - t0, pen[k], fy, intact1 - world:bond_count())
  end,
  on_finish = function(world)
    print(string.format("punch: peak force %.4g N/m (%.4g MPa under the punch), %d of %d bonds broken",
                        peak, peak / b / 1e6, intact1 - world:bond_count(), intact1))
    local x, y = {}, {}
    for k = 1, #force do x[k], y[k] = 1e3 * pen[k], force[k] / 1e3 end
    porelab.chart {
      file = "punch_curve.png", title = "Strip punch: force against penetration",
      xlabel = "punch penetration (mm)", ylabel = "punch force (kN per m of thickness)", legend = "none",
      series = { { name = "punch force", x = x, y = y } },
    }
  end,
  results = function(world)
    return { peak_force = { value = peak, unit = "N/m" }, bonds_broken = intact1 - world:bond_count(),
             broken_at_rest = intact0 - intact1 }
  end,
}
