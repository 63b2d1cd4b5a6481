-- Lid-driven cavity at Re = 100 (seed 004 §6.2; Ghia, Ghia & Shin 1982): a 1 m square box of
-- fluid whose top side slides at 1 m/s; no grains. The resolved Navier-Stokes model
-- (docs/navier-stokes.md) steps BDF2 from rest towards the steady vortex; the frame shows the
-- pressure (Pa). The validation against Ghia's centreline velocities is the ctest
-- test_ns_validation (stationary Newton on a finer mesh).
--   porelab run scenes/navier_stokes/cavity.lua
local w = porelab.world { gravity = { 0, 0 }, dt = 0.002 }
local steel = w:material { name = "box", density = 7800, kn = 1e6 }
-- the cavity's sides, drawn as walls just outside the fluid box (segments are not fluid holes)
for _, s in ipairs { { { 0, 0 }, { 1, 0 } }, { { 1, 0 }, { 1, 1 } }, { { 1, 1 }, { 0, 1 } }, { { 0, 1 }, { 0, 0 } } } do
  w:wall { from = s[1], to = s[2], material = steel }
end
w:navier_stokes { x_min = 0, y_min = 0, x_max = 1, y_max = 1, density = 1, viscosity = 0.01,
                  lid_velocity = 1, h_far = 0.05, h_near = 0.05, solve_every = 25 }
return {
  world = w,
  run = { t_end = 10.0, fps = 2 },
  render = { size = { 640, 640 }, camera = { -0.05, -0.05, 1.05, 1.05 },
             layers = "pressure,colorbar,title,time",
             title = "Lid-driven cavity, Re = 100: pressure" },
}
