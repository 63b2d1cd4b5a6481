-- Liquefaction on a shaking table (docs/soil.md §5.3). Three tanks side by side on one
-- table:  LOOSE + WATER  |  LOOSE + DRY  |  DENSE + WATER.
-- Each holds a sand layer (840 discs rained in), a heavy "building" block set on the surface
-- and a light buried "pipe"; the buildings are held level while they bed in and free to rotate
-- from 0.2 s before the shaking. From t = 1.4 s to 5.4 s the table shakes sideways (5 Hz, 0.35 g,
-- 20 cycles). In the loose saturated tank the skeleton tries to compact, the water cannot leave
-- fast enough (low permeability), so the pore pressure rises until it carries the grains'
-- weight (r_u = excess pore pressure / initial vertical effective stress reaches 1 in the free
-- field): the sand loses its strength, the building sinks and tilts, the pipe floats up. The
-- dry tank compacts a little but keeps its strength; the dense saturated tank dilates when
-- sheared and draws water in (suction). Gauges (free field, under the building, whole layer)
-- -> ru.csv and ru.png; the run prints the peak r_u during shaking and the r_u left at the end
-- (0.8 s after) of each, and asserts the scene's criteria (docs/soil.md §5.3): free-field r_u
-- during shaking above 0.9 in the loose saturated tank and below 0.5 in the dense one, exactly
-- 0 in the dry one; the loose saturated tank's pipe floats up and its building sinks more than
-- the dry tank's.
-- Parameter: amp_mm (porelab run --param amp_mm=5: 0.5 g); --seed N rains other packings.
-- Results (manifest.json; the ensemble: docs/soil.md §5.3, docs/scaling.md): ru_peak, ru_end
-- (loose saturated free field), dense_ru_peak, settlement_mm / dry_settlement_mm /
-- dense_settlement_mm, pipe_rise_mm / dry_pipe_rise_mm, criteria_met.
--   porelab run scenes/soil/liquefaction.lua
local packing = require "porelab.packing"

local P = porelab.params {
  { name = "amp_mm", unit = "mm", value = 3.5, min = 0.5, max = 8,
    doc = "shaking amplitude at 5 Hz (3.5 mm: 0.35 g; 5 mm: 0.5 g)" },
}

