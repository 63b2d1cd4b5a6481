# Fluid module sources (Darcy finite elements, seed 000 ch. 3). Owned by the fluid work.
list(APPEND PL_ENGINE_SOURCES
  src/fluid/fluid_mesh.c
  src/fluid/fluid_system.c
  src/fluid/fluid_solve.c
  src/fluid/fluid_field.c
  src/fluid/fluid_porosity.c
  src/fluid/fluid_forces.c
  src/fluid/fluid_world.c
  src/fluid/fluid_output.c
  src/fluid/fluid_hook.c
  src/fluid/fluid_consolidation.c
  src/fluid/fluid_soil.c
  src/fluid/fluid_snapshot.c)
