# Resolved Stokes flow by boundary elements (porelab/stokes.h, seed 003 ch. 4): kernels, the
# dense solve with LAPACK, parameters and the model class.
list(APPEND PL_ENGINE_SOURCES
  src/fluid/stokes_bem/stokes_kernels.c
  src/fluid/stokes_bem/stokes_solve.c
  src/fluid/stokes_bem/stokes_params.c
  src/fluid/stokes_bem/stokes_model.c)
