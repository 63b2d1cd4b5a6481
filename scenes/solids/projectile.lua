-- A projectile of triangles strikes a plate of grains (seed 002 §7.4, docs/solids.md): an
-- elasto-plastic ring of triangles (meshed by gmsh) flies at 20 m/s into a layer of stiff
-- discs resting on the floor of a closed box. Its centre speed, the solid's energy terms, the
-- largest von Mises stress in it and the grains' force on it go to out/projectile/impact.csv.
-- At 10 m/s into discs ten times softer (kn = 5e7 N/m) the ring stays elastic: its largest
-- Mises stress is 4.9 MPa, half the yield stress (docs/solids.md).
--   porelab run scenes/solids/projectile.lua
local packing = require "porelab.packing"

local t_end = 3e-3
local speed = 20                         -- m/s
local kn = 5e8                           -- N/m per m, grain-grain and grain-ring contacts
local w = porelab.world { gravity = { 0, 0 }, dt_safety = 0.3 }
local grain = w:material { name = "grain", density = 2500, kn = kn, friction = 0.3, restitution = 0.5 }
packing.box(w, { lo = { 0, 0 }, hi = { 0.2, 0.2 }, material = grain, open_top = false })
packing.lattice(w, { lo = { 0.002, 0.002 }, hi = { 0.198, 0.04 }, radius = 0.002, material = grain })

w:solid { young = 1e9, poisson = 0.35, density = 2700, formulation = "fic_semi_implicit",
          yield_stress = 1e7, hardening = 1e8, large_strain = true, contact_stiffness = kn }
w:solid_annulus { cx = 0.1, cy = 0.06, ri = 0.004, ro = 0.015, nr = 4, nt = 32 }
w:solid_initial_velocity { box = { 0.08, 0.04, 0.12, 0.08 }, vy = -speed }
local info = w:solid_info()
print(string.format("projectile: %d nodes, %d triangles, critical step %.3g s; world step %.3g s",
                    info.nodes, info.elements, info.critical_dt, w:dt()))

local csv = porelab.csv("impact.csv", { "t", "v_centre", "kinetic", "elastic", "plastic", "mises_max", "fy" })
local function centre_speed()
  local u0x, u0y = w:solid_displacement(0.1, 0.06 - 0.015)
  return u0y
end
local last_u, last_t = centre_speed(), w:time()
local v_min, mises_peak = 0, 0
while w:time() < t_end do
  local mises
  for _ = 1, 10 do
    w:step(10)
    mises = w:solid_extremes()
    mises_peak = math.max(mises_peak, mises)
  end
  local u = centre_speed()
  local v = (u - last_u) / (w:time() - last_t)
  last_u, last_t = u, w:time()
  local e = w:solid_energy()
  local _, fy = w:solid_contact_force()
  csv:row(w:time(), v, e.kinetic, e.elastic, e.plastic, mises, fy)
  v_min = math.min(v_min, v)
end
csv:close()
local e = w:solid_energy()
local _, eps_p = w:solid_extremes()
local ke0 = 0.5 * 2700 * math.pi * (0.015^2 - 0.004^2) * speed^2
print(string.format("t = %.4g s: projectile kinetic %.4g J/m (from %.4g), plastic work %.4g J/m, elastic %.4g J/m",
                    w:time(), e.kinetic, ke0, e.plastic, e.elastic))
print(string.format("largest von Mises stress %.4g MPa (yield stress 10 MPa), largest plastic strain %.4g",
                    mises_peak / 1e6, eps_p))
assert(e.kinetic < ke0, "the grains must slow the projectile")
