-- porelab.rock: bonded rock specimens and their laboratory measurements (docs/rock.md).
--   local rock = require "porelab.rock"
--   local s = rock.specimen(w, {lo = {0, 0}, hi = {0.04, 0.08}, material = granite,
--                               wall_material = steel, radius_range = {1e-3, 1.5e-3}})
--   -- s.discs, s.box (walls), s.bonds, s.porosity, s.report (a line for the log)
-- The specimen is made in three stages, so that it is at rest and nearly stress-free when the
-- bonds are made: (1) random discs without overlap fill the box; (2) servo walls compact them
-- with frictionless grains and local damping to a low confining stress; (3) with the walls
-- fixed and friction restored the packing comes to rest (damped); then every pair at most
-- `gap` apart is bonded. A disc-shaped specimen (Brazilian test) is carved afterwards out of
-- the square packing (`carve = 0.95`), then bonded.
local porelab = require "porelab"
local packing = require "porelab.packing"

local rock = {}

local fail, check_fields = require("porelab.check").for_module("rock.")

local function length(b)
  local v = b:vertices()
  return math.sqrt((v[2][1] - v[1][1]) ^ 2 + (v[2][2] - v[1][2]) ^ 2)
end

--- Servo compaction of the box walls to the stress p (Pa); returns the steps taken and the
-- largest relative wall-force error at the end. The servo gain is the wall speed vmax while
-- the wall is free and is lowered to half the stability limit F / (k dt) (k the sum of the
-- springs of the wall's contacts, counted every 100 steps) once grains touch it.
local function compact(w, box, p, vmax, kn, max_steps, tol)
  local set = { { box.left, { 1, 0 } }, { box.right, { -1, 0 } }, { box.top, { 0, -1 } } }
  for _, s in ipairs(set) do s[3] = p * length(s[1]) end
  local steps, err, calm = 0, math.huge, 0
  while steps < max_steps do
    for _, s in ipairs(set) do
      local n = w:touching(s[1]) + 4
      local g = math.min(vmax, 0.5 * s[3] / (n * kn * w:dt()))
      s[1]:servo { direction = s[2], force = s[3], gain = g, vmax = vmax }
    end
    w:step(100)
    steps = steps + 100
    err = 0
    for _, s in ipairs(set) do
      local fx, fy = s[1]:force()
      local f = -(fx * s[2][1] + fy * s[2][2])
      err = math.max(err, math.abs(f - s[3]) / s[3])
    end
    calm = err < tol and calm + 1 or 0
    if calm >= 5 then break end
  end
  for _, s in ipairs(set) do s[1]:set_motion("fixed") end
  return steps, err
end

-- The strength parameters the laboratory scenes share (docs/rock.md, "Calibration").
local STRENGTH = {
  { name = "kn", unit = "N/m", value = 2e10, min = 1e8, max = 1e12, doc = "bond and contact normal stiffness" },
  { name = "kt_ratio", unit = "", value = 0.5, min = 0.05, max = 1, doc = "bond k_t / k_n" },
  { name = "rn", unit = "N/m", value = 2.5e4, min = 1e2, max = 1e8, doc = "bond tensile strength R_n" },
  { name = "rt_ratio", unit = "", value = 2, min = 0.25, max = 10, doc = "bond shear strength R_t / R_n" },
}

--- A scene's own porelab.params list with the shared strength parameters appended: kn (bond
-- and contact normal stiffness, N/m, default 2e10), kt_ratio (k_t / k_n, 0.5), rn (bond tensile
-- strength R_n, N/m, 2.5e4) and rt_ratio (R_t / R_n, 2).
--   local P = porelab.params(rock.with_strength_params { {name = "size", ...}, ... })
function rock.with_strength_params(list)
  local out = {}
  for i, p in ipairs(list) do out[i] = p end
  for _, p in ipairs(STRENGTH) do out[#out + 1] = p end
  return out
end

--- The laboratory's materials: granite grains (2650 kg/m3) and steel platens (7800 kg/m3), both
-- with normal stiffness S.kn, tangential S.kt_ratio x S.kn and friction 0.5, and the brittle
-- granite-granite bond law (k_n, k_t as the contacts; R_n = S.rn, R_t = S.rt_ratio x S.rn).
-- S holds the fields of rock.with_strength_params (a scene's P); without it, their defaults.
-- Returns granite, steel.
function rock.lab_materials(w, S)
  if not S then
    S = {}
    for _, p in ipairs(STRENGTH) do S[p.name] = p.value end
  end
  local kt = S.kt_ratio * S.kn
  local granite = w:material { name = "granite", density = 2650, kn = S.kn, ks = kt, friction = 0.5 }
  local steel = w:material { name = "steel", density = 7800, kn = S.kn, ks = kt, friction = 0.5 }
  w:bond_law { a = granite, b = granite, law = "brittle", kn = S.kn, kt = kt, rn = S.rn,
               rt = S.rt_ratio * S.rn }
  return granite, steel
end

--- Steps until the kinetic energy is below `ratio` times the elastic energy (or max_steps).
function rock.rest(w, ratio, max_steps)
  ratio, max_steps = ratio or 1e-4, max_steps or 20000
  local steps = 0
  while steps < max_steps do
    w:step(100)
    steps = steps + 100
    local e = w:energy()
    if e.kinetic <= ratio * math.max(e.elastic, 1e-30) then break end
  end
  return steps
end

--- A bonded specimen. Fields: lo, hi (the box, m), material (of the grains; its bond law must
-- be set with w:bond_law before), wall_material, radius_range (m, default {1e-3, 1.5e-3}),
-- fill_porosity (of the random fill, default 0.56), pressure (compaction stress, Pa, default
-- 1e5), vmax (servo wall speed, m/s, default 0.5), gap (bond gap, m, default 0.1 x the
-- smallest radius), seed (default 1), carve (a fraction f in (0, 1]: keep only the discs inside the circle of
-- diameter f x the smaller side of the compacted box, at its centre),
-- damping (local damping while the specimen is made, default 0.7; the world's value is kept
-- afterwards), friction (the grains' friction after compaction, default the material's).
-- Returns {discs =, box =, bonds =, porosity (of the compacted box) =, size = {w, h} (of the
-- compacted box), circle = {center, radius} (with carve), report =}.
function rock.specimen(w, def)
  check_fields("specimen", def, { "lo", "hi", "material", "wall_material", "radius_range",
                                   "fill_porosity", "pressure", "vmax", "gap", "seed", "carve",
                                   "damping" })
  local m, wm = def.material, def.wall_material
  if not m or not wm then fail("specimen", "material and wall_material are required") end
  local rr = def.radius_range or { 1e-3, 1.5e-3 }
  local x0, y0, x1, y1 = def.lo[1], def.lo[2], def.hi[1], def.hi[2]
  local box = packing.box(w, { lo = def.lo, hi = def.hi, material = wm, open_top = false })
  local discs, n0 = packing.fill(w, { lo = { x0 + 1e-6, y0 + 1e-6 }, hi = { x1 - 1e-6, y1 - 1e-6 },
                                      radius_range = rr, porosity = def.fill_porosity or 0.56,
                                      material = m, seed = def.seed or 1 })
  local damping = w:flag("LOCAL_DAMPING")
  w:set_flag("LOCAL_DAMPING", def.damping or 0.7)
  -- compaction: frictionless, first with contacts 100 x softer (a 10 x longer step and a
  -- 100 x faster stable servo), then with the real stiffness, back to the same stress
  local pm, pw = w:pair_params(m, m), w:pair_params(m, wm)
  local p = def.pressure or 1e5
  local vmax = def.vmax or 0.5
  w:pair(m, m, { friction = 0, kn = pm.kn / 100, ks = pm.ks / 100 })
  w:pair(m, wm, { friction = 0, kn = pw.kn / 100, ks = pw.ks / 100 })
  local c_steps, c_err = compact(w, box, p, vmax, pw.kn / 100, 100000, 0.05)
  w:pair(m, m, { kn = pm.kn, ks = pm.ks })
  w:pair(m, wm, { kn = pw.kn, ks = pw.ks })
  local c2_steps
  c2_steps, c_err = compact(w, box, p, vmax, pw.kn, 20000, 0.2)
  c_steps = c_steps + c2_steps
  w:pair(m, m, { friction = pm.friction })
  w:pair(m, wm, { friction = pw.friction })
  local r_steps = rock.rest(w, 1e-5, 10000)
  local xl, yb = box.left:position(), select(2, box.bottom:position())
  local xr, yt = box.right:position(), select(2, box.top:position())
  local solid = 0
  for _, d in ipairs(discs) do solid = solid + d:area() end
  local porosity = 1 - solid / ((xr - xl) * (yt - yb))
  local circle
  if def.carve then
    -- the largest circle of the compacted box, times the fraction
    local cx, cy = 0.5 * (xl + xr), 0.5 * (yb + yt)
    local R = 0.5 * math.min(xr - xl, yt - yb) * def.carve
    local kept = {}
    for _, d in ipairs(discs) do
      local x, y = d:position()
      if (x - cx) ^ 2 + (y - cy) ^ 2 > (R - d:radius()) ^ 2 then w:remove(d) else kept[#kept + 1] = d end
    end
    discs = kept
    circle = { center = { cx, cy }, radius = R }
  end
  local gap = def.gap or 0.1 * rr[1]
  local nb = w:bond_touching(gap)
  w:set_flag("LOCAL_DAMPING", damping)
  local s = { discs = discs, box = box, bonds = nb, porosity = porosity, circle = circle,
              size = { xr - xl, yt - yb } }
  s.report = string.format("%d discs, fill porosity %.3f, compacted to %.3g Pa in %d steps "
                           .. "(wall error %.3f), rest %d steps, porosity %.3f, %d bonds "
                           .. "(%.2f per disc)", #discs, n0, p, c_steps, c_err, r_steps,
                           s.porosity, nb, 2 * nb / #discs)
  return s
end

--- Linear least-squares slope of y on x over the samples with lo <= key <= hi.
function rock.slope(x, y, key, lo, hi)
  local n, sx, sy, sxx, sxy = 0, 0, 0, 0, 0
  for i = 1, #x do
    if key[i] >= lo and key[i] <= hi then
      n = n + 1
      sx, sy = sx + x[i], sy + y[i]
      sxx, sxy = sxx + x[i] * x[i], sxy + x[i] * y[i]
    end
  end
  if n < 2 then return 0 / 0 end
  return (n * sxy - sx * sy) / (n * sxx - sx * sx)
end

--- Height of the top of a list of discs: the largest y + r (m).
function rock.surface(discs)
  local top = 0
  for _, d in ipairs(discs) do
    local _, y = d:position()
    top = math.max(top, y + d:radius())
  end
  return top
end

--- Mean position of a list of discs (those not removed).
function rock.centroid(w, list)
  local sx, sy, n = 0, 0, 0
  for _, d in ipairs(list) do
    if not w:removed(d) then
      local x, y = d:position()
      sx, sy, n = sx + x, sy + y, n + 1
    end
  end
  return sx / math.max(n, 1), sy / math.max(n, 1)
end

return rock
