-- A buried pipe ovalising under load (seed 002 §7.5, docs/solids.md): an elastic ring of
-- triangles in a box of grains; a rigid plate pushes down on the sand at constant speed. The
-- pipe's ovalisation (D_max - D_min) / (D_max + D_min), from its horizontal and vertical
-- diameters, goes against the plate's load to out/buried_pipe/ovalisation.csv.
--   porelab run scenes/solids/buried_pipe.lua
local packing = require "porelab.packing"

local t_end = 0.045
local w = porelab.world { gravity = { 0, -9.81 }, dt_safety = 0.3 }
local sand = w:material { name = "sand", density = 2600, kn = 2e6, friction = 0.5, restitution = 0.2 }
packing.box(w, { lo = { 0, 0 }, hi = { 0.16, 0.2 }, material = sand })
-- a hexagonal lattice of discs around the pipe (centre (0.08, 0.06)), none inside it
local R, t, r = 0.025, 0.003, 0.0025
local d = 2 * r
local row = 0
local y = r + 0.0005
while y < 0.12 do
  local x = r + 0.0005 + (row % 2) * r
  while x < 0.16 - r do
    if math.sqrt((x - 0.08)^2 + (y - 0.06)^2) > R + r + 0.0005 then
      w:disc { center = { x, y }, radius = r, material = sand }
    end
    x = x + d
  end
  y = y + d * math.sqrt(3) / 2
  row = row + 1
end

w:solid { young = 5e7, poisson = 0.4, density = 1000, formulation = "fic_semi_implicit",
          contact_stiffness = 2e6, contact_damping = 5 }
w:solid_annulus { cx = 0.08, cy = 0.06, ri = R - t, ro = R, nr = 2, nt = 64 }
local plate = w:wall { from = { 0.16, 0.125 }, to = { 0.0, 0.125 }, material = sand, velocity = { 0, -0.2 } }

local csv = porelab.csv("ovalisation.csv", { "t", "load", "ovalisation" })
local function diameters()
  local ax = select(1, w:solid_displacement(0.08 + R, 0.06))
  local bx = select(1, w:solid_displacement(0.08 - R, 0.06))
  local _, ay = w:solid_displacement(0.08, 0.06 + R)
  local _, by = w:solid_displacement(0.08, 0.06 - R)
  return 2 * R + ax - bx, 2 * R + ay - by
end
while w:time() < t_end do
  w:step(200)
  local dx, dy = diameters()
  local load = math.abs(select(2, plate:force()))
  local ov = (math.max(dx, dy) - math.min(dx, dy)) / (dx + dy)
  csv:row(w:time(), load, ov)
end
csv:close()
local dx, dy = diameters()
print(string.format("t = %.4g s: horizontal diameter %.5f m, vertical %.5f m, ovalisation %.3g, plate load %.4g N/m",
                    w:time(), dx, dy, (math.max(dx, dy) - math.min(dx, dy)) / (dx + dy), math.abs(select(2, plate:force()))))
assert(dy < dx, "the pipe must flatten under the load")
