-- Unconfined compression (UCS) of a bonded random packing (seed 002 §7.1, docs/rock.md): a
-- rectangle of discs of radius 1-1.5 mm, bonded at rest, is squeezed between two frictional
-- steel platens; the bottom one is fixed, the top one moves down at a constant speed. The
-- stress-strain curve (platen stress against the strain measured inside the specimen) goes to
-- out/ucs/ucs.csv and out/ucs/ucs_curve.png; the last frame shows the cracks (broken bonds:
-- red in tension, blue in shear). The run reports E, nu (from 10-50 % of the peak) and the UCS.
--   porelab run scenes/rock/ucs.lua                  (a quick 125-disc specimen)
--   porelab run scenes/rock/ucs.lua --param width=60   (the 706-disc specimen of docs/rock.md)
--   porelab run scenes/rock/ucs.lua --param width=60 --param speed=0.025 --out out/ucs_half   (quasi-static check)
local rock = require "porelab.rock"

local P = porelab.params(rock.with_strength_params {
  { name = "width", unit = "mm", value = 25, min = 10, max = 200, doc = "width of the box the discs are compacted in (height 2.2 x width); the specimen comes out about 3/4 as wide" },
  { name = "speed", unit = "m/s", value = 0.05, min = 0.001, max = 2, doc = "top platen speed" },
  { name = "strain_max", unit = "%", value = 0.25, min = 0.02, max = 5, doc = "platen strain at the end of the run" },
  { name = "seed", unit = "", value = 1, min = 1, max = 1000000, doc = "packing seed" },
})

local W = P.width * 1e-3
local w = porelab.world { gravity = { 0, 0 }, dt_safety = 0.2, local_damping = 0.7 }
local granite, steel = rock.lab_materials(w, P)

local s = rock.specimen(w, { lo = { 0, 0 }, hi = { W, 2.2 * W }, material = granite,
                             wall_material = steel, seed = math.floor(P.seed) })
print("ucs: specimen " .. s.report)
local box = s.box
-- the side walls go away; the top platen moves down
local xl = box.left:position()
local xr = box.right:position()
box.left:set_state { position = { xl - W, W } }
box.right:set_state { position = { xr + W, W } }
local width, height = s.size[1], s.size[2]
local intact0 = w:bond_count()
rock.rest(w, 1e-6, 20000)
local intact1 = w:bond_count()
print(string.format("ucs: %d x %d mm, %d bonds intact after the side walls went (%d broke), dt %.3g s",
                    math.floor(width * 1e3 + 0.5), math.floor(height * 1e3 + 0.5), intact1,
                    intact0 - intact1, w:dt()))
box.top:set_velocity(0, -P.speed)

-- gauge groups inside the specimen: bands at 1/5 and 4/5 of the height, and the left and right
-- fifths at mid height (the platen contacts' compliance stays out of the strains)
local bot, top, left, right = {}, {}, {}, {}
local xmin, xmax = math.huge, -math.huge
for _, d in ipairs(s.discs) do
  local x = d:position()
  xmin, xmax = math.min(xmin, x), math.max(xmax, x)
end
for _, d in ipairs(s.discs) do
  local x, y = d:position()
  if math.abs(y - 0.2 * height) < 0.05 * height then bot[#bot + 1] = d end
  if math.abs(y - 0.8 * height) < 0.05 * height then top[#top + 1] = d end
  if math.abs(y - 0.5 * height) < 0.2 * height then
    if x < xmin + 0.15 * width then left[#left + 1] = d end
    if x > xmax - 0.15 * width then right[#right + 1] = d end
  end
end
local function gauges()
  local _, yb = rock.centroid(w, bot)
  local _, yt = rock.centroid(w, top)
  local xa = rock.centroid(w, left)
  local xb = rock.centroid(w, right)
  return yt - yb, xb - xa
end
local L0, B0 = gauges()
local _, y_top0 = box.top:position()
local t0 = w:time()

local csv = porelab.csv("ucs.csv", { "t", "platen_strain", "axial_strain", "lateral_strain", "stress", "bonds_broken" },
                        { "s", "", "", "", "Pa", "" })
local e_pl, e_ax, e_lat, sig, broken = {}, {}, {}, {}, {}
local peak = 0
local function sample(world)
  local L, B = gauges()
  local _, yt = box.top:position()
  local _, fy = box.top:force()
  local k = #sig + 1
  e_pl[k] = (y_top0 - yt) / height
  e_ax[k] = (L0 - L) / L0
  e_lat[k] = (B - B0) / B0
  sig[k] = fy / width
  broken[k] = intact1 - world:bond_count()
  peak = math.max(peak, sig[k])
  csv:row(world:time() - t0, e_pl[k], e_ax[k], e_lat[k], sig[k], broken[k])
end

local function moduli()
  -- the loading branch before the peak, 10-50 % of the peak stress
  local kpk = 1
  for k = 1, #sig do if sig[k] > sig[kpk] then kpk = k end end
  local x, y, l, key = {}, {}, {}, {}
  for k = 1, kpk do x[k], y[k], l[k], key[k] = e_ax[k], sig[k], e_lat[k], sig[k] / peak end
  local E = rock.slope(x, y, key, 0.1, 0.5)
  local nu = rock.slope(x, l, key, 0.1, 0.5)
  return E, nu, e_ax[kpk]
end

local t_end = t0 + P.strain_max * 1e-2 * height / P.speed
return {
  world = w,
  run = { t_end = t_end, every = math.max(1, math.floor((t_end - t0) / w:dt() / 200)) },
  render = {
    size = { 560, 900 },
    camera = { -0.25 * W, -0.1 * W, 1.25 * W, 2.35 * W },
    time_offset = -t0,
    colors = { granite = "#c9c2b6", steel = "#3a3a3a" },
    layers = { "bodies", "bonds", "time", "title", "overlay" },
    title = "Unconfined compression",
    overlay = function(world)
      local k = #sig
      return { { text = string.format("stress %.1f MPa   cracks: red tension, blue shear", k > 0 and sig[k] / 1e6 or 0),
                 at = { 280, 880 }, space = "pixel", anchor = "center" } }
    end,
  },
  on_frame = function(world) sample(world) end,
  on_finish = function(world)
    local E, nu, e_peak = moduli()
    print(string.format("ucs: E = %.4g GPa, nu = %.3f, UCS = %.4g MPa at axial strain %.3g %%, %d of %d bonds broken",
                        E / 1e9, nu, peak / 1e6, 100 * e_peak, broken[#broken], intact1))
    local sx, sy, px, py = {}, {}, {}, {}
    for k = 1, #sig do sx[k], sy[k], px[k] = 100 * e_ax[k], sig[k] / 1e6, 100 * e_pl[k] end
    porelab.chart {
      file = "ucs_curve.png", title = "Unconfined compression: stress against strain",
      xlabel = "axial strain (%)", ylabel = "axial stress (MPa)", legend = "top left",
      series = { { name = "strain inside the specimen", x = sx, y = sy },
                 { name = "platen strain", x = px, y = sy, style = "dashed", color = "#888888" } },
    }
  end,
  results = function(world)
    local E, nu = moduli()
    if E ~= E then E, nu = 0, 0 end -- too short a run to fit the moduli
    return { E_GPa = { value = E / 1e9, unit = "GPa" }, nu = nu,
             ucs_MPa = { value = peak / 1e6, unit = "MPa" },
             bonds = intact1, broken_before_loading = intact0 - intact1,
             discs = #s.discs }
  end,
}
