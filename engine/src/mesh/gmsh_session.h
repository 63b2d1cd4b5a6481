/* Starting gmsh's C API from the engine (the rooms that mesh with gmsh call this instead of
 * gmshInitialize). */
#ifndef PL_MESH_GMSH_SESSION_H
#define PL_MESH_GMSH_SESSION_H

/* gmshInitialize without its side effects on the user's files: Debian's libgmsh is built with
 * FLTK, whose preferences are created under $HOME/.fltk at initialisation even with
 * readConfigFiles = 0 — a write outside the scene's output folder. HOME points at /dev/null
 * (where nothing can be created) for the duration of the call and is restored after. Not
 * thread-safe (neither is gmsh). Returns gmsh's error code (0: initialised). */
int pl__gmsh_initialize(void);

#endif
