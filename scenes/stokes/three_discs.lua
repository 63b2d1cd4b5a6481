-- Seed 003 §5.2 (Tan 1990): three identical discs sedimenting side by side in a large container
-- of viscous liquid, the fluid resolved by boundary elements (docs/stokes.md). The discs never
-- touch: the problem is one of fluid-solid interaction only, and the walls make it asymmetric
-- (Tan's Fig. 5.4-5.8; Durlofsky et al.'s three spheres in a vertical plane are the
-- unbounded analogue).
-- The seed's case in SI units: discs r = 1 cm, liquid rho_l = 1000 kg/m^3, mu = 10 Pa s
-- (100 P); disc centres 1.16 m from the left wall, then 5 cm and 7 cm apart, the right wall
-- 72 cm from disc 3 (a container 2.00 m wide), 8.10 m above the floor; the container's top is
-- not given (taken 9.00 m). The seed prints the discs' density as rho_s = 1 g/cm^3 -- the
-- liquid's own, with which nothing would sediment; its fall speeds (about 20 cm/s at most,
-- Re = 0.4) need rho_s = 2 g/cm^3, used here (the same as §5.1).
-- Frames: excess pressure and fluid velocity around the discs' start; the panel on the right
-- draws the trajectories so far with the horizontal scale exaggerated (as the seed's Fig. 5.5).
-- At the end the scene charts the trajectories and x(t), y(t) (three_discs_*.png).
-- Run:   porelab run scenes/stokes/three_discs.lua --out out/three_discs
local R, RHO_S, RHO_L, MU, G = 0.01, 2000, 1000, 10.0, 9.80
local W, H = 2.00, 9.00
local X = { 1.16, 1.21, 1.28 }
local Y0 = 8.10
local T_END = 40
local DT = 0.004
local w = porelab.world { gravity = { 0, -G }, dt = DT }
local mat = w:material { name = "disc", density = RHO_S, kn = 1e6, friction = 0.3 }
w:wall { from = { -0.05, 0 }, to = { W + 0.05, 0 }, material = mat }
w:wall { from = { W, -0.05 }, to = { W, H + 0.05 }, material = mat }
w:wall { from = { W + 0.05, H }, to = { -0.05, H }, material = mat }
w:wall { from = { 0, H + 0.05 }, to = { 0, -0.05 }, material = mat }
local discs = {}
for k = 1, 3 do discs[k] = w:disc { center = { X[k], Y0 }, radius = R, material = mat } end
w:stokes { viscosity = MU, density = RHO_L, disc_elements = 16, element_length = 0.1, field_grid = 160 }

local COLORS = { "#1f4e9c", "#9b2226", "#2a7f3f" }
local hist = { t = {}, x = { {}, {}, {} }, y = { {}, {}, {} }, vy = { {}, {}, {} } }

-- trajectory panel in pixels (right part of the frame): x - x0 in cm across, height in m down
local PX0, PY0, PW, PH = 600, 80, 280, 620
local XR, YR = { -6, 6 }, { 0, 8.4 }
local function panel()
  local items = { { polygon = { { PX0, PY0 }, { PX0 + PW, PY0 }, { PX0 + PW, PY0 + PH }, { PX0, PY0 + PH } },
                    color = "#444444", width = 1, fill = "#ffffff", space = "pixel" } }
  local function px(x, y)
    x = math.max(XR[1], math.min(XR[2], x))
    return { PX0 + (x - XR[1]) / (XR[2] - XR[1]) * PW, PY0 + PH - (y - YR[1]) / (YR[2] - YR[1]) * PH }
  end
  items[#items + 1] = { text = "trajectories", at = { PX0 + PW / 2, PY0 - 12 }, anchor = "center", size = 15, space = "pixel" }
  items[#items + 1] = { text = "x \u{2212} x\u{2080} of each disc (cm)", at = { PX0 + PW / 2, PY0 + PH + 34 }, anchor = "center",
                        size = 13, space = "pixel" }
  items[#items + 1] = { text = "height (m)", at = { PX0 + 6, PY0 + 14 }, size = 13, space = "pixel" }
  for v = -6, 6, 3 do
    local q = px(v, YR[1])
    items[#items + 1] = { line = { { q[1], PY0 + PH }, { q[1], PY0 + PH + 5 } }, color = "#444444", width = 1, space = "pixel" }
    items[#items + 1] = { text = string.format("%d", v), at = { q[1], PY0 + PH + 17 }, anchor = "center", size = 12, space = "pixel" }
  end
  for v = 0, 8, 2 do
    local q = px(XR[1], v)
    items[#items + 1] = { line = { { PX0 - 5, q[2] }, { PX0, q[2] } }, color = "#444444", width = 1, space = "pixel" }
    items[#items + 1] = { text = string.format("%d", v), at = { PX0 - 8, q[2] }, anchor = "right", size = 12, space = "pixel" }
  end
  for k = 1, 3 do
    local line = {}
    local n = #hist.t
    local step = math.max(1, math.floor(n / 1000))
    for i = 1, n, step do line[#line + 1] = px(100 * (hist.x[k][i] - X[k]), hist.y[k][i]) end
    if #line >= 2 then items[#items + 1] = { line = line, color = COLORS[k], width = 2, space = "pixel" } end
    if n > 0 then
      items[#items + 1] = { circle = px(100 * (hist.x[k][n] - X[k]), hist.y[k][n]), radius = 5, color = COLORS[k],
                            fill = COLORS[k], space = "pixel" }
    end
    items[#items + 1] = { text = string.format("disc %d", k), at = { PX0 + PW - 70, PY0 + 10 + 18 * k }, size = 13,
                          color = COLORS[k], space = "pixel" }
  end
  return items
end

local function record(world)
  hist.t[#hist.t + 1] = world:time()
  for k = 1, 3 do
    local x, y = discs[k]:position()
    local _, vy = discs[k]:velocity()
    hist.x[k][#hist.x[k] + 1] = x
    hist.y[k][#hist.y[k] + 1] = y
    hist.vy[k][#hist.vy[k] + 1] = -100 * vy
  end
end

return {
  world = w,
  run = { t_end = T_END, fps = 5 },
  render = { size = { 1200, 800 }, camera = { 1.00, 7.80, 1.90, 8.40 },
             layers = "bodies,pressure,velocity,colorbar,title,time,overlay", fluid_field = "excess_pressure",
             fluid_range = { -30, 30 }, velocity_scale = 0.3,
             colors = { disc = "#e3b96b" },
             title = "Three discs sedimenting in a viscous liquid (Stokes flow, Tan 1990, \u{00A7}5.2)",
             overlay = panel },
  on_frame = function(world) record(world) end,
  on_finish = function(world)
    record(world)
    local n = #hist.t
    local vmax = 0
    for k = 1, 3 do for i = 1, n do vmax = math.max(vmax, hist.vy[k][i]) end end
    print(string.format("three discs: t = %.1f s, heights %.3f / %.3f / %.3f m, sideways drift %+.2f / %+.2f / %+.2f cm, "
                        .. "largest fall speed %.1f cm/s (Re = %.2f; seed: about 20 cm/s, Re = 0.4)",
                        world:time(), hist.y[1][n], hist.y[2][n], hist.y[3][n], 100 * (hist.x[1][n] - X[1]),
                        100 * (hist.x[2][n] - X[2]), 100 * (hist.x[3][n] - X[3]), vmax,
                        RHO_L * vmax / 100 * 2 * R / MU))
    local tr, xt, yt = {}, {}, {}
    for k = 1, 3 do
      local xs = {}
      for i = 1, n do xs[i] = 100 * hist.x[k][i] end
      tr[k] = { name = string.format("disc %d", k), x = xs, y = hist.y[k], color = COLORS[k] }
      xt[k] = { name = string.format("disc %d", k), x = hist.t, y = xs, color = COLORS[k] }
      yt[k] = { name = string.format("disc %d", k), x = hist.t, y = hist.vy[k], color = COLORS[k] }
    end
    -- x range: the data and 1 cm on either side (the curves do not run along the frame); the
    -- legend bottom left, where no disc passes (disc 1 keeps right of x = 119 cm below 2.5 m)
    local xlo, xhi = math.huge, -math.huge
    for k = 1, 3 do for _, x in ipairs(tr[k].x) do xlo, xhi = math.min(xlo, x), math.max(xhi, x) end end
    porelab.chart { file = "three_discs_trajectories.png", title = "Three sedimenting discs: trajectories (Tan 1990, section 5.2)",
                    xlabel = "x (cm; horizontal scale exaggerated)", ylabel = "height y (m)", series = tr,
                    xrange = { math.floor(xlo) - 1, math.ceil(xhi) + 1 }, legend = "bottom left" }
    porelab.chart { file = "three_discs_x.png", title = "Three sedimenting discs: horizontal position",
                    xlabel = "time (s)", ylabel = "x (cm)", series = xt, legend = "top right" }
    porelab.chart { file = "three_discs_fall_speed.png", title = "Three sedimenting discs: fall speed",
                    xlabel = "time (s)", ylabel = "fall speed (cm/s)", series = yt, legend = "bottom right" }
  end,
}
