-- Seed 003 §5.1 (Tan 1990): one disc falling midway between two parallel walls in a viscous
-- liquid, the fluid resolved by boundary elements (docs/stokes.md). The seed's case in SI
-- units: disc r = 0.5 cm, rho_s = 2000 kg/m^3, liquid rho_l = 1000 kg/m^3, mu = 5 Pa s (50 P),
-- walls 2b = 5 cm apart and 40 cm high, g = 9.80 m/s^2.
-- The disc reaches its terminal velocity within a few hundredths of a second. References:
-- v = (rho_s - rho_l) pi r^2 g / K with K from Faxén's series (0.9312 cm/s) and from Takaisi's
-- formula as printed in the seed (eq. 5.1: 0.9535 cm/s; Tan's own BEM: 0.9306 cm/s). The scene
-- prints v and both, and charts v(t) against the exact solution of m dv/dt = W' - K v.
-- Run:   porelab run scenes/stokes/falling_disc.lua --out out/falling_disc
local R, RHO_S, RHO_L, MU, B, H, G = 0.005, 2000, 1000, 5.0, 0.025, 0.40, 9.80
local DT = 5e-4
local w = porelab.world { gravity = { 0, -G }, dt = DT }
local mat = w:material { name = "disc", density = RHO_S, kn = 1e6, friction = 0.3 }
w:wall { from = { -B - 0.01, -H / 2 }, to = { B + 0.01, -H / 2 }, material = mat }
w:wall { from = { B, -H / 2 - 0.01 }, to = { B, H / 2 + 0.01 }, material = mat }
w:wall { from = { B + 0.01, H / 2 }, to = { -B - 0.01, H / 2 }, material = mat }
w:wall { from = { -B, H / 2 + 0.01 }, to = { -B, -H / 2 - 0.01 }, material = mat }
local disc = w:disc { center = { 0, 0 }, radius = R, material = mat }
w:stokes { viscosity = MU, density = RHO_L, disc_elements = 32, element_length = 0.004, field_grid = 100 }

local k = R / B
local A = math.pi * R * R
local W = (RHO_S - RHO_L) * A * G
local K_faxen = MU * 4 * math.pi / (math.log(1 / k) - 0.9157 + 1.7244 * k ^ 2 - 1.7302 * k ^ 4 + 2.4056 * k ^ 6
                                    - 4.5913 * k ^ 8)
local K_takaisi = MU * math.pi * (8 - 4 * k ^ 2) / (2 * math.log(1 / k) + 3.4486 * k ^ 2 - 1.8312)
local ts, vs, vf = {}, {}, {}
local m = RHO_S * A
local done = false

return {
  world = w,
  run = { t_end = 0.05, fps = 100 },
  render = { size = { 640, 800 }, camera = { -0.032, -0.030, 0.032, 0.030 },
             layers = "bodies,pressure,velocity,colorbar,title,time", fluid_field = "excess_pressure", fluid_range = { -25, 25 },
             title = "Disc falling between walls (Stokes flow)" },
  on_frame = function(world, frame)
    local _, vy = disc:velocity()
    ts[#ts + 1] = world:time(); vs[#vs + 1] = -100 * vy
    vf[#vf + 1] = 100 * W / K_faxen * (1 - math.exp(-K_faxen * world:time() / m))
    if world:time() >= 0.05 - 1e-9 and not done then
      done = true
      local v = -vy
      local r = world:stokes_body(disc)
      print(string.format("terminal velocity %.4f cm/s; Faxen %.4f (%+.2f %%); Takaisi (seed eq. 5.1) %.4f (%+.2f %%); "
                          .. "Tan 0.9306; K = %.2f N s/m^2, stable step %.2e s", 100 * v, 100 * W / K_faxen,
                          100 * (v * K_faxen / W - 1), 100 * W / K_takaisi, 100 * (v * K_takaisi / W - 1), r.k, r.dt_safe))
      porelab.chart { file = "falling_disc_velocity.png", title = "Disc falling between walls (Tan 1990, 5.1)",
                      xlabel = "time (s)", ylabel = "fall velocity (cm/s)",
                      series = { { name = "boundary elements", x = ts, y = vs, style = "points" },
                                 { name = "m dv/dt = W' - K v, K from Faxen", x = ts, y = vf, style = "dashed",
                                   color = "#222222" } },
                      legend = "bottom right" }
    end
  end,
}
