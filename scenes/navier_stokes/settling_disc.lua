-- A disc settling midway between two walls in a viscous liquid (Stokes limit, k = r/b = 0.125):
-- r = 1 cm, rho_P = 2500 kg/m^3 in a liquid of rho_F = 1000 kg/m^3 and eta = 50 Pa s, box
-- 16 cm x 40 cm. The disc's buoyant weight balances Faxén's wall-corrected drag at the
-- terminal velocity 8.74 mm/s (the ctest test_ns_world_long measures 8.84 mm/s, +1.1 %).
-- The pore space is remeshed by gmsh around the moving disc at every fluid step.
--   porelab run scenes/navier_stokes/settling_disc.lua
local w = porelab.world { gravity = { 0, -9.81 }, dt = 1e-4 }
local m = w:material { name = "grain", density = 2500, kn = 1e5 }
w:disc { center = { 0, 0.25 }, radius = 0.01, material = m }
w:navier_stokes { x_min = -0.08, y_min = 0, x_max = 0.08, y_max = 0.4, density = 1000, viscosity = 50,
                  core_fraction = 1.0, h_near = 0.003, h_far = 0.03, grade_distance = 0.04,
                  disc_sides = 64, solve_every = 20, force_relaxation = 0.3 }
return {
  world = w,
  run = { t_end = 0.4, fps = 10 },
  render = { size = { 360, 800 }, camera = { -0.09, -0.01, 0.09, 0.41 },
             layers = "bodies,pressure,colorbar,title,time",
             title = "Disc settling between walls" },
}
