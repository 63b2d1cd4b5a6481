# Fluid module sources (Darcy finite elements). Owned by the fluid work.
list(APPEND PL_ENGINE_SOURCES src/fluid/fluid_hook.c)
