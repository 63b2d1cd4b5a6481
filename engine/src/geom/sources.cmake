list(APPEND PL_ENGINE_SOURCES src/geom/polygon.c src/geom/clip.c src/geom/shapes.c src/geom/rng.c)
