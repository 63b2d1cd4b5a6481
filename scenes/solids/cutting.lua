-- Rock cutting with a finite-element tool (seed 002 §7.2, docs/solids.md): a blade of
-- elasto-plastic linear triangles (FIC pressure, J2 with linear hardening, updated Lagrangian)
-- is driven at 4 m/s through a block of bonded granite discs, made as scenes/rock/cutting.lua
-- makes its rock (porelab.rock: compacted in a box of servo walls, at rest, then bonded; the
-- left wall lowered so that the tool comes in from the left). The cutting force (the grains'
-- force on the tool, N per m of tool width), the largest Mises stress and plastic strain in the
-- tool and the bonds broken so far go to out/cutting/cutting_force.csv, the force to
-- cutting_force.png.
--   porelab run scenes/solids/cutting.lua
-- cutting_frames.lua draws the same cut (it requires this file for the set-up).
local rock = require "porelab.rock"

local SPEED = 4.0                        -- m/s
local DEPTH = 4e-3                       -- m, the tool's lower edge below the rock's surface

-- The world with the rock and the tool; returns w, the holder (prescribed nodes) and the
-- number of intact bonds when the tool starts.
local function build()
  local w = porelab.world { gravity = { 0, 0 }, dt_safety = 0.2, local_damping = 0.7 } -- damped while the rock is made
  local granite, steel = rock.lab_materials(w)
  local L = 0.07                         -- m, length of the box the rock is compacted in
  local s = rock.specimen(w, { lo = { 0, 0 }, hi = { L, 0.5 * L }, material = granite,
                               wall_material = steel, fill_porosity = 0.6 })
  local box = s.box
  local xl = box.left:position()
  local xr = box.right:position()
  local _, yt = box.top:position()
  box.top:set_state { position = { 0.5 * (xl + xr), yt + L } }
  local surface = rock.surface(s.discs)
  -- the left wall (length 0.5 L) is lowered below the cut: the tool comes in from the left
  box.left:set_state { position = { xl, surface - DEPTH - 2e-3 - 0.25 * L } }
  rock.rest(w, 1e-5, 5000)
  w:set_flag("LOCAL_DAMPING", 0.1)       -- cutting is dynamic: light damping from here on

  -- the tool: a blade 10 mm wide at its lower edge, leaning 6 mm forward over its 26 mm
  -- height, its front face 2 mm from the rock at the surface; the top nodes are the holder
  local kn = w:pair_params(granite, granite).kn
  w:solid { young = 2e10, poisson = 0.3, density = 7800, formulation = "fic_semi_implicit",
            yield_stress = 1e8, hardening = 1e9, large_strain = true,
            contact_stiffness = kn,       -- the rock's own contact spring
            contact_damping = 3e3,        -- about a tenth of critical for a 1.25 mm granite disc
            friction = 0.4 }
  local x0, y0 = xl - 13e-3, surface - DEPTH
  w:solid_polygon { points = { { x0, y0 }, { x0 + 0.010, y0 }, { x0 + 0.016, y0 + 0.026 },
                               { x0 + 0.006, y0 + 0.026 } }, h = 0.0015 }
  local holder = w:solid_velocity { box = { x0 - 0.01, y0 + 0.021, x0 + 0.04, y0 + 0.027 },
                                    vx = SPEED, vy = 0.0 }
  print(string.format("cutting: rock %.0f x %.0f mm, %s; tool depth %.1f mm, speed %g m/s",
                      (xr - xl) * 1e3, surface * 1e3, s.report, DEPTH * 1e3, SPEED))
  return w, holder, w:bond_count(), { x0 - 4e-3, surface - 14e-3, xl + 36e-3, surface + 24e-3 }
end

if ... == "cutting" then return build end -- required as a module (cutting_frames.lua)

local t_end = 3e-3                       -- s (12 mm of travel at 4 m/s)
local w, holder, bonds0 = build()
local t0 = w:time()
local info = w:solid_info()
print(string.format("tool: %d nodes, %d triangles, critical step %.3g s; world step %.3g s",
                    info.nodes, info.elements, info.critical_dt, w:dt()))
local csv = porelab.csv("cutting_force.csv",
                        { "t", "fx", "fy", "holder_fx", "mises_max", "eps_p_max", "bonds_broken" },
                        { "s", "N/m", "N/m", "N/m", "Pa", "1", "" })
local ts, fc = {}, {}
local peak, t_peak, sum = 0, 0, 0
local cpu0, steps = os.clock(), 0
while w:time() - t0 < t_end do
  w:step(200)
  steps = steps + 200
  local fx, fy = w:solid_contact_force()
  local hx = w:solid_reaction(holder)
  local smax, pmax = w:solid_extremes()
  local t = w:time() - t0
  csv:row(t, fx, fy, hx, smax, pmax, bonds0 - w:bond_count())
  ts[#ts + 1], fc[#fc + 1] = 1e3 * t, -fx / 1e3
  if -fx > peak then peak, t_peak = -fx, t end
  sum = sum - fx
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
                    w:time() - t0, fx, fy, smax / 1e6, pmax))
print(string.format("cutting: peak cutting force %.4g N/m at t = %.3g ms, mean %.4g N/m; %d of %d bonds broken",
                    peak, 1e3 * t_peak, sum / #fc, bonds0 - w:bond_count(), bonds0))
porelab.chart { file = "cutting_force.png", title = "Cutting force on the tool at 4 m/s",
                xlabel = "time (ms)", ylabel = "cutting force (kN per m of tool width)", legend = "none",
                series = { { name = "cutting force", x = ts, y = fc } } }
assert(peak > 0, "the rock must push back on the tool")
assert(bonds0 > w:bond_count(), "the tool must break bonds in the rock")
