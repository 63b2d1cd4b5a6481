-- porelab.packing: helpers that build containers and fill them with grains.
--   local packing = require "porelab.packing"
--   packing.box(w, {lo = {0, 0}, hi = {1, 1}, material = steel})
--   packing.lattice(w, {lo = .., hi = .., radius = 0.01, material = sand, hex = true})
--   packing.rain(w, {lo = .., hi = .., radii = {0.01, 0.015}, count = 300, material = sand})
-- Every function checks its table like the built-in constructors and reports errors at the
-- line of the scene that called it.
local porelab = require "porelab"
local random = require "porelab.random"

local packing = {}

-- porelab.error locates the message at the scene line that called the helper.
local function fail(fn, msg, ...)
  porelab.error(string.format("packing." .. fn .. ": " .. msg, ...))
end

local function check_fields(fn, def, valid)
  if type(def) ~= "table" then fail(fn, "expected a table of fields (got %s)", type(def)) end
  local ok = {}
  for _, k in ipairs(valid) do ok[k] = true end
  for k in pairs(def) do
    if not ok[k] then
      fail(fn, "unknown field '%s' (valid: %s)", tostring(k), table.concat(valid, ", "))
    end
  end
end

local function vec(fn, def, field)
  local v = def[field]
  if type(v) ~= "table" or type(v[1] or v.x) ~= "number" or type(v[2] or v.y) ~= "number" then
    fail(fn, "%s is required (a vector {x, y} in m)", field)
  end
  return v[1] or v.x, v[2] or v.y
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
  if type(v) ~= "number" or not (v > 0) then
    fail(fn, "%s must be > 0 (got %s)", field, tostring(v))
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
  if type(gap) ~= "number" or gap < 0 then fail("lattice", "gap must be >= 0 (got %s)", tostring(gap)) end
  local d = 2 * r * (1 + gap)
  local hex = def.hex ~= false
  local dy = hex and d * math.sqrt(3) / 2 or d
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
    if type(r) ~= "number" or not (r > 0) then fail("rain", "radii[%d] must be > 0 (got %s)", i, tostring(r)) end
    rmax = math.max(rmax, r)
  end
  local weights = def.weights or {}
  if def.weights and #weights ~= #radii then fail("rain", "weights must have one entry per radius (%d)", #radii) end
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

return packing
