-- Description: Simple shear of a saturated 20-disc sample with the pore water resolved by boundary elements.
-- Constant-volume simple shear of the 20-disc sample of Tan (1990, §5.4-5.6, Table 5.1), the
-- pore fluid resolved between the grains by boundary elements (docs/stokes.md), beside the same
-- sample sheared dry at constant volume in the same world.
--   SATURATED  the fluid fills the left box only (w:stokes{ container = its four walls }); the
--              top wall holds the vertical force F_A it carried when the fluid was added
--              (load_wall, load_contacts: the fluid gets F_A minus what the contacts carry,
--              Tan's rule of §5.3.2). The fluid is incompressible and sealed, so the box keeps
--              its volume and the pore pressure rises by what the skeleton drops;
--   DRY, CV    the right box: the same sample, the top wall at its height, no fluid.
-- Both are compressed by servo walls to 892.8 kPa (the seed's 8.1 kgF on 0.89 cm), then
-- sheared at 5 1/s to 12.5 % with the side walls hinged at the floor. The criterion
-- (Dyvik et al. 1987): the pore-pressure rise of the sealed saturated sample equals the drop
-- of vertical effective stress of the dry constant-volume one. The same sample sheared with
-- the Darcy/consolidation fluid is scenes/soil/simple_shear.lua (docs/soil.md §5.4); its
-- table (docs/data/soil_simple_shear_monotonic.csv) is drawn on this scene's chart.
-- Frames: excess pore pressure and fluid velocity in the saturated box, contact forces.
-- Output: simple_shear_bem.csv, simple_shear_bem.png (pore pressure and drop of effective
-- stress against shear strain).
--   porelab run scenes/stokes/simple_shear.lua --out out/simple_shear_bem
local mm = 1e-3
local KN = 1875e3 * 9.80665e-3 / 1e-2 * 100          -- Table 5.1 per m of depth (docs/soil.md §5.4)
local MU_DD, MU_DW = math.tan(math.rad(22)), math.tan(math.rad(10))
local ZETA = 0.05
local E_REST = math.exp(-math.pi * ZETA / math.sqrt(1 - ZETA * ZETA))
local RHO_S = 2000
local SIZES = { { 3, 1.5 * mm }, { 6, 1.0 * mm }, { 11, 0.5 * mm } }
local SIGMA_V = 892.8e3                              -- Pa
-- Option (for tests): a global SIMPLE_SHEAR_BEM = { gamma_end = } set before the scene is loaded
-- ends the shear early (tests/stokes/simple_shear_short.lua); the result is left in the global
-- SIMPLE_SHEAR_BEM_RESULT = { sv0 =, rows = { {g =, ut =, ub =, drop =}, ... } }.
local opt = rawget(_G, "SIMPLE_SHEAR_BEM") or {}
local RATE, GAMMA_END = 5, opt.gamma_end or 0.125    -- 1/s, shear strain
if type(GAMMA_END) ~= "number" or not (GAMMA_END > 0 and GAMMA_END <= 0.125) then
  error(string.format("simple_shear: SIMPLE_SHEAR_BEM.gamma_end must be a shear strain in (0, 0.125] (got %s)",
    tostring(opt.gamma_end)), 0)
end
local DT = 1.0e-6
local W0, H0 = 10 * mm, 8 * mm
local GAP = 0.1 * mm                                 -- artificial gap: the largest disc carries the whole lid, 41 um into it
local FPS = 2000
-- fluid solves every SOLVE_EVERY grain steps: the drag's explicit limit 2 m/K of the smallest discs
-- falls to 1.0e-4 s at 7 % strain as the grains close up (solve_every = 100 was refused there)
local SOLVE_EVERY = 10

local w = porelab.world { gravity = { 0, 0 }, dt = DT, energy_surge_ratio = 1e12 }
local grain = w:material { name = "grain", density = RHO_S, kn = KN, ks = KN, friction = MU_DD, restitution = E_REST }
local wallm = w:material { name = "wall", density = RHO_S, kn = KN, ks = KN, friction = MU_DW, restitution = E_REST }
w:pair(grain, wallm, { friction = MU_DW })

-- the sample of scenes/soil/simple_shear.lua: random sequential addition, largest discs first
local rng = require("porelab.random").new(3)
local sample = {}
for _, s in ipairs(SIZES) do
  for _ = 1, s[1] do
    for _ = 1, 20000 do
      local x, y = rng:uniform(s[2], W0 - s[2]), rng:uniform(s[2], H0 - s[2])
      local ok = true
      for _, d in ipairs(sample) do
        if (x - d[1]) ^ 2 + (y - d[2]) ^ 2 < (s[2] + d[3] + 0.02 * mm) ^ 2 then ok = false; break end
      end
      if ok then sample[#sample + 1] = { x, y, s[2] }; break end
    end
  end
end
assert(#sample == 20, "simple_shear: could not place the 20 discs")

local boxes = {}
for c, name in ipairs { "sat", "dry" } do
  local ox, oy = 1.004 + (c - 1) * 16 * mm, 1.004
  local b = { name = name, ox = ox, oy = oy }
  b.bottom = w:wall { from = { ox - 4 * mm, oy }, to = { ox + W0 + 4 * mm, oy }, material = wallm }
  b.right = w:wall { from = { ox + W0, oy - 1 * mm }, to = { ox + W0, oy + 12 * mm }, material = wallm }
  b.top = w:wall { from = { ox + W0 + 4 * mm, oy + H0 }, to = { ox - 4 * mm, oy + H0 }, material = wallm }
  b.left = w:wall { from = { ox, oy + 12 * mm }, to = { ox, oy - 1 * mm }, material = wallm }
  for _, d in ipairs(sample) do w:disc { center = { ox + d[1], oy + d[2] }, radius = d[3], material = grain } end
  boxes[c] = b
end
local sat, dry = boxes[1], boxes[2]

-- 1. compression by servo walls to sigma_v on all sides (Tan 1990 eqs. 5.11-5.12)
local function size(b)
  local xl, xr = b.left:position(), b.right:position()
  local _, yt = b.top:position()
  return xl, xr, yt
end
local ok = 0
while w:time() < 0.2 do
  for _, b in ipairs(boxes) do
    local xl, xr, yt = size(b)
    b.left:servo { direction = { 1, 0 }, force = SIGMA_V * (yt - b.oy), gain = 0.5, vmax = 0.01 }
    b.right:servo { direction = { -1, 0 }, force = SIGMA_V * (yt - b.oy), gain = 0.5, vmax = 0.01 }
    b.top:servo { direction = { 0, -1 }, force = SIGMA_V * (xr - xl), gain = 0.5, vmax = 0.01 }
  end
  w:step(200)
  local worst = 0
  for _, b in ipairs(boxes) do
    local xl, xr, yt = size(b)
    local _, fy = b.top:force()
    worst = math.max(worst, math.abs(-b.left:force() / (SIGMA_V * (yt - b.oy)) - 1), math.abs(fy / (SIGMA_V * (xr - xl)) - 1))
  end
  ok = worst < 0.02 and ok + 1 or 0
  if ok >= 20 then break end
end
for _, b in ipairs(boxes) do
  b.left:set_velocity(0, 0); b.right:set_velocity(0, 0); b.top:set_velocity(0, 0)
end
w:run_until(w:time() + 0.005)
for _, b in ipairs(boxes) do
  local xl, xr, yt = size(b)
  b.xl, b.xr, b.W, b.H = xl, xr, xr - xl, yt - b.oy
  local _, fy = b.top:force()
  b.FA = fy
end
print(string.format("simple_shear (resolved fluid): compressed in %.3f s to %.2f x %.2f mm; sigma'_v %.1f / %.1f kPa (target %.1f)",
  w:time(), 1e3 * sat.W, 1e3 * sat.H, sat.FA / sat.W / 1e3, dry.FA / dry.W / 1e3, SIGMA_V / 1e3))

-- 2. the pore water in the left box: it holds the top wall's force (the unbalanced part)
w:stokes { viscosity = 1e-3, density = 1000, gap = GAP, disc_elements = 16, element_length = 0.3 * mm,
           field_grid = 50, solve_every = SOLVE_EVERY, container = { sat.bottom, sat.right, sat.top, sat.left },
           load_wall = sat.top, load_force = sat.FA, load_contacts = 1 }

-- 3. shear: the top walls slide at RATE H, the side walls turn about their feet
local T0 = w:time()
for _, b in ipairs(boxes) do
  b.top:set_velocity(RATE * b.H, 0)
  b.left:hinge { pivot = { b.xl, b.oy }, follow = b.top, height = b.H }
  b.right:hinge { pivot = { b.xr, b.oy }, follow = b.top, height = b.H }
end

local csv = porelab.csv("simple_shear_bem.csv",
  { "t", "gamma", "u_top", "u_bottom", "sv_sat", "sv_dry", "drop_sv_dry" },
  { "s", "", "Pa", "Pa", "Pa", "Pa", "Pa" })
local hist = {}
local function record(world)
  local t = world:time() - T0
  if t < 0 then return end
  local _, fs = sat.top:force()
  local _, fd = dry.top:force()
  local h = { t = t, g = RATE * t, ut = world:stokes_wall_pressure(sat.top), ub = world:stokes_wall_pressure(sat.bottom),
              ss = fs / sat.W, sd = fd / dry.W }
  h.drop = dry.FA / dry.W - h.sd
  hist[#hist + 1] = h
  csv:row(t, h.g, h.ut, h.ub, h.ss, h.sd, h.drop)
end

local function overlay()
  local h = hist[#hist]
  local items = {
    { text = "saturated (resolved pore water)", at = { sat.ox + W0 / 2, sat.oy - 1.4 * mm }, anchor = "center", size = 14 },
    { text = "dry, constant volume", at = { dry.ox + W0 / 2, dry.oy - 1.4 * mm }, anchor = "center", size = 14 },
  }
  if h then
    -- two short lines above each box, clear of its leaning side walls
    items[#items + 1] = { text = string.format("\u{03B3} = %.1f %%", 100 * h.g),
      at = { sat.ox + W0 / 2, sat.oy + 10.8 * mm }, anchor = "center", size = 13 }
    items[#items + 1] = { text = string.format("pore pressure %.0f kPa, \u{03C3}\u{2032}\u{1D65} %.0f kPa", h.ut / 1e3, h.ss / 1e3),
      at = { sat.ox + W0 / 2, sat.oy + 10.1 * mm }, anchor = "center", size = 13 }
    items[#items + 1] = { text = string.format("\u{03C3}\u{2032}\u{1D65} %.0f kPa (drop %.0f kPa)", h.sd / 1e3, h.drop / 1e3),
      at = { dry.ox + W0 / 2, dry.oy + 10.1 * mm }, anchor = "center", size = 13 }
  end
  return items
end

-- the Darcy/consolidation version's record (scenes/soil/simple_shear.lua run into the same output
-- folder first): its undrained pore-pressure rise against its shear strain
local function darcy_table()
  local f = io.open(porelab.out_dir .. "/simple_shear_monotonic.csv", "r")
  if not f then return nil end
  local g, du, u0 = {}, {}, nil
  for line in f:lines() do
    local v = {}
    for x in line:gmatch("[^,]+") do v[#v + 1] = tonumber(x) end
    if #v >= 13 and v[2] then   -- t, gamma, ..., u_lid (column 13)
      u0 = u0 or v[13]
      g[#g + 1] = 100 * v[2]; du[#du + 1] = (v[13] - u0) / 1e3
    end
  end
  f:close()
  if #g < 2 then return nil end
  return g, du
end

return {
  world = w,
  run = { t_end = T0 + GAMMA_END / RATE + 0.5 / FPS, fps = FPS },
  render = {
    size = { 1200, 640 }, camera = { 1.0015, 1.0005, 1.0315, 1.0165 },
    layers = "bodies,forces,pressure,velocity,colorbar,scalebar,title,time,overlay",
    fluid_field = "pressure", fluid_range = { 0, 800e3 }, velocity_scale = 0.02, time_offset = -T0,
    colors = { grain = "#c9b48a", wall = "#2f2f2f" }, force_color = "#9b2226", force_max_width = 4,
    title = "Simple shear of 20 discs: saturated (pore water resolved) and dry at constant volume",
    overlay = overlay,
  },
  on_frame = record,
  on_finish = function(world)
    record(world)
    local G, UT, UB, DR = {}, {}, {}, {}
    for _, h in ipairs(hist) do
      G[#G + 1] = 100 * h.g; UT[#UT + 1] = h.ut / 1e3; UB[#UB + 1] = h.ub / 1e3; DR[#DR + 1] = h.drop / 1e3
    end
    local sv0 = sat.FA / sat.W
    local function at(gq, key)
      local best
      for _, h in ipairs(hist) do
        if not best or math.abs(h.g - gq) < math.abs(best.g - gq) then best = h end
      end
      return best and best[key] or 0 / 0
    end
    print("simple_shear (resolved fluid):   gamma   pore pressure top / bottom (kPa)   drop of sigma'_v dry CV (kPa)   difference / sigma'_v0")
    local rows = {}
    for _, gq in ipairs { 0.01, 0.02, 0.03, 0.05, 0.08, 0.10, 0.125 } do
      if gq > GAMMA_END + 1e-9 then break end
      local ut, ub, dr = at(gq, "ut"), at(gq, "ub"), at(gq, "drop")
      rows[#rows + 1] = { g = gq, ut = ut, ub = ub, drop = dr }
      print(string.format("                                  %5.1f %%   %8.1f / %8.1f                 %8.1f                     %+7.3f",
        100 * gq, ut / 1e3, ub / 1e3, dr / 1e3, (ut - dr) / sv0))
    end
    SIMPLE_SHEAR_BEM_RESULT = { sv0 = sv0, rows = rows }
    local series = {
      { name = "pore pressure on the top wall (resolved fluid)", x = G, y = UT, color = "#1f4e9c" },
      { name = "pore pressure on the bottom wall (resolved fluid)", x = G, y = UB, color = "#2a7f3f", style = "dashed" },
      { name = "drop of vertical effective stress, dry constant volume", x = G, y = DR, color = "#9b2226" },
    }
    local dg, ddu = darcy_table()
    if dg then
      series[#series + 1] = { name = "pore pressure rise, Darcy / consolidation fluid (same sample)", x = dg, y = ddu,
                              color = "#222222", style = "dashed" }
    end
    porelab.chart { file = "simple_shear_bem.png", title = "Undrained simple shear of a 20-disc sample",
                    xlabel = "shear strain (%)", ylabel = "stress (kPa)", series = series, legend = "top left" }
  end,
}
