-- Method: hydrostatic water (engine/src/fluid/hydrostatic): the exact outline integral of the
-- still-water pressure, no mesh; with an optional linear drag law (w:water{drag = beta}).
-- Resolution knob: the grain time step (the model itself has no mesh).
return {
  name = "hydrostatic",
  label = "hydrostatic",
  model = "water",
  problems = {
    buoyancy = { knob = "time step", unit = "s", values = { 4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4 },
                 attach = function(w, ctx, dt)
                   local T = ctx.tank
                   w:water { x_min = T.x_min, x_max = T.x_max, bottom = T.bottom, level = T.level,
                             density = T.density }
                   return { dt = dt }
                 end },
    -- the drag law: Faxen's wall-corrected Stokes drag spread over the disc's area
    -- (beta = F/U / (pi a^2)), so this method carries the reference's physics and its error is
    -- the time integration's
    settling = { knob = "time step", unit = "s", values = { 4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4 },
                 attach = function(w, ctx, dt)
                   local C, a = ctx.channel, ctx.disc.radius
                   w:water { x_min = C.x_min, x_max = C.x_max, bottom = C.bottom, level = C.top,
                             density = ctx.density, drag = ctx.drag_per_speed / (math.pi * a * a) }
                   return { dt = dt }
                 end },
  },
}
