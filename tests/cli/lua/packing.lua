-- Imperative check of the packing helpers (run by ctest as cli_packing_helpers):
-- random fill to a target porosity and to a count, size distributions, and isotropic
-- compression with servo walls holding the target stress.
local packing = require "porelab.packing"
local w = porelab.world { gravity = { 0, 0 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.3, restitution = 0.3 }
local box = packing.box(w, { lo = { 0, 0 }, hi = { 0.4, 0.4 }, material = m, open_top = false })

local grains, n = packing.fill(w, { lo = { 0, 0 }, hi = { 0.4, 0.4 }, radius_range = { 0.008, 0.012 },
                                    porosity = 0.62, material = m, seed = 3 })
assert(n <= 0.62 and n > 0.60, "fill: porosity " .. n)
for _, g in ipairs(grains) do
  local r = g:radius()
  assert(r >= 0.008 and r <= 0.012, "fill: radius out of the range " .. r)
end
assert(w:contact_count() == 0, "fill: grains overlap")

local p = 2e3 -- Pa per unit thickness
local t, err = packing.compress(w, { walls = box, pressure = p })
assert(err < 0.02, string.format("compress: wall force error %.3f after %.2f s", err, t))
-- every wall carries p x its length: the normal force, which the servo controls (the grains'
-- friction on the wall, up to mu times it, comes on top; with it the magnitude was 831 for a
-- target of 800 on the left wall once the contact damping matched the restitution exactly)
local inward = { left = { 1, 0 }, right = { -1, 0 }, top = { 0, -1 } }
for _, name in ipairs { "left", "right", "top" } do
  local b = box[name]
  local v = b:vertices()
  local len = math.sqrt((v[2][1] - v[1][1]) ^ 2 + (v[2][2] - v[1][2]) ^ 2)
  local fx, fy = b:force()
  local f = -(fx * inward[name][1] + fy * inward[name][2])
  assert(math.abs(f - p * len) < 0.03 * p * len, string.format("%s wall force %.2f, target %.2f", name, f, p * len))
end
assert(box.left:motion() == "fixed", "compress: walls fixed at the end")

local few = packing.fill(w, { lo = { 1, 1 }, hi = { 1.2, 1.2 }, lognormal = { median = 0.005, sigma = 0.3 },
                              count = 25, material = m, seed = 9 })
assert(#few == 25)
local ok, msg = pcall(packing.fill, w, { lo = { 0, 0 }, hi = { 0.1, 0.1 }, radius = 0.01, count = 3 })
assert(not ok and msg:find("material is required"), msg)
print(string.format("fill porosity %.3f; compressed in %.2f s, wall error %.4f, %d grains, Z = %.2f",
                    n, t, err, #grains, w:coordination()))
