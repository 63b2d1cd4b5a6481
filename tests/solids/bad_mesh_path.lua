-- Sandbox check of w:solid_mesh (ctest solid_mesh_outside_folder): a mesh file outside the
-- scene's folder and the output folder is refused with the file and the rule.
local w = porelab.world {}
w:solid {}
w:solid_mesh { file = "../../scenes/solids/plate_hole.msh" }
