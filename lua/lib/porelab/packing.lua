-- porelab.packing: helpers that build containers and fill them with grains.
--   local packing = require "porelab.packing"
--   packing.box(w, {lo = {0, 0}, hi = {1, 1}, material = steel})
--   packing.lattice(w, {lo = .., hi = .., radius = 0.01, material = sand, hex = true})
--   packing.rain(w, {lo = .., hi = .., radii = {0.01, 0.015}, count = 300, material = sand})
--   packing.fill(w, {lo = .., hi = .., radius_range = {0.008, 0.012}, porosity = 0.6, material = sand})
--   packing.compress(w, {walls = box, pressure = 1e4})
-- Every function checks its table like the built-in constructors and reports errors at the
-- line of the scene that called it.
local porelab = require "porelab"
local random = require "porelab.random"
local check = require "porelab.check"

local packing = {}

local fail, check_fields = check.for_module("packing.")
local finite = check.finite

-- A region larger than this (m) is refused: no porelab scene needs one, and beyond it the
-- rounding of positions exceeds any grain size that fits the lattice/body limit.
local MAX_EXTENT = 1e6
-- Most bodies one helper may create (each one costs a Lua table and engine storage).
local MAX_BODIES = 1000000

local function vec(fn, def, field)
  local v = def[field]
  if type(v) ~= "table" or type(v[1] or v.x) ~= "number" or type(v[2] or v.y) ~= "number" then
    fail(fn, "%s is required (a vector {x, y} in m)", field)
  end
  local x, y = v[1] or v.x, v[2] or v.y
  if not (finite(x) and finite(y) and math.abs(x) <= MAX_EXTENT and math.abs(y) <= MAX_EXTENT) then
    fail(fn, "%s must be a vector of finite numbers within +-%g m (got {%s, %s})", field, MAX_EXTENT,
         tostring(x), tostring(y))
  end
  return x, y
end

-- weights: one finite number >= 0 per entry, not all zero
local function check_weights(fn, weights, n)
  if type(weights) ~= "table" or #weights ~= n then fail(fn, "weights must have one entry per radius (%d)", n) end
  local total = 0
  for i = 1, n do
    local v = weights[i]
    if not finite(v) or v < 0 then fail(fn, "weights[%d] must be a finite number >= 0 (got %s)", i, tostring(v)) end
    total = total + v
  end
  if not (total > 0) then fail(fn, "weights must not all be 0") end
end

local function region(fn, def)
  local x0, y0 = vec(fn, def, "lo")
  local x1, y1 = vec(fn, def, "hi")
  if not (x1 > x0 and y1 > y0) then
    fail(fn, "hi must lie above and right of lo (got lo = {%g, %g}, hi = {%g, %g})",
         x0, y0, x1, y1)
  end
  return x0, y0, x1, y1
end

local function positive(fn, def, field, default)
  local v = def[field]
  if v == nil then v = default end
  if not finite(v) or not (v > 0) then
    fail(fn, "%s must be a finite number > 0 (got %s)", field, tostring(v))
  end
  return v
end

--- Walls around the rectangle lo..hi: bottom, left, right and (unless open_top) top.
-- Returns a table {bottom =, left =, right =, top =} of wall bodies.
function packing.box(w, def)
  check_fields("box", def, { "lo", "hi", "material", "open_top" })
  local x0, y0, x1, y1 = region("box", def)
  local m = def.material
  local walls = {
    bottom = w:wall { from = { x0, y0 }, to = { x1, y0 }, material = m },
    left = w:wall { from = { x0, y1 }, to = { x0, y0 }, material = m },
    right = w:wall { from = { x1, y0 }, to = { x1, y1 }, material = m },
  }
  if def.open_top == false then
    walls.top = w:wall { from = { x1, y1 }, to = { x0, y1 }, material = m }
  end
  return walls
end

