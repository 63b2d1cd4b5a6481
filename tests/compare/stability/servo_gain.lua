-- Stability sweep: the servo wall (seed 003 eqs. 5.11-5.12, engine/src/dem/motion): a lid held
-- at a force F = 100 N moves with v = G (F - F_c) / F, F_c the contact force it feels. The lid
-- presses on a very heavy disc (1e9 kg/m^3: its own oscillation on the contact springs,
-- period 2 pi sqrt(m / 2k) = 2.4 s, is frozen over the run) through one contact of kn = 1e6 N/m,
-- dt = 1e-5 s, no gravity. Then F_c changes by k v dt per step and the force error by the
-- factor 1 - G k dt / F: the servo is stable for G < 2 F / (k dt) = 20 m/s, the limit the
-- run-time check in engine/src/dem/guards.c enforces (with k the sum of kn of the lid's
-- contacts). The sweep sets G at multiples of that limit (vmax far above any speed reached) and
-- runs 400 steps from first touch. To see the scheme itself past the limit, the world checks its
-- guards only at the end of each w:step call (guard_interval = 1e9) and the sweep steps in
-- chunks that end between the servo check's steps (every tenth); ctest cli_guard_servo_gain
-- shows the check. Measured: the largest |F_c - F| / F over the last 100 steps (sampled every
-- 10); failure: above 0.5 (the lid bounces off the disc) or the run stops.
local KN, F, DT = 1e6, 100, 1e-5

return {
  name = "servo_gain",
  kind = "stability",
  title = "Servo wall on a stiff contact (force 100 N, k_n = 1e6 N/m)",
  quantity = "largest |F_c - F| / F, last 100 steps",
  unit = "1",
  sweep = { knob = "servo gain", unit = "m/s", values = { 0.3, 0.6, 0.9, 0.95, 0.99, 1.01, 1.05, 1.1, 1.5, 2, 3 } },
  run = function(_, res)
    local limit = 2 * F / (KN * DT)
    local w = porelab.world { gravity = { 0, 0 }, dt = DT, guard_interval = 1000000000 }
    local m = w:material { name = "steel", density = 1e9, kn = KN, friction = 0, restitution = 1 }
    w:wall { from = { -0.02, -0.01 }, to = { 0.02, -0.01 }, material = m }
    w:disc { center = { 0, 0 }, radius = 0.01, material = m }
    local lid = w:wall { from = { 0.02, 0.01 }, to = { -0.02, 0.01 }, material = m }
    lid:servo { direction = { 0, -1 }, force = F, gain = res.value * limit, vmax = 1e3 }
    local worst, ok, err = 0, true, nil
    ok, err = pcall(w.step, w, 5)            -- steps 1-5; then chunks of 10 end at 15, 25, ...
    for c = 1, 40 do
      if not ok then break end
      ok, err = pcall(w.step, w, 10)
      if ok and c > 30 then
        local _, fy = lid:force()
        worst = math.max(worst, math.abs(fy - F) / F)
      end
    end
    local failed = (not ok) or not (worst <= 0.5)
    return { ratio = res.value, measure = worst, limit = limit, failed = failed,
             message = not ok and tostring(err):match("unstable[^;]*") or (failed and "the lid bounces off the disc" or "") }
  end,
}