local WT, GAP = 0.22, 0.05          -- tank width and gap between tanks, m
local HS = 0.12                     -- water surface (mesh top) above each tank floor, m
local A, F = P.amp_mm / 1000, 5.0    -- shaking amplitude (m) and frequency (Hz): 0.35 g by default
local K_SAND = 1e-5                -- m/s: conductivity of the packed sand once settled (a fine sand)
local T_BUILD, T_SHAKE, T_STOP, T_END = 0.9, 1.4, 5.4, 6.2
-- coupling on (and the packed sand's conductivity) 0.2 s after the building is set, once its
-- load has been taken by the skeleton, drained: coupled at once, the building's load was
-- still held by the water when the shaking began (up to half of sigma'_v0 in the free field),
-- which capped r_u (docs/soil.md §5.3)
local T_COUPLE = 1.1
local T_REF = 0.2                  -- s before shaking over which sigma'_v0 and u0 are averaged
local T_RELEASE = T_SHAKE - T_REF  -- the buildings, held level while they bed in, free to rotate
local DENSE_AT = 0.7                -- the dense tank's grains get their friction back here

local w = porelab.world { gravity = { 0, -9.81 }, rayleigh_alpha = 5 }
local sand = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5, restitution = 0.2 }
local dsand = w:material { name = "dense_sand", density = 2650, kn = 1e6, friction = 0.5, restitution = 0.2 }
local wall = w:material { name = "wall", density = 2650, kn = 1e6, friction = 0.5, restitution = 0.2 }
local block = w:material { name = "building", density = 3000, kn = 1e6, friction = 0.5, restitution = 0.2 }
local pipe_m = w:material { name = "pipe", density = 600, kn = 1e6, friction = 0.5, restitution = 0.2 }
-- the dense tank is rained in without friction (grains slide into a dense packing)
w:pair(dsand, dsand, { friction = 0 })
w:pair(dsand, wall, { friction = 0 })

local tanks = {}
for k = 1, 3 do
  local x0 = (k - 1) * (WT + GAP)
  local t = { x0 = x0, wet = (k ~= 2), dense = (k == 3),
              name = ({ "loose + water", "loose + dry", "dense + water" })[k] }
  t.walls = { w:wall { from = { x0 - 0.03, 0 }, to = { x0 + WT + 0.03, 0 }, material = wall } }
  if t.wet then
    -- side walls of a wet tank are solid slabs: the mesh reaches into them, so that the
    -- water beside the grains moves with the wall instead of being pumped (docs/soil.md §5.3)
    t.walls[2] = w:rectangle { center = { x0 - 0.01, 0.125 }, width = 0.02, height = 0.25, material = wall,
                               motion = "prescribed" }
    t.walls[3] = w:rectangle { center = { x0 + WT + 0.01, 0.125 }, width = 0.02, height = 0.25, material = wall,
                               motion = "prescribed" }
  else
    t.walls[2] = w:wall { from = { x0, 0 }, to = { x0, 0.25 }, material = wall }
    t.walls[3] = w:wall { from = { x0 + WT, 0 }, to = { x0 + WT, 0.25 }, material = wall }
  end
  t.pipe = w:disc { center = { x0 + 0.185, 0.035 }, radius = 0.012, material = pipe_m, fixed = true }
  packing.rain(w, { lo = { x0 + 0.003, 0.06 }, hi = { x0 + WT - 0.003, 0.40 },
                    radii = { 0.00225, 0.00275 }, count = 840,
                    material = t.dense and dsand or sand, seed = 11 + k })
  t.building = w:rectangle { center = { x0 + 0.07, 0.5 }, width = 0.07, height = 0.05,
                             material = block, fixed = true }
  if t.wet then
    -- the mesh reaches into the wall slabs by more than the shaking amplitude, so grains
    -- never leave it; head line (pressure head 0) at the water surface
    local a, b = x0 - 0.008, x0 + WT + 0.008
    w:fluid_quad { corners = { { a, 0 }, { b, 0 }, { b, HS }, { a, HS } }, ndivx = 11, ndivy = 6 }
    w:fluid_bc { from = { a, HS }, to = { b, HS }, head = 0 }
  end
  tanks[k] = t
end

w:set_flag("DT_SAFETY", 0.2)              -- grain step 0.2 x critical (default 0.1): twice the pace, same picture (docs/soil.md §5.3)
w:set_flag("FLUIDS_ON", 1)
w:set_flag("FIRST_STEP_STATIC", 1)
w:set_flag("FLUID_PERM", 1)              -- conductivity from the local void ratio
w:set_flag("FLUID_PERM_LOW", 0.05)       -- m/s while the sand is rained in (lowered at T_COUPLE)
w:set_flag("FLUID_PERM_HIGH", 0.5)       -- m/s in open water
w:set_flag("FLUID_STORAGE", 0)
w:set_flag("FLUID_CONSOLIDATION", 0)     -- switched on at T_COUPLE, once the sand and the building have settled
w:set_flag("FLUID_BULK_MODULUS", 3e5)    -- Pa: about the skeleton's constrained modulus (docs/soil.md §2)
w:set_flag("FLUID_SOLVE_TIMESTEPS", 1)     -- pressure solved every grain step: the stiff undrained coupling stays stable
w:set_flag("FLUID_POROSITY_TIMESTEPS", 10) -- grains cut against the elements every 10 steps (docs/soil.md §2)
w:set_flag("FLUID_FORCE_REUSE", 1)       -- fluid forces computed at each fluid update (every step)

-- r_u gauges (docs/soil.md §5.3). r_u = (mean excess pore pressure - its mean before shaking)
-- / sigma'_v0, area means over a rectangle (exact integral of the pressure field), the
-- references averaged over the last T_REF before shaking. sigma'_v0 is geostatic, as in
-- shaking-table practice: the submerged weight of the grains in the gauge's column above each
-- level (soil_region's overburden). The contact stress of the grains in a gauge (some 120)
-- scatters between packings and is printed beside it. The criterion is read in the FREE
-- FIELD, the usual place for r_u: the whole depth of the layer between the building and the
-- pipe (6 x 5.5 cm, some 120 grains). Under the building the static load adds to sigma'_v0
-- (twice the free field's) and the soil is sheared by the rocking footing, and the layer-wide
-- mean mixes both; they are logged and printed beside it.
local GAUGES = { "free", "layer", "under" }
local function gauge(t, name)
  if name == "free" then return { lo = { t.x0 + 0.11, 0.015 }, hi = { t.x0 + 0.17, 0.07 } } end
  if name == "under" then return { lo = { t.x0 + 0.035, 0.015 }, hi = { t.x0 + 0.105, 0.07 } } end
  return { lo = { t.x0 + 0.01, 0.015 }, hi = { t.x0 + 0.21, 0.07 } }
end

local function surface(t, xa, xb)
  local top = 0
  for i = 1, w:body_count() do
    local b = w:body(i)
    if b:shape() == "disc" and b:material():name() ~= "pipe" then
      local x, y = b:position()
      if x > xa and x < xb then top = math.max(top, y + b:radius()) end
    end
  end
  return top
end

-- Water pushed up out of the sand: the Darcy flux (relative to the grains and the table)
-- through the horizontal mesh line y = Y_SEEP across a wet tank, from the elements on either
-- side of it (each triangle with an edge on the line contributes q_y x edge length / 2),
-- integrated over time from the start of the shaking; reported as the depth of water it
-- would make over the tank (mm). Negative: water drawn down into the sand.
local Y_SEEP = 0.08
local seep_edges -- per tank: { {element, edge length}, ... }
local function seep_setup(world)
  local xy, tri = world:fluid_nodes(), world:fluid_triangles()
  seep_edges = {}
  for k, tk in ipairs(tanks) do
    seep_edges[k] = {}
    for e, v in ipairs(tri) do
      for q = 1, 3 do
        local a, b = xy[v[q]], xy[v[q % 3 + 1]]
        local xm = 0.5 * (a[1] + b[1])
        if math.abs(a[2] - Y_SEEP) < 1e-9 and math.abs(b[2] - Y_SEEP) < 1e-9 and xm > tk.x0 - 0.01
           and xm < tk.x0 + WT + 0.01 then
          table.insert(seep_edges[k], { e, math.abs(b[1] - a[1]) })
        end
      end
    end
  end
end
local function seep_flux(world, k) -- m^2/s upward through the line, per m of depth
  local vy, q = world:fluid_element_field("vy"), 0
  for _, ed in ipairs(seep_edges[k]) do q = q + 0.5 * vy[ed[1]] * ed[2] end
  return q
end

local log = porelab.csv("ru.csv", { "t", "tank", "du_free", "sigma_v0_free", "ru_free", "ru_free_period_mean",
                                    "ru_layer_period_mean", "ru_under_period_mean", "building_y",
                                    "building_tilt_deg", "pipe_y", "water_up_mm" },
                        { "s", "", "Pa", "Pa", "", "", "", "", "m", "deg", "m", "mm" })
local placed, coupled, dense_done, ref_done, shaking, released = false, false, false, false, false, false
local summary -- the results, filled by on_finish

return {
  world = w,
  run = { t_end = T_END, fps = 30 },
  render = {
    size = { 1280, 480 }, camera = { -0.01, -0.005, 3 * WT + 2 * GAP + 0.01, 0.185 },
    layers = "bodies,pressure,colorbar,scalebar,title,time,overlay",
    -- signed (the dense tank draws water in): diverging, symmetric, fixed for the whole video
    fluid_field = "excess_pressure", fluid_range = { -900, 900 },
    record_from = T_SHAKE - 0.3,   -- the sand's raining-in and the building's placing are not shown
    colors = { sand = "#d9b36c8c", dense_sand = "#b08a4a8c", wall = "#555555", building = "#5b5b66", pipe = "#e6c229" },
    title = "Liquefaction on a shaking table",
    -- the window's live charts (porelab view: "charts"): the gauges' r_u and the buildings' settlement
    live = {
      { title = "r\u{1D64}, free field (mean over a period)", range = { -1, 1.5 },
        series = (function()
          local l = {}
          for k, t in ipairs(tanks) do
            l[k] = { name = t.name, value = function() return t.g and t.g.free.sv0 and t.g.free.mean or nil end }
          end
          return l
        end)() },
      { title = "building settlement (mm)",
        series = (function()
          local l = {}
          for k, t in ipairs(tanks) do
            l[k] = { name = t.name, value = function()
              return t.y0 and 1000 * (t.y0 - select(2, t.building:position())) or nil end }
          end
          return l
        end)() },
    },
    overlay = function(world)
      local items = {}
      for k, t in ipairs(tanks) do
        local g = gauge(t, "free")
        items[#items + 1] = { polygon = { { g.lo[1], g.lo[2] }, { g.hi[1], g.lo[2] }, { g.hi[1], g.hi[2] },
                                          { g.lo[1], g.hi[2] } }, color = "#000000", width = 1 }
        items[#items + 1] = { text = string.format("%s   r\u{1D64} = %.2f", t.name, t.g and t.g.free.mean or 0),
                              at = { t.x0 + WT / 2, 0.172 }, anchor = "center", size = 17 }
        if t.wet then
          items[#items + 1] = { line = { { t.x0, HS }, { t.x0 + WT, HS } }, color = "#1f77b4", width = 1 }
        end
      end
      local tt = world:time()
      if tt >= T_SHAKE and tt <= T_STOP then
        items[#items + 1] = { text = "shaking: 5 Hz, 0.35 g", at = { 24, 72 }, space = "pixel", size = 16, color = "#b00000" }
      end
      return items
    end,
  },
  on_frame = function(world)
    local t = world:time()
    if t >= DENSE_AT and not dense_done then
      world:pair(dsand, dsand, { friction = 0.5 })
      world:pair(dsand, wall, { friction = 0.5 })
      dense_done = true
    end
    if t >= T_BUILD and not placed then
      -- set the building on the settled surface and release the pipe
      for _, tk in ipairs(tanks) do
        local s = surface(tk, tk.x0 + 0.030, tk.x0 + 0.110)
        tk.building:set_motion("dynamic")
        tk.building:set_state { position = { tk.x0 + 0.07, s + 0.0255 }, angle = 0, velocity = { 0, 0 } }
        -- held level while it beds in (set on the few highest grains, a free block tipped by
        -- 3-4 degrees before the shaking began); free to rotate from T_RELEASE on
        tk.building:set_fixed_rotation(true)
        tk.pipe:set_motion("dynamic")
        tk.y0 = s + 0.0255
        tk.pipe_y0 = select(2, tk.pipe:position())
      end
      placed = true
    end
    if t >= T_COUPLE and not coupled then
      -- from now on grains moving into or out of the pores change the pore pressure, and
      -- the packed sand has the conductivity of a fine sand (the building's load is already
      -- on the skeleton)
      world:set_flag("FLUID_CONSOLIDATION", 1)
      world:set_flag("FLUID_PERM_LOW", K_SAND)
      world:soil_reset()
      coupled = true
    end
    -- sigma'_v0 and u0: means over the last T_REF before shaking (the contact stress of a
    -- group of grains fluctuates from frame to frame; a single snapshot is a noisy reference)
    if t >= T_SHAKE - T_REF then
      for _, tk in ipairs(tanks) do
        tk.g = tk.g or {}
        for _, name in ipairs(GAUGES) do
          local g = tk.g[name] or { n = 0, s = 0, c = 0, u = 0, hist = {}, peak = 0, mean = 0, ln = 0, l = 0 }
          tk.g[name] = g
          local r = world:soil_region(gauge(tk, name))
          if not ref_done then
            g.n, g.s, g.c, g.u = g.n + 1, g.s + r.overburden, g.c + r.syy, g.u + r.u_excess
            if t >= T_SHAKE - 1e-9 then g.sv0, g.sc0, g.u0 = g.s / g.n, g.c / g.n, g.u / g.n end
          end
          if g.sv0 then
            g.du = r.u_excess - g.u0
            g.ru = g.sv0 > 0 and g.du / g.sv0 or 0
            -- running mean over one shaking period (time-based, so independent of the frame rate)
            table.insert(g.hist, { t, g.ru })
            while g.hist[1][1] < t - 1 / F + 1e-9 do table.remove(g.hist, 1) end
            local m = 0
            for _, v in ipairs(g.hist) do m = m + v[2] / #g.hist end
            g.mean = m
            -- the peak counts full periods only (the first period's mean has few samples)
            if t <= T_STOP + 1e-9 and t >= T_SHAKE + 1 / F - 1e-9 then
              if m > g.peak then g.peak = m end
              if t >= T_STOP - 1 then g.ln, g.l = g.ln + 1, g.l + g.ru end -- last second of shaking
            end
          end
        end
      end
      if t >= T_SHAKE - 1e-9 then ref_done = true end
    end
    if ref_done then
      if not seep_edges then seep_setup(world) end
      for k, tk in ipairs(tanks) do
        local _, by = tk.building:position()
        local _, py = tk.pipe:position()
        local g = tk.g
        if tk.wet then
          local q = seep_flux(world, k)
          tk.up = (tk.up or 0) + 0.5 * (q + (tk.q or q)) * (t - (tk.tq or t)) -- trapezoid over the frame
          tk.q, tk.tq = q, t
        end
        log:row(t, k, g.free.du, g.free.sv0, g.free.ru, g.free.mean, g.layer.mean, g.under.mean, by,
                math.deg(tk.building:angle()), py, 1000 * (tk.up or 0) / WT)
        tk.hist = tk.hist or { t = {}, ru = {} }
        if t >= T_SHAKE + 1 / F - 1e-9 then -- charted once a whole period has been sampled
          tk.hist.t[#tk.hist.t + 1] = t
          tk.hist.ru[#tk.hist.ru + 1] = g.free.mean
        end
      end
    end
    if t >= T_RELEASE and not released then
      for _, tk in ipairs(tanks) do tk.building:set_fixed_rotation(false) end
      released = true
    end
    if t >= T_SHAKE - T_REF and not shaking then
      for _, tk in ipairs(tanks) do
        for _, wl in ipairs(tk.walls) do
          wl:shake { amplitude = { A, 0 }, frequency = F, start = T_SHAKE, stop = T_STOP }
        end
      end
      -- the pore water is accelerated with the table (Darcy's law in its frame, docs/soil.md §2)
      world:fluid_frame(tanks[1].walls[2])
      shaking = true
    end
  end,
  on_finish = function(world)
    local out = {}
    for k, tk in ipairs(tanks) do
      local _, by = tk.building:position()
      local _, py = tk.pipe:position()
      local parts = {}
      for _, name in ipairs(GAUGES) do
        local g = tk.g and tk.g[name]
        if g and g.sv0 then
          parts[#parts + 1] = string.format("%s: peak %.2f, last second %.2f, at the end %.2f (sigma'_v0 %.0f Pa, "
                                            .. "contacts %.0f Pa, excess pressure before %.0f Pa)", name, g.peak,
                                            g.ln > 0 and g.l / g.ln or 0, g.mean, g.sv0, g.sc0, g.u0)
        end
      end
      out[#out + 1] = string.format("%s: r_u %s; building settled %.1f mm (tilt %.1f deg), pipe moved %+.1f mm, "
                                    .. "water pushed up through y = %.2f m %+.2f mm", tk.name, table.concat(parts, "; "),
                                    1000 * ((tk.y0 or by) - by), math.deg(tk.building:angle()),
                                    1000 * (py - (tk.pipe_y0 or py)), Y_SEEP, 1000 * (tk.up or 0) / WT)
    end
    print(table.concat(out, "\n"))
    -- chart of the free-field r_u (mean over a shaking period) of the three tanks
    local series = {}
    for _, tk in ipairs(tanks) do
      if tk.hist and #tk.hist.t > 0 then
        series[#series + 1] = { name = tk.name, x = tk.hist.t, y = tk.hist.ru, style = "line" }
      end
    end
    if #series > 0 then
      local t0, t1 = T_SHAKE + 1 / F, world:time()
      series[#series + 1] = { name = "liquefied: r#du#u > 0.9", x = { t0, t1 }, y = { 0.9, 0.9 }, style = "dashed",
                              color = "#444444", width = 1 }
      series[#series + 1] = { name = "shaking stops", x = { T_STOP, T_STOP }, y = { -1.5, 1.5 }, style = "dashed",
                              color = "#c00000", width = 1 }
      porelab.chart { file = "ru.png", title = "Excess pore pressure ratio in the free field",
                      xlabel = "time (s)", ylabel = "r#du#u = #gDu / #gs'#dv0#u (mean over a period)",
                      series = series, legend = "bottom left" }
    end
    local fs, ss = world:fluid_stats(), world:soil_stats()
    print(string.format("fluid time: porosity %.2f s, assembly %.2f s, factorization %.2f s, solve %.2f s, forces %.2f s, "
                        .. "consolidation source %.2f s (%d updates)", fs.t_porosity, fs.t_assembly, fs.t_factor,
                        fs.t_solve, fs.t_forces, ss.t_source, fs.updates))
    if world:time() >= T_END - 1e-6 then
      local loose, dense = tanks[1].g.free, tanks[3].g.free
      local rise, sink = {}, {}
      for k, tk in ipairs(tanks) do
        rise[k] = select(2, tk.pipe:position()) - tk.pipe_y0
        sink[k] = tk.y0 - select(2, tk.building:position())
      end
      local dry_zero = true
      for _, name in ipairs(GAUGES) do
        local g = tanks[2].g[name]
        dry_zero = dry_zero and g.peak == 0 and g.du == 0
      end
      summary = {
        ru_peak = loose.peak, ru_end = loose.mean, dense_ru_peak = dense.peak,
        settlement_mm = { value = 1000 * sink[1], unit = "mm" },
        dry_settlement_mm = { value = 1000 * sink[2], unit = "mm" },
        dense_settlement_mm = { value = 1000 * sink[3], unit = "mm" },
        pipe_rise_mm = { value = 1000 * rise[1], unit = "mm" },
        dry_pipe_rise_mm = { value = 1000 * rise[2], unit = "mm" },
        criteria_met = loose.peak > 0.9 and dense.peak < 0.5 and rise[1] > 0.005 and rise[1] - rise[2] > 0.005
                       and sink[1] - sink[2] > 0.005 and dry_zero,
      }
    end
    -- with the default amplitude and packings (the ctest) the criteria are asserted; in a sweep
    -- they are reported (criteria_met) and the run goes on
    if world:time() >= T_END - 1e-6 and P.amp_mm == 3.5 and porelab.seed() == 0 then
      -- the scene's point, checked (ctest soil_liquefaction runs it whole) on the free-field
      -- gauge's period mean, with the criteria's thresholds; measured over six packings at 0.35 g
      -- (docs/soil.md §5.3): loose saturated peak during shaking 0.92-1.09, dense peak <= 0,
      -- dry exactly 0 (no fluid mesh); the loose saturated tank's pipe rose 15-50 mm (dry tank
      -- -0.5..+0.3 mm) and its building sank 32-43 mm (dry tank 15-22 mm)
      local loose, dense = tanks[1].g.free, tanks[3].g.free
      local rise, sink = {}, {}
      for k, tk in ipairs(tanks) do
        rise[k] = select(2, tk.pipe:position()) - tk.pipe_y0
        sink[k] = tk.y0 - select(2, tk.building:position())
      end
      assert(loose.peak > 0.9, string.format("loose saturated tank: r_u reached only %.2f during shaking (liquefied: > 0.9)",
                                             loose.peak))
      assert(dense.peak < 0.5, string.format("dense saturated tank: r_u reached %.2f during shaking (expected: < 0.5)",
                                             dense.peak))
      assert(rise[1] > 0.005 and rise[1] - rise[2] > 0.005, string.format("pipe: rose %.1f mm in the loose saturated "
                                                                          .. "tank, %.1f mm in the dry one", 1000 * rise[1],
                                                                          1000 * rise[2]))
      assert(sink[1] - sink[2] > 0.005, string.format("building: sank %.1f mm in the loose saturated tank, %.1f mm in the "
                                                      .. "dry one", 1000 * sink[1], 1000 * sink[2]))
      for _, name in ipairs(GAUGES) do
        local g = tanks[2].g[name]
        assert(g.peak == 0 and g.du == 0, string.format("dry tank: excess pore pressure %.3g Pa", g.du))
      end
      -- the row of docs/validation.md (tests/harness.h: pl_validation; ctest label validation-doc)
      print(string.format("VALIDATION|soil.liquefaction|liquefaction on a shaking table|criterion: r_u > 0.9 loose "
                          .. "saturated, < 0.5 dense, 0 dry (free field, period mean, σ'_v0 geostatic)|loose peak "
                          .. "during shaking > 0.9, dense peak < 0.5, dry 0; pipe rises > 5 mm and 5 mm more than dry; "
                          .. "building sinks 5 mm more than dry|loose peak %.2f, dense peak %.2f, dry %.2f; pipe %+.1f mm "
                          .. "(dry %+.1f); building %.1f mm (dry %.1f)", loose.peak, dense.peak, tanks[2].g.free.peak,
                          1000 * rise[1], 1000 * rise[2], 1000 * sink[1], 1000 * sink[2]))
    end
  end,
  results = function() return summary or {} end,
}
