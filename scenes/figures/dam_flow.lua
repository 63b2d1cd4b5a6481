-- Seed 000 (Klosek 1997) §4.1, Figs. 4-2 and 4-3: flow under a dam, drawn for the figures of
-- tools/figures.sh. The commands are those of scenes/mimes/dam_flow.lua (Appendix C.1, see
-- there), repeated because a sandboxed scene loads files from its own folder only; the
-- render options differ: the field is the head phi (40 on top of region A, 0 on top of C),
-- equipotentials every 2.5, and the camera frames the channel.
--   porelab still scenes/figures/dam_flow.lua -o dam.png --layers bodies,isolines,title
local M = require("porelab.mimes").session()
local set = M.set

M.add_fluid_mesh_ui(50, 50, 250, 50, 250, 300, 50, 300, 4, 4, 1000)
M.add_fluid_mesh_ui(250, 50, 350, 50, 350, 100, 250, 100, 4, 4, 1001)
M.add_fluid_mesh_ui(350, 50, 480, 50, 480, 300, 350, 300, 4, 4, 1002)
M.add_fluid_bc_ui(50, 300, 250, 300, 40)
M.add_fluid_bc_ui(350, 300, 480, 300, 0)
M.add_rectangle_ui(30, 300, 50, 300, 50, 30, 30, 30, 100, 1)
M.set_velocity(1, 1, 1, 0, 0, 0, 100)
M.add_rectangle_ui(30, 50, 500, 50, 500, 30, 30, 30, 101, 1)
M.set_velocity(1, 1, 1, 0, 0, 0, 101)
M.add_rectangle_ui(480, 30, 480, 300, 500, 300, 500, 30, 102, 1)
M.set_velocity(1, 1, 1, 0, 0, 0, 102)
M.add_rectangle_ui(250, 100, 250, 310, 350, 310, 350, 100, 103, 1)
M.set_velocity(1, 1, 1, 0, 0, 0, 103)
set("FLUIDS_ON", 1)
set("FIRST_STEP_STATIC", 1)
set("MAX_DT_CR", 0.001)
set("TIMESTEPS", 1)
set("FLUID_PERM", 0)
set("FLUID_SOLVE_TIMESTEPS", 2000)
set("FLUID_PERM_LOW", 0.001)
set("FLUID_PERM_HIGH", 5.0)
set("FLUID_DENSITY", 0.1)
M.apply_mimes_params()

return M.scene {
  render = {
    title = "Flow under a dam: head \u{03C6} = 40 upstream (A), 0 downstream (C)",
    layers = "bodies,mesh,pressure,isolines,velocity,colorbar,title",
    size = { 900, 560 },
    camera = { 20, 20, 510, 330 },
    fluid_field = "pressure_head",
    fluid_range = { 0, 40 },
    isolines = 16,
    overlay = {
      { text = "A", at = { 60, 285 }, size = 18 },
      { text = "B", at = { 300, 40 }, anchor = "center", size = 18 }, -- on the floor under B
      { text = "C", at = { 470, 285 }, anchor = "right", size = 18 },
    },
  },
}
