-- Benchmark problem: Terzaghi's one-dimensional consolidation. A column loaded at t = 0 carries
-- the load first in its pore water (excess pore pressure u0 everywhere), drains at one end and is
-- sealed at the other. Terzaghi (1925; Verruijt, Soil Mechanics, eq. 15.17):
--   u(z, t) / u0 = sum_m (2 / M) sin(M z / H) exp(-M^2 T_v),  M = pi (2m + 1) / 2,  T_v = c_v t / H^2
-- with z measured from the drained end. Measured: u / u0 at the sealed end (z = H, sin M =
-- (-1)^m) at T_v = 0.2, a number without units, from the series below (40 terms).
--
-- The grain-free column (methods darcy_be, darcy_cn, darcy_explicit): height H = 1 m (width
-- 0.1 m), no gravity, D = 1 m/s, storage S = 1 1/m (so c_v = D / S = 1 m^2/s), an excess head
-- u0 = 1 m everywhere at t = 0, drained at the top (head 0), sealed at the bottom; the measured
-- value is the head at the bottom over u0.
-- Methods: problems.terzaghi = {knob, unit, values, attach = function(w, ctx, value)} returning
-- {steps = N}; ctx.darcy_mesh(w, cells) builds the column mesh (cells along the height).
--
-- A method that builds its own column (grain_column: discs under a piston, its c_v measured
-- from its own loading) gives instead measure = function(ctx, value) returning u / u0 at the
-- sealed end at its own T_v = ctx.Tv.
local ctx = { height = 1.0, width = 0.1, conductivity = 1.0, storage = 1.0, u0 = 1.0, Tv = 0.2 }
ctx.t_end = ctx.Tv * ctx.height ^ 2 * ctx.storage / ctx.conductivity

local function terzaghi_bottom(Tv)
  local s = 0
  for m = 0, 39 do
    local M = math.pi * (2 * m + 1) / 2
    s = s + 2 / M * (m % 2 == 0 and 1 or -1) * math.exp(-M * M * Tv)
  end
  return s
end

function ctx.darcy_mesh(w, cells)
  w:fluid_quad { corners = { { 0, 0 }, { ctx.width, 0 }, { ctx.width, ctx.height }, { 0, ctx.height } },
                 ndivx = 1, ndivy = cells }
  w:fluid_bc { from = { 0, ctx.height }, to = { ctx.width, ctx.height }, head = 0.0 }
  w:darcy { on = true, perm_mode = 0, perm_high = ctx.conductivity, storage = ctx.storage, drag = false }
  w:fluid_set_pressure_head(ctx.u0)
end

return {
  name = "terzaghi",
  title = "Terzaghi consolidation of a column (grain-free and grain columns)",
  quantity = "u / u#d0#u at the sealed end, T#dv#u = 0.2",
  unit = "1",
  reference = { value = terzaghi_bottom(ctx.Tv),
                source = "Terzaghi 1925; series of Verruijt, Soil Mechanics, eq. 15.17" },
  run = function(method, res)
    local m = method.problems.terzaghi
    if m.measure then return m.measure(ctx, res.value) end
    local w = porelab.world { gravity = { 0, 0 } }
    local opts = m.attach(w, ctx, res.value) or {}
    local steps = opts.steps or 1
    for _ = 1, steps do w:fluid_advance(ctx.t_end / steps) end
    local _, head = w:fluid_pressure_at(ctx.width / 2, 0.0)
    return head / ctx.u0
  end,
}
