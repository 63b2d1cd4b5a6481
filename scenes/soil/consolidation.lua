-- Description: Terzaghi consolidation: loaded grain columns squeeze their pore water out.
-- Terzaghi consolidation of columns of grains (docs/soil.md §5.2).
-- NCOL saturated columns of discs side by side (the same recipe, different random packings),
-- each in its own box under its own rigid piston, drained at the bottom only (a porous stone
-- under the column: a head line on the floor); the piston seals the top (it reaches through the
-- top of the column's fluid mesh, so the solid it pushes into the mesh displaces water, as in
-- the Skempton test). The experiment is an oedometer load increment:
--   1. the grains settle in water (drained, coupling off);
--   2. the piston is set on the column with a pre-load P0 and the column settles under it,
--      still drained: the piston seats, the loose surface layer closes and the effective
--      stress becomes P0 + gamma' z, nearly uniform (P0 >> gamma' H), so the skeleton's modulus
--      is nearly the same at every depth;
--   3. at T_LOAD the load increment DP is applied, the pore pressure is coupled to the grain
--      motion (FLUID_CONSOLIDATION 1) and the column gets the conductivity of a fine sand.
-- The water first carries the increment (B = 1 / (1 + n M / K_f), close to 1), then drains
-- through the floor; the isochrones move up from the floor. For each column: M = DP H / (final
-- settlement of the increment), c_v = D M B / (rho_f g) (the fluid's compressibility
-- included), and the degree of consolidation U is measured from the instantaneous undrained
-- settlement s0 = (1 - B) s_final, as in Terzaghi's theory. A column of ~130 grains is one
-- sample of a heterogeneous skeleton (its layers' stiffness varies by tens of per cent), so a
-- single column's U scatters about Terzaghi's by up to ~13%; the scene compares the mean U of
-- the NCOL columns with the series (docs/soil.md §5.2) and asserts it within 5% at T_v = 0.2
-- and 0.5 and 10% at 0.1 (ctest soil_consolidation). Log: consolidation.csv.
--   porelab run scenes/soil/consolidation.lua
local packing = require "porelab.packing"

-- tests may set the global CONSOLIDATION = { columns = N, tol = x } before running this file
-- (tests/soil/consolidation_short.lua: one column, the single-column tolerance)
local opt = rawget(_G, "CONSOLIDATION") or {}
local NCOL = opt.columns or 4        -- columns (independent packings)
local W, GAP = 0.04, 0.015           -- column width and gap between columns, m
local HMESH = 0.080                  -- top of the fluid mesh: inside the piston at all times, m
local T_SEAT, T_LOAD, T_END = 0.8, 1.3, 2.5 -- s
local P0 = 3000                      -- pre-load (drained), Pa (force P0 W per m)
local DP = 3000                      -- load increment studied, Pa
local D_SAND = 1e-3                  -- hydraulic conductivity of the columns, m/s
local KF = 1e6                       -- fluid bulk modulus, Pa (~10 x the columns' modulus)
local RHO_F, G = 1000, 9.81
-- tolerance on the mean U of the columns: 5% at T_v = 0.2 and 0.5; 10% at 0.1, where
-- four measured ensembles gave +1.4 to +5.3% (an early-time bias of ~+4% not explained, plus
-- ~4% standard error of a four-column mean: docs/soil.md §5.2)
local TOL = opt.tol and { [0.1] = opt.tol, [0.2] = opt.tol, [0.5] = opt.tol } or { [0.1] = 0.10, [0.2] = 0.05, [0.5] = 0.05 }
local PH = 0.03                      -- piston height: it always reaches through the mesh top, m

local w = porelab.world { gravity = { 0, -G }, rayleigh_alpha = 20, dt_safety = 0.05, local_damping = 0.3 }
local sand = w:material { name = "sand", density = 2650, kn = 2e5, friction = 0.3, restitution = 0.2 }
local wall = w:material { name = "wall", density = 2650, kn = 2e5, friction = 0.0, restitution = 0.2 }
-- floor and piston are rough (grain friction): on a frictionless floor or cap the end layer of
-- grains slides apart under the load and is softer than the rest of the column
local stone = w:material { name = "stone", density = 2650, kn = 2e5, friction = 0.3, restitution = 0.2 }
local pmat = w:material { name = "piston", density = 1000, kn = 2e5, friction = 0.3, restitution = 0.2 }

local cols = {}
for c = 1, NCOL do
  local x0 = (c - 1) * (W + GAP)
  local col = { x0 = x0, hist = {} }
  w:wall { from = { x0 - 0.005, 0 }, to = { x0 + W + 0.005, 0 }, material = stone }
  w:wall { from = { x0, 0 }, to = { x0, 0.3 }, material = wall }
  w:wall { from = { x0 + W, 0 }, to = { x0 + W, 0.3 }, material = wall }
  col.first = w:body_count() + 1
  packing.rain(w, { lo = { x0 + 0.001, 0.002 }, hi = { x0 + W - 0.001, 0.25 }, radii = { 0.0020, 0.0026 },
                    count = 130, material = sand, seed = 4 + c })
  col.last = w:body_count()
  -- the piston waits above the column (fixed until T_SEAT). An oedometer's piston is guided:
  -- it moves only vertically under the load and never turns (guide = {0, 1}: the guide takes
  -- the side force and the moment). Free, it tilted 3-5 degrees on the uneven column and a
  -- corner entered a side wall by up to 0.8 mm.
  col.piston = w:rectangle { center = { x0 + W / 2, 0.2 }, width = W - 0.0006, height = PH, material = pmat,
                             fixed = true, guide = { 0, 1 } }
  w:fluid_quad { corners = { { x0, 0 }, { x0 + W, 0 }, { x0 + W, HMESH }, { x0, HMESH } }, ndivx = 4, ndivy = 13 }
  -- drained at the floor only: pressure head HMESH there (still water up to the mesh top)
  w:fluid_bc { from = { x0, 0 }, to = { x0 + W, 0 }, head = HMESH }
  cols[c] = col
end
w:set_flag("FLUIDS_ON", 1)
w:set_flag("FIRST_STEP_STATIC", 1)
-- one conductivity for the whole column, as Terzaghi assumes: a Kozeny-Carman value per element
-- (FLUID_PERM 1) varies with the porosity of elements one or two grains wide (wall voids,
-- local loose spots) and makes fast channels (docs/soil.md §5.2)
w:set_flag("FLUID_PERM", 0)
w:set_flag("FLUID_PERM_HIGH", 0.05)         -- drained phases; D_SAND from T_LOAD
w:set_flag("FLUID_STORAGE", 0)
w:set_flag("FLUID_CONSOLIDATION", 0)        -- on at T_LOAD
w:set_flag("FLUID_BULK_MODULUS", KF)
w:set_flag("FLUID_SOLVE_TIMESTEPS", 1)

local function column_top(col)
  local top = 0
  for i = col.first, col.last do
    local b = w:body(i)
    top = math.max(top, select(2, b:position()) + b:radius())
  end
  return top
end

local function solid_area(col)
  local a = 0
  for i = col.first, col.last do a = a + math.pi * w:body(i):radius() ^ 2 end
  return a
end

local function U_series(Tv)
  local s = 0
  for m = 0, 100 do
    local M = (2 * m + 1) * math.pi / 2
    s = s + 2 / (M * M) * math.exp(-M * M * Tv)
  end
  return 1 - s
end

local function u_series(Z, Tv) -- Z = distance from the drained boundary / H
  local s = 0
  for m = 0, 200 do
    local M = (2 * m + 1) * math.pi / 2
    s = s + 2 / M * math.sin(M * Z) * math.exp(-M * M * Tv)
  end
  return s
end

local log = porelab.csv("consolidation.csv", { "t", "column", "settlement", "u_top", "u_mid", "u_bottom", "u_column" },
                        { "s", "", "m", "Pa", "Pa", "Pa", "Pa" })
local seated, loaded = false, false

-- analysis of one column: M, B, c_v, s0 and U, u at the requested T_v (linear interpolation
-- between frames)
local function analyse(col)
  local h = col.hist
  local n, sf = 0, 0
  -- final settlement of the increment: mean of the last 10% of the record (T_v > 2 there)
  for i = math.floor(#h * 0.9), #h do sf = sf + h[i][2]; n = n + 1 end
  sf = sf / n
  local r = { H = col.H, sf = sf }
  r.M = DP * col.H / sf
  r.n = 1 - solid_area(col) / (W * col.H)
  r.B = 1 / (1 + r.n * r.M / KF)
  -- Terzaghi with a compressible pore fluid: c_v = k / (gamma_w (1/M + n/K_f)) = D M B /
  -- (rho_f g); the water first carries B DP, so the instantaneous (undrained) settlement is
  -- s0 = (1 - B) s_final and U = (s - s0) / (s_final - s0)
  r.cv = D_SAND * r.M * r.B / (RHO_F * G)
  r.s0 = (1 - r.B) * sf
  r.Tv_end = r.cv * h[#h][1] / (col.H * col.H)
  r.at = {}
  for _, Tv in ipairs { 0.1, 0.2, 0.5 } do
    local tq = Tv * col.H * col.H / r.cv
    for i = 2, #h do
      if h[i][1] >= tq then
        local a, b = h[i - 1], h[i]
        local f = (tq - a[1]) / (b[1] - a[1])
        local function lerp(k) return a[k] + f * (b[k] - a[k]) end
        r.at[Tv] = { U = (lerp(2) - r.s0) / (sf - r.s0), ut = lerp(3) / (r.B * DP), um = lerp(4) / (r.B * DP),
                     Up = 1 - lerp(5) / (r.B * DP), t = tq }
        break
      end
    end
  end
  -- uniformity of the skeleton: vertical strain of the increment in four bands (mean
  -- displacement of the grains near each band edge); a uniform M gives equal strains
  local nb, disp, cnt = 4, {}, {}
  for k = 0, nb do disp[k], cnt[k] = 0, 0 end
  for i = col.first, col.last do
    local y = col.y_load[i]
    local z = y / col.H * nb
    local k = math.floor(z + 0.5)
    if k >= 1 and k < nb and math.abs(z - k) < 0.35 then
      disp[k] = disp[k] + (y - select(2, w:body(i):position()))
      cnt[k] = cnt[k] + 1
    end
  end
  disp[0], cnt[0] = 0, 1
  disp[nb], cnt[nb] = h[#h][2], 1
  r.bands = {}
  for k = 1, nb do
    r.bands[k] = (disp[k] / math.max(cnt[k], 1) - disp[k - 1] / math.max(cnt[k - 1], 1)) / (col.H / nb) /
                 (h[#h][2] / col.H)
  end
  return r
end

return {
  world = w,
  run = { t_end = T_END, fps = 120 },  -- the frames are also the samples of settlement and pressure
  render = {
    size = { 1000, 480 }, camera = { -0.01, -0.005, NCOL * W + (NCOL - 1) * GAP + 0.01, 0.11 },
    layers = "bodies,pressure,isolines,colorbar,scalebar,title,time,overlay",
    fluid_field = "excess_pressure", fluid_range = { 0, DP },
    isolines = 6,
    record_from = T_LOAD - 0.1,  -- the columns' settling and the pistons' seating are not shown
    title = "Terzaghi consolidation: a load step on four grain columns drained at the floor",
    overlay = function(world)
      local items = {}
      for _, col in ipairs(cols) do
        if col.y0 then
          local _, py = col.piston:position()
          items[#items + 1] = { text = "settlement", at = { col.x0 + W / 2, 0.1068 }, anchor = "center", size = 13 }
          items[#items + 1] = { text = string.format("%.2f mm", 1000 * (col.y0 - py)),
                                at = { col.x0 + W / 2, 0.1022 }, anchor = "center", size = 13 }
        end
      end
      return items
    end,
  },
  on_frame = function(world)
    local t = world:time()
    if not seated and t >= T_SEAT then
      -- each piston is set on its column with the pre-load; the columns settle under it while
      -- still freely drained (coupling off, high conductivity)
      for _, col in ipairs(cols) do
        local p = col.piston
        p:set_motion("dynamic")
        p:set_state { position = { col.x0 + W / 2, column_top(col) + PH / 2 + 0.0003 }, velocity = { 0, 0 } }
        p:set_load(0, -(P0 * W - p:mass() * G))
      end
      seated = true
    end
    if not loaded and t >= T_LOAD then
      -- the increment: constant total load (P0 + DP) W; from now on the water must drain
      -- through the columns (conductivity D_SAND) and the pore pressure responds to the
      -- skeleton's compression
      for _, col in ipairs(cols) do
        local p = col.piston
        p:set_load(0, -((P0 + DP) * W - p:mass() * G))
        col.y0 = select(2, p:position())
        col.H = col.y0 - PH / 2                -- drainage path: the column, floor to piston
        col.y_load = {}
        for i = col.first, col.last do col.y_load[i] = select(2, world:body(i):position()) end
      end
      world:set_flag("FLUID_PERM_HIGH", D_SAND)
      world:set_flag("FLUID_CONSOLIDATION", 1)
      world:soil_reset()
      loaded = true
    end
    if loaded then
      for c, col in ipairs(cols) do
        local _, py = col.piston:position()
        local u = {}
        for k, f in ipairs { 0.85, 0.5, 0.15 } do
          local y = f * col.H
          u[k] = world:soil_region { lo = { col.x0 + 0.002, y - 0.004 }, hi = { col.x0 + W - 0.002, y + 0.004 } }.u_excess
        end
        -- mean excess pore pressure of the whole column (exact integral of the field)
        local uc = world:soil_region { lo = { col.x0, 0 }, hi = { col.x0 + W, col.H } }.u_excess
        col.hist[#col.hist + 1] = { t - T_LOAD, col.y0 - py, u[1], u[2], uc }
        log:row(t - T_LOAD, c, col.y0 - py, u[1], u[2], u[3], uc)
      end
    end
  end,
  on_finish = function(world)
    if not loaded or #cols[1].hist < 10 then return end
    local res = {}
    for c, col in ipairs(cols) do
      local r = analyse(col)
      res[c] = r
      print(string.format("column %d: H = %.4f m, n = %.3f, final settlement %.4f mm, M = %.4g Pa, B = %.4f, "
                          .. "s0 = %.4f mm, c_v = %.4g m^2/s, T_v at the end %.2f; strain by band (floor to "
                          .. "piston, / mean) %.2f %.2f %.2f %.2f", c, r.H, r.n, 1000 * r.sf, r.M, r.B, 1000 * r.s0,
                          r.cv, r.Tv_end, r.bands[1], r.bands[2], r.bands[3], r.bands[4]))
    end
    local worst, fail = 0, nil
    for _, Tv in ipairs { 0.1, 0.2, 0.5 } do
      local Ut = U_series(Tv)
      local each, mU, mUp, mum, mut, k = {}, 0, 0, 0, 0, 0
      for c, r in ipairs(res) do
        local a = r.at[Tv]
        if a then
          each[#each + 1] = string.format("%.3f", a.U)
          mU, mUp, mum, mut, k = mU + a.U, mUp + a.Up, mum + a.um, mut + a.ut, k + 1
        end
      end
      if k == #res then
        mU, mUp, mum, mut = mU / k, mUp / k, mum / k, mut / k
        local err = (mU - Ut) / Ut
        worst = math.max(worst, math.abs(err))
        if math.abs(err) > TOL[Tv] and not fail then
          fail = string.format("degree of consolidation at T_v = %.1f off by %+.1f%% (tolerance %.0f%%)", Tv,
                               100 * err, 100 * TOL[Tv])
        end
        print(string.format("T_v = %.1f: U of the columns %s; mean %.4f, Terzaghi %.4f (%+.1f%%); from the pore "
                            .. "pressure %.4f (%+.1f%%); u/(B DP) at mid-depth %.3f (series %.3f), at 0.85 H %.3f "
                            .. "(series %.3f)", Tv, table.concat(each, " "), mU, Ut, 100 * err, mUp,
                            100 * (mUp - Ut) / Ut, mum, u_series(0.5, Tv), mut, u_series(0.85, Tv)))
        -- a part of a row of docs/validation.md (tests/harness.h: pl_validation; the ctest label
        -- validation-doc collects these lines)
        print(string.format("VALIDATION|%s|consolidation of grain columns (%d pre-loaded "
                            .. "column%s, increment, drained at the floor)|Terzaghi U(T_v) at T_v = 0.1, 0.2, 0.5, c_v "
                            .. "from the measured M|%.0f %% / %.0f %% / %.0f %%|T_v = %.1f: %+.1f %%",
                            NCOL == 1 and "soil.consolidation_grains_short" or "soil.consolidation_grains", NCOL, NCOL == 1 and "" or "s", 100 * TOL[0.1],
                            100 * TOL[0.2], 100 * TOL[0.5], Tv, 100 * err))
      else
        worst = math.huge
        fail = fail or string.format("T_v = %.1f: beyond the run", Tv)
        print(string.format("T_v = %.1f: beyond the run", Tv))
      end
    end
    print(string.format("worst |mean U - U_Terzaghi| / U_Terzaghi = %.1f%%", 100 * worst))
    -- chart: each column's degree of consolidation U = (s - s0)/(s_final - s0) against
    -- T_v = c_v t / H^2, beside Terzaghi's U(T_v)
    local series = {}
    for c, col in ipairs(cols) do
      local r, xs, ys = res[c], {}, {}
      for _, h in ipairs(col.hist) do
        local Tv = r.cv * h[1] / (r.H * r.H)
        if Tv > 0 and Tv <= 1 then xs[#xs + 1] = Tv; ys[#ys + 1] = (h[2] - r.s0) / (r.sf - r.s0) end
      end
      if #xs > 0 then series[#series + 1] = { name = "column " .. c, x = xs, y = ys, style = "points" } end
    end
    local tx, ty = {}, {}
    for k = 1, 100 do tx[k] = k / 100; ty[k] = U_series(k / 100) end
    series[#series + 1] = { name = "Terzaghi U(T#dv#u)", x = tx, y = ty, style = "dashed", color = "#222222" }
    porelab.chart { file = "consolidation_U.png", title = "Consolidation of grain columns against Terzaghi",
                    xlabel = "time factor T#dv#u = c#dv#u t / H#u2#d", ylabel = "degree of consolidation U",
                    series = series, xrange = { 0, 1 }, yrange = { 0, 1.1 }, legend = "bottom right" }
    if world:time() >= T_END - 1e-6 then
      assert(not fail, fail)
    end
  end,
}
