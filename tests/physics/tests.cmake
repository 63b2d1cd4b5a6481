# Physics validation of the disc engine against seed 003 and analytic solutions.
pl_add_c_test(test_seed003_validation SOURCES physics/test_seed003_validation.c LABEL physics)
pl_add_c_test(test_contact_laws SOURCES physics/test_contact_laws.c LABEL physics)
pl_add_c_test(test_boundary_motion SOURCES physics/test_boundary_motion.c LABEL physics)
