-- A solid part read from a gmsh mesh file (docs/solids.md): plate_hole.msh beside this scene is
-- a 2 m x 1 m steel plate with a hole of radius 0.25 m (triangles made by gmsh). The plate is
-- clamped on its left edge and pulled on its right edge by 10 MPa; the scene prints the end's
-- displacement and the largest Mises stress (the hole concentrates the stress, about 3 x the
-- nominal 10 MPa in an infinite plate).
--   porelab run scenes/solids/mesh_file.lua
local w = porelab.world { gravity = { 0, 0 } }
w:solid { young = 2e11, poisson = 0.3, density = 7800, damping = 2e4 }
w:solid_mesh { file = "plate_hole.msh" }
w:solid_fix { box = { -1e-6, -1, 1e-6, 2 } }
w:solid_traction { box = { 2 - 1e-6, -1, 2 + 1e-6, 2 }, tx = 1e7 }
local info = w:solid_info()
print(string.format("plate_hole.msh: %d nodes, %d triangles", info.nodes, info.elements))
w:step(4000)
local ux = w:solid_displacement(2, 0.5)
local smax = w:solid_extremes()
print(string.format("end displacement %.4g m, Mises max %.4g MPa (nominal 10 MPa)", ux, smax / 1e6))
assert(ux > 0 and smax > 1.5e7, "the plate must stretch and the hole concentrate the stress")
