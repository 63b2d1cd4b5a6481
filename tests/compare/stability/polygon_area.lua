-- Stability sweep: the grain step for polygons, whose contact force follows the overlap area
-- (seed 004 eq. 1: F = kn A / l_c, engine/src/dem/contact_polygon.c), so the spring a face
-- presents is dF/d(depth) = kn w / l_c (w the overlap's chord, l_c the characteristic length),
-- not kn. A square (side 2 cm, 2650 kg/m^3, kn = 1e6, no friction, restitution 1: undamped)
-- is let go face down touching a floor, no rotation, under gravity: a mass on that spring. The
-- engine's computed critical step (w:dt_report().dt_critical) takes kn as the spring:
-- 2 sqrt(m / kn). The sweep fixes dt at multiples of it and runs 1000 steps (the energy guard's
-- ratio raised: released at rest touching, the square's energy budget is nearly zero). Released
-- at rest, an undamped square dips and comes back at most to its release height; a step that
-- feeds energy in lifts it above. Measured: the largest rise above the release height over the
-- depth of the first dip; failure: above 0.1 or the run stops.
local S, RHO, KN, G = 0.02, 2650, 1e6, 9.81

return {
  name = "polygon_area",
  kind = "stability",
  title = "Grain step, polygon on its face (area law)",
  quantity = "largest rise above release / first dip",
  unit = "1",
  sweep = { knob = "time step", unit = "s", values = { 0.2, 0.3, 0.4, 0.5, 0.55, 0.6, 0.65, 0.7, 0.8, 1.0, 1.3 } },
  run = function(_, res)
    local w = porelab.world { gravity = { 0, -G }, energy_surge_ratio = 1e6 }
    local m = w:material { name = "grain", density = RHO, kn = KN, friction = 0, restitution = 1 }
    w:wall { from = { -0.1, 0 }, to = { 0.1, 0 }, material = m }
    local sq = w:rectangle { center = { 0, S / 2 }, width = S, height = S, material = m, fixed_rotation = true }
    local limit = w:dt_report().dt_critical
    w:set_flag("DT", res.value * limit)
    local dip, rise, ok, err = 0, 0, true, nil
    for n = 1, 1000 do
      ok, err = pcall(w.step, w, 1)
      if not ok then break end
      local _, y = sq:position()
      if n <= 50 then dip = math.max(dip, S / 2 - y) end
      rise = math.max(rise, y - S / 2)
      if dip > 0 and rise > 100 * dip then break end
    end
    local measure = dip > 0 and rise / dip or 0
    local failed = (not ok) or not (measure <= 0.1)
    return { ratio = res.value, measure = measure, limit = limit, failed = failed,
             message = not ok and tostring(err):match("unstable[^;]*") or (failed and "the square jumps off the floor" or "") }
  end,
}
