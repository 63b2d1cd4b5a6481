-- Description: Simple shear of small grain samples, dry and saturated, steady and cyclic.
-- Constant-volume simple shear of the 20-disc samples of Tan (1990, §5.4-5.6,
-- Table 5.1), dry and saturated, monotonic and cyclic (docs/soil.md §5.4).
--
-- Six boxes of the same compressed sample, in two rows (top: monotonic shear to 12.5 %;
-- bottom: cyclic shear, +-2.5 % for 5 cycles), three columns:
--   DRY, SERVO      the top wall holds the vertical force (Tan 1990 §5.5.3, Figs. 5.22-5.23):
--                   the sample changes volume (a loose sample contracts);
--   DRY, CONST. VOL the top wall is held at its height: no volume change, so the vertical
--                   effective stress sigma'_v changes instead;
--   UNDRAINED       pore water (FLUID_CONSOLIDATION 1, K_f of water), sealed (no head line),
--                   the top wall holds the TOTAL vertical force (contacts + water), as in seed
--                   003 §5.5.4 (Figs. 5.31-5.32): the water cannot leave, so the volume stays
--                   (nearly) constant and the pore pressure u rises by what the skeleton drops.
-- The classic equivalence (Dyvik et al. 1987): the pore-pressure rise of the undrained test
-- equals the drop of sigma'_v of the dry constant-volume test. The scene prints both, at fixed
-- strains (monotonic) and cycle by cycle (cyclic), and writes them to CSV; the frames show the
-- contact forces, the pore pressure (back pressure + rise) and the curves.
--   porelab run scenes/soil/simple_shear.lua          (out/simple_shear/: frames, CSV)
-- Options (for tests): a global SIMPLE_SHEAR = { cycles =, coupling =, sample = "loose"/"dense",
-- rows = "both"/"monotonic"/"cyclic" } set before the scene is loaded (see tests/soil/).
local opt = rawget(_G, "SIMPLE_SHEAR") or {}
local CYCLES = opt.cycles or 5
local COUPLING = opt.coupling ~= false
local SAMPLE = opt.sample or "loose"
local ROWS = opt.rows or "both"

local mm = 1e-3
-- Tan 1990 Table 5.1 and §5.4.1, converted to SI per metre of depth (the thesis uses a 1 cm
-- thick slice: k_N = 1875e3 gF/cm per cm of depth = 1.8387e8 N/m per m of depth)
local KN = 1875e3 * 9.80665e-3 / 1e-2 * 100
local MU_DD, MU_DW = math.tan(math.rad(22)), math.tan(math.rad(10))
local ZETA = 0.05                                    -- 5 % of critical damping
local E_REST = math.exp(-math.pi * ZETA / math.sqrt(1 - ZETA * ZETA))
local RHO_S = 2000
local SIZES = { { 3, 1.5 * mm }, { 6, 1.0 * mm }, { 11, 0.5 * mm } }
local SIGMA_V = 892.8e3                              -- Pa: 8.1 kgF on 0.89 cm x 1 cm (§5.5.1)
local KF = 2.2e9                                     -- Pa, water
local D_SAND = 1e-3                                  -- m/s, conductivity inside the sample
local U_BACK = 2e6                                   -- Pa, back pressure of the undrained samples
local RATE = 5                                       -- shear strain rate, 1/s
local GAMMA_MONO, GAMMA_CYC = 0.125, 0.025
local DT = 1.0e-6                                    -- s (0.17 of the critical step of the 0.5 mm discs)
local W0, H0 = 10 * mm, 8 * mm                       -- box before compression (§5.4.1)
local T_WALL = 2.5 * mm                              -- wall slab thickness
local FPS = 1000
local VMAX_C = 0.01                                  -- m/s, wall speed limit during the compression

local w = porelab.world { gravity = { 0, 0 }, dt = DT }
local grain = w:material { name = "grain", density = RHO_S, kn = KN, ks = KN, friction = MU_DD, restitution = E_REST }
local wall = w:material { name = "wall", density = RHO_S, kn = KN, ks = KN, friction = MU_DW, restitution = E_REST }
-- the top wall is a polygon slab (it must displace water when it moves); a disc against a
-- polygon uses the area-based law (docs/contact-laws-polygons.md), which is softer at small
-- overlaps than the disc-wall spring: 15 x k_N gives about k_N at the working load
local lidm = w:material { name = "lid", density = RHO_S, kn = 15 * KN, ks = KN, friction = MU_DW, restitution = E_REST }
-- slabs behind the hinged side walls of the saturated boxes: they carry the volume of the wall
-- across the fluid mesh boundary and touch nothing (a stiffness of 1e-3 N/m)
local ghost = w:material { name = "ghost", density = RHO_S, kn = 1e-3, friction = 0, restitution = E_REST }
w:pair(grain, wall, { friction = MU_DW })

