-- Stability sweep: the explicit finite-element solid (engine/src/solid, docs/solids.md; central
-- differences on lumped masses). A steel cantilever 0.1 m x 0.02 m of 10 x 2 cells of linear
-- triangles (plain displacement form), clamped at its left end, no gravity, set swinging by an
-- initial velocity of 0.1 m/s. The computed limit is the solid's own critical step
-- (w:solid_info().critical_dt: 2 / omega_max bounded element by element, the largest eigenvalue
-- of each element's stiffness over its lumped mass); the sweep fixes dt at multiples of it and
-- runs 400 steps. Above the limit the solid refuses the step before it is taken (the run-time
-- check, ctest cli_guard_solid_step): the model has no switch to turn the check off, so this sweep
-- shows the stable side and the refusal; the element-by-element bound is an upper bound on the
-- mesh's highest frequency, so the true boundary lies at or above the computed limit. Measured: the largest kinetic + elastic energy over that after the first step
-- (about 1 for a stable undamped swing); failure: the run stops or it exceeds 10.
local function build()
  local w = porelab.world { gravity = { 0, 0 } }
  w:solid { young = 2e11, poisson = 0.3, density = 7800, formulation = "plain" }
  w:solid_rectangle { x0 = 0, y0 = 0, x1 = 0.1, y1 = 0.02, nx = 10, ny = 2 }
  w:solid_fix { box = { -1e-6, -1e-6, 1e-6, 0.02 + 1e-6 }, x = true, y = true }
  w:solid_initial_velocity { box = { 1e-6, -1, 1, 1 }, vy = 0.1 }
  return w
end

return {
  name = "solid_step",
  kind = "stability",
  title = "Explicit FE solid (steel cantilever, linear triangles)",
  quantity = "largest (kinetic + elastic) / after the first step",
  unit = "1",
  sweep = { knob = "time step", unit = "s", values = { 0.3, 0.6, 0.9, 0.95, 0.99, 1.01, 1.05, 1.1, 1.5 } },
  run = function(_, res)
    local w = build()
    local limit = w:solid_info().critical_dt
    w:set_flag("DT", res.value * limit)
    local ok, err = pcall(w.step, w, 1)
    local e1 = w:solid_energy()
    local e0 = e1.kinetic + e1.elastic
    local worst = 0
    for _ = 2, 400 do
      if not ok then break end
      ok, err = pcall(w.step, w, 1)
      if not ok then break end
      local e = w:solid_energy()
      worst = math.max(worst, (e.kinetic + e.elastic) / e0)
      if not (worst < 1e12) then break end
    end
    local failed = (not ok) or not (worst <= 10)
    return { ratio = res.value, measure = worst, limit = limit, failed = failed,
             message = not ok and (tostring(err):match("exceeds the critical step") and "refused: dt exceeds the critical step"
                                   or tostring(err)) or (failed and "energy x 10" or "") }
  end,
}
