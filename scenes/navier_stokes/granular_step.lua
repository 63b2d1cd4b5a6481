-- Collapse of a granular step under water (seed 004 §6.3, after the experiments of Rondon et al.
-- 2011): a box 70 cm wide and 15 cm tall of a liquid with rho_F = 1000 kg/m^3 and
-- eta = 0.023 Pa s; in its bottom-left corner a step 4 cm wide and 2 cm tall of 37 polygonal
-- grains with 6 to 8 corners (mean contact "shadow" diameter about 4 mm, rho_P = 2500 kg/m^3).
-- The fluid sees each grain's core, 0.75 of its outline (seed §5).
--
-- Preparation, as in the seed: the rightmost column of grains is held fixed while the rest of
-- the step is filled by grains raining in dry (DEM only, damped) until they settle. Then the
-- water is added, the damping switched off and the column released at t = 0 of the frames; the
-- step collapses (the seed: the grains come to rest by about 0.35 s; here the last grains stop
-- by about 0.5 s and the kinetic energy falls to 1e-10 of its peak by 0.7 s, docs/navier-stokes.md).
--
-- The mesh (gmsh) is graded from h_near on the cores to h_far at grade_distance; it follows the
-- grains by node relocation and is rebuilt when its smallest angle falls below remesh_angle.
-- The default mesh is coarse (h_near = 1.2 mm) so that the run takes a few minutes; the seed's
-- resolution is about h_near = 0.5 mm:
--   porelab run scenes/navier_stokes/granular_step.lua
--   porelab run scenes/navier_stokes/granular_step.lua --param h_near=0.0006
-- The run writes ke.csv (kinetic energy of the grains and its largest grain speed against
-- time), the chart granular_step_ke.png and prints the cost per coupled step.
local random = require "porelab.random"

local P = porelab.params {
  { name = "h_near", unit = "m", value = 0.0012, min = 0.0004, max = 0.003,
    doc = "mesh size on the grain cores" },
  { name = "t_end", unit = "s", value = 0.7, min = 0.005, max = 2,
    doc = "simulated time after the release" },
  { name = "solve_every", unit = "steps", value = 20, min = 1, max = 100,
    doc = "grain steps per fluid step (fluid step = solve_every dt, dt = 50 us)" },
  { name = "rest_speed", unit = "m/s", value = 0, min = 0, max = 1,
    doc = "if > 0, the run fails unless every grain is slower than this at the end and the "
       .. "kinetic energy has fallen below 1e-8 of its peak (the ctest's check)" },
}
P.solve_every = math.floor(P.solve_every)

local W, H = 0.70, 0.15        -- box, m
local SW, SH = 0.04, 0.02      -- step, m
-- The grain step: 50 us, 0.14 of the critical step porelab computes. At 100 us (0.27 of it) a
-- grain held by several contacts keeps a period-two rocking oscillation of about 1 mm/s that
-- never dies (the estimate is made per contact; docs/navier-stokes.md, "The granular step").
local w = porelab.world { gravity = { 0, -9.81 }, dt = 5e-5, local_damping = 0.5 }
local grain = w:material { name = "grain", density = 2500, kn = 2e5, friction = 0.5,
                           restitution = 0.2 }
local box = w:material { name = "box", density = 2500, kn = 2e5, friction = 0.5, restitution = 0.2 }
w:wall { from = { 0, 0 }, to = { W, 0 }, material = box }
w:wall { from = { 0, H }, to = { 0, 0 }, material = box }
w:wall { from = { W, 0 }, to = { W, H }, material = box }

-- the retaining column: 5 grains at the step's right edge, fixed during the rain
local rng = random.new(2020)
local function grain_at(x, y, seed, fixed)
  return w:random_polygon { center = { x, y }, seed = seed, corners = { 6, 8 },
                            axis = { 0.0018, 0.0022 }, aspect = { 0.8, 1.0 }, material = grain,
                            angle = rng:uniform(0, 2 * math.pi),
                            motion = fixed and "fixed" or "dynamic" }
