-- Method: Darcy seepage with the Kozeny-Carman permeability of the grains (engine/src/fluid/darcy,
-- FLUID_PERM 1, FLUID_KC_MODE 1): each element's conductivity from its areal porosity n,
-- K = C1 e^3 / (1 + e) = C1 n^3 / (1 - n)^2 (seed 000 eq. 3.8) with C1 = rho g d^2 / (80 mu):
-- Kozeny-Carman for fibres (Kozeny constant 5, specific surface 4 / d). The permeability of the
-- bed is then the model's constitutive law; the mesh only averages the porosity. Measured: the
-- mean Darcy velocity q of the bed's elements under a head drop dh across it,
-- k = mu q L / (rho g dh). Resolution knob: array spacings per mesh cell (3: the whole bed one
-- cell of two triangles; 1: one cell per disc, the disc split in halves). Finer meshes are
-- meaningless for a porosity law: cells between the discs would hold no grain (n = 1).
return {
  name = "darcy_kc",
  label = "Darcy, Kozeny-Carman",
  model = "darcy",
  problems = {
    fixed_bed = { knob = "array spacings per mesh cell", unit = "1", values = { 3, 1 },
                  attach = function(w, ctx, n)
                    local B, g, dh = ctx.bed, 9.81, 0.01
                    -- the discs are fixed: gravity only sets K = k rho g / mu and the head
                    w:set_flag("GRAVITY_Y", -g)
                    local x0, x1, y1 = B.x_min, B.x_max, B.rows * B.l
                    w:fluid_quad { corners = { { x0, 0 }, { x1, 0 }, { x1, y1 }, { x0, y1 } },
                                   ndivx = B.cols // n, ndivy = B.rows // n }
                    w:fluid_bc { from = { x0, 0 }, to = { x0, y1 }, head = dh }
                    w:fluid_bc { from = { x1, 0 }, to = { x1, y1 }, head = 0 }
                    local d = 2 * B.a
                    w:darcy { on = true, density = ctx.density, viscosity = ctx.viscosity, storage = 0,
                              perm_mode = 1, kc_mode = 1, porosity_map = 0,
                              kc_c1 = ctx.density * g * d * d / (80 * ctx.viscosity),
                              perm_low = 0, perm_high = 1e30 }
                    return { permeability = function()
                      w:fluid_solve_static()
                      local vx = w:fluid_element_field("vx")
                      local q = 0
                      for i = 1, #vx do q = q + vx[i] / #vx end
                      return ctx.viscosity * q * (x1 - x0) / (ctx.density * g * dh)
                    end }
                  end },
  },
}
