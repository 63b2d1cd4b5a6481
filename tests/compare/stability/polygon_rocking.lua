-- Stability sweep: the grain step for a polygon sticking on a face, free to turn. On a face of
-- length L at distance h from the centroid the area law (seed 004, contact_polygon.c) makes a
-- tangential spring ks L / h acting at the lever arm h and a rocking spring kn L^3 / (12 h) (the
-- moment of the pressure kn d(x) / h across the face); with the sliding and the turning coupled,
-- the highest frequency is the largest eigenvalue of that 2 x 2 problem (with the normal spring,
-- 3 x 3), omega^2 = 4 kn / m for a square with the default ks = 2/3 kn. The engine's computed
-- critical step (kind "polygon face", engine/src/dem/timestep.c) is 2 / omega. A square (side
-- 2 cm, 2650 kg/m^3, kn = 1e6, no dashpot, friction high enough that it sticks) rests face down
-- on a floor at its static depth and is given a sideways speed of 1 mm/s; the sweep fixes dt at
-- multiples of the computed limit and runs 600 steps (the energy guard's ratio raised, see
-- grain_rotation.lua). Measured: the largest sideways speed over the initial one; failure: above
-- 100 (growth) or the run stops.
local S, RHO, KN, G = 0.02, 2650, 1e6, 9.81

return {
  name = "polygon_rocking",
  kind = "stability",
  title = "Grain step, polygon sticking on its face (sliding and rocking)",
  quantity = "largest sideways speed / initial speed",
  unit = "1",
  sweep = { knob = "time step", unit = "s", values = { 0.5, 0.8, 0.9, 0.95, 0.99, 1.01, 1.05, 1.1, 1.5 } },
  run = function(_, res)
    local w = porelab.world { gravity = { 0, -G }, energy_surge_ratio = 1e6 }
    local m = w:material { name = "grain", density = RHO, kn = KN, friction = 100 }
    w:wall { from = { -0.1, 0 }, to = { 0.1, 0 }, material = m }
    local static = RHO * S * S * G / (2 * KN)
    local sq = w:rectangle { center = { 0, S / 2 - static }, width = S, height = S, material = m,
                             velocity = { 1e-3, 0 } }
    local limit = w:dt_report().dt_critical
    w:set_flag("DT", res.value * limit)
    local amp, ok, err = 0, true, nil
    for _ = 1, 600 do
      ok, err = pcall(w.step, w, 1)
      if not ok then break end
      local vx = math.abs(sq:velocity())
      amp = math.max(amp, vx / 1e-3)
      if amp > 1e6 then break end
    end
    local measure = ok and amp or 1e6
    local failed = (not ok) or measure > 100
    return { ratio = res.value, measure = measure, limit = limit, failed = failed,
             message = not ok and tostring(err):match("unstable[^;]*") or (failed and "the rocking grows" or "") }
  end,
}