-- the same random sample in every box: random sequential addition, largest discs first
local rng = require("porelab.random").new(3)
local sample = {}
for _, s in ipairs(SIZES) do
  for _ = 1, s[1] do
    local r = s[2]
    for _ = 1, 20000 do
      local x, y = rng:uniform(r, W0 - r), rng:uniform(r, H0 - r)
      local ok = true
      for _, d in ipairs(sample) do
        if (x - d[1]) ^ 2 + (y - d[2]) ^ 2 < (r + d[3] + 0.02 * mm) ^ 2 then ok = false; break end
      end
      if ok then sample[#sample + 1] = { x, y, r }; break end
    end
  end
end
assert(#sample == 20, "simple_shear: could not place the 20 discs")

local COLS = { "servo", "cv", "und" }
local rows = {}
if ROWS ~= "cyclic" then rows[#rows + 1] = { kind = "monotonic", oy = 1.022 } end
if ROWS ~= "monotonic" then rows[#rows + 1] = { kind = "cyclic", oy = (#rows == 0) and 1.022 or 1.004 } end

local boxes = {}
for _, row in ipairs(rows) do
  row.box = {}
  for c, col in ipairs(COLS) do
    -- every coordinate lies in [1, 2) m, where doubles share one spacing: boxes that differ
    -- only by their origin then evolve bit for bit alike until the water makes them differ
    local ox, oy = 1.004 + (c - 1) * 16 * mm, row.oy
    local b = { col = col, row = row, ox = ox, oy = oy, grains = {} }
    b.bottom = w:wall { from = { ox - 4 * mm, oy }, to = { ox + W0 + 4 * mm, oy }, material = wall }
    b.left = w:wall { from = { ox, oy }, to = { ox, oy + 14 * mm }, material = wall }
    b.right = w:wall { from = { ox + W0, oy }, to = { ox + W0, oy + 14 * mm }, material = wall }
    -- a wide lid for the compression (replaced by one that fits between the walls)
    b.lid = w:rectangle { center = { ox + W0 / 2, oy + H0 + T_WALL / 2 }, width = W0 + 4 * mm, height = T_WALL,
                          material = lidm, fixed = true }
    for _, d in ipairs(sample) do
      b.grains[#b.grains + 1] = w:disc { center = { ox + d[1], oy + d[2] }, radius = d[3], material = grain }
    end
    row.box[col] = b
    boxes[#boxes + 1] = b
  end
end
local solid = 0
for _, d in ipairs(sample) do solid = solid + math.pi * d[3] ^ 2 end

-- 1. compression with servo walls to sigma_v on all sides (Tan 1990 §5.5.1 moves walls 2, 3, 4
--    inward); the dense sample (§5.6.1.1) is compressed without friction
if SAMPLE == "dense" then w:pair(grain, grain, { friction = 0 }); w:pair(grain, wall, { friction = 0 }); w:pair(grain, lidm, { friction = 0 }) end
local function geometry(b)
  local xl = b.left:position()
  local xr = b.right:position()
  local _, yl = b.lid:position()
  return xl, xr, yl - T_WALL / 2
end
local function set_servos(b)
  local xl, xr, yt = geometry(b)
  local Hs, Ws = yt - b.oy, xr - xl
  b.left:servo { direction = { 1, 0 }, force = SIGMA_V * Hs, gain = 0.5, vmax = VMAX_C }
  b.right:servo { direction = { -1, 0 }, force = SIGMA_V * Hs, gain = 0.5, vmax = VMAX_C }
  b.lid:servo { direction = { 0, -1 }, force = SIGMA_V * Ws, gain = 0.5, vmax = VMAX_C }
end
local ok_count, t_c = 0, 0
while w:time() < 0.15 do
  for _, b in ipairs(boxes) do set_servos(b) end
  w:step(200)
  local worst = 0
  for _, b in ipairs(boxes) do
    local xl, xr, yt = geometry(b)
    local fl = b.left:force()
    local _, fy = b.lid:force()
    worst = math.max(worst, math.abs(-fl / (SIGMA_V * (yt - b.oy)) - 1), math.abs(fy / (SIGMA_V * (xr - xl)) - 1))
  end
  ok_count = worst < 0.02 and ok_count + 1 or 0
  if ok_count >= 20 then break end
end
t_c = w:time()
local compress_ok = ok_count >= 20
if SAMPLE == "dense" then
  w:pair(grain, grain, { friction = MU_DD }); w:pair(grain, wall, { friction = MU_DW }); w:pair(grain, lidm, { friction = MU_DW })
end

-- 2. side walls fixed where they are; a lid that fits between them, held at F_A = sigma_v W by
--    its servo; relaxation (§5.5.1)
for _, b in ipairs(boxes) do
  local xl, xr, yt = geometry(b)
  b.left:set_motion("fixed"); b.right:set_motion("fixed")
  b.lid:set_state { position = { b.ox + W0 / 2, b.oy + 0.3 } }   -- parked out of sight
  b.lid:set_motion("fixed")
  b.W = xr - xl
  b.xl, b.xr = xl, xr
  b.FA = SIGMA_V * b.W
  b.lid = w:rectangle { center = { (xl + xr) / 2, yt + T_WALL / 2 }, width = b.W - 0.3 * mm, height = T_WALL,
                        material = lidm, fixed = true }
  b.lid:servo { direction = { 0, -1 }, force = b.FA, gain = 0.2, vmax = 0.02 }
end
w:run_until(w:time() + 0.01)

-- 3. the saturated boxes: ghost slabs behind the side walls reaching past the mesh, and a
--    fluid mesh over the sample ending inside the lid (sealed: no head line anywhere)
local A_MESH = 1.2 * mm                 -- mesh reaches this far into the side slabs
local H_EL = 1.2 * mm                   -- element size (cells of 4 triangles)
for _, b in ipairs(boxes) do
  local _, _, yt = geometry(b)
  b.H = yt - b.oy
  if b.col == "und" then
    b.gl = w:rectangle { center = { b.xl - T_WALL / 2, b.oy + 2 * mm }, width = T_WALL, height = 2 * mm + 2 * b.H,
                         material = ghost, fixed = true }
    b.gr = w:rectangle { center = { b.xr + T_WALL / 2, b.oy + 2 * mm }, width = T_WALL, height = 2 * mm + 2 * b.H,
                         material = ghost, fixed = true }
    -- slabs from 0.5 mm below the floor to well above the lid
    b.gl:set_state { position = { b.xl - T_WALL / 2, b.oy - 0.5 * mm + (2 * mm + 2 * b.H) / 2 } }
    b.gr:set_state { position = { b.xr + T_WALL / 2, b.oy - 0.5 * mm + (2 * mm + 2 * b.H) / 2 } }
    local x0, x1, y1 = b.xl - A_MESH, b.xr + A_MESH, yt + 1.0 * mm
    b.mesh = { x0, b.oy, x1, y1 }
    w:fluid_quad { corners = { { x0, b.oy }, { x1, b.oy }, { x1, y1 }, { x0, y1 } },
                   ndivx = math.floor((x1 - x0) / H_EL + 0.5), ndivy = math.floor((y1 - b.oy) / H_EL + 0.5) }
  end
end
w:set_flag("FLUIDS_ON", 1)
w:set_flag("FIRST_STEP_STATIC", 0)   -- sealed: no head line, start from u = 0
w:set_flag("FLUID_PERM", 0)
w:set_flag("FLUID_PERM_HIGH", D_SAND)
w:set_flag("FLUID_STORAGE", COUPLING and 0 or 1e-4)  -- grains: the skeleton supplies the compliance; uncoupled: a transient field without sources
w:set_flag("FLUID_BULK_MODULUS", KF)
w:set_flag("FLUID_CONSOLIDATION", COUPLING and 1 or 0)
w:set_flag("FLUID_SOLVE_TIMESTEPS", 4)
w:set_flag("FLUID_FORCE_REUSE", 1)
-- all lids held where they are while the water is added, so that the dry and the saturated
-- boxes start the shear from the same state
for _, b in ipairs(boxes) do b.lid:set_velocity(0, 0) end
w:run_until(w:time() + 0.001)
-- back pressure (as in laboratory undrained tests): the water starts at U_BACK so that it never
-- goes below zero, where porelab's fluid stops pushing (partial submersion, fluid.md)
w:fluid_set_pressure_head(U_BACK / (1000 * 9.80665))
w:run_until(w:time() + 0.001)
w:soil_reset()
-- the vertical force each lid holds from now on: the dry servo lid its contact force, the
-- undrained lid the total (contacts + water); the constant-volume lid stays at its height
for _, b in ipairs(boxes) do
  local _, fy = b.lid:force()
  b.FA = fy
  if b.col == "und" then
    local _, fw = w:fluid_body_force(b.lid)
    b.FA = fy + fw
  end
end

-- 4. shear: hinged side walls follow the lid; the lid's horizontal motion is a ramp
--    (monotonic) or a triangle wave (cyclic, strain-controlled)
local T0 = w:time()
local function lid_x_target(b, t)
  local s = (t - T0) * RATE       -- strain travelled
  if b.row.kind == "monotonic" then return math.min(s, GAMMA_MONO) * b.H end
  local P = 4 * GAMMA_CYC          -- strain travelled per cycle
  if s >= CYCLES * P then return 0 end
  local q = (s % P) / GAMMA_CYC    -- 0..4 quarter cycles
  local g
  if q < 1 then g = q elseif q < 3 then g = 2 - q else g = q - 4 end
  return g * GAMMA_CYC * b.H
end
local function drive(b, vx)
  if b.col == "cv" then
    b.lid:set_velocity(vx, 0)
  else
    b.lid:servo { direction = { 0, -1 }, force = b.FA, gain = b.col == "und" and 0.05 or 0.2, vmax = 0.02, drive = { vx, 0 }, fluid = b.col == "und" }
  end
end
for _, b in ipairs(boxes) do
  b.x0 = b.lid:position()
  local _, yl = b.lid:position()
  b.y0 = yl
  drive(b, 0)
  b.left:hinge { pivot = { b.xl, b.oy }, follow = b.lid, height = b.H }
  b.right:hinge { pivot = { b.xr, b.oy }, follow = b.lid, height = b.H }
  if b.gl then
    b.gl:hinge { pivot = { b.xl, b.oy }, follow = b.lid, height = b.H }
    b.gr:hinge { pivot = { b.xr, b.oy }, follow = b.lid, height = b.H }
  end
end

local function fluid_on_walls(b)
  -- mean pore pressure along the bottom and under the lid (0.1 mm inside), and the water's
  -- vertical force on the lid per unit width
  if not b.mesh then return 0, 0, 0 end
  local xl = b.xl
  local _, yl = b.lid:position()
  local ylb = yl - T_WALL / 2
  local sb, st, n = 0, 0, 0
  for k = 1, 9 do
    local x = xl + b.W * (k - 0.5) / 9
    local pb = w:fluid_pressure_at(x, b.oy + 0.1 * mm)
    local pt = w:fluid_pressure_at(x + (ylb - b.oy) * (b.lid:position() - b.x0) / b.H, ylb - 0.1 * mm)
    if pb and pt then sb = sb + pb; st = st + pt; n = n + 1 end
  end
  local _, fy = w:fluid_body_force(b.lid)
  return n > 0 and st / n or 0, n > 0 and sb / n or 0, fy / b.W
end

local function measure(b)
  local x, y = b.lid:position()
  -- shear forces S3 (top) and S1 (bottom) of Tan 1990 Fig. 5.22: the grains' horizontal force
  -- on the lid and on the floor, positive along the shear; fy > 0 pushes the lid up (the lid is
  -- kinematic: the force is the contacts', the water is measured separately)
  local fx, fy = b.lid:force()
  local bx = b.bottom:force()
  local ut, ub, ul = fluid_on_walls(b)
  -- the sample's own mean shear stress from its contacts (sigma = (1/A) sum f l, w:stress), the
  -- region's mean rescaled to the sample area W H; with the hinged walls pushing the sample, the
  -- wall shear forces S1, S3 are not the whole story (the side walls carry horizontal force too)
  local lo, hi = { b.xl - 2 * mm, b.oy }, { b.xr + 2 * mm, b.oy + b.H }
  local st = w:stress { lo = lo, hi = hi }
  local scale = (hi[1] - lo[1]) * (hi[2] - lo[2]) / (b.W * b.H)
  return { gamma = (x - b.x0) / b.H, tau_top = fx / b.W, tau_bot = bx / b.W, tau_int = -st.xy * scale,
           sv = fy / b.W, dh = (y - b.y0) / b.H, u_top = ut, u_bot = ub, u_lid = ul }
end

for _, row in ipairs(rows) do
  row.csv = porelab.csv("simple_shear_" .. row.kind .. ".csv",
    { "t", "gamma", "tau_servo", "tau_cv", "tau_und", "sv_servo", "sv_cv", "sv_und", "dh_servo", "dh_und",
      "u_top", "u_bottom", "u_lid", "drop_sv_cv", "tau_int_servo", "tau_int_cv", "tau_int_und" },
    { "s", "", "Pa", "Pa", "Pa", "Pa", "Pa", "Pa", "", "", "Pa", "Pa", "Pa", "Pa", "Pa", "Pa", "Pa" })
  row.hist = {}
  row.sv0 = {}
  for _, col in ipairs(COLS) do row.sv0[col] = measure(row.box[col]).sv end
  row.u0 = measure(row.box.und).u_lid
end

local function record(world)
  local t = world:time()
  for _, row in ipairs(rows) do
    local m = {}
    for _, col in ipairs(COLS) do m[col] = measure(row.box[col]) end
    local tau = function(col) return 0.5 * (m[col].tau_top + m[col].tau_bot) end
    local h = { t = t - T0, gamma = m.cv.gamma, tau_servo = tau("servo"), tau_cv = tau("cv"), tau_und = tau("und"),
                sv_servo = m.servo.sv, sv_cv = m.cv.sv, sv_und = m.und.sv, dh_servo = m.servo.dh, dh_und = m.und.dh,
                u_top = m.und.u_top, u_bot = m.und.u_bot, u_lid = m.und.u_lid,
                du = m.und.u_lid - row.u0, drop = row.sv0.cv - m.cv.sv,
                ti_servo = m.servo.tau_int, ti_cv = m.cv.tau_int, ti_und = m.und.tau_int }
    row.hist[#row.hist + 1] = h
    row.csv:row(h.t, h.gamma, h.tau_servo, h.tau_cv, h.tau_und, h.sv_servo, h.sv_cv, h.sv_und, h.dh_servo,
                h.dh_und, h.u_top, h.u_bot, h.u_lid, h.drop, h.ti_servo, h.ti_cv, h.ti_und)
  end
end

-- The lids are steered from this hook: at each call every lid gets the velocity that lands it on
-- its schedule at the next call, and the stresses are sampled. A quarter of a cycle lasts
-- GAMMA_CYC / RATE = 5 ms and each checkpoint averages +-0.5 ms, so the hook must be called at
-- least every 1 / FPS = 1 ms. Called less often (porelab run --fps 30, 100 or 200 was tried),
-- a lid kept its velocity for the whole interval and overshot the schedule many times over:
-- the grains were crushed into the walls and the run stopped at the overlap guard (50 % of a
-- radius). Such a run is refused here, at the second call, with the reason.
local t_last
local function on_frame(world)
  local t = world:time()
  local dt_f = 1 / FPS
  if t_last and t > t_last then
    dt_f = t - t_last
    if dt_f > (1 + 1e-6) / FPS then
      error(string.format("simple_shear: the hook is called every %.3g ms (--fps or --every); the lids are steered "
        .. "and the stresses sampled from it, which needs a call at least every %.3g ms: --fps must be in [%d, 10000] "
        .. "frames/s, or --every in [1, %d] steps of %g s (or neither: the scene runs at %d frames/s)",
        1e3 * dt_f, 1e3 / FPS, FPS, math.floor(1 / (FPS * DT) + 0.5), DT, FPS))
    end
    if math.abs(dt_f * FPS - 1) < 1e-6 then dt_f = 1 / FPS end   -- the scene's own rate, free of round-off
  end
  t_last = t
  -- lid velocity that lands each lid on its schedule at the next call
  local tn = t + dt_f
  for _, b in ipairs(boxes) do
    local x = b.lid:position()
    drive(b, (b.x0 + lid_x_target(b, tn) - x) / (tn - t))
  end
  record(world)
end

-- ------------------------------------------------------------------ summary
local RESULT = { rows = {} }
SIMPLE_SHEAR_RESULT = RESULT
local function mean_window(hist, t0, t1, key)
  local s, n = 0, 0
  for _, h in ipairs(hist) do
    if h.t >= t0 and h.t <= t1 then s = s + h[key]; n = n + 1 end
  end
  return n > 0 and s / n or 0 / 0
end
local function on_finish(world)
  local n_por = 1 - solid / (boxes[1].W * boxes[1].H)
  print(string.format("simple_shear: %s sample, 20 discs compressed to %.0f kPa in %.3f s: box %.2f x %.2f mm, areal porosity %.3f, void ratio e = %.3f (Tan 1990, loose sample: 8.9 x 6.9 mm, e = 0.261)",
    SAMPLE, SIGMA_V / 1e3, t_c, boxes[1].W / mm, boxes[1].H / mm, n_por, n_por / (1 - n_por)))
  if not compress_ok then print("  note: the compression stopped at its time limit before the wall forces were within 2 %") end
  print(string.format("  undrained boxes: K_f = %.3g Pa, conductivity %.3g m/s, sealed; coupling %s", KF, D_SAND, COUPLING and "on" or "OFF"))
  for _, row in ipairs(rows) do
    local sv0 = row.sv0.cv
    local R = { kind = row.kind, sv0 = sv0, points = {} }
    RESULT.rows[#RESULT.rows + 1] = R
    print(string.format("  %s: sigma'_v0 = %.1f kPa (dry CV box); undrained box: total vertical force held %.1f N/m = %.1f kPa x W, back pressure %.0f kPa",
      row.kind, sv0 / 1e3, row.box.und.FA, row.box.und.FA / row.box.und.W / 1e3, U_BACK / 1e3))
    print("    where                 du undrained   drop of sigma'_v (dry CV)   difference / sigma'_v0   tau CV / und (kPa)       dh servo")
    local win = 0.1 * GAMMA_CYC / RATE   -- averaging window: +-10 % of a quarter cycle
    local marks = {}
    if row.kind == "monotonic" then
      for _, g in ipairs { 0.02, 0.05, 0.08, 0.1, 0.125 } do marks[#marks + 1] = { string.format("gamma = %5.1f %%", 100 * g), g / RATE } end
    else
      for k = 1, CYCLES do
        marks[#marks + 1] = { string.format("cycle %d peak +", k), ((k - 1) * 4 + 1) * GAMMA_CYC / RATE }
        marks[#marks + 1] = { string.format("cycle %d end   ", k), (k * 4) * GAMMA_CYC / RATE }
      end
    end
    for _, mk in ipairs(marks) do
      local tq = mk[2]
      local du = mean_window(row.hist, tq - win, tq + win, "du")
      local drop = mean_window(row.hist, tq - win, tq + win, "drop")
      local tc = mean_window(row.hist, tq - win, tq + win, "tau_cv")
      local tu = mean_window(row.hist, tq - win, tq + win, "tau_und")
      local dh = mean_window(row.hist, tq - win, tq + win, "dh_servo")
      if du == du then
        R.points[#R.points + 1] = { label = mk[1], du = du, drop = drop }
        print(string.format("    %-20s %9.1f kPa   %9.1f kPa                 %+7.3f                %7.1f / %7.1f    %+6.2f %%",
          mk[1], du / 1e3, drop / 1e3, (du - drop) / sv0, tc / 1e3, tu / 1e3, 100 * dh))
      end
    end
    -- over the whole record: rms of (du - drop) and the correlation
    local s2, n, sd, su = 0, 0, 0, 0
    for _, h in ipairs(row.hist) do s2 = s2 + (h.du - h.drop) ^ 2; sd = sd + h.drop; su = su + h.du; n = n + 1 end
    R.rms = math.sqrt(s2 / n)
    R.mean_drop, R.mean_du = sd / n, su / n
    print(string.format("    whole record: mean du %.1f kPa, mean drop %.1f kPa, rms(du - drop) = %.1f kPa = %.3f sigma'_v0",
      R.mean_du / 1e3, R.mean_drop / 1e3, R.rms / 1e3, R.rms / sv0))
  end
end

-- ------------------------------------------------------------------ drawing
local W_PX, H_PX = 1720, 860
local CAM = { 0.999, 0.996, 1.099, 0.996 + 0.1 * H_PX / W_PX }
-- round ticks (steps 1, 2, 2.5, 5 x 10^k), about five per axis, zero printed as 0
local function nice_ticks(lo, hi)
  local raw = (hi - lo) / 5
  local p = 10 ^ math.floor(math.log(raw, 10))
  local step = p
  for _, m in ipairs { 1, 2, 2.5, 5, 10 } do
    if m * p <= raw * 1.25 then step = m * p end
  end
  local out = {}
  local v = math.ceil(lo / step - 1e-9) * step
  while v <= hi + 1e-9 * step do
    out[#out + 1] = math.abs(v) < 1e-9 * step and 0 or v
    v = v + step
  end
  return out
end

-- text of the charts: 0.75 of the frame's base font (min(W, H) / 38 px), the smallest size
-- porelab draws a scene's text at, so that the layout below holds
local FS = math.floor(0.75 * math.min(W_PX, H_PX) / 38 + 0.5)
local function panel(items, x0, y0, pw, ph, title, xlab, ylab, xr, yr, series)
  local function px(x, y)
    return { x0 + (x - xr[1]) / (xr[2] - xr[1]) * pw, y0 + ph - (y - yr[1]) / (yr[2] - yr[1]) * ph }
  end
  items[#items + 1] = { polygon = { { x0, y0 }, { x0 + pw, y0 }, { x0 + pw, y0 + ph }, { x0, y0 + ph } }, color = "#444444", width = 1, fill = "#ffffff", space = "pixel" }
  local z = px(xr[1], 0)
  if yr[1] < 0 and yr[2] > 0 then items[#items + 1] = { line = { { x0, z[2] }, { x0 + pw, z[2] } }, color = "#bbbbbb", width = 1, space = "pixel" } end
  local zx = px(0, yr[1])
  if xr[1] < 0 and xr[2] > 0 then items[#items + 1] = { line = { { zx[1], y0 }, { zx[1], y0 + ph } }, color = "#bbbbbb", width = 1, space = "pixel" } end
  items[#items + 1] = { text = title, at = { x0 + pw / 2, y0 - 0.8 * FS }, anchor = "center", size = FS, space = "pixel" }
  items[#items + 1] = { text = xlab, at = { x0 + pw / 2, y0 + ph + 4 + 2.0 * FS }, anchor = "center", size = FS, space = "pixel" }
  items[#items + 1] = { text = ylab, at = { x0 + 6, y0 + 0.9 * FS }, anchor = "left", size = FS, space = "pixel" }
  for _, v in ipairs(nice_ticks(xr[1], xr[2])) do
    local q = px(v, yr[1])
    items[#items + 1] = { line = { { q[1], y0 + ph }, { q[1], y0 + ph + 4 } }, color = "#444444", width = 1, space = "pixel" }
    items[#items + 1] = { text = string.format("%g", v), at = { q[1], y0 + ph + 4 + 0.75 * FS }, anchor = "center", size = FS, space = "pixel" }
  end
  for _, v in ipairs(nice_ticks(yr[1], yr[2])) do
    local q = px(xr[1], v)
    items[#items + 1] = { line = { { x0 - 4, q[2] }, { x0, q[2] } }, color = "#444444", width = 1, space = "pixel" }
    items[#items + 1] = { text = string.format("%g", v), at = { x0 - 6, q[2] }, anchor = "right", size = FS, space = "pixel" }
  end
  -- legend top left, under the axis label (the curves keep to the lower part of each chart)
  local ly = y0 + 2.3 * FS
  for _, s in ipairs(series) do
    if #s.pts >= 2 then
      local line = {}
      local step = math.max(1, math.floor(#s.pts / 1500))
      for i = 1, #s.pts, step do
        local p = s.pts[i]
        local q = px(math.max(xr[1], math.min(xr[2], p[1])), math.max(yr[1], math.min(yr[2], p[2])))
        line[#line + 1] = q
      end
      items[#items + 1] = { line = line, color = s.color, width = s.width or 2, space = "pixel" }
    end
    items[#items + 1] = { line = { { x0 + 8, ly }, { x0 + 8 + 1.6 * FS, ly } }, color = s.color, width = 3, space = "pixel" }
    items[#items + 1] = { text = s.name, at = { x0 + 12 + 1.6 * FS, ly }, size = FS, space = "pixel" }
    ly = ly + 1.3 * FS
  end
end

local function overlay(world)
  local items = {}
  for _, row in ipairs(rows) do
    local b0 = row.box.servo
    if row.kind == "monotonic" then
      items[#items + 1] = { text = "monotonic shear", at = { 0.9995, row.oy + 15.5 * mm }, size = 16 }
    else -- two short lines, clear of the upper row's box names and of this row's walls
      items[#items + 1] = { text = "cyclic", at = { 0.9995, row.oy + 15.3 * mm }, size = 16 }
      items[#items + 1] = { text = string.format("\u{00B1}%.1f %%", 100 * GAMMA_CYC), at = { 0.9995, row.oy + 14.0 * mm },
                            size = 16 }
    end
    for _, col in ipairs(COLS) do
      local b = row.box[col]
      local name = ({ servo = "dry, servo (drained)", cv = "dry, constant volume", und = "saturated, undrained" })[col]
      items[#items + 1] = { text = name, at = { b.ox + W0 / 2, row.oy - 1.6 * mm }, anchor = "center", size = 13 }
    end
    local h = row.hist[#row.hist]
    if h then
      local b = row.box.und
      items[#items + 1] = { text = string.format("\u{0394}u = %.0f kPa", (h.du) / 1e3), at = { b.ox + W0 / 2, row.oy + b.H + 4.2 * mm }, anchor = "center", size = 13, color = "#1f4e9c" }
      items[#items + 1] = { text = string.format("\u{03C3}\u{2032}\u{1D65} drop = %.0f kPa", h.drop / 1e3), at = { row.box.cv.ox + W0 / 2, row.oy + b.H + 4.2 * mm }, anchor = "center", size = 13, color = "#9b2226" }
      items[#items + 1] = { text = string.format("height %+.2f %%", 100 * h.dh_servo), at = { b0.ox + W0 / 2, row.oy + b.H + 4.2 * mm }, anchor = "center", size = 13 }
    end
  end
  -- charts: per row, shear stress and (du, drop of sigma'_v) against shear strain
  local x0, pw, ph = 770, 260, 300
  for r, row in ipairs(rows) do
    local y0 = 70 + (r - 1) * 400
    local tauS, tauC, tauU, du, drop = {}, {}, {}, {}, {}
    for _, h in ipairs(row.hist) do
      local g = 100 * h.gamma
      tauS[#tauS + 1] = { g, h.tau_servo / 1e3 }
      tauC[#tauC + 1] = { g, h.tau_cv / 1e3 }
      tauU[#tauU + 1] = { g, h.tau_und / 1e3 }
      local xc = row.kind == "monotonic" and g or h.t * RATE / (4 * GAMMA_CYC)   -- cycles
      du[#du + 1] = { xc, h.du / 1e3 }
      drop[#drop + 1] = { xc, h.drop / 1e3 }
    end
    local gx = row.kind == "monotonic" and { 0, 100 * GAMMA_MONO } or { -100 * GAMMA_CYC, 100 * GAMMA_CYC }
    panel(items, x0, y0, pw, ph, "shear stress on the walls", "shear strain \u{03B3} (%)", "\u{03C4} (kPa)", gx, { -150, 150 },
      { { name = "dry servo", color = "#777777", pts = tauS }, { name = "dry const. vol.", color = "#9b2226", pts = tauC },
        { name = "undrained", color = "#1f4e9c", pts = tauU } })
    local cyc = row.kind ~= "monotonic"
    panel(items, x0 + pw + 90, y0, pw, ph, "\u{0394}u and drop of \u{03C3}\u{2032}\u{1D65}", cyc and "cycles" or "shear strain \u{03B3} (%)", "kPa",
      cyc and { 0, CYCLES } or gx, cyc and { -200, 400 } or { -300, 900 },
      { { name = "\u{0394}u undrained", color = "#1f4e9c", pts = du }, { name = "\u{03C3}\u{2032}\u{1D65} drop (const. vol.)", color = "#9b2226", pts = drop, width = 1.5 } })
  end
  return items
end

local T_END = (ROWS == "monotonic") and GAMMA_MONO / RATE or CYCLES * 4 * GAMMA_CYC / RATE
if ROWS == "both" then T_END = math.max(GAMMA_MONO / RATE, CYCLES * 4 * GAMMA_CYC / RATE) end
return {
  world = w,
  run = { t_end = T0 + T_END + 0.5 / FPS, fps = FPS },
  render = {
    size = { W_PX, H_PX }, camera = CAM,
    layers = "bodies,forces,pressure,colorbar,scalebar,title,time,overlay",
    colors = { grain = "#c9b48a", wall = "#2f2f2f", lid = "#2f2f2f", ghost = "#6d6d6d" },
    hide = { "ghost" },  -- the slabs that confine the fluid mesh are numerical, not apparatus
    force_color = "#9b2226", force_max_width = 5,
    -- the colour is the change of pore pressure from the back pressure (excess pore pressure,
    -- signed: diverging map, symmetric about zero); the reference head is the back pressure's
    -- at the middle height of the two rows (elevation differences there are under 300 Pa)
    fluid_field = "excess_pressure", excess_reference = U_BACK / (1000 * 9.80665) + 1.02,
    fluid_range = { -900e3, 900e3 },
    title = "Simple shear of 20-disc samples (Tan 1990): dry drained, dry constant volume, undrained",
    overlay = overlay,
  },
  on_frame = on_frame,
  on_finish = on_finish,
}
