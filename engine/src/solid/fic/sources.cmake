# Finite-element solids (porelab/solid.h, docs/solids.md): kernels on plain structs
# (solid_internal.h), gmsh meshing, the FIC pressure, the model class.
list(APPEND PL_ENGINE_SOURCES
  src/solid/fic/solid_params.c
  src/solid/fic/solid_element.c
  src/solid/fic/solid_bond.c
  src/solid/fic/solid_pressure.c
  src/solid/fic/solid_step.c
  src/solid/fic/solid_mesh_gmsh.c
  src/solid/fic/solid_model.c)
