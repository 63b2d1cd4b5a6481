-- Benchmark problem: the pressure wave of seed 000 §4.3 (Figs. 4-10 to 4-12), as in
-- tests/fluid/wave_rod.h. A 1 m x 0.1 m rod, no gravity, D = 1 m/s, storage S = 1 1/m, head
-- 1 m at x = 0 and 0 at x = 1 from t = 0 (0 everywhere before). While the wave has not
-- reached the far end the head is h(x, t) = erfc(x / (2 sqrt(D t / S))) (Carslaw & Jaeger
-- 1959, §2.4). Measured: the head at x = 0.2 m, t = 0.01 s: erfc(1) = 0.157299207050285.
--
-- Methods answer it with problems.wave = {knob, unit, values, attach = function(w, ctx, value)}:
-- attach puts its model on the world w (ctx.darcy_mesh builds the rod's mesh and boundary lines
-- for a Darcy method) and returns {steps = N}, the number of fluid steps to t_end (default 1).
local ctx = { length = 1.0, height = 0.1, conductivity = 1.0, storage = 1.0, t_end = 0.01,
              probe = { 0.2, 0.05 } }

function ctx.darcy_mesh(w, cells)
  w:fluid_quad { corners = { { 0, 0 }, { ctx.length, 0 }, { ctx.length, ctx.height }, { 0, ctx.height } },
                 ndivx = cells, ndivy = 1 }
  w:fluid_bc { from = { 0, 0 }, to = { 0, ctx.height }, head = 1.0 }
  w:fluid_bc { from = { ctx.length, 0 }, to = { ctx.length, ctx.height }, head = 0.0 }
  w:darcy { on = true, perm_mode = 0, perm_high = ctx.conductivity, storage = ctx.storage, drag = false }
  w:fluid_set_pressure_head(0.0)
end

return {
  name = "wave",
  title = "Pressure wave in a rod (Klosek 1997 §4.3)",
  quantity = "head at x = 0.2 m, t = 0.01 s",
  unit = "m",
  reference = { value = 0.157299207050285, source = "erfc(x / 2 sqrt(D t / S)), Carslaw & Jaeger 1959 2.4" },
  run = function(method, res)
    local w = porelab.world { gravity = { 0, 0 } }
    local opts = method.problems.wave.attach(w, ctx, res.value) or {}
    local steps = opts.steps or 1
    for _ = 1, steps do w:fluid_advance(ctx.t_end / steps) end
    local _, head = w:fluid_pressure_at(ctx.probe[1], ctx.probe[2])
    return head
  end,
}
