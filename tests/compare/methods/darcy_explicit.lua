-- Method: Darcy seepage on linear triangles (engine/src/fluid/darcy), explicit (seed 000 eq. 3.18) time
-- stepping (w:darcy{method = 2}). Resolution knob: cells of the mesh along the direction of
-- flow; the number of fluid steps grows with it as written below (one fluid step: the
-- explicit update sub-steps itself below its stability limit, FLUID_EXPLICIT_SAFETY 0.9).
local function attach(steps_of)
  return function(w, ctx, cells)
    ctx.darcy_mesh(w, cells)
    w:darcy { method = 2 }
    return { steps = math.max(1, steps_of(cells)) }
  end
end

return {
  name = "darcy_explicit",
  label = "Darcy, explicit (Klosek 1997 eq. 3.18)",
  model = "darcy",
  problems = {
    wave = { knob = "cells along the rod", unit = "1", values = { 10, 20, 40, 80, 160 },
             attach = attach(function(cells) return 1 end) },
    terzaghi = { knob = "cells along the column", unit = "1", values = { 4, 8, 16, 32, 64, 128 },
                 attach = attach(function(cells) return 1 end) },
  },
}
