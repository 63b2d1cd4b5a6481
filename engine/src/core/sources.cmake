list(APPEND PL_ENGINE_SOURCES src/core/status.c src/core/hash.c src/core/params.c
  src/core/alloc.c src/core/assert.c)
