# The world layer: facade, attached models, flags (MIMES compatibility), snapshots, state image, hash.
list(APPEND PL_ENGINE_SOURCES
  src/world/world.c
  src/world/models.c
  src/world/model_services.c
  src/world/flags.c
  src/world/snapshot.c
  src/world/image.c
  src/world/snapshot_file.c
  src/world/hash.c)
