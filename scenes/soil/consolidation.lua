-- Terzaghi consolidation of a column of grains (docs/soil.md §5.2).
-- A saturated column of discs in a box, drained at the top only. A rigid piston is set on the
-- column at T_SEAT and loaded with a constant force at T_LOAD. The mesh ends at the column top, where a head
-- line holds the pore pressure at 0: the piston's underside is a drained boundary (a porous
-- stone), and as the piston settles it simply enters that boundary. At first the water
-- carries the load (excess pore pressure ~ applied stress, the grains barely move); the water
-- then escapes upwards, the pressure falls from the top down and the column settles. The
-- scene logs settlement and pore pressure at three depths (consolidation.csv) and compares the
-- degree of consolidation U = settlement / final settlement with Terzaghi's series U(T_v),
-- T_v = c_v t / H^2, c_v = k M / (rho_f g), where M is the column's constrained modulus
-- measured from its own final settlement (printed at the end).
--   porelab run scenes/soil/consolidation.lua
local packing = require "porelab.packing"

local W = 0.04                       -- column width, m
local HMESH = 0.074                  -- mesh top = drained boundary just under the column top, m
local T_SEAT, T_LOAD, T_END = 0.8, 1.1, 2.6 -- s
local P = 3000                       -- applied vertical stress, Pa (force P W per m)
local D_SAND = 1e-3                  -- hydraulic conductivity of the packed column, m/s
local KF = 1e6                       -- fluid bulk modulus, Pa (>~ 10 x the column's modulus)

local w = porelab.world { gravity = { 0, -9.81 }, rayleigh_alpha = 20, dt_safety = 0.05, local_damping = 0.3 }
local sand = w:material { name = "sand", density = 2650, kn = 2e5, friction = 0.3, restitution = 0.2 }
local wall = w:material { name = "wall", density = 2650, kn = 2e5, friction = 0.0, restitution = 0.2 }
w:wall { from = { -0.01, 0 }, to = { W + 0.01, 0 }, material = wall }
w:wall { from = { 0, 0 }, to = { 0, 0.3 }, material = wall }
w:wall { from = { W, 0 }, to = { W, 0.3 }, material = wall }
packing.rain(w, { lo = { 0.001, 0.002 }, hi = { W - 0.001, 0.25 }, radii = { 0.0020, 0.0026 },
                  count = 130, material = sand, seed = 5 })
-- the piston waits above the column (fixed until T_LOAD)
local pmat = w:material { name = "piston", density = 1000, kn = 2e5, friction = 0.0, restitution = 0.2 }
local piston = w:rectangle { center = { W / 2, 0.2 }, width = W - 0.0006, height = 0.005, material = pmat, fixed = true }

w:fluid_quad { corners = { { 0, 0 }, { W, 0 }, { W, HMESH }, { 0, HMESH } }, ndivx = 4, ndivy = 12 }
w:fluid_bc { from = { 0, HMESH }, to = { W, HMESH }, head = 0 }   -- drained at the top only
w:set_flag("FLUIDS_ON", 1)
w:set_flag("FIRST_STEP_STATIC", 1)
w:set_flag("FLUID_PERM", 1)
w:set_flag("FLUID_PERM_LOW", 0.05)          -- fast settling first; D_SAND from T_LOAD
w:set_flag("FLUID_PERM_HIGH", 1.0)
w:set_flag("FLUID_STORAGE", 0)
w:set_flag("FLUID_CONSOLIDATION", 0)        -- on at T_LOAD
w:set_flag("FLUID_BULK_MODULUS", KF)
w:set_flag("FLUID_SOLVE_TIMESTEPS", 1)

local function column_top()
  local top, n, s = 0, 0, 0
  for i = 1, w:body_count() do
    local b = w:body(i)
    if b:shape() == "disc" then top = math.max(top, select(2, b:position()) + b:radius()) end
  end
  return top
end

local log = porelab.csv("consolidation.csv", { "t", "settlement", "u_top", "u_mid", "u_bottom", "U_measured" })
local seated, loaded, H0, y0, s_hist = false, false, nil, nil, {}
local gauges = {}

local function U_series(Tv)
  local s = 0
  for m = 0, 100 do
    local M = (2 * m + 1) * math.pi / 2
    s = s + 2 / (M * M) * math.exp(-M * M * Tv)
  end
  return 1 - s
end

local function u_series(Z, Tv) -- Z = depth / H below the drained top
  local s = 0
  for m = 0, 200 do
    local M = (2 * m + 1) * math.pi / 2
    s = s + 2 / M * math.sin(M * Z) * math.exp(-M * M * Tv)
  end
  return s
end

return {
  world = w,
  run = { t_end = T_END, fps = 30 },
  render = {
    size = { 420, 800 }, camera = { -0.02, -0.005, W + 0.02, 0.1 },
    layers = "bodies,pressure,isolines,colorbar,title,time,overlay",
    fluid_field = "excess_pressure", fluid_range = { 0, P },
    title = "Terzaghi consolidation",
    overlay = function(world)
      local items = {}
      if y0 then
        local _, py = piston:position()
        items[#items + 1] = { text = string.format("settlement %.2f mm", 1000 * (y0 - py)), at = { 10, 60 },
                              space = "pixel", size = 15 }
      end
      return items
    end,
  },
  on_frame = function(world)
    local t = world:time()
    if not seated and t >= T_SEAT then
      -- the piston is set on the column first, under its own weight only (it seats into the
      -- surface roughness while the column is still freely drained)
      H0 = column_top()   -- highest grain: the piston is set just above it
      piston:set_motion("dynamic")
      piston:set_state { position = { W / 2, H0 + 0.0028 }, velocity = { 0, 0 } }
      seated = true
    end
    if not loaded and t >= T_LOAD then
      -- constant total load P W (N per m), the piston's weight included; from now on the
      -- water must drain through the column (conductivity D_SAND) and the pore pressure
      -- responds to the skeleton's compression
      piston:set_load(0, -(P * W - piston:mass() * 9.81))
      world:set_flag("FLUID_PERM_LOW", D_SAND)
      world:set_flag("FLUID_CONSOLIDATION", 1)
      world:soil_reset()
      y0 = select(2, piston:position())
      H0 = HMESH           -- drainage path: floor to the drained boundary
      gauges = { H0 * 0.85, H0 * 0.5, H0 * 0.1 }
      loaded = true
    end
    if loaded then
      local _, py = piston:position()
      local u = {}
      for k, y in ipairs(gauges) do
        local r = world:soil_region { lo = { 0.002, y - 0.004 }, hi = { W - 0.002, y + 0.004 } }
        u[k] = r.u_excess
      end
      s_hist[#s_hist + 1] = { t - T_LOAD, y0 - py, u[2], u[3] }
      log:row(t, y0 - py, u[1], u[2], u[3], 0)
    end
  end,
  on_finish = function(world)
    if not loaded or #s_hist < 10 then return end
    -- final settlement: mean of the last 5% of the record (U -> 1 by the end of the run)
    local n, sf = 0, 0
    for i = math.floor(#s_hist * 0.95), #s_hist do sf = sf + s_hist[i][2]; n = n + 1 end
    sf = sf / n
    -- Terzaghi: no immediate settlement (water and grains incompressible, B ~ 1); the
    -- settlement one frame after loading is printed to show it is small
    local s0 = 0
    -- constrained modulus from the column's own final settlement under the load
    local M = P * H0 / (sf - s0)
    local cv = D_SAND * M / (1000 * 9.81)
    print(string.format("column H = %.4f m, final settlement %.3f mm (%.3f mm one frame after loading): M = %.4g Pa, c_v = %.4g m^2/s",
                        H0, 1000 * sf, 1000 * s_hist[2][2], M, cv))
    for _, Tv in ipairs { 0.1, 0.2, 0.5 } do
      local tq = Tv * H0 * H0 / cv
      local U, um, ub
      for i = 2, #s_hist do
        if s_hist[i][1] >= tq then
          -- linear interpolation between frames
          local a, b = s_hist[i - 1], s_hist[i]
          local f = (tq - a[1]) / (b[1] - a[1])
          U = ((a[2] + f * (b[2] - a[2])) - s0) / (sf - s0)
          um = (a[3] + f * (b[3] - a[3])) / P
          ub = (a[4] + f * (b[4] - a[4])) / P
          break
        end
      end
      if U then
        print(string.format("T_v = %.1f (t = %.3f s after loading): U measured %.3f, Terzaghi %.3f (%+.1f%%); "
                            .. "u/P at mid-depth %.3f (series %.3f), near the floor %.3f (series %.3f)", Tv, tq, U,
                            U_series(Tv), 100 * (U - U_series(Tv)) / U_series(Tv), um, u_series(0.5, Tv), ub,
                            u_series(0.9, Tv)))
      else
        print(string.format("T_v = %.1f: beyond the run", Tv))
      end
    end
  end,
}
