-- Benchmark problem: flow through a fixed bed of discs, its permeability. A square array of
-- discs (radius a = 5 mm, spacing l, solid fraction c = pi a^2 / l^2 = 0.1), NROW rows by NCOL
-- columns, fixed in a channel of height NROW l; a liquid of mu = 100 Pa s, 1000 kg/m^3 flows
-- through it at the superficial speed U = 1 mm/s (particle Reynolds number rho U 2a / mu = 1e-4,
-- no gravity). Measured: the permeability of the array, k = mu U_c l^2 / F, with F the drag per
-- unit length on the middle disc of the bed and U_c the mean speed through its cell (the flow
-- across the cell's downstream side, sampled from the model's velocity field): the force balance
-- of one cell, dp l = F, with Darcy's law U_c = k dp / (mu l).
-- Reference: Drummond & Tahir (1984), square array, flow along a row,
--   F / (mu U) = 4 pi / (-ln(c)/2 - 0.738 + c - 0.887 c^2 + 2.038 c^3),
-- a dilute expansion good to about 0.2 % at c = 0.1 (tests/stokes/test_stokes_array.c checks the
-- boundary elements against it in an exactly periodic cell: -0.17 %). Here k = 1.2662 a^2.
-- The bed in this problem is not periodic: the channel's walls take a share of the flow that
-- differs from the array's, so the middle cell carries a little more than U; measuring U_c in the
-- cell itself removes that (the rest of the walls' and the ends' effect on the middle disc decays
-- within a spacing: the screening length sqrt(k) = 1.1 a is a fifth of one).
--
-- Methods: problems.fixed_bed = {knob, unit, values, attach = function(w, ctx, value)} puts the
-- liquid on the world (ctx: channel {x_min, x_max, bottom, top}, the bed {x_min, x_max, a, l,
-- rows, cols, c}, U, density, viscosity, discs (the bodies, row by row), middle (the middle disc))
-- and returns {solve = function() end, drag = function(body) return fx end,
-- velocity = function(x, y) return vx end} (after solve: the drag on a body in N/m and the
-- fluid's velocity at a point in m/s), or {permeability = function() return k end} for a model
-- whose permeability is its constitutive law (Darcy).
local a, c, NROW, NCOL, AHEAD = 0.005, 0.1, 3, 3, 1
local l = a * math.sqrt(math.pi / c)
local ctx = { density = 1000, viscosity = 100, U = 1e-3,
              bed = { a = a, l = l, c = c, rows = NROW, cols = NCOL, x_min = AHEAD * l, x_max = (AHEAD + NCOL) * l },
              channel = { x_min = 0, x_max = (2 * AHEAD + NCOL) * l, bottom = 0, top = NROW * l } }
local FDT = 4 * math.pi / (-0.5 * math.log(c) - 0.738 + c - 0.887 * c * c + 2.038 * c * c * c)
local k_ref = l * l / FDT

return {
  name = "fixed_bed",
  title = "Flow through a fixed bed of discs (square array, c = 0.1)",
  quantity = "permeability of the array",
  unit = "m^2",
  reference = { value = k_ref, source = "Drummond & Tahir 1984, square array: k = l^2 mu U / F" },
  run = function(method, res)
    local w = porelab.world { gravity = { 0, 0 } }
    local m = w:material { name = "disc", density = 2500, kn = 1e5, friction = 0.3 }
    local B = ctx.bed
    ctx.discs = {}
    for r = 1, B.rows do
      for col = 1, B.cols do
        ctx.discs[#ctx.discs + 1] = w:disc { center = { B.x_min + (col - 0.5) * l, (r - 0.5) * l }, radius = a,
                                             material = m, motion = "fixed" }
      end
    end
    ctx.middle = ctx.discs[(B.rows // 2) * B.cols + B.cols // 2 + 1]
    local opts = method.problems.fixed_bed.attach(w, ctx, res.value) or {}
    if opts.permeability then return opts.permeability() end
    opts.solve()
    local F = opts.drag(ctx.middle)
    -- U_c: mean of u_x over the middle cell's downstream side (Gauss-Legendre, 4 x 5 points)
    local x, y = ctx.middle:position()
    x = x + l / 2
    local gx = { -0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831, 0.9061798459386640 }
    local gw = { 0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891 }
    local q, parts = 0, 4
    for p = 0, parts - 1 do
      local y0 = y - l / 2 + p * l / parts
      for i = 1, 5 do q = q + gw[i] / 2 * opts.velocity(x, y0 + (gx[i] + 1) / 2 * l / parts) / parts end
    end
    ctx.measured_U = q
    return ctx.viscosity * q * l * l / F
  end,
}
