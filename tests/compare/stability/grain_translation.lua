-- Stability sweep: the grain step, translation. A disc (radius 0.01 m, 2650 kg/m^3) rests on a
-- wall under gravity on an undamped linear spring kn = 1e6 N/m: a mass on a spring, so central
-- differences are stable for dt < 2 sqrt(m / kn) (seed 003 §2.2.4.4; the engine's computed
-- critical step, w:dt_report().dt_critical, kind "translation"). The sweep fixes dt at a
-- multiple of that limit and runs 600 steps from rest 10 % of the static overlap m g / kn above
-- the equilibrium (so it stays in contact). Measured: the largest distance from the
-- equilibrium over that initial distance (about 1 for a stable oscillation);
-- failure: the guards stop the run (energy surge, overlap, non-finite state) or the amplitude
-- exceeds 10.
local R, RHO, KN, G = 0.01, 2650, 1e6, 9.81

return {
  name = "grain_translation",
  kind = "stability",
  title = "Grain step, translation (disc on a spring)",
  quantity = "oscillation amplitude / initial amplitude",
  unit = "1",
  sweep = { knob = "time step", unit = "s", values = { 0.5, 0.8, 0.9, 0.95, 0.99, 1.01, 1.05, 1.1, 1.5, 2 } },
  run = function(_, res)
    local w = porelab.world { gravity = { 0, -G } }
    local m = w:material { name = "grain", density = RHO, kn = KN, friction = 0 }
    w:wall { from = { -0.1, 0 }, to = { 0.1, 0 }, material = m }
    local area = math.pi * R * R
    local static = RHO * area * G / KN
    local yeq = R - static
    local d = w:disc { center = { 0, yeq + 0.1 * static }, radius = R, material = m, fixed_rotation = true }
    local rep = w:dt_report()
    local limit = rep.dt_critical
    w:set_flag("DT", res.value * limit)
    local amp, ok, err = 0, true, nil
    for _ = 1, 600 do
      ok, err = pcall(w.step, w, 1)
      if not ok then break end
      local _, y = d:position()
      amp = math.max(amp, math.abs(y - yeq) / (0.1 * static))
      if amp > 1e6 then break end
    end
    local failed = (not ok) or amp > 10
    return { ratio = res.value, measure = amp, limit = limit, failed = failed,
             message = not ok and tostring(err):match("unstable[^;]*") or (failed and "amplitude > 10" or "") }
  end,
}
