-- Benchmark problem: a disc settling midway between two walls in a viscous liquid. Disc radius
-- a = 0.01 m, 1100 kg/m^3, in a channel of half-width l = 0.05 m (k = a / l = 0.2) filled with
-- a liquid of 1000 kg/m^3 and viscosity mu = 1 Pa s (particle Reynolds number about 0.4). At
-- low Reynolds number the drag per unit length on a cylinder moving midway between two plane
-- walls is F = 4 pi mu U / C(k) with
--   C(k) = ln(1/k) - 0.9157 + 1.7244 k^2 - 1.7302 k^4 + 2.4056 k^6 - 4.5913 k^8
-- (Faxen 1946; Happel & Brenner, Low Reynolds Number Hydrodynamics, 1965, eq. 7-5.51), so the
-- terminal speed is U = (rho_s - rho_f) g pi a^2 C(k) / (4 pi mu) = 0.01863 m/s. Measured: the
-- disc's downward speed after 0.5 s (about 24 relaxation times m / (4 pi mu / C)).
--
-- Methods: problems.settling = {knob, unit, values, attach = function(w, ctx, value)} puts the
-- liquid (ctx: channel {x_min, x_max, bottom, top}, density, viscosity, disc {radius, center})
-- on the world and returns {dt = grain step} (default automatic). The resolved models (Stokes
-- by boundary elements, Navier-Stokes) answer it without a drag law.
local ctx = { channel = { x_min = 0, x_max = 0.1, bottom = 0, top = 1.0 }, density = 1000,
              viscosity = 1.0, disc = { radius = 0.01, density = 1100, center = { 0.05, 0.8 } },
              g = 9.81, t_end = 0.5 }
local k = ctx.disc.radius / ((ctx.channel.x_max - ctx.channel.x_min) / 2)
ctx.faxen_C = math.log(1 / k) - 0.9157 + 1.7244 * k ^ 2 - 1.7302 * k ^ 4 + 2.4056 * k ^ 6 - 4.5913 * k ^ 8
ctx.drag_per_speed = 4 * math.pi * ctx.viscosity / ctx.faxen_C      -- N s/m^2 per unit length
local a = ctx.disc.radius
local U = (ctx.disc.density - ctx.density) * ctx.g * math.pi * a * a / ctx.drag_per_speed

return {
  name = "settling",
  title = "A disc settling between two walls (Re_p = 0.4)",
  quantity = "settling speed at t = 0.5 s",
  unit = "m/s",
  reference = { value = U, source = "Faxen 1946; Happel & Brenner 1965, eq. 7-5.51" },
  run = function(method, res)
    local w = porelab.world { gravity = { 0, -ctx.g } }
    local wall = w:material { name = "wall", density = 2500, kn = 1e5, friction = 0.3, restitution = 0.3 }
    local m = w:material { name = "disc", density = ctx.disc.density, kn = 1e5, friction = 0.3, restitution = 0.3 }
    local C = ctx.channel
    w:wall { from = { C.x_min, C.bottom }, to = { C.x_max, C.bottom }, material = wall }
    w:wall { from = { C.x_min, C.bottom }, to = { C.x_min, C.top + 0.1 }, material = wall }
    w:wall { from = { C.x_max, C.bottom }, to = { C.x_max, C.top + 0.1 }, material = wall }
    local disc = w:disc { center = ctx.disc.center, radius = a, material = m, fixed_rotation = true }
    local opts = method.problems.settling.attach(w, ctx, res.value) or {}
    if opts.dt then w:set_flag("DT", opts.dt) end
    w:run_until(ctx.t_end)
    local _, vy = disc:velocity()
    return -vy
  end,
}
