-- Quicksand: a sand bed under rising upward seepage (native fluid API; docs/fluid.md §6).
-- 160 grains settle in a water-filled box (frictionless side walls); from t = 0.5 s the
-- pressure head under the bed rises steadily. When the hydraulic gradient across the bed
-- reaches i_c = (1 - n)(G_s - 1) the seepage force carries the grains' buoyant weight: the
-- bed loosens and lifts ("quick" condition). The head line and the measured gradient go to
-- out/fluid_quicksand/gradient.csv: t, excess head (m), gradient across the bed.
--   porelab run scenes/fluid_quicksand.lua
local packing = require "porelab.packing"

local W, H = 0.08, 0.20               -- box width and water depth, m
local w = porelab.world { gravity = { 0, -9.81 }, rayleigh_alpha = 20 }
local sand = w:material { name = "sand", density = 2650, kn = 2e5, friction = 0.3, restitution = 0.3 }
local wall = w:material { name = "wall", density = 2650, kn = 2e5, friction = 0.0, restitution = 0.3 }
w:wall { from = { -0.01, 0 }, to = { W + 0.01, 0 }, material = wall }
w:wall { from = { 0, 0 }, to = { 0, 0.3 }, material = wall }
w:wall { from = { W, 0 }, to = { W, 0.3 }, material = wall }
packing.rain(w, { lo = { 0.001, 0.002 }, hi = { W - 0.001, 0.12 }, radii = { 0.0020, 0.0026 },
                  count = 160, material = sand, seed = 7 })

-- water: one quad over the box, 8 x 20 cells; pressure head H at the floor, 0 at the surface
w:fluid_quad { corners = { { 0, 0 }, { W, 0 }, { W, H }, { 0, H } }, ndivx = 8, ndivy = 20 }
w:fluid_bc { from = { 0, 0 }, to = { W, 0 }, head = H }
w:fluid_bc { from = { 0, H }, to = { W, H }, head = 0 }
w:set_flag("FLUIDS_ON", 1)
w:set_flag("FIRST_STEP_STATIC", 1)
w:set_flag("FLUID_PERM", 1)            -- conductivity from the local void ratio
w:set_flag("FLUID_PERM_LOW", 1e-3)     -- m/s in the bed
w:set_flag("FLUID_PERM_HIGH", 1.0)     -- m/s in open water
w:set_flag("FLUID_STORAGE", 0)         -- quasi-static seepage
w:set_flag("FLUID_SOLVE_TIMESTEPS", 10)
w:set_flag("FLUID_DENSITY", 1000)

local log = porelab.csv("gradient.csv", { "t", "excess_head", "gradient" }, { "s", "m", "" })
local rate = 0.04                       -- m of excess head per second after t = 0.5 s
local last = 0

local function bed_top(world)
  local top = 0
  for i = 1, world:body_count() do
    local b = world:body(i)
    if b:shape() == "disc" then
      local _, y = b:position()
      top = math.max(top, y + b:radius())
    end
  end
  return top
end

return {
  world = w,
  run = { t_end = 2.5, fps = 20 },
  render = { size = { 480, 720 }, camera = { -0.01, -0.01, W + 0.01, 0.22 },
             layers = "bodies,pressure,velocity,colorbar,title,time",
             title = "Quicksand (upward seepage)" },
  on_frame = function(world)
    local t = world:time()
    local dh = t > 0.5 and rate * (t - 0.5) or 0
    if dh ~= last then
      world:clear_fluid_bcs()
      world:fluid_bc { from = { 0, 0 }, to = { W, 0 }, head = H + dh }
      world:fluid_bc { from = { 0, H }, to = { W, H }, head = 0 }
      last = dh
    end
    local top = bed_top(world)
    local _, h0 = world:fluid_pressure_at(W / 2, 1e-6)
    local _, h1 = world:fluid_pressure_at(W / 2, top)
    log:row(t, dh, (h0 and h1) and (h0 - h1) / top or 0)
  end,
}
