-- Method: Darcy seepage on linear triangles (engine/src/fluid/darcy), backward Euler time
-- stepping (w:darcy{method = 0}). Resolution knob: cells of the mesh along the direction of
-- flow; the number of fluid steps grows with it as written below.
local function attach(steps_of)
  return function(w, ctx, cells)
    ctx.darcy_mesh(w, cells)
    w:darcy { method = 0 }
    return { steps = math.max(1, steps_of(cells)) }
  end
end

return {
  name = "darcy_be",
  label = "Darcy, backward Euler",
  model = "darcy",
  problems = {
    wave = { knob = "cells along the rod", unit = "1", values = { 10, 20, 40, 80, 160 },
             attach = attach(function(cells) return cells * cells // 10 end) },
    terzaghi = { knob = "cells along the column", unit = "1", values = { 4, 8, 16, 32, 64 },
                 attach = attach(function(cells) return cells * cells // 2 end) },
  },
}
