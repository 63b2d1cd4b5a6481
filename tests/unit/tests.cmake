# Engine core unit tests.
pl_add_c_test(test_engine_unit SOURCES unit/test_engine_unit.c LABEL unit)
# The core allocator, growable array and PL_ASSERT (engine/src/core).
pl_add_c_test(test_core_alloc SOURCES unit/test_core_alloc.c LABEL unit)
