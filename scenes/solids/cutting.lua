-- Cutting with a finite-element tool (seed 002 §7.2, docs/solids.md): a blade of elasto-plastic
-- linear triangles (FIC pressure, J2 with linear hardening) is driven at 4 m/s through a bed of
-- unbonded sand grains (the bonded rock of the seed needs the bonds of the rock issue). The
-- cutting force (the grains' force on the tool, N per m of tool width) goes to
-- out/cutting/cutting_force.csv with the largest Mises stress and plastic strain in the tool.
--   porelab run scenes/solids/cutting.lua
local packing = require "porelab.packing"

local t_end = 3e-3                       -- s (12 mm of travel at 4 m/s)
local w = porelab.world { gravity = { 0, -9.81 }, dt_safety = 0.3 }
local sand = w:material { name = "sand", density = 2600, kn = 5e6, friction = 0.5, restitution = 0.3 }
packing.box(w, { lo = { 0, 0 }, hi = { 0.12, 0.05 }, material = sand })
packing.lattice(w, { lo = { 0.001, 0.001 }, hi = { 0.119, 0.03 }, radius = 0.002, material = sand })

-- the tool: a blade with its tip 6 mm below the sand surface, moving to +x
w:solid { young = 2e9, poisson = 0.3, density = 7800, formulation = "fic_semi_implicit",
          yield_stress = 2e7, hardening = 2e8, large_strain = true,
          contact_stiffness = 5e6, contact_damping = 20, friction = 0.4 }
w:solid_polygon { points = { { 0.010, 0.024 }, { 0.020, 0.024 }, { 0.026, 0.050 }, { 0.016, 0.050 } }, h = 0.0015 }
local holder = w:solid_velocity { box = { 0.0, 0.045, 0.05, 0.051 }, vx = 4.0, vy = 0.0 }

local info = w:solid_info()
print(string.format("tool: %d nodes, %d triangles, critical step %.3g s; world step %.3g s",
                    info.nodes, info.elements, info.critical_dt, w:dt()))
local csv = porelab.csv("cutting_force.csv", { "t", "fx", "fy", "holder_fx", "mises_max", "eps_p_max" })
local cpu0, steps = os.clock(), 0
while w:time() < t_end do
  w:step(200)
  steps = steps + 200
  local fx, fy = w:solid_contact_force()
  local hx = w:solid_reaction(holder)
  local smax, pmax = w:solid_extremes()
  csv:row(w:time(), fx, fy, hx, smax, pmax)
end
csv:close()
-- cost split (CPU; the solid's parts on the monotonic clock, the same on a single-threaded run)
local cpu = os.clock() - cpu0
local ci = w:solid_info()
print(string.format("cost per step: %.3g ms (grains %.3g ms, solid %.3g ms, contact %.3g ms) over %d steps",
                    1e3 * cpu / steps, 1e3 * (cpu - ci.solid_seconds - ci.contact_seconds) / steps,
                    1e3 * ci.solid_seconds / steps, 1e3 * ci.contact_seconds / steps, steps))
local fx, fy = w:solid_contact_force()
local smax, pmax = w:solid_extremes()
print(string.format("t = %.4g s: cutting force %.4g N/m (vertical %.4g N/m), Mises max %.4g MPa, plastic strain max %.3g",
                    w:time(), fx, fy, smax / 1e6, pmax))
assert(fx < 0, "the sand must push back on the tool")
