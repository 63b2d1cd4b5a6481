-- Flow past a cylinder in a channel, Schäfer & Turek DFG 2D-1 geometry (Re = 20): channel
-- 2.2 x 0.41 m, a fixed disc of radius 0.05 m at (0.2, 0.2), parabolic inflow with centreline
-- velocity 0.3 m/s on the left, do-nothing outflow on the right, nu = 1e-3 m^2/s. The model
-- steps BDF2 from rest to the steady flow; the frame shows the pressure (Pa). The benchmark's
-- drag, lift and pressure difference are checked by the ctest test_ns_validation.
--   porelab run scenes/navier_stokes/cylinder_channel.lua
local w = porelab.world { gravity = { 0, 0 }, dt = 0.004 }
local m = w:material { name = "obstacle", density = 1000, kn = 1e5 }
w:disc { center = { 0.2, 0.2 }, radius = 0.05, material = m, fixed = true }
w:navier_stokes { x_min = 0, y_min = 0, x_max = 2.2, y_max = 0.41, density = 1, viscosity = 1e-3,
                  core_fraction = 1.0, inflow_velocity = 0.3, open_right = 1,
                  h_near = 0.01, h_far = 0.05, grade_distance = 0.2, disc_sides = 48, solve_every = 25 }
return {
  world = w,
  run = { t_end = 8.0, fps = 2 },
  render = { size = { 1100, 260 }, camera = { -0.02, -0.02, 2.22, 0.43 },
             layers = "bodies,pressure,colorbar,title,time",
             fluid_range = { 0, 0.15 },
             title = "Cylinder in a channel (DFG 2D-1, Re = 20): pressure" },
}
