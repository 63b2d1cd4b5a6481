-- Stability sweep: the grain step, rotation. A disc (radius 0.01 m, 2650 kg/m^3) rests on a
-- floor under gravity with a shear spring ks = 4 kn stiffer than its normal spring, no dashpot,
-- and friction high enough that it sticks; it is given a small sideways speed (1 mm/s). The
-- rocking mode of a sticking disc couples sliding and turning through the contact point:
-- m x'' = -ks s, I th'' = -ks a s with s = x + a th (a = r the lever arm), whose frequency is
-- sqrt(ks (1/m + a^2/I)) = sqrt(3 ks / m) for a solid disc; central differences are stable for
-- dt < 2 / omega, the engine's computed critical step here (w:dt_report().dt_critical, kind
-- "rotation", engine/src/dem/timestep.c). The sweep fixes dt at multiples of it and runs 600
-- steps (the energy guard's ratio raised: near the limit the half-step velocities the guard
-- reads overstate a stable oscillation's kinetic energy by 1 / cos^2(theta/2), 10 times at 0.95
-- of the limit). Measured: the largest sideways speed over the initial one (a stable oscillation's
-- half-step speed peaks at 1 / cos(theta/2) of it, 7 at 0.99 of the limit); failure: above 100
-- (growth) or the run stops.
local R, RHO, KN, G = 0.01, 2650, 1e6, 9.81

return {
  name = "grain_rotation",
  kind = "stability",
  title = "Grain step, rotation (disc sticking on a floor, k_s = 4 k_n)",
  quantity = "largest sideways speed / initial speed",
  unit = "1",
  sweep = { knob = "time step", unit = "s", values = { 0.5, 0.8, 0.9, 0.95, 0.99, 1.01, 1.05, 1.1, 1.5 } },
  run = function(_, res)
    local w = porelab.world { gravity = { 0, -G }, energy_surge_ratio = 1e6 }
    local m = w:material { name = "grain", density = RHO, kn = KN, ks = 4 * KN, friction = 100 }
    w:wall { from = { -0.1, 0 }, to = { 0.1, 0 }, material = m }
    local d = w:disc { center = { 0, R - RHO * math.pi * R * R * G / KN }, radius = R, material = m,
                       velocity = { 1e-3, 0 } }
    local rep = w:dt_report()
    local limit = rep.dt_critical
    w:set_flag("DT", res.value * limit)
    local amp, ok, err = 0, true, nil
    for _ = 1, 600 do
      ok, err = pcall(w.step, w, 1)
      if not ok then break end
      local vx = math.abs(d:velocity())
      amp = math.max(amp, vx / 1e-3)
      if amp > 1e6 then break end
    end
    local measure = ok and amp or 1e6
    local failed = (not ok) or measure > 100
    return { ratio = res.value, measure = measure, limit = limit, failed = failed,
             message = not ok and tostring(err):match("unstable[^;]*") or (failed and "the rocking grows" or "") }
  end,
}
