-- Window benchmark scene (tests/bench/bench_window.sh): N grains (default 10,000; the
-- benchmark writes a copy with N = 50000) in a water-filled box with a pressure field.
local N = 10000
local nx = math.floor(math.sqrt(N * 16 / 9))
local ny = math.ceil(N / nx)
local r = 0.005
local W, H = 2 * r * nx, 2 * r * ny * 0.9
local w = porelab.world { gravity = { 0, -9.81 }, rayleigh_alpha = 10, dt = 2e-5 }
local sand = w:material { name = "sand", density = 2650, kn = 2e5, friction = 0.4, restitution = 0.3 }
w:wall { from = { 0, 0 }, to = { W, 0 }, material = sand }
w:wall { from = { 0, 0 }, to = { 0, H * 1.2 }, material = sand }
w:wall { from = { W, 0 }, to = { W, H * 1.2 }, material = sand }
local n = 0
for j = 0, ny - 1 do
  for i = 0, nx - 1 do
    if n < N then
      w:disc { center = { r + 2 * r * i + (j % 2) * 0.5 * r, r + 1.8 * r * j },
               radius = r * (0.85 + 0.1 * ((i * 7 + j * 3) % 5) / 4), material = sand }
      n = n + 1
    end
  end
end
w:fluid_quad { corners = { { 0, 0 }, { W, 0 }, { W, H }, { 0, H } }, ndivx = 64, ndivy = 36 }
w:fluid_bc { from = { 0, H }, to = { W, H }, head = 0 }
w:set_flag("FLUIDS_ON", 1)
w:set_flag("FLUID_STORAGE", 0)
w:set_flag("FLUID_SOLVE_TIMESTEPS", 50)
return {
  world = w,
  run = { t_end = 10, fps = 30 },
  render = { size = { 1280, 720 }, layers = "bodies,forces,pressure,time,colorbar" },
}
