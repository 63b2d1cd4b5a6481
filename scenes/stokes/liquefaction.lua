-- Seed 003 §5.3 (Tan 1990): "artificial liquefaction" of a column of three discs under a
-- stress-controlled top wall, the pore fluid resolved by boundary elements (docs/stokes.md).
-- 1. Dry: discs A (bottom), B (0.1 left of the axis) and C (top) stand in a column without
--    touching; the top wall moves down (servo) until the contacts carry F_y = 1e7.
-- 2. Fluid (mu = 25) fills the voids; each particle shrunk by gap/2 (Tan's artificial gap,
--    §3.4) so the fluid stays connected. Tan's gap is 0.05, kept constant by shrinking only the
--    discs in contact; porelab shrinks every disc by gap/2, so a disc pressed 0.013 into a wall
--    keeps only gap/2 - 0.013 of fluid there, and the lubrication resistance across that film
--    sets the explicit step (2m/K): gap = 0.2 keeps solve_every x dt = 5 ms stable. The top wall now stays at its height and holds
--    the load: the part of F_y the contacts on it do not carry goes to the fluid as a traction
--    (Tan's rule, §5.3.2: w:stokes{ load_wall = top, load_force = F_y, load_contacts = 1 }:
--    each solve gives the fluid F_y minus the contact force on the wall in the last step).
-- 3. Simple shear (the side walls hinged, the top sliding at the rate 7e-3 rad per unit time)
--    makes the column lean and unload; the pore pressure on the top wall rises towards the
--    applied stress F_y / L as the contacts open: the fluid carries the load (liquefaction).
-- Tan's units are artificial (L, M, T, F); they are used here as m, kg, s, N. The seed prints
-- rho_s = 2400 but m = 157080 for r = 5 per unit thickness, which is rho_s = 2000 (used here).
-- Frames: excess pressure and fluid velocity, contact forces. Chart at the end
-- (liquefaction_pressure.png): applied stress, pore pressure on the top and bottom walls, the
-- contact stress of disc C on the top wall (the seed's Fig. 5.14).
-- Run:   porelab run scenes/stokes/liquefaction.lua --out out/liquefaction
local R, RHO_S, MU, KN = 5.0, 2000, 25.0, 0.75e9
local FY = 1e7
local GAP = 0.2
local RATE = 7e-3
local GAMMA_END = 0.016
local ZETA = 0.05
local E_REST = math.exp(-math.pi * ZETA / math.sqrt(1 - ZETA * ZETA))
local DT = 1e-3
local FPS = 100

local w = porelab.world { gravity = { 0, 0 }, dt = DT, energy_surge_ratio = 1e12 }
local grain = w:material { name = "grain", density = RHO_S, kn = KN, ks = KN, friction = math.tan(math.rad(22)),
                           restitution = E_REST }
local wallm = w:material { name = "wall", density = RHO_S, kn = KN, ks = KN, friction = math.tan(math.rad(10)),
                           restitution = E_REST }
w:pair(grain, wallm, { friction = math.tan(math.rad(10)) })
local W0, H0 = 30, 31
local bottom = w:wall { from = { -1, 0 }, to = { W0 + 1, 0 }, material = wallm }
local right = w:wall { from = { W0, -1 }, to = { W0, H0 + 1 }, material = wallm }
local top = w:wall { from = { W0 + 1, H0 }, to = { -1, H0 }, material = wallm }
local left = w:wall { from = { 0, H0 + 1 }, to = { 0, -1 }, material = wallm }
local A = w:disc { center = { 15, 5.05 }, radius = R, material = grain }
local B = w:disc { center = { 14.9, 15.1 }, radius = R, material = grain }
local C = w:disc { center = { 15, 25.15 }, radius = R, material = grain }

-- 1. dry loading to F_y
local ok = 0
while w:time() < 5 do
  top:servo { direction = { 0, -1 }, force = FY, gain = 1, vmax = 1 }
  w:step(20)
  local _, fy = top:force()
  ok = math.abs(fy / FY - 1) < 0.03 and ok + 1 or 0
  if ok >= 3 then break end
end
top:set_velocity(0, 0)
w:run_until(w:time() + 0.05)
local _, H = top:position()
local _, fc0 = top:force()
print(string.format("liquefaction: column loaded dry to %.4g N/m (target %.4g) in %.2f s; box %.2f x %.3f",
                    fc0, FY, w:time(), W0, H))

-- 2. the fluid, with the held top wall
w:stokes { viscosity = MU, density = 1000, gap = GAP, disc_elements = 32, element_length = 1.0, field_grid = 60,
           solve_every = 5, load_wall = top, load_force = FY, load_contacts = 1 }

-- 3. shear: the top slides, the side walls hinge about their feet
local T0 = w:time()
local VX = RATE * H
top:set_velocity(VX, 0)
left:hinge { pivot = { 0, 0 }, follow = top, height = H }
right:hinge { pivot = { W0, 0 }, follow = top, height = H }

local L = W0
local hist = { g = {}, applied = {}, ptop = {}, pbot = {}, contact = {} }
local function record(world)
  local _, fy = top:force()
  hist.g[#hist.g + 1] = 100 * RATE * (world:time() - T0)
  hist.applied[#hist.applied + 1] = FY / L / 1e3
  hist.ptop[#hist.ptop + 1] = world:stokes_wall_pressure(top) / 1e3
  hist.pbot[#hist.pbot + 1] = world:stokes_wall_pressure(bottom) / 1e3
  hist.contact[#hist.contact + 1] = fy / L / 1e3
end

local function label()
  local n = #hist.g
  if n == 0 then return {} end
  return { { text = string.format("\u{03B3} = %.2f %%: the fluid carries %.0f of the applied %.0f kPa, the contacts %.0f kPa",
                                  hist.g[n], hist.ptop[n], hist.applied[n], hist.contact[n]),
              at = { 15, 32.6 }, anchor = "center", size = 14 } }
end

return {
  world = w,
  run = { t_end = T0 + GAMMA_END / RATE, fps = FPS },
  render = { size = { 1000, 860 }, camera = { -2, -2, 32, 34 },
             layers = "bodies,forces,pressure,velocity,colorbar,title,time,overlay", fluid_field = "pressure",
             fluid_range = { 0, 360e3 }, velocity_scale = 3, time_offset = -T0,
             colors = { grain = "#e3b96b" },
             title = "Artificial liquefaction under a held load (Tan 1990, \u{00A7}5.3)",
             overlay = label },
  on_frame = function(world)
    if world:time() > T0 then
      record(world)
    end
  end,
  on_finish = function(world)
    record(world)
    local n = #hist.g
    local first = nil
    for i = 1, n do
      if hist.contact[i] < 0.01 * FY / L / 1e3 then first = hist.g[i]; break end
    end
    print(string.format("liquefaction: at gamma = %.2f %%: pore pressure on the top wall %.1f kPa, on the bottom %.1f kPa, "
                        .. "applied %.1f kPa, contacts on the top wall %.1f kPa; contacts gone at gamma = %s",
                        hist.g[n], hist.ptop[n], hist.pbot[n], hist.applied[n], hist.contact[n],
                        first and string.format("%.2f %%", first) or "(not within the run)"))
    porelab.chart { file = "liquefaction_pressure.png", title = "Artificial liquefaction (Tan 1990, 5.3, Fig. 5.14)",
                    xlabel = "shear strain (%)", ylabel = "stress on the walls (kPa)",
                    series = { { name = "applied stress F/L", x = hist.g, y = hist.applied, style = "dashed", color = "#222222" },
                               { name = "pore pressure, top wall", x = hist.g, y = hist.ptop, color = "#1f4e9c" },
                               { name = "pore pressure, bottom wall", x = hist.g, y = hist.pbot, style = "points",
                                 color = "#2a7f3f" },
                               { name = "contact stress, disc C on the top wall", x = hist.g, y = hist.contact,
                                 color = "#9b2226" } },
                    yrange = { -20, 520 }, legend = "top left" }
  end,
}
