-- Stability sweep: the explicit drag coupling of the resolved Stokes model (engine/src/fluid/
-- stokes_bem, docs/stokes.md). A disc (radius 5 mm, 2000 kg/m^3) falls midway between the walls
-- of a closed box 5 cm x 10 cm filled with a liquid of mu = 5 Pa s (seed 003 §5.1). The drag is
-- computed from the velocity at the start of the step and held over solve_every steps, so the
-- speed relaxes as v_{n+1} - v_T = (1 - K dt / m) (v_n - v_T): stable for solve_every dt < 2 m / K
-- (and 2 I / K_rot for spin). The computed limit is 2 m / K with K = w:stokes_body(disc).k from
-- the model's own factorisation (the disc falls without spinning, so the spin limit 2 I / K_rot,
-- 0.64 of it here, never acts; the model's run-time refusal, dt_safe, takes the smaller of the
-- two). The sweep fixes dt at multiples of 2 m / K with check_stability = false (the refusal off)
-- and runs 60 steps from rest. Measured: the largest |v - v_T| / v_T over the last 10 steps (v_T = W' / K, the
-- terminal speed of the model's own K); failure: it exceeds 1 or the run stops.
local R, RHO, MU, B, H = 0.005, 2000, 5.0, 0.025, 0.10

local function build(dt, check)
  local w = porelab.world { gravity = { 0, -9.81 }, dt = dt }
  local m = w:material { name = "disc", density = RHO, kn = 1e6, friction = 0.3 }
  w:wall { from = { -B - 0.001, -H / 2 }, to = { B + 0.001, -H / 2 }, material = m }
  w:wall { from = { B, -H / 2 - 0.001 }, to = { B, H / 2 + 0.001 }, material = m }
  w:wall { from = { B + 0.001, H / 2 }, to = { -B - 0.001, H / 2 }, material = m }
  w:wall { from = { -B, H / 2 + 0.001 }, to = { -B, -H / 2 - 0.001 }, material = m }
  local disc = w:disc { center = { 0, 0 }, radius = R, material = m }
  w:stokes { viscosity = MU, density = 1000, disc_elements = 16, element_length = 0.005, check_stability = check }
  return w, disc
end

return {
  name = "stokes_drag",
  kind = "stability",
  title = "Stokes drag coupling (disc falling between walls)",
  quantity = "|v - v_T| / v_T, last 10 steps",
  unit = "1",
  sweep = { knob = "solve interval \u{00D7} time step", unit = "s", values = { 0.3, 0.6, 0.8, 0.9, 0.94, 0.96, 0.98, 1.02, 1.1, 1.3 } },
  run = function(_, res)
    local w0, d0 = build(1e-4, true)
    w0:stokes_solve()
    local r = w0:stokes_body(d0)
    local mass = RHO * math.pi * R * R
    local limit = 2 * mass / r.k
    local W = (RHO - 1000) * math.pi * R * R * 9.81
    local vT = W / r.k
    local w, disc = build(res.value * limit, false)
    local worst, ok, err = 0, true, nil
    for n = 1, 60 do
      ok, err = pcall(w.step, w, 1)
      if not ok then break end
      local _, vy = disc:velocity()
      if n > 50 then worst = math.max(worst, math.abs(-vy - vT) / vT) end
      if not (worst < 1e6) then break end
    end
    local failed = (not ok) or not (worst <= 1)
    return { ratio = res.value, measure = worst, limit = limit, failed = failed,
             message = not ok and ("the disc leaves the fluid: " .. (tostring(err):match("reaches through the container side of wall %d+") or tostring(err))) or (failed and "|v - v_T| > v_T" or "") }
  end,
}
