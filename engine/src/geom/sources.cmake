list(APPEND PL_ENGINE_SOURCES src/geom/polygon.c)
