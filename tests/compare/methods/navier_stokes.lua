-- Method: resolved Navier-Stokes water (engine/src/fluid/navier_stokes, docs/navier-stokes.md):
-- P2 + bubble / P1 triangles on a gmsh mesh of the pore space, Newton and BDF2 in time, the
-- grains' cores as holes (core_fraction 1: the core is the grain). Resolution knob: the mesh
-- size on the grains, h_near, as a fraction of the disc radius (h_far = 4 h_near; the discs'
-- outlines, polygons of 4 pi a / h_near sides, lose a fraction (2 pi / sides)^2 / 6 of their
-- area: 1.3 % at 0.8, 0.3 % at 0.4).
local function mesh(a, f)
  local h = f * a
  return h, 4 * h, math.max(16, math.ceil(4 * math.pi / f))
end

return {
  name = "navier_stokes",
  label = "Navier-Stokes, finite elements",
  model = "navier_stokes",
  problems = {
    -- the channel is the fluid box (walls on all four sides); the mesh follows the disc as it
    -- falls; fluid step 10 grain steps of 0.2 ms (a tenth of the disc's relaxation time m / K:
    -- with the disc only 1.1 times as dense as the liquid, longer fluid steps of this explicit
    -- coupling oscillate). The buoyancy comes from the pressure on the polygonal core, so the
    -- core's missing area (above) is ten times larger in the net weight
    settling = { knob = "mesh size on the disc / radius", unit = "1", values = { 0.8, 0.4 },
                 attach = function(w, ctx, f)
                   local C, a = ctx.channel, ctx.disc.radius
                   local h_near, h_far, sides = mesh(a, f)
                   w:navier_stokes { x_min = C.x_min, x_max = C.x_max, y_min = C.bottom, y_max = C.top,
                                     density = ctx.density, viscosity = ctx.viscosity, core_fraction = 1.0,
                                     h_near = h_near, h_far = math.min(h_far, 0.02), grade_distance = 4 * a,
                                     disc_sides = sides, solve_every = 10 }
                   return { dt = 2e-4 }
                 end },
    -- parabolic inflow on the left (mean speed U), do-nothing outflow on the right, walls above
    -- and below; the steady flow after 10 fluid steps of 0.02 s (5 viscous times H^2 rho / mu)
    fixed_bed = { knob = "mesh size on the discs / radius", unit = "1", values = { 0.8, 0.4, 0.2 },
                  attach = function(w, ctx, f)
                    local C, a = ctx.channel, ctx.bed.a
                    local h_near, h_far, sides = mesh(a, f)
                    w:navier_stokes { x_min = C.x_min, x_max = C.x_max, y_min = C.bottom, y_max = C.top,
                                      density = ctx.density, viscosity = ctx.viscosity, core_fraction = 1.0,
                                      h_near = h_near, h_far = h_far, grade_distance = 2 * a, disc_sides = sides,
                                      inflow_velocity = 1.5 * ctx.U, open_right = 1, solve_every = 1,
                                      force_relaxation = 1 }
                    return { solve = function()
                               w:set_flag("DT", 0.02)
                               w:step(10)
                             end,
                             drag = function(b) return (w:navier_stokes_force(b)) end,
                             velocity = function(x, y) return (w:navier_stokes_at(x, y)) end }
                  end },
  },
}
