# Bonded rock, heat and wear (porelab/bonds.h, docs/rock.md): closed-form checks.
pl_add_c_test(test_bond_laws SOURCES rock/test_bond_laws.c LABEL physics)
pl_add_c_test(test_lattice SOURCES rock/test_lattice.c LABEL physics)
pl_add_c_test(test_rock_state SOURCES rock/test_rock_state.c LABEL physics)
pl_add_c_test(test_heat_wear SOURCES rock/test_heat_wear.c LABEL physics)