end
local column = {}
for j = 0, 4 do column[#column + 1] = grain_at(SW - 0.002, 0.002 + 0.004 * j, 100 + j, true) end
-- 32 grains raining in from a loose lattice above the step (8 columns x 4 rows)
for j = 0, 3 do
  for i = 0, 7 do
    grain_at(0.0025 + 0.0044 * i + rng:uniform(-3e-4, 3e-4), 0.004 + 0.0055 * j, 8 * j + i + 1,
             false)
  end
end
assert(w:body_count() == 3 + 37)
-- dry rain: 0.6 s under gravity with damping (the grains settle to a few mm/s)
w:run_until(0.6)
w:set_flag("LOCAL_DAMPING", 0)
local t0 = w:time()

w:navier_stokes { x_min = 0, y_min = 0, x_max = W, y_max = H, density = 1000, viscosity = 0.023,
                  core_fraction = 0.75, h_near = P.h_near, h_far = 0.03, grade_distance = 0.06,
                  solve_every = P.solve_every, force_relaxation = 0.5, remesh_angle = 20 }
for _, b in ipairs(column) do b:set_motion("dynamic") end

-- kinetic energy of the grains (translation and rotation, J per m of thickness)
local ts, ke, vmax = {}, {}, {}
local csv = porelab.csv("ke.csv", { "t_s", "kinetic_J_per_m", "max_speed_m_per_s" })
local function record(world)
  local e, vm = 0, 0
  for i = 1, world:body_count() do
    local b = world:body(i)
    if b:motion() == "dynamic" then
      local vx, vy = b:velocity()
      local om = b:omega()
      e = e + 0.5 * b:mass() * (vx * vx + vy * vy) + 0.5 * b:inertia() * om * om
      vm = math.max(vm, math.sqrt(vx * vx + vy * vy))
    end
  end
  local t = world:time() - t0
  ts[#ts + 1], ke[#ke + 1], vmax[#vmax + 1] = t, e, vm
  csv:row(t, e, vm)
end

return {
  world = w,
  run = { t_end = t0 + P.t_end, every = 2 * P.solve_every },
  render = { size = { 960, 420 }, camera = { -0.004, -0.004, 0.124, 0.052 },
             layers = "bodies,pressure,velocity,mesh,colorbar,title,time,scalebar",
             fluid_field = "speed", fluid_range = { 0, 0.3 }, velocity_scale = 0.02,
             time_offset = -t0,
             colors = { grain = "#e3cfa6", box = "#3a3a3a" },
             title = "Granular step collapsing in water (after Mueller et al. 2020, §6.3): speed, velocity, mesh" },
  on_frame = function(world, frame) record(world) end,
  on_finish = function(world)
    csv:close()
    local s = world:navier_stokes_stats()
    local n = math.max(s.fluid_steps, 1)
    print(string.format("coupling: largest beta (1 + D tau / m) = %.3f (body %d; stable below 2)", s.coupling_ratio, s.coupling_body))
    print(string.format("granular step: %d fluid steps, %d remeshes, %d relocations, %d Newton "
                        .. "iterations; mesh %d vertices, %d unknowns", s.fluid_steps, s.remeshes,
                        s.relocations, s.newton_iters, s.vertices, s.unknowns))
    print(string.format("cost per coupled step (ms): remesh %.1f, relocation %.1f, interpolation "
                        .. "%.1f, projection %.1f, assembly %.1f, factorization %.1f, solve %.1f, forces %.2f, "
                        .. "coupling check %.1f", 1e3 * s.t_mesh / n, 1e3 * s.t_relocate / n,
                        1e3 * s.t_interp / n, 1e3 * s.t_project / n, 1e3 * s.t_assembly / n,
                        1e3 * s.t_factor / n, 1e3 * s.t_solve / n, 1e3 * s.t_forces / n,
                        1e3 * s.t_stability / n))
    local last = ke[#ke]
    print(string.format("kinetic energy: peak %.3g J/m, at the end (t = %.3f s) %.3g J/m; largest "
                        .. "grain speed at the end %.3g m/s", math.max(table.unpack(ke)), ts[#ts],
                        last, vmax[#vmax]))
    local pos = {}
    for i = 1, #ke do pos[i] = math.max(ke[i], 1e-15) end
    porelab.chart { file = "granular_step_ke.png",
                    title = "Granular step under water: kinetic energy of the grains",
                    xlabel = "time after release (s)", ylabel = "kinetic energy (J per m)",
                    logy = true, legend = "none",
                    series = { { name = "kinetic energy", x = ts, y = pos } } }
    if P.rest_speed > 0 then
      local peak = math.max(table.unpack(ke))
      assert(vmax[#vmax] < P.rest_speed and last < 1e-8 * peak,
             string.format("the grains are not at rest at t = %.3f s: largest speed %.3g m/s "
                           .. "(limit %.3g), kinetic energy %.3g of its peak (limit 1e-8)",
                           ts[#ts], vmax[#vmax], P.rest_speed, last / peak))
      print(string.format("at rest: largest grain speed %.3g m/s < %.3g m/s, kinetic energy %.3g of its peak",
                          vmax[#vmax], P.rest_speed, last / peak))
    end
  end,
}
