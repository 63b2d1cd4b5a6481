# Hydrostatic water (porelab/hydrostatic.h): kernels on plain structs and the model class.
list(APPEND PL_ENGINE_SOURCES
  src/fluid/hydrostatic/hydrostatic_kernels.c
  src/fluid/hydrostatic/hydrostatic_params.c
  src/fluid/hydrostatic/hydrostatic.c)
