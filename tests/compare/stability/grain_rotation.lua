-- Stability sweep: the grain step, rotation. A disc (radius 0.01 m, 2650 kg/m^3) rests on a
-- floor under gravity with a shear spring ks = 4 kn stiffer than its normal spring and friction
-- high enough that it sticks; it is given a small sideways speed (1 mm/s). The engine's
-- computed critical step is then the rotational one, 2 sqrt(I / (ks r^2)) (kind "rotation",
-- engine/src/dem/timestep.c). The rocking mode of a sticking disc couples translation and
-- rotation through the contact point: m x'' = -ks s, I th'' = -ks r s with s = x + r th, whose
-- frequency is sqrt(ks (1/m + r^2/I)) = sqrt(3 ks / m) (a solid disc), so central differences
-- fail at sqrt(2/3) = 0.816 of the computed limit. Measured: the largest sideways speed over the
-- initial one; failure: the guards stop the run or it exceeds 10.
local R, RHO, KN, G = 0.01, 2650, 1e6, 9.81

return {
  name = "grain_rotation",
  kind = "stability",
  title = "Grain step, rotation (disc sticking on a floor, ks = 4 kn)",
  quantity = "largest sideways speed / initial speed",
  unit = "1",
  sweep = { knob = "time step", unit = "s", values = { 0.5, 0.7, 0.78, 0.8, 0.83, 0.86, 0.9, 1.0, 1.2, 1.5 } },
  run = function(_, res)
    local w = porelab.world { gravity = { 0, -G } }
    local m = w:material { name = "grain", density = RHO, kn = KN, ks = 4 * KN, friction = 100 }
    w:wall { from = { -0.1, 0 }, to = { 0.1, 0 }, material = m }
    local d = w:disc { center = { 0, R - 2 * RHO * math.pi * R * R * G / KN }, radius = R, material = m,
                       velocity = { 1e-3, 0 } }
    local rep = w:dt_report()
    local limit = rep.dt_critical
    w:set_flag("DT", res.value * limit)
    local V0 = 1e-3
    local amp, ok, err = 0, true, nil
    for _ = 1, 600 do
      ok, err = pcall(w.step, w, 1)
      if not ok then break end
      local vx = d:velocity()
      amp = math.max(amp, math.abs(vx) / V0)
      if amp > 1e6 then break end
    end
    local failed = (not ok) or amp > 10
    return { ratio = res.value, measure = amp, limit = limit, failed = failed,
             message = not ok and tostring(err):match("unstable[^;]*") or (failed and "amplitude > 10" or "") }
  end,
}
