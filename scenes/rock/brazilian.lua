-- Brazilian (diametral compression) test of a bonded random packing (seed 002 §7.1,
-- docs/rock.md): a disc-shaped specimen carved out of a compacted packing of discs of radius
-- 1-1.5 mm, bonded at rest, is squeezed across a diameter between two steel platens (the
-- bottom one fixed, the top one moving down at a constant speed). The indirect tensile
-- strength is sigma_t = 2 P / (pi D), P the peak platen force per unit thickness (N/m) and D
-- the specimen diameter. The load against the platen displacement goes to
-- out/brazilian/brazilian.csv and brazilian_curve.png; the frames show the crack (broken
-- bonds: red in tension, blue in shear) running along the loaded diameter.
--   porelab run scenes/rock/brazilian.lua                 (a quick small disc)
--   porelab run scenes/rock/brazilian.lua --param size=80   (the 284-disc specimen of docs/rock.md)
--   porelab run scenes/rock/brazilian.lua --param size=80 --param speed=0.025 --out out/brazilian_half
local rock = require "porelab.rock"

local P = porelab.params(rock.with_strength_params {
  { name = "size", unit = "mm", value = 30, min = 15, max = 200, doc = "side of the box the discs are compacted in; the specimen diameter comes out about 3/4 of it" },
  { name = "speed", unit = "m/s", value = 0.05, min = 0.001, max = 2, doc = "top platen speed" },
  { name = "disp_max", unit = "mm", value = 0.15, min = 0.005, max = 5, doc = "platen displacement at the end of the run" },
  { name = "seed", unit = "", value = 1, min = 1, max = 1000000, doc = "packing seed" },
})

local S = P.size * 1e-3
local w = porelab.world { gravity = { 0, 0 }, dt_safety = 0.2, local_damping = 0.7 }
local granite, steel = rock.lab_materials(w, P)

local s = rock.specimen(w, { lo = { 0, 0 }, hi = { S, S }, material = granite, wall_material = steel,
                             seed = math.floor(P.seed), carve = 0.96 })
print("brazilian: specimen " .. s.report)
local box = s.box
-- side walls away; the platens moved onto the specimen's top and bottom
local lo_y, hi_y = math.huge, -math.huge
for _, d in ipairs(s.discs) do
  local _, y = d:position()
  lo_y, hi_y = math.min(lo_y, y - d:radius()), math.max(hi_y, y + d:radius())
end
local xm = s.circle.center[1]
box.left:set_state { position = { -S, 0.5 * S } }
box.right:set_state { position = { 2 * S, 0.5 * S } }
box.bottom:set_state { position = { xm, lo_y } }
box.top:set_state { position = { xm, hi_y } }
local D = hi_y - lo_y
local intact0 = w:bond_count()
rock.rest(w, 1e-5, 10000)
local intact1 = w:bond_count()
print(string.format("brazilian: diameter %.1f mm, %d bonds intact at rest (%d broke), dt %.3g s",
                    D * 1e3, intact1, intact0 - intact1, w:dt()))
box.top:set_velocity(0, -P.speed)
local _, y_top0 = box.top:position()
local t0 = w:time()

local csv = porelab.csv("brazilian.csv", { "t", "displacement", "force", "sigma", "bonds_broken" },
                        { "s", "m", "N/m", "Pa", "" })
local disp, force, broken = {}, {}, {}
local peak = 0
local function sample(world)
  local _, yt = box.top:position()
  local _, fy = box.top:force()
  local k = #force + 1
  disp[k], force[k], broken[k] = y_top0 - yt, fy, intact1 - world:bond_count()
  peak = math.max(peak, fy)
  csv:row(world:time() - t0, disp[k], fy, 2 * fy / (math.pi * D), broken[k])
end
local function sigma_t() return 2 * peak / (math.pi * D) end

local t_end = t0 + P.disp_max * 1e-3 / P.speed
return {
  world = w,
  run = { t_end = t_end, every = math.max(1, math.floor((t_end - t0) / w:dt() / 200)) },
  render = {
    size = { 800, 800 },
    camera = { xm - 0.6 * D, lo_y - 0.15 * D, xm + 0.6 * D, hi_y + 0.15 * D },
    time_offset = -t0,
    colors = { granite = "#c9c2b6", steel = "#3a3a3a" },
    layers = { "bodies", "bonds", "time", "title", "overlay" },
    title = "Brazilian test",
    overlay = function(world)
      local k = #force
      return { { text = string.format("2P/(pi D) = %.2f MPa   cracks: red tension, blue shear",
                                      k > 0 and 2 * force[k] / (math.pi * D) / 1e6 or 0),
                 at = { 400, 780 }, space = "pixel", anchor = "center" } }
    end,
  },
  on_frame = function(world) sample(world) end,
  on_finish = function(world)
    print(string.format("brazilian: D = %.1f mm, peak P = %.4g N/m, sigma_t = 2P/(pi D) = %.4g MPa, %d of %d bonds broken",
                        D * 1e3, peak, sigma_t() / 1e6, broken[#broken], intact1))
    local x, y = {}, {}
    for k = 1, #force do x[k], y[k] = 1e6 * disp[k], 2 * force[k] / (math.pi * D) / 1e6 end
    porelab.chart {
      file = "brazilian_curve.png", title = "Brazilian test: load against platen displacement",
      xlabel = "platen displacement (µm)", ylabel = "2P/(pi D) (MPa)", legend = "none",
      series = { { name = "2P/(pi D)", x = x, y = y } },
    }
  end,
  results = function(world)
    return { sigma_t_MPa = { value = sigma_t() / 1e6, unit = "MPa" },
             peak_N_per_m = { value = peak, unit = "N/m" },
             diameter_mm = { value = D * 1e3, unit = "mm" },
             bonds = intact1, broken_before_loading = intact0 - intact1, discs = #s.discs }
  end,
}