--- Discs of one radius on a square or hexagonal lattice filling lo..hi.
-- Fields: lo, hi, radius (m), material, hex (default true), gap (fraction of the diameter
-- left between neighbours, default 0), fixed (default false). Returns the list of bodies.
function packing.lattice(w, def)
  check_fields("lattice", def, { "lo", "hi", "radius", "material", "hex", "gap", "fixed" })
  local x0, y0, x1, y1 = region("lattice", def)
  local r = positive("lattice", def, "radius")
  local gap = def.gap or 0
  if not finite(gap) or gap < 0 then fail("lattice", "gap must be a finite number >= 0 (got %s)", tostring(gap)) end
  local d = 2 * r * (1 + gap)
  local hex = def.hex ~= false
  local dy = hex and d * math.sqrt(3) / 2 or d
  -- count first: a tiny radius would otherwise create discs until memory runs out
  local nx = math.max(0, math.floor((x1 - x0 - 2 * r) / d + 1e-9) + 1)
  local ny = math.max(0, math.floor((y1 - y0 - 2 * r) / dy + 1e-9) + 1)
  if nx * ny > MAX_BODIES then
    fail("lattice", "radius %g m in a %g x %g m region makes about %.0f discs (at most %d): use a larger radius or a smaller region",
         r, x1 - x0, y1 - y0, nx * ny, MAX_BODIES)
  end
  if x0 + d == x0 or x1 + d == x1 or y0 + dy == y0 or y1 + dy == y1 then
    fail("lattice", "radius %g m is below the rounding of the coordinates (%g, %g)", r, x1, y1)
  end
  local bodies = {}
  local row = 0
  local y = y0 + r
  while y + r <= y1 + 1e-12 do
    local x = x0 + r + ((hex and row % 2 == 1) and d / 2 or 0)
    while x + r <= x1 + 1e-12 do
      bodies[#bodies + 1] = w:disc { center = { x, y }, radius = r, material = def.material,
                                     fixed = def.fixed or false }
      x = x + d
    end
    y = y + dy
    row = row + 1
  end
  if #bodies == 0 then fail("lattice", "the region is too small for one disc of radius %g", r) end
  return bodies
end

