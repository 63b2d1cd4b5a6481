-- Stability sweep: the staggered grain-water coupling under undrained loading
-- (FLUID_CONSOLIDATION with a compressible pore fluid). Sixteen discs (radius 4 mm,
-- 2650 kg/m^3, soft contacts kn = 100 N/m so that the contacts do not limit the step) in a
-- sealed 4 cm box filled by a Darcy mesh (8 x 8 cells, conductivity 1e-4 m/s, K_f = 1e6 Pa, no
-- gravity); the discs start with small velocities (1 mm/s, alternating). The fluid is solved
-- every grain step, so the grains feel the pressure of the previous update: an explicit spring.
-- The computed limit (engine/src/fluid/darcy/darcy_stagger.c, w:fluid_stats().stagger_dt_limit):
--   dt < 2 sqrt(m / k),  k = K_f d^2 / (n A_e) / (1 + dt / tau),  tau = (n rho_f g / K_f) A_e / D
-- (the undrained spring of a grain of diameter d in elements of area A_e, relaxed by the seepage
-- between neighbouring elements over the step). The sweep fixes dt at multiples of that limit
-- with FLUID_STAGGER_CHECK 0 (the check off) and runs 400 steps. Measured: the largest kinetic
-- energy over the initial one; failure: the guards stop the run or it exceeds 100.
local R, RHO = 0.004, 2650

local function build(dt)
  local w = porelab.world { gravity = { 0, 0 }, dt = dt }
  local m = w:material { name = "grain", density = RHO, kn = 100, friction = 0.3 }
  local L = 0.04
  w:wall { from = { 0, 0 }, to = { L, 0 }, material = m }
  w:wall { from = { L, 0 }, to = { L, L }, material = m }
  w:wall { from = { L, L }, to = { 0, L }, material = m }
  w:wall { from = { 0, L }, to = { 0, 0 }, material = m }
  local k = 0
  for i = 0, 3 do
    for j = 0, 3 do
      k = k + 1
      local s = (k % 2 == 0) and 1 or -1
      w:disc { center = { 0.005 + 0.01 * i, 0.005 + 0.01 * j }, radius = R, material = m,
               velocity = { 1e-3 * s, -1e-3 * s } }
    end
  end
  w:fluid_quad { corners = { { 0, 0 }, { L, 0 }, { L, L }, { 0, L } }, ndivx = 8, ndivy = 8 }
  w:darcy { on = true, consolidation = true, bulk_modulus = 1e6, storage = 0, perm_mode = 0,
            perm_high = 1e-4, solve_every = 1, stagger_check = false }
  return w
end

return {
  name = "undrained_stagger",
  kind = "stability",
  title = "Grain - undrained water staggering (K_f = 1e6 Pa)",
  quantity = "largest kinetic energy / initial",
  unit = "1",
  sweep = { knob = "time step", unit = "s", values = { 0.3, 0.6, 0.8, 0.9, 0.95, 1.0, 1.1, 1.25, 1.5, 2, 3, 5 } },
  run = function(_, res)
    -- the limit at the start (it depends on dt through the seepage relaxation: iterate)
    local lim = 1e-4
    for _ = 1, 20 do
      local w = build(res.value * lim)
      w:step(3)
      lim = w:fluid_stats().stagger_dt_limit
    end
    local w = build(res.value * lim)
    local e0 = w:energy().kinetic
    local worst, ok, err = 1, true, nil
    for _ = 1, 400 do
      ok, err = pcall(w.step, w, 1)
      if not ok then break end
      worst = math.max(worst, w:energy().kinetic / e0)
      if worst > 1e8 then break end
    end
    local failed = (not ok) or worst > 100
    return { ratio = res.value, measure = worst, limit = lim, failed = failed,
             message = not ok and tostring(err):match("unstable[^;]*") or (failed and "kinetic energy x 100" or "") }
  end,
}
