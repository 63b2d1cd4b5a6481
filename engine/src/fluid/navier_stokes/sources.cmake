# Resolved Navier–Stokes flow in the pore space (seed 004; porelab/navier_stokes.h): element
# kernels, the mesh and gmsh meshing, the global system with UMFPACK, the model class.
list(APPEND PL_ENGINE_SOURCES
  src/fluid/navier_stokes/ns_element.c
  src/fluid/navier_stokes/ns_mesh.c
  src/fluid/navier_stokes/ns_gmsh.c
  src/fluid/navier_stokes/ns_system.c
  src/fluid/navier_stokes/ns_params.c
  src/fluid/navier_stokes/navier_stokes.c)
