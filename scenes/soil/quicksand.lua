-- Description: Quicksand: rising seepage lifts a sand bed at the critical gradient; the block sinks.
-- Quicksand tank (docs/soil.md §5.1). Water is pushed up through a sand bed; the excess head
-- under the bed is raised step by step (plateaus). Below the critical gradient
-- i_c = (1 - n)(G_s - 1) the bed holds and carries a heavy block on its surface; at i ~ i_c
-- the seepage force equals the grains' buoyant weight, the effective stress vanishes, the bed
-- boils (expands, grains lift) and the block sinks. Pore pressure from grain motion is on
-- (FLUID_CONSOLIDATION), so moving grains also drag and push the water.
-- The scene prints, at each plateau, the measured gradient across the bed, the effective
-- stress at mid-depth, the bed's expansion and the block's settlement, and at the end the
-- measured onset gradient beside i_c. Log: quicksand.csv.
--   porelab run scenes/soil/quicksand.lua
local packing = require "porelab.packing"

local W, H = 0.10, 0.16               -- box width and water depth (mesh top), m
local T_SETTLE, T_STEP = 0.8, 0.35    -- settling time, duration of each plateau (s)
local LEVELS = { 0, 0.3, 0.6, 0.8, 0.9, 0.95, 1.0, 1.05, 1.1, 1.2, 1.3 } -- excess head / (i_c x bed height)
local T_END = T_SETTLE + #LEVELS * T_STEP

local w = porelab.world { gravity = { 0, -9.81 }, rayleigh_alpha = 20 }
local sand = w:material { name = "sand", density = 2650, kn = 2e5, friction = 0.3, restitution = 0.3 }
local wall = w:material { name = "wall", density = 2650, kn = 2e5, friction = 0.0, restitution = 0.3 }
local heavy = w:material { name = "block", density = 4500, kn = 2e5, friction = 0.3, restitution = 0.3 }
w:wall { from = { -0.01, 0 }, to = { W + 0.01, 0 }, material = wall }
w:wall { from = { 0, 0 }, to = { 0, 0.3 }, material = wall }
w:wall { from = { W, 0 }, to = { W, 0.3 }, material = wall }
packing.rain(w, { lo = { 0.001, 0.002 }, hi = { W - 0.001, 0.15 }, radii = { 0.0020, 0.0026 },
                  count = 230, material = sand, seed = 3 })
local block = w:rectangle { center = { 0.03, 0.25 }, width = 0.025, height = 0.018, material = heavy, fixed = true }

w:fluid_quad { corners = { { 0, 0 }, { W, 0 }, { W, H }, { 0, H } }, ndivx = 10, ndivy = 16 }
w:fluid_bc { from = { 0, 0 }, to = { W, 0 }, head = H }
w:fluid_bc { from = { 0, H }, to = { W, H }, head = 0 }
w:set_flag("FLUIDS_ON", 1)
w:set_flag("FIRST_STEP_STATIC", 1)
w:set_flag("FLUID_PERM", 1)             -- conductivity from the local void ratio
w:set_flag("FLUID_PERM_LOW", 1e-3)      -- m/s in the bed
w:set_flag("FLUID_PERM_HIGH", 1.0)      -- m/s in open water
w:set_flag("FLUID_STORAGE", 0)
w:set_flag("FLUID_CONSOLIDATION", 0)    -- on once the bed has settled (T_SETTLE - 0.3 s)
w:set_flag("FLUID_BULK_MODULUS", 2.2e9) -- water
w:set_flag("FLUID_SOLVE_TIMESTEPS", 2)

