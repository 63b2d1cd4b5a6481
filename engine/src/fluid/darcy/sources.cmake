# Darcy seepage on finite elements (seed 000 ch. 3; the MIMES fluid), a model under world/model.h.
list(APPEND PL_ENGINE_SOURCES
  src/fluid/darcy/darcy_params.c
  src/fluid/darcy/darcy_system.c
  src/fluid/darcy/darcy_solve.c
  src/fluid/darcy/darcy_field.c
  src/fluid/darcy/darcy_porosity.c
  src/fluid/darcy/darcy_forces.c
  src/fluid/darcy/darcy_world.c
  src/fluid/darcy/darcy_output.c
  src/fluid/darcy/darcy_model.c
  src/fluid/darcy/darcy_consolidation.c
  src/fluid/darcy/darcy_stagger.c
  src/fluid/darcy/darcy_soil.c
  src/fluid/darcy/darcy_snapshot.c)
