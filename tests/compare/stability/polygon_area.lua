-- Stability sweep: the grain step for a polygon pressed on a face. The area law (seed 004
-- eq. 1: F = kn A / l_c, engine/src/dem/contact_polygon.c) makes a face of length L at distance
-- h from the centroid a spring kn L / h against a wall (l_c = h), 2 kn for a square; the
-- engine's computed critical step (w:dt_report().dt_critical, kind "polygon face",
-- engine/src/dem/timestep.c) is 2 / omega of that spring for a square that does not turn.
-- A square (side 2 cm, 2650 kg/m^3, kn = 1e6, no friction, restitution 1: undamped, rotation
-- held) rests face down on a floor under gravity, let go 10 % of the static depth m g / (2 kn)
-- below its equilibrium so that it stays in contact. The sweep fixes dt at multiples of the
-- computed limit and runs 1000 steps (the energy guard's ratio raised, as for the disc).
-- Measured: the largest distance from the equilibrium over the initial one (about 1 when
-- stable); failure: above 10 or the run stops.
local S, RHO, KN, G = 0.02, 2650, 1e6, 9.81

return {
  name = "polygon_area",
  kind = "stability",
  title = "Grain step, polygon on its face (area law)",
  quantity = "oscillation amplitude / initial amplitude",
  unit = "1",
  sweep = { knob = "time step", unit = "s", values = { 0.5, 0.8, 0.9, 0.95, 0.99, 1.01, 1.05, 1.1, 1.5 } },
  run = function(_, res)
    local w = porelab.world { gravity = { 0, -G }, energy_surge_ratio = 1e6 }
    local m = w:material { name = "grain", density = RHO, kn = KN, friction = 0, restitution = 1 }
    w:wall { from = { -0.1, 0 }, to = { 0.1, 0 }, material = m }
    local static = RHO * S * S * G / (2 * KN)
    local yeq = S / 2 - static
    local sq = w:rectangle { center = { 0, yeq - 0.1 * static }, width = S, height = S, material = m,
                             fixed_rotation = true }
    local limit = w:dt_report().dt_critical
    w:set_flag("DT", res.value * limit)
    local amp, ok, err = 0, true, nil
    for _ = 1, 1000 do
      ok, err = pcall(w.step, w, 1)
      if not ok then break end
      local _, y = sq:position()
      amp = math.max(amp, math.abs(y - yeq) / (0.1 * static))
      if amp > 1e6 then break end
    end
    local failed = (not ok) or amp > 10
    return { ratio = res.value, measure = amp, limit = limit, failed = failed,
             message = not ok and tostring(err):match("unstable[^;]*") or (failed and "amplitude > 10" or "") }
  end,
}
