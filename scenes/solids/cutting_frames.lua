-- Frames of the cutting scene (seed 002 §7.2, docs/solids.md): the same elasto-plastic tool at
-- 4 m/s through unbonded sand as cutting.lua, drawn with a field layer of the tool:
-- von Mises stress by default, or the equivalent plastic strain with --param field=2.
--   porelab run scenes/solids/cutting_frames.lua --out out/cutting_mises
--   porelab run scenes/solids/cutting_frames.lua --param field=2 --out out/cutting_plastic
local packing = require "porelab.packing"

local P = porelab.params {
  { name = "field", unit = "1", value = 1, min = 1, max = 2,
    doc = "field drawn in the tool: 1 von Mises stress, 2 equivalent plastic strain" },
}
local w = porelab.world { gravity = { 0, -9.81 }, dt_safety = 0.3 }
local sand = w:material { name = "sand", density = 2600, kn = 5e6, friction = 0.5, restitution = 0.3 }
packing.box(w, { lo = { 0, 0 }, hi = { 0.12, 0.05 }, material = sand })
packing.lattice(w, { lo = { 0.001, 0.001 }, hi = { 0.119, 0.03 }, radius = 0.002, material = sand })
w:solid { young = 2e9, poisson = 0.3, density = 7800, formulation = "fic_semi_implicit",
          yield_stress = 2e7, hardening = 2e8, large_strain = true,
          contact_stiffness = 5e6, contact_damping = 20, friction = 0.4 }
w:solid_polygon { points = { { 0.010, 0.024 }, { 0.020, 0.024 }, { 0.026, 0.050 }, { 0.016, 0.050 } }, h = 0.0015 }
w:solid_velocity { box = { 0.0, 0.045, 0.05, 0.051 }, vx = 4.0, vy = 0.0 }

local plastic = P.field >= 2
return {
  world = w,
  run = { t_end = 3e-3, fps = 2000 },
  render = {
    size = { 960, 480 }, camera = { 0.0, 0.0, 0.08, 0.055 },
    layers = "bodies,pressure,colorbar,scalebar,title,time",
    fluid_field = plastic and "plastic_strain" or "mises",
    fluid_range = plastic and { 0, 0.03 } or { 0, 2e7 },   -- Mises up to the yield stress
    colors = { sand = "#d9b36c" },
    title = plastic and "Cutting tool at 4 m/s: equivalent plastic strain"
                    or "Cutting tool at 4 m/s: von Mises stress",
  },
}
