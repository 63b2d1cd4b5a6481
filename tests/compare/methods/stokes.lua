-- Method: resolved Stokes flow by boundary elements (engine/src/fluid/stokes_bem, docs/stokes.md):
-- only the container's walls and the grains' outlines carry unknowns; the drag comes from the
-- tractions. Resolution knob: boundary elements per disc (the walls get elements of the same
-- length, element_length = 2 pi a / n).
local ELEMENT_LENGTH = 0.01
local function walls(w, C, velocity)
  local mat = w:material { name = "stokes wall", density = 2500, kn = 1e5, friction = 0.3 }
  local e = 0.01 * (C.x_max - C.x_min)
  local v = velocity and { velocity[1], velocity[2] } or nil
  local function wall(from, to)
    return w:wall { from = from, to = to, material = mat, velocity = v }
  end
  wall({ C.x_min - e, C.bottom }, { C.x_max + e, C.bottom })
  wall({ C.x_max, C.bottom - e }, { C.x_max, C.top + e })
  wall({ C.x_max + e, C.top }, { C.x_min - e, C.top })
  wall({ C.x_min, C.top + e }, { C.x_min, C.bottom - e })
end

return {
  name = "stokes",
  label = "Stokes, boundary elements",
  model = "stokes",
  problems = {
    -- the channel's own side walls and floor, closed by a lid at the channel's top; the disc's
    -- drag is explicit (2 m / K = 0.04 s, far above the step)
    settling = { knob = "elements per disc", unit = "1", values = { 8, 16, 32, 64 },
                 attach = function(w, ctx, n)
                   local C, a = ctx.channel, ctx.disc.radius
                   local mat = w:material { name = "lid", density = 2500, kn = 1e5, friction = 0.3 }
                   w:wall { from = { C.x_max + 0.001, C.top }, to = { C.x_min - 0.001, C.top }, material = mat }
                   w:stokes { viscosity = ctx.viscosity, density = ctx.density, disc_elements = n,
                              element_length = ELEMENT_LENGTH, wall_elements = 4, solve_every = 5 }
                   return { dt = 2e-3 }
                 end },
    -- the container moves with the superficial speed U (inflow and outflow through its ends, the
    -- side walls sliding along at U)
    fixed_bed = { knob = "elements per disc", unit = "1", values = { 8, 16, 32, 64 },
                  attach = function(w, ctx, n)
                    walls(w, ctx.channel, { ctx.U, 0 })
                    local a = ctx.bed.a
                    w:stokes { viscosity = ctx.viscosity, density = ctx.density, disc_elements = n,
                               element_length = 2 * math.pi * a / n, wall_elements = 4 }
                    return { solve = function() w:stokes_solve() end,
                             drag = function(b) return w:stokes_body(b).drag[1] end,
                             velocity = function(x, y) return (w:stokes_point(x, y)) end }
                  end },
  },
}
