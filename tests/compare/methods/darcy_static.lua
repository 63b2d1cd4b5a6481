-- Method: Darcy seepage on linear triangles (engine/src/fluid/darcy) solved quasi-statically
-- (FLUID_STORAGE 0) at every grain step: the pressure around each outline from the mesh, with
-- the porous skeleton's drag (FLUID_DRAG 1). Resolution knob: mesh cells along the height
-- (the width gets cells in proportion). Grain step 1e-3 s.
local function mesh(w, x0, x1, y0, y1, ny, density, conductivity)
  local nx = math.max(1, math.floor(ny * (x1 - x0) / (y1 - y0) + 0.5))
  w:fluid_quad { corners = { { x0, y0 }, { x1, y0 }, { x1, y1 }, { x0, y1 } }, ndivx = nx, ndivy = ny }
  w:fluid_bc { from = { x0, y1 }, to = { x1, y1 }, head = 0 }
  w:darcy { on = true, density = density, storage = 0, perm_mode = 0, perm_high = conductivity,
            solve_every = 1 }
end

return {
  name = "darcy_static",
  label = "Darcy, static solve every step",
  model = "darcy",
  problems = {
    buoyancy = { knob = "cells along the depth", unit = "1", values = { 3, 6, 12, 24 },
                 attach = function(w, ctx, ny)
                   local T = ctx.tank
                   mesh(w, T.x_min, T.x_max, T.bottom, T.level, ny, T.density, 5)
                   return { dt = 1e-3 }
                 end },
    -- open liquid: the conductivity of a grain-free region (k = 1e-4 m^2 as if very open) has no
    -- physical meaning; Darcy gives buoyancy but no viscous drag on a single disc
    settling = { knob = "cells along the height", unit = "1", values = { 10, 20, 40 },
                 attach = function(w, ctx, ny)
                   local C = ctx.channel
                   mesh(w, C.x_min, C.x_max, C.bottom, C.top, ny, ctx.density,
                        1e-4 * ctx.density * ctx.g / ctx.viscosity)
                   return { dt = 1e-3 }
                 end },
  },
}
