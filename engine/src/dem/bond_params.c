/* Parameter tables of the bond laws and of the thermal/wear properties (porelab/bonds.h). */
#include "porelab/bonds.h"
#include <stddef.h>

#define R(lua, field, type, unit, lo, hi, def, doc) \
    {lua, NULL, offsetof(pl_bond_def, field), PL_PARAM_##type, unit, lo, hi, def, doc}
const pl_param pl_bond_params[PL_BOND_PARAM_COUNT] = {
    R("kn", kn, DOUBLE, "N/m", 0, 1e30, 0, "normal bond stiffness k_n (> 0, required)"),
    R("kt", kt, DOUBLE, "N/m", -1, 1e30, -1, "tangential bond stiffness k_t; -1: k_n / 2"),
    R("kr", kr, DOUBLE, "N m/rad", 0, 1e30, 0, "rotational (rolling) bond stiffness k_r; 0: no moment"),
    R("rn", rn, DOUBLE, "N", 0, 1e30, 0, "tensile strength R_n (> 0, required)"),
    R("rt", rt, DOUBLE, "N", 0, 1e30, 0, "shear strength R_t (> 0, required)"),
    R("combined", combined, BOOL, "0/1", 0, 1, 0, "brittle: elliptic criterion (N/R_n)^2 + (S/R_t)^2 > 1"),
    R("soften", soften, DOUBLE, "1", 1.000001, 1e6, 5, "plastic, damage: opening at failure / elastic limit u_f/u_e"),
    R("tension_only", tension_only, BOOL, "0/1", 0, 1, 0, "damage: only tension damages (shear brittle at R_t)"),
    R("beam", beam, BOOL, "0/1", 0, 1, 0, "brittle: the moment enters the strength, N + 3|M|/R > R_n (Potyondy-Cundall)"),
};
#undef R
#define T(lua, field, unit, lo, hi, def, doc) \
    {lua, NULL, offsetof(pl_thermal_def, field), PL_PARAM_DOUBLE, unit, lo, hi, def, doc}
const pl_param pl_thermal_params[PL_THERMAL_PARAM_COUNT] = {
    T("heat_capacity", heat_capacity, "J/(kg K)", 1e-30, 1e30, 800, "specific heat c"),
    T("conductivity", conductivity, "W/(m K)", 0, 1e30, 0, "thermal conductivity k_th of the contact conductance k_th w/d"),
    T("wear", wear, "1", 0, 1e30, 0, "Archard wear coefficient k"),
    T("hardness", hardness, "Pa", 1e-30, 1e30, 1e9, "hardness H_0 at t_ref"),
    T("softening", softening, "1/K", 0, 1e30, 0, "beta of H(T) = H_0 max(h_min, 1 - beta (T - t_ref))"),
    T("t_ref", t_ref, "K", 0, 1e30, 293.15, "reference temperature of the hardness law"),
    T("h_min", h_min, "1", 1e-6, 1, 0.1, "smallest H(T)/H_0"),
};
#undef T
