# Triangle meshes: the MIMES quad mesher and point location.
list(APPEND PL_ENGINE_SOURCES src/mesh/quad_mesh.c)
list(APPEND PL_ENGINE_SOURCES src/mesh/gmsh_session.c)
