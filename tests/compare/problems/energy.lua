-- Benchmark problem: energy conservation of an elastic impact. Two equal discs (radius 0.01 m,
-- 2650 kg/m^3, kn = 1e6 N/m, no damping: restitution 1) meet head-on at 1 m/s each, no
-- gravity, no friction. An exact integration conserves the kinetic energy; the central
-- difference scheme conserves a shadow energy, so the kinetic energy after the contact differs
-- from before by O(dt^2) (Hairer, Lubich & Wanner, Geometric Numerical Integration, 2006,
-- ch. IX). Measured: kinetic energy after / before (reference 1).
--
-- Methods: problems.energy = {knob, unit, values, attach = function(w, ctx, value)} returning
-- {dt_safety = fraction of the critical step} or {dt = step}.
local ctx = { radius = 0.01, density = 2650, kn = 1e6, v = 1.0 }

return {
  name = "energy",
  title = "Kinetic energy after an elastic impact of two discs",
  quantity = "kinetic energy after / before",
  unit = "1",
  reference = { value = 1.0, source = "energy conservation (restitution 1)" },
  run = function(method, res)
    local opts = method.problems.energy.attach(nil, ctx, res.value) or {}
    local w = porelab.world { gravity = { 0, 0 }, dt_safety = opts.dt_safety, dt = opts.dt }
    local m = w:material { name = "disc", density = ctx.density, kn = ctx.kn, friction = 0, restitution = 1 }
    local r = ctx.radius
    local a = w:disc { center = { -r - 0.001, 0 }, radius = r, material = m, velocity = { ctx.v, 0 } }
    local b = w:disc { center = { r + 0.001, 0 }, radius = r, material = m, velocity = { -ctx.v, 0 } }
    local e0 = w:energy().kinetic
    w:run_until(0.001 / ctx.v + 0.006)
    return w:energy().kinetic / e0
  end,
}
