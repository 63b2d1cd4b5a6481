list(APPEND PL_ENGINE_SOURCES
  src/dem/material.c
  src/dem/body.c
  src/dem/neighbor.c
  src/dem/crowding.c
  src/dem/contact_polygon.c
  src/dem/contact_dispatch.c
  src/dem/parallel.c
  src/dem/integrate.c
  src/dem/servo_drive.c
  src/dem/timestep.c
  src/dem/guards.c
  src/dem/diagnostics.c
  src/dem/stress.c
  src/dem/bond.c
  src/dem/bond_params.c
  src/dem/heat.c
  src/dem/box_query.c

  src/dem/vtk.c)
