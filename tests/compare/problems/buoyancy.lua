-- Benchmark problem: a floating block. A wooden block (0.10 m x 0.05 m, 600 kg/m^3) is let go
-- 5 mm above its floating position in a 0.4 m wide tank of still water 0.3 m deep
-- (1000 kg/m^3); mass-proportional damping (rayleigh_alpha = 10 1/s) brings it to rest.
-- Archimedes: at rest it displaces its own weight, so its draft is (rho_b / rho_f) B = 0.030 m.
-- Measured: the draft (water level minus the block's underside) averaged over the last 0.3 s of
-- a 2.5 s run.
--
-- Methods: problems.buoyancy = {knob, unit, values, attach = function(w, ctx, value)} puts the
-- water (ctx.tank: x_min, x_max, bottom, level, density) on the world and returns
-- {dt = grain step} (default: automatic).
local ctx = { tank = { x_min = 0, x_max = 0.4, bottom = 0, level = 0.3, density = 1000 },
              block = { width = 0.10, height = 0.05, density = 600 } }
local B = ctx.block.height
local draft = ctx.block.density / ctx.tank.density * B

return {
  name = "buoyancy",
  title = "A floating block: its draft at rest",
  quantity = "draft of the block",
  unit = "m",
  reference = { value = draft, source = "Archimedes: draft = (rho_b / rho_f) B" },
  run = function(method, res)
    local w = porelab.world { gravity = { 0, -9.81 }, rayleigh_alpha = 10 }
    local wall = w:material { name = "tank", density = 2500, kn = 2e5, friction = 0.4, restitution = 0.2 }
    local wood = w:material { name = "wood", density = ctx.block.density, kn = 2e5, friction = 0.4,
                              restitution = 0.2 }
    local T = ctx.tank
    w:wall { from = { T.x_min - 0.02, T.bottom }, to = { T.x_max + 0.02, T.bottom }, material = wall }
    w:wall { from = { T.x_min, T.bottom }, to = { T.x_min, 0.45 }, material = wall }
    w:wall { from = { T.x_max, T.bottom }, to = { T.x_max, 0.45 }, material = wall }
    local yc = T.level - draft + B / 2 + 0.005
    local block = w:rectangle { center = { (T.x_min + T.x_max) / 2, yc }, width = ctx.block.width,
                                height = B, material = wood, fixed_rotation = true }
    local opts = method.problems.buoyancy.attach(w, ctx, res.value) or {}
    if opts.dt then w:set_flag("DT", opts.dt) end
    w:run_until(2.2)
    local sum, n = 0, 0
    while w:time() < 2.5 do
      w:step(1)
      local _, y = block:position()
      sum = sum + (T.level - (y - B / 2))
      n = n + 1
    end
    return sum / n
  end,
}
