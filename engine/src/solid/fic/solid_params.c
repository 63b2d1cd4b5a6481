/* The solid's parameter table and defaults (porelab/solid.h), apart from the class so that the
 * kernels' tests need no world. */
#include "porelab/solid.h"
#include <stddef.h>
#include <string.h>

#define SF_OFF(f) offsetof(pl_solid_def, f)

const pl_param pl_solid_params[PL_SOLID_PARAM_COUNT] = {
    {"young", NULL, SF_OFF(young), PL_PARAM_DOUBLE, "Pa", 1e-30, 1e30, 2e11, "Young's modulus E"},
    {"poisson", NULL, SF_OFF(poisson), PL_PARAM_DOUBLE, "1", 0, 0.49999, 0.3, "Poisson's ratio nu (plane strain)"},
    {"density", NULL, SF_OFF(density), PL_PARAM_DOUBLE, "kg/m^3", 1e-30, 1e30, 7800, "density rho"},
    {"formulation", NULL, SF_OFF(formulation), PL_PARAM_INT, "0..3", 0, 3, PL_SOLID_FIC_SEMI_IMPLICIT,
     "0 plain triangles, 1 FIC explicit, 2 FIC semi-implicit (CHOLMOD), 3 Q1/P0 quadrilaterals"},
    {"large_strain", NULL, SF_OFF(large_strain), PL_PARAM_BOOL, "0/1", 0, 1, 0,
     "1: updated Lagrangian (current configuration, stress rotated by the spin)"},
    {"yield_stress", NULL, SF_OFF(yield_stress), PL_PARAM_DOUBLE, "Pa", 0, 1e30, 0,
     "J2 initial yield stress sigma_y (0: elastic)"},
    {"hardening", NULL, SF_OFF(hardening), PL_PARAM_DOUBLE, "Pa", 0, 1e30, 0,
     "linear isotropic hardening modulus H: yield sigma_y + H eps_p"},
    {"fic_alpha", NULL, SF_OFF(fic_alpha), PL_PARAM_DOUBLE, "1", 0, 100, 0.1,
     "FIC stabilisation: tau = alpha h^2 / (2 G), h^2 = 2 A"},
    {"damping", NULL, SF_OFF(damping), PL_PARAM_DOUBLE, "1/s", 0, 1e30, 0,
     "mass-proportional damping c: nodal force -c m v"},
    {"contact_stiffness", NULL, SF_OFF(contact_stiffness), PL_PARAM_DOUBLE, "N/m/m", 0, 1e30, 1e8,
     "grain-edge normal spring k_n per m thickness"},
    {"contact_damping", NULL, SF_OFF(contact_damping), PL_PARAM_DOUBLE, "N s/m/m", 0, 1e30, 0,
     "grain-edge normal dashpot c_n per m thickness"},
    {"friction", NULL, SF_OFF(friction), PL_PARAM_DOUBLE, "1", 0, 100, 0, "grain-edge Coulomb coefficient mu"},
    {"slip_velocity", NULL, SF_OFF(slip_velocity), PL_PARAM_DOUBLE, "m/s", 1e-12, 1e30, 1e-3,
     "regularised Coulomb: F_t = mu F_n tanh(|v_t| / v_e)"},
};

pl_solid_def pl_default_solid_def(void) {
    pl_solid_def d;
    memset(&d, 0, sizeof d);
    pl_params_defaults(pl_solid_params, PL_SOLID_PARAM_COUNT, &d);
    return d;
}
