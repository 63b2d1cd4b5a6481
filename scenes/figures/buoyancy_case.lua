-- The buoyancy problem of seed 000 (Klosek 1997) §4.2 / Appendix C.2 with the density ratio as
-- a parameter, for the end-state figures (Figs. 4-6 to 4-8; the thesis "changed the density of
-- the particle by altering the MIMES input source"). The commands are those of
-- scenes/mimes/buoyancy.lua (see its transcription notes), repeated here because a sandboxed
-- scene may only load files from its own folder. Used by buoyancy_half/equal/heavy.lua:
--   return require("buoyancy_case")(0.5, "floats, half submerged")
-- Run directly, it is the ratio-1/2 case.
local function case(ratio, what)
  local M = require("porelab.mimes").session()
  local set = M.set
  set("matnum", 2)
  M.create_material_list_ui(2)
  set("E(1)", 200)
  set("nu(1)", 0.3)
  set("density(1)", 1.5)
  set("E(2)", 200)
  set("nu(2)", 0.3)
  set("density(2)", ratio * 1.0) -- FLUID_DENSITY = 1
  M.apply_material_list(2)
  set("fric(1,1)", 0.1)
  set("fric(2,1)", 0.1)
  set("fric(2,2)", 0.1)
  M.apply_fric(2)
  set("k_normal(1,1)", 400000)
  set("k_normal(2,1)", 400000)
  set("k_normal(2,2)", 400000)
  M.apply_kn(2)
  set("k_shear(1,1)", 600000)
  set("k_shear(2,1)", 600000)
  set("k_shear(2,2)", 600000)
  M.apply_ks(2)
  M.add_superquad_ui(131, 396, 250, 321, 42, 2, 2, 0, 1, 16, 0, 0)
  M.add_fluid_mesh_ui(100, 100, 300, 100, 300, 300, 100, 300, 4, 4, 10)
  M.add_fluid_bc_ui(100, 100, 300, 100, 200)
  M.add_fluid_bc_ui(100, 300, 300, 300, 0)
  M.add_rectangle_ui(100, 80, 80, 80, 80, 300, 100, 300, 187, 2)
  M.add_rectangle_ui(100, 80, 100, 100, 320, 100, 320, 80, 188, 2)
  M.add_rectangle_ui(300, 100, 300, 300, 320, 300, 320, 100, 189, 2)
  M.set_velocity(1, 1, 1, 0, 0, 0, 187)
  M.set_velocity(1, 1, 1, 0, 0, 0, 188)
  M.set_velocity(1, 1, 1, 0, 0, 0, 189)
  set("GRAVITY_Y", -9.81)
  set("FLUIDS_ON", 1)
  set("PRINT_INT", 400)
  set("TIMESTEPS", 40000)
  set("RAYLEIGH_FACTOR", 1.0)
  set("MAX_DT_CR", 0.005)
  set("FIRST_STEP_STATIC", 1)
  set("FLUID_SOLVE_TIMESTEPS", 10000)
  set("FLUID_PERM", 0)
  set("FLUID_GEOMETRY_FLAG", 0)
  set("FLUID_PRESSES_FLAG", 0)
  set("FLUID_PERM_LOW", 0.0001)
  set("FLUID_DENSITY", 1)
  set("FLUID_PERM_HIGH", 4.0)
  M.apply_mimes_params()

  local label = ratio == 0.5 and "1/2" or string.format("%g", ratio)
  return M.scene {
    render = {
      title = string.format("\u{03C1}p / \u{03C1}f = %s: %s", label, what),
      layers = "bodies,mesh,pressure,colorbar,title,time,overlay",
      camera = { 70, 70, 360, 410 }, -- the same frame for the three cases
      size = { 640, 620 },
      overlay = {
        -- the free surface of the standing water (pressure head 0 at y = 300)
        { line = { { 100, 300 }, { 300, 300 } }, color = "#1f5fbf", width = 2 },
        { text = "water surface", at = { 297, 309 }, anchor = "left", size = 13,
          color = "#1f5fbf" },
      },
    },
  }
end

if ... == "buoyancy_case" then return case end -- required as a module
return case(0.5, "floats, half submerged")