local function discs_top(xa, xb)
  local top, s, n = 0, 0, 0
  local list = {}
  for i = 1, w:body_count() do
    local b = w:body(i)
    if b:shape() == "disc" then
      local x, y = b:position()
      if x >= xa and x <= xb then list[#list + 1] = y + b:radius() end
    end
  end
  table.sort(list)
  -- mean of the 8 highest grains: the surface level
  for k = math.max(1, #list - 7), #list do s = s + list[k]; n = n + 1 end
  return n > 0 and s / n or 0, list[#list] or 0
end

local solid = 0
for i = 1, w:body_count() do
  local b = w:body(i)
  if b:shape() == "disc" then solid = solid + b:area() end
end

local log = porelab.csv("quicksand.csv", { "t", "level", "gradient", "i_c", "sigma_v_eff_mid", "u_excess_mid",
                                           "expansion_mm", "block_settlement_mm" },
                        { "s", "", "", "", "Pa", "Pa", "mm", "mm" })
local st = { level = 0, placed = false }
local function head_at(y)
  local s, n = 0, 0
  for k = 1, 20 do
    local p, h = w:fluid_pressure_at(W * (k - 0.5) / 20, y)
    if p then s = s + h; n = n + 1 end
  end
  return s / n
end

local function set_level(k)
  local dh = LEVELS[k] * st.i_c * st.Hb
  w:clear_fluid_bcs()
  w:fluid_bc { from = { 0, 0 }, to = { W, 0 }, head = H + dh }
  w:fluid_bc { from = { 0, H }, to = { W, H }, head = 0 }
end

return {
  world = w,
  run = { t_end = T_END, fps = 20 },
  render = {
    size = { 560, 800 }, camera = { -0.005, -0.005, W + 0.005, 0.17 },
    layers = "bodies,pressure,isolines,velocity,colorbar,scalebar,title,time,overlay",
    -- excess pore pressure above the outlet's hydrostatic state (head H at the water surface):
    -- zero in still open water; fixed range and arrow scale for the whole video (the largest
    -- excess head is 1.3 i_c times the bed height, about 0.9 kPa; the Darcy velocity reaches
    -- ~5 cm/s once the bed boils)
    fluid_field = "excess_pressure", excess_reference = H, fluid_range = { 0, 1000 },
    velocity_scale = 0.15,  -- m of arrow per m/s: 5 cm/s draws 7.5 mm
    isolines = 8,
    colors = { sand = "#d9b36c", block = "#5b5b66", wall = "#555555" },
    title = "Quicksand: upward seepage",
    overlay = function(world)
      if not st.i_c then return {} end
      -- above the water surface, clear of the walls
      return { { text = string.format("gradient i = %.2f (critical %.2f)", st.i or 0, st.i_c),
                 at = { W / 2, 0.1655 }, anchor = "center", size = 16,
                 color = (st.i or 0) >= st.i_c and "#b00000" or "#000000" } }
    end,
  },
  on_frame = function(world)
    local t = world:time()
    if not st.placed and t >= T_SETTLE - 0.3 then
      local surf, top = discs_top(0.0, W)
      local _, btop = discs_top(0.015, 0.045)
      -- from now on grains moving into / out of the pores change the pressure
      world:set_flag("FLUID_CONSOLIDATION", 1)
      block:set_motion("dynamic")
      block:set_state { position = { 0.03, btop + 0.0095 }, velocity = { 0, 0 } }
      world:soil_reset()
      st.placed = true
    end
    if st.placed and not st.i_c and t >= T_SETTLE then
      local surf = discs_top(0.06, W)
      st.Hb = surf
      st.n = 1 - solid / (W * surf)
      st.i_c = (1 - st.n) * (2.65 - 1)
      st.surf0 = surf
      st.by0 = select(2, block:position())
      st.k = 1
      st.t_next = t + T_STEP
      print(string.format("bed: height %.1f mm, areal porosity n = %.3f, G_s = 2.65: i_c = (1 - n)(G_s - 1) = %.3f",
                          1000 * surf, st.n, st.i_c))
    end
    if st.i_c then
      local surf = discs_top(0.06, W)
      st.i = (head_at(1e-6) - head_at(st.Hb)) / st.Hb
      local r = world:soil_region { lo = { 0.055, 0.3 * st.Hb }, hi = { W - 0.005, 0.7 * st.Hb } }
      local exp_mm = 1000 * (surf - st.surf0)
      local bs = 1000 * (st.by0 - select(2, block:position()))
      log:row(t, LEVELS[st.k], st.i, st.i_c, r.syy, r.u_excess, exp_mm, bs)
      -- onset (quick condition): the vertical effective stress at mid-depth in the free field
      -- has fallen below 10% of its value before the seepage (the grains no longer press on
      -- each other). The bed's expansion is not used: the soft DEM contacts rebound
      -- elastically as the effective stress falls, long before the bed boils.
      st.sv0 = st.sv0 or r.syy
      if not st.onset and r.syy < 0.1 * st.sv0 then
        st.onset = st.i
        print(string.format("t = %.2f s: quick condition (sigma'_v < 10%% of its initial value) at i = %.3f (i_c = %.3f, %+.1f%%)", t, st.i, st.i_c,
                            100 * (st.i - st.i_c) / st.i_c))
      end
      if t >= st.t_next - 1e-9 then
        print(string.format("plateau %.2f i_c: i = %.3f, sigma'_v(mid) = %6.1f Pa, bed expansion %5.1f mm, block settlement %5.1f mm",
                            LEVELS[st.k], st.i, r.syy, exp_mm, bs))
        if st.k < #LEVELS then
          st.k = st.k + 1
          set_level(st.k)
        end
        st.t_next = st.t_next + T_STEP
      end
    end
  end,
  on_finish = function(world)
    if st.i_c then
      print(string.format("measured onset gradient %s, critical gradient i_c = (1 - n)(G_s - 1) = %.3f",
                          st.onset and string.format("%.3f", st.onset) or "(not reached)", st.i_c))
    end
  end,
}