--- Grains of several sizes placed without overlap in lo..hi, ready to fall ("rain").
-- Fields: lo, hi, radii (list, m), weights (relative number fractions, default equal),
-- count, material or materials (one per radius), seed (integer, default 1), jitter (0..1,
-- fraction of the free space used to randomise positions, default 1), velocity {vx, vy}.
-- Grains fill a grid of cells sized to the largest grain, bottom row first, each shifted
-- randomly inside its cell, so the same seed gives the same packing everywhere.
function packing.rain(w, def)
  check_fields("rain", def, { "lo", "hi", "radii", "weights", "count", "material",
                              "materials", "seed", "jitter", "velocity" })
  local x0, y0, x1, y1 = region("rain", def)
  local radii = def.radii
  if type(radii) ~= "table" or #radii == 0 then fail("rain", "radii must be a non-empty list of radii in m") end
  local rmax = 0
  for i, r in ipairs(radii) do
    if not finite(r) or not (r > 0) then fail("rain", "radii[%d] must be a finite number > 0 (got %s)", i, tostring(r)) end
    rmax = math.max(rmax, r)
  end
  local weights = def.weights or {}
  if def.weights then check_weights("rain", weights, #radii) end
  if not def.weights then for i = 1, #radii do weights[i] = 1 end end
  local mats = def.materials
  if mats then
    if #mats ~= #radii then fail("rain", "materials must have one entry per radius (%d)", #radii) end
  elseif def.material then
    mats = {}
    for i = 1, #radii do mats[i] = def.material end
  else
    fail("rain", "material (or materials, one per radius) is required")
  end
  local count = def.count
  if math.type(count) ~= "integer" or count < 1 then fail("rain", "count must be an integer >= 1 (got %s)", tostring(count)) end
  local jitter = def.jitter or 1
  if type(jitter) ~= "number" or jitter < 0 or jitter > 1 then fail("rain", "jitter must be in 0..1 (got %s)", tostring(jitter)) end
  local cell = 2 * rmax * 1.05
  local nx = math.floor((x1 - x0) / cell)
  local ny = math.floor((y1 - y0) / cell)
  if nx * ny < count then
    fail("rain", "count must be <= %d: the region holds %d x %d cells of %g m (got %d)",
         nx * ny, nx, ny, cell, count)
  end
  local rng = random.new(def.seed or 1)
  local bodies = {}
  for k = 0, count - 1 do
    local i, j = k % nx, k // nx
    local which = rng:choose(weights)
    local r = radii[which]
    local free = cell / 2 - r
    local cx = x0 + (i + 0.5) * cell + jitter * rng:uniform(-free, free)
    local cy = y0 + (j + 0.5) * cell + jitter * rng:uniform(-free, free)
    bodies[#bodies + 1] = w:disc { center = { cx, cy }, radius = r, material = mats[which],
                                   velocity = def.velocity }
  end
  return bodies
end

--- A radius sampler from a size distribution given in def (used by fill):
--   radius = r                          one size
--   radii = {r1, r2, ...}, weights = {} discrete sizes with number fractions
--   radius_range = {rmin, rmax}         uniform in radius
--   lognormal = {median = m, sigma = s, min = a, max = b}  log-normal radii, truncated
local function sampler(fn, def, rng)
  local n = (def.radius and 1 or 0) + (def.radii and 1 or 0) + (def.radius_range and 1 or 0)
            + (def.lognormal and 1 or 0)
  if n ~= 1 then
    fail(fn, "give exactly one size distribution: radius, radii (+ weights), radius_range or lognormal")
  end
  if def.radius then
    local r = positive(fn, def, "radius")
    return function() return r end, r, r
  elseif def.radii then
    local radii, weights = def.radii, def.weights
    if type(radii) ~= "table" or #radii == 0 then fail(fn, "radii must be a non-empty list (m)") end
    local lo, hi = math.huge, 0
    for i, r in ipairs(radii) do
      if not finite(r) or not (r > 0) then fail(fn, "radii[%d] must be a finite number > 0 (got %s)", i, tostring(r)) end
      lo, hi = math.min(lo, r), math.max(hi, r)
    end
    if weights then check_weights(fn, weights, #radii) end
    if not weights then weights = {}; for i = 1, #radii do weights[i] = 1 end end
    return function() return radii[rng:choose(weights)] end, lo, hi
  elseif def.radius_range then
    local a, b = def.radius_range[1], def.radius_range[2]
    if not finite(a) or not finite(b) or not (a > 0 and b >= a) then
      fail(fn, "radius_range must be {rmin, rmax} with 0 < rmin <= rmax (m)")
    end
    return function() return rng:uniform(a, b) end, a, b
  else
    local ln = def.lognormal
    local m, sg = ln.median, ln.sigma
    if not finite(m) or not (m > 0) then fail(fn, "lognormal.median must be a finite number > 0 (m)") end
    if not finite(sg) or not (sg >= 0 and sg <= 5) then fail(fn, "lognormal.sigma must be in 0 .. 5") end
    local a, b = ln.min or m * math.exp(-2 * sg), ln.max or m * math.exp(2 * sg)
    return function()
      while true do -- Box-Muller, truncated to [a, b]
        local u1, u2 = rng:uniform(), rng:uniform()
        local z = math.sqrt(-2 * math.log(1 - u1)) * math.cos(2 * math.pi * u2)
        local r = m * math.exp(sg * z)
        if r >= a and r <= b then return r end
      end
    end, a, b
  end
end

--- Random non-overlapping discs in lo..hi (random sequential addition), to a target count or
-- a target areal porosity of the region. Fields: lo, hi, material, one size distribution
-- (see sampler above), count or porosity (0 < n < 1), seed, max_tries (default 1000 per
-- grain), fixed. Returns the list of bodies and the porosity reached. Random sequential
-- addition jams near an areal solid fraction of about 0.55 for discs of one size; denser
-- packings need rain and settling, or compress().
function packing.fill(w, def)
  check_fields("fill", def, { "lo", "hi", "material", "radius", "radii", "weights", "radius_range",
                              "lognormal", "count", "porosity", "seed", "max_tries", "fixed" })
  local x0, y0, x1, y1 = region("fill", def)
  if def.material == nil then fail("fill", "material is required") end
  local rng = random.new(def.seed or 1)
  local draw, rmin, rmax = sampler("fill", def, rng)
  if (def.count == nil) == (def.porosity == nil) then fail("fill", "give either count or porosity") end
  local area = (x1 - x0) * (y1 - y0)
  local target_solid
  if def.porosity ~= nil then
    local n = def.porosity
    if type(n) ~= "number" or not (n > 0 and n < 1) then fail("fill", "porosity must be in (0, 1) (got %s)", tostring(n)) end
    target_solid = (1 - n) * area
  elseif math.type(def.count) ~= "integer" or def.count < 1 then
    fail("fill", "count must be an integer >= 1 (got %s)", tostring(def.count))
  end
  local tries = def.max_tries or 1000
  -- spatial hash of placed discs, cell = largest diameter
  local cell = 2 * rmax
  local grid = {}
  local function key(i, j) return i * 1000003 + j end
  local placed, solid = {}, 0
  local function free(x, y, r)
    local ci, cj = math.floor((x - x0) / cell), math.floor((y - y0) / cell)
    for i = ci - 1, ci + 1 do
      for j = cj - 1, cj + 1 do
        local list = grid[key(i, j)]
        if list then
          for _, d in ipairs(list) do
            local dx, dy = x - d[1], y - d[2]
            if dx * dx + dy * dy < (r + d[3]) ^ 2 then return false end
          end
        end
      end
    end
    return true
  end
  local bodies = {}
  while true do
    if def.count and #bodies >= def.count then break end
    if target_solid and solid >= target_solid then break end
    local r = draw()
    local ok = false
    for _ = 1, tries do
      local x, y = rng:uniform(x0 + r, x1 - r), rng:uniform(y0 + r, y1 - r)
      if x1 - x0 >= 2 * r and y1 - y0 >= 2 * r and free(x, y, r) then
        local k = key(math.floor((x - x0) / cell), math.floor((y - y0) / cell))
        grid[k] = grid[k] or {}
        table.insert(grid[k], { x, y, r })
        bodies[#bodies + 1] = w:disc { center = { x, y }, radius = r, material = def.material,
                                       fixed = def.fixed or false }
        solid = solid + math.pi * r * r
        ok = true
        break
      end
    end
    if not ok then
      fail("fill", "jammed after %d grains at porosity %.3f: no free place found in %d tries "
                   .. "(ask for fewer grains or a higher porosity, or use rain and settle)",
           #bodies, 1 - solid / area, tries)
    end
  end
  return bodies, 1 - solid / area
end

--- Isotropic compression with servo walls (seed 000 §2.1.1, seed 003 eqs. 5.11-5.12): the
-- left, right and top walls of a box made by packing.box{..., open_top = false} push with the
-- stress p (Pa per unit thickness: force = p x wall length) until every wall force is within
-- tol of its target (or t_max). Fields: walls (from packing.box), pressure, gain (m/s,
-- default 0.05), vmax (m/s, default 0.05), tol (default 0.02), t_max (s, default 5),
-- fix (default true: walls fixed where they stop). Returns the time it took and the largest
-- relative force error.
function packing.compress(w, def)
  check_fields("compress", def, { "walls", "pressure", "gain", "vmax", "tol", "t_max", "fix" })
  local walls = def.walls
  if type(walls) ~= "table" or not (walls.left and walls.right and walls.top and walls.bottom) then
    fail("compress", "walls must be the table returned by packing.box{..., open_top = false}")
  end
  local p = positive("compress", def, "pressure")
  local gain, vmax = def.gain or 0.05, def.vmax or 0.05
  local tol, t_max = def.tol or 0.02, def.t_max or 5
  local function length(b)
    local v = b:vertices()
    return math.sqrt((v[2][1] - v[1][1]) ^ 2 + (v[2][2] - v[1][2]) ^ 2)
  end
  local set = {
    { walls.left, { 1, 0 } }, { walls.right, { -1, 0 } }, { walls.top, { 0, -1 } },
  }
  for _, s in ipairs(set) do
    s[3] = p * length(s[1])
    s[1]:servo { direction = s[2], force = s[3], gain = gain, vmax = vmax }
  end
  local t0, err = w:time(), math.huge
  local check = math.max(1, math.floor(0.005 / w:dt()))
  local calm = 0
  while w:time() - t0 < t_max do
    w:step(check)
    err = 0
    for _, s in ipairs(set) do
      local fx, fy = s[1]:force()
      local f = -(fx * s[2][1] + fy * s[2][2])
      err = math.max(err, math.abs(f - s[3]) / s[3])
    end
    calm = err < tol and calm + 1 or 0
    if calm >= 20 then break end -- held for 20 checks in a row
  end
  if def.fix ~= false then
    for _, s in ipairs(set) do s[1]:set_motion("fixed") end
  end
  return w:time() - t0, err
end

return packing
