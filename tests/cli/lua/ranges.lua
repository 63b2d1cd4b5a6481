-- Numeric fields out of range are refused at the scene line with the field and its range
-- (run by ctest as cli_field_ranges; issue 13 items 12 and 13). Each case below was accepted
-- before (inf/nan energies, a 3 GB lattice, a zero-length boundary line).
local packing = require "porelab.packing"
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.3 }

local n = 0
-- f must raise an error located at this file and naming `want` (plain text)
local function refused(f, want)
  local ok, msg = pcall(f)
  assert(not ok, "accepted: " .. want)
  assert(msg:find("ranges.lua:%d+: "), "no file:line in: " .. msg)
  assert(msg:find(want, 1, true), "expected '" .. want .. "' in: " .. msg)
  n = n + 1
end

refused(function() porelab.world { gravity = { 0, 1e308 } } end,
        "world: gravity must be a vector of finite numbers within +-1000000 m/s^2 (got {0, 1e+308})")
refused(function() porelab.world { skin = 1 / 0 } end, "world: skin must be a finite number in [0, 1000000] m")
refused(function() w:material { name = "a", density = 1e308, kn = 1e6 } end,
        "material: density must be a finite number in (0, 1000000000] kg/m^3 (got 1e+308)")
refused(function() w:material { name = "b", density = 1000, kn = 1e6, cohesion = 1 / 0 } end,
        "material: cohesion must be a finite number in [0, 1e+15] N (got inf)")
refused(function() w:material { name = "c", density = 1000, kn = 1e6, cn = 1 / 0 } end,
        "material: cn must be a finite number in [0, 1e+12] N s/m (got inf)")
refused(function() w:material { name = "d", density = 1000, kn = 1e6, ks = 1 / 0 } end,
        "material: ks must be a finite number in [0, 1e+15] N/m (got inf)")
refused(function() w:material { name = "e", density = 1000, young = 0 / 0 } end, "material: young must be")
refused(function() w:material { name = "f", density = 1000, kn = 1e6, friction = 1 / 0 } end,
        "material: friction must be a finite number in [0, 100]")
refused(function() w:pair(m, m, { cohesion = 1 / 0 }) end, "pair: cohesion must be a finite number in [0, 1e+15] N")
refused(function() w:disc { center = { 0, 0 }, radius = 0.01, material = m, velocity = { 1e308, 0 } } end,
        "disc: velocity must be a vector of finite numbers within +-1000000 m/s")
refused(function() w:disc { center = { 0, 0 }, radius = 0.01, material = m, omega = 1e308 } end,
        "disc: omega must be a finite number in [-1000000, 1000000] rad/s")
refused(function() w:disc { center = { 1e308, 0 }, radius = 0.01, material = m } end,
        "disc: center must be a vector of finite numbers within +-1000000 m")
refused(function() w:wall { from = { -1e308, 0 }, to = { 1e308, 0 }, material = m } end,
        "wall: from must be a vector of finite numbers within +-1000000 m")
local d = w:disc { center = { 0, 0 }, radius = 0.01, material = m }
refused(function() d:set_load(1e308, 0) end, "set_load: force must be a vector of finite numbers within +-1e+15 N")
refused(function() d:set_density(1e308) end, "set_density: density must be a finite number in (0, 1000000000] kg/m^3")
refused(function() d:set_velocity(0, 0, 1 / 0) end, "set_velocity: omega must be a finite number")
refused(function() d:set_state { velocity = { 0 / 0, 0 } } end, "set_state: velocity must be a vector of finite numbers")
refused(function() packing.lattice(w, { lo = { 0, 0 }, hi = { 1, 1 }, radius = 1e-6, material = m }) end,
        "packing.lattice: radius 1e-06 m in a 1 x 1 m region makes about")
refused(function() packing.rain(w, { lo = { 0, 0 }, hi = { 1, 1 }, radii = { 0.01, 0.02 }, weights = { -1, 0 / 0 },
                                     count = 3, material = m }) end,
        "packing.rain: weights[1] must be a finite number >= 0 (got -1)")
refused(function() packing.rain(w, { lo = { 0, 0 }, hi = { 1, 1 }, radii = { 0.01, 0.02 }, weights = { 1, 0 / 0 },
                                     count = 3, material = m }) end,
        "packing.rain: weights[2] must be a finite number >= 0")
refused(function() packing.fill(w, { lo = { 0, 0 }, hi = { 1, 1 }, radius = 1 / 0, count = 3, material = m }) end,
        "packing.fill: radius must be a finite number > 0 (got inf)")
w:fluid_quad { corners = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
refused(function() w:fluid_bc { from = { 0, 0 }, to = { 0, 0 }, head = 1 } end, "fluid_bc: from and to must differ")
print(string.format("field ranges: %d out-of-range inputs refused with file:line, field and range", n))
