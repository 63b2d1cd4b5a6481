-- A layer of grains glued to an elastic block, then pulled off (docs/solids.md, "Cohesion,
-- heat and wear"): three rows of bonded discs rest on the top face of a block of FIC triangles
-- fixed at its base; every disc of the bottom row is tied to the block's edge by a brittle
-- grain-edge bond (w:solid_bond), weaker than the bonds between the discs (w:bond_touching).
-- The top row is lifted slowly (0.5 mm/s, 2 µm) until the glue has failed, then at 0.5 m/s
-- so that the layer is seen to come away. The pull force, the block's base reaction and the
-- glue bonds still intact go to out/glued_layer/pull_off.csv, the slow pull to pull_off.png;
-- the frames show the block's von Mises stress and the layer.
--   porelab run scenes/solids/glued_layer.lua --out out/glued_layer
local packing = require "porelab.packing"

local speed = 5e-4                       -- m/s, the top row (slow: the layer's and the block's
                                         -- wave periods are about 2e-5 and 4e-5 s)
local t_ramp = 2e-4                      -- s, the speed is raised linearly over this time
local lift = 2e-6                        -- m, the top row's travel in the slow pull
local v_fast, t_fast_ramp, t_fast = 0.5, 2e-3, 6e-3   -- then: raised to 0.5 m/s over 2 ms, 6 ms in all
local kn_glue, rn_glue = 2e6, 2.0        -- N/m per m and N/m: one glue bond opens 1 µm at break
local w = porelab.world { gravity = { 0, 0 }, dt_safety = 0.3, local_damping = 0.7 }
local grain = w:material { name = "grain", density = 2500, kn = 2e7, friction = 0.5 }
w:bond_law { a = grain, b = grain, law = "brittle", kn = 2e7, kt = 1e7, rn = 50, rt = 50 }

-- the block [0, 60] x [0, 15] mm, fixed at its base
w:solid { young = 2e8, poisson = 0.3, density = 1500, formulation = "fic_semi_implicit",
          contact_stiffness = 2e7, friction = 0.5, damping = 2000 }
w:solid_rectangle { x0 = 0, y0 = 0, x1 = 0.06, y1 = 0.015, nx = 60, ny = 15 }
local base = w:solid_fix { box = { -1, -1e-9, 1, 1e-9 } }

-- three hexagonal rows of 1 mm discs on the top face, bonded to each other and glued to it
local discs = packing.lattice(w, { lo = { 0.005, 0.015 }, hi = { 0.055, 0.0205 }, radius = 0.001,
                                   material = grain })
local n_grain_bonds = w:bond_touching(1e-6)
local n_glue = w:solid_bond { law = "brittle", kn = kn_glue, kt = kn_glue / 2, rn = rn_glue, rt = rn_glue, gap = 1e-6 }
local y_top = -math.huge
for _, d in ipairs(discs) do y_top = math.max(y_top, select(2, d:position())) end
local top = {}
for _, d in ipairs(discs) do
  local _, y = d:position()
  if y > y_top - 1e-6 then top[#top + 1] = d end
end
print(string.format("glued layer: %d discs (%d pulled), %d disc-disc bonds, %d glue bonds (R_n = %g N/m each)",
                    #discs, #top, n_grain_bonds, n_glue, rn_glue))
local t_slow = lift / speed + t_ramp / 2 -- end of the slow pull, s
local function drive(t)
  local v = speed * math.min(1, t / t_ramp)
  if t > t_slow then v = speed + (v_fast - speed) * math.min(1, (t - t_slow) / t_fast_ramp) end
  for _, d in ipairs(top) do d:set_velocity(0, v) end
end
local y_top0 = y_top
drive(0)

local csv = porelab.csv("pull_off.csv", { "t", "lift", "pull", "base_reaction", "glue_intact", "grain_bonds_intact" },
                        { "s", "m", "N/m", "N/m", "", "" })
local lifts, pulls, intact = {}, {}, {}
local peak, peak_lift = 0, 0
local function sample(world)
  local f = 0
  for _, d in ipairs(top) do f = f + select(2, d:force()) end
  local pull = -f                        -- the layer holds the pulled row back
  local _, ry = world:solid_reaction(base)
  local _, glue = world:solid_bonds()
  csv:row(world:time(), select(2, top[1]:position()) - y_top0, pull, ry, glue, (world:bond_count()))
  if world:time() > t_slow then return end  -- the chart shows the slow pull
  local k = #lifts + 1
  lifts[k], pulls[k], intact[k] = select(2, top[1]:position()) - y_top0, pull, glue
  if pull > peak then peak, peak_lift = pull, lifts[k] end
end

local t_end = t_slow + t_fast
return {
  world = w,
  run = { t_end = t_end, every = math.max(1, math.floor(t_slow / w:dt() / 100)) },
  render = {
    size = { 1200, 560 }, camera = { 0.0, 0.004, 0.06, 0.030 },
    layers = "bodies,bonds,pressure,colorbar,scalebar,title,time",
    fluid_field = "mises", fluid_range = { 0, 1500 },
    colors = { grain = "#d9b36c" },
    title = "Grain layer pulled off an elastic block: von Mises stress in the block",
  },
  on_frame = function(world)
    sample(world)
    drive(world:time())
  end,
  on_finish = function(world)
    print(string.format("glued layer: peak pull %.4g N/m at a lift of %.3g µm (%d glue bonds x R_n = %.4g N/m); "
                        .. "%d of %d glue bonds intact at the end",
                        peak, 1e6 * peak_lift, n_glue, n_glue * rn_glue, intact[#intact], n_glue))
    local x, y, z = {}, {}, {}
    for k = 1, #lifts do x[k], y[k], z[k] = 1e6 * lifts[k], pulls[k], n_glue * rn_glue * intact[k] / n_glue end
    porelab.chart {
      file = "pull_off.png", title = "Pull-off of a glued grain layer",
      xlabel = "lift of the top row (µm)", ylabel = "force per unit thickness (N/m)",
      series = { { name = "pull force", x = x, y = y },
                 { name = "intact glue bonds x R_n", x = x, y = z, style = "dashed", color = "#444444" } },
    }
  end,
  results = function(world)
    return { peak_pull = { value = peak, unit = "N/m" }, glue_bonds = n_glue,
             glue_strength = { value = n_glue * rn_glue, unit = "N/m" } }
  end,
}
