# Engine core unit tests.
pl_add_c_test(test_engine_unit SOURCES unit/test_engine_unit.c LABEL unit)
