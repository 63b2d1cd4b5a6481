-- Benchmark problem: the coefficient of restitution of a disc hitting a wall head-on (no
-- gravity). Disc radius 0.01 m, 2650 kg/m^3, kn = 1e6 N/m, restitution e = 0.5 given to the
-- material: the linear spring-dashpot's damping ratio is set from e so that an exact
-- integration of the contact gives v_out / v_in = e (Tsuji et al. 1992; docs/method-dem.md).
-- Measured: -v_out / v_in after the disc left the wall.
--
-- Methods: problems.restitution = {knob, unit, values, attach = function(w, ctx, value)}
-- returns {dt_safety = fraction of the critical step} or {dt = step}.
local ctx = { radius = 0.01, density = 2650, kn = 1e6, e = 0.5, v_in = 1.0 }

return {
  name = "restitution",
  title = "Restitution of a disc hitting a wall (e = 0.5)",
  quantity = "restitution v_out / v_in",
  unit = "1",
  reference = { value = ctx.e, source = "the material's restitution (spring-dashpot, Tsuji et al. 1992)" },
  run = function(method, res)
    local opts = method.problems.restitution.attach(nil, ctx, res.value) or {}
    local w = porelab.world { gravity = { 0, 0 }, dt_safety = opts.dt_safety, dt = opts.dt }
    local wall = w:material { name = "wall", density = 2650, kn = ctx.kn, friction = 0, restitution = ctx.e }
    local m = w:material { name = "disc", density = ctx.density, kn = ctx.kn, friction = 0, restitution = ctx.e }
    w:wall { from = { -0.1, 0 }, to = { 0.1, 0 }, material = wall }
    local r = ctx.radius
    local disc = w:disc { center = { 0, r + 0.002 }, radius = r, material = m, velocity = { 0, -ctx.v_in } }
    local dt = w:dt()
    -- the contact lasts pi sqrt(m / k) ~ 1.6e-3 s; run until the disc is clear of the wall
    w:run_until(0.002 / ctx.v_in + 0.01)
    local _, vy = disc:velocity()
    return vy / ctx.v_in
  end,
}
