# Bonded rock, heat and wear (porelab/bonds.h, docs/rock.md): closed-form checks.
pl_add_c_test(test_bond_laws SOURCES rock/test_bond_laws.c LABEL physics)
pl_add_c_test(test_lattice SOURCES rock/test_lattice.c LABEL physics)
