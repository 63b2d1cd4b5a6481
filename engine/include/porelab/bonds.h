/// Bonded rock, frictional heat and wear of the grain engine (seed 002, Oñate & Rojek 2004,
/// §3 cohesive bonds, §4 heat and wear; docs/rock.md gives every law with its source).
///
/// A bond ties two discs with a spring that carries tension, shear and (optionally) a moment
/// until it breaks; it is a persistent object: created between touching or nearly touching
/// discs (pl_world_bond_touching, pl_world_add_bond), never created or dropped by the
/// broadphase, kept (intact or broken) for the life of the world, in the state hash, the
/// snapshots and the restart files. A bond acts in parallel with the pair's contact law (the
/// parallel bond of Potyondy & Cundall 2004): where the outlines overlap the contact pushes as
/// for any pair; the bond adds its springs while intact. Once broken the pair is an ordinary
/// frictional contact of its materials, without a jump of force or energy.
///
/// Bond kinematics (discs a, b; n from a to b, t = (-n.y, n.x); l_a, l_b = d r_a/(r_a + r_b),
/// d r_b/(r_a + r_b) the arms from the centres to the bond point):
///   u_n = d - d_0                       (normal opening, m; d_0 the distance at creation)
///   du_t = [(v_b - v_a).t - l_a w_a - l_b w_b] dt   (tangential slip, m)
///   dtheta = (w_b - w_a) dt             (relative rotation, rad)
/// Forces: the bond pulls with N (tension positive) and resists slip with S:
///   force on b = -N n - S t, on a the opposite; moment -M on b, +M on a (plus the moments of
///   S about the centres).
/// Laws (per material pair, pl_world_set_bond_law):
///   brittle (seed 002 §3.1, eqs. 45-50): N = k_n u_n, S = k_t u_t, M = k_r theta; breaks
///     when N > R_n or |S| > R_t (separate), or (max(N,0)/R_n)^2 + (S/R_t)^2 > 1 (combined);
///     with beam = 1 the tension is N + 3|M|/R (Potyondy & Cundall 2004: N/A + |M|R/I).
///   plastic (§3.2): elastic up to R_n (R_t), then linear softening of the yield force,
///     R(kappa) = R_n (1 - kappa/u_f), kappa the accumulated plastic opening (slip), u_f =
///     soften x R_n/k_n; unloading elastic; breaks when kappa reaches u_f. Compression elastic.
///   damage (§3.3): N = (1 - w_n) k_n u_n, w_n from the largest opening kappa reached:
///     w = 1 - (u_e/kappa)(u_f - kappa)/(u_f - u_e) (linear strain softening), u_e = R_n/k_n,
///     u_f = soften x u_e; compression is carried undamaged (crack closure). Shear damages the
///     same way with R_t unless tension_only = 1 (then shear is brittle at R_t). Breaks at w = 1.
/// Energy (pl_world_energy): the bond springs' energy is in `elastic`; what softening, damage
/// and breaking release is in `fracture`, part of the balance.
#ifndef PORELAB_BONDS_H
#define PORELAB_BONDS_H

#include "porelab/params.h"
#include "porelab/world.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum pl_bond_law_kind {
    PL_BOND_BRITTLE = 0, ///< elastic perfectly brittle (seed 002 §3.1)
    PL_BOND_PLASTIC = 1, ///< elasto-plastic with linear softening (§3.2)
    PL_BOND_DAMAGE = 2   ///< elastic with damage, linear strain softening (§3.3)
} pl_bond_law_kind;

/// Bond law of a material pair. Fill with pl_default_bond_def(). Stiffnesses per unit
/// thickness like the contact springs (2D, forces in N per metre of thickness).
typedef struct pl_bond_def {
    pl_bond_law_kind law; ///< default PL_BOND_BRITTLE
    double kn;            ///< normal bond stiffness k_n, N/m; > 0 (required)
    double kt;            ///< tangential bond stiffness k_t, N/m; >= 0. Default -1: kn/2.
    double kr;            ///< rotational (rolling) stiffness k_r, N m/rad; >= 0; 0 = no moment. Default 0.
    double rn;            ///< tensile strength R_n, N; > 0 (required)
    double rt;            ///< shear strength R_t, N; > 0 (required)
    int combined;         ///< brittle: 1 = elliptic criterion (N/R_n)^2 + (S/R_t)^2 > 1; default 0
    double soften;        ///< plastic, damage: u_f / u_e, the opening at failure over the elastic
                          ///< limit (> 1; the area under the curve is R u_f / 2). Default 5.
    int tension_only;     ///< damage: 1 = only tension damages, shear is brittle at R_t; default 0
    int beam;             ///< brittle: 1 = the moment enters the strength (Potyondy & Cundall 2004,
                          ///< eq. 9): the bond is a beam of width 2R (R = min(r_a, r_b)), area
                          ///< A = 2R, inertia I = (2R)^3/12 per metre; it breaks when
                          ///< sigma = N/A + |M| R / I > R_n / A, i.e. N + 3|M|/R > R_n (tension,
                          ///< or with `combined` this effective tension enters the ellipse), or
                          ///< tau = |S|/A > R_t / A. Needs kr > 0 to matter. Default 0.
} pl_bond_def;

pl_bond_def pl_default_bond_def(void);
/// Parameter table of pl_bond_def (the numeric fields; `law` is given by name in Lua).
#define PL_BOND_PARAM_COUNT 9
extern const pl_param pl_bond_params[PL_BOND_PARAM_COUNT];

/// Sets the bond law of the material pair (both orders). Bonds created afterwards use it;
/// existing bonds keep theirs.
pl_status pl_world_set_bond_law(pl_world *w, int material_a, int material_b, const pl_bond_def *def);

/// Bonds every pair of discs (any motion type, one of them dynamic or both fixed) whose
/// surfaces are at most `gap` apart (m, >= 0; overlapping discs too) and whose material pair
/// has a bond law; a pair already bonded is skipped. The rest length is the distance now.
/// Returns the number of bonds created (>= 0) or a negative pl_status.
int pl_world_bond_touching(pl_world *w, double gap);
/// Bonds discs a and b (their material pair must have a law; any distance). Returns the bond
/// index (>= 0) or a negative pl_status.
int pl_world_add_bond(pl_world *w, int a, int b);

/// Bonds ever created (intact and broken) and intact ones.
int pl_world_bond_total(const pl_world *w);
int pl_world_bond_count(const pl_world *w);

typedef enum pl_bond_state {
    PL_BOND_INTACT = 0,
    PL_BOND_BROKEN_TENSION = 1, ///< N reached R_n (plastic, damage: the softening ended in tension)
    PL_BOND_BROKEN_SHEAR = 2,   ///< |S| reached R_t
    PL_BOND_BROKEN_COMBINED = 3,///< the combined criterion
    PL_BOND_BROKEN_REMOVED = 4  ///< one of its grains was worn away
} pl_bond_state;

typedef struct pl_bond_info {
    int a, b;           ///< body indices (a < b)
    int state;          ///< pl_bond_state
    double n, s, m;     ///< tension N (N, > 0 pulling), shear S (N), moment M (N m), last step
    double un, ut;      ///< opening u_n and slip u_t, m
    double damage;      ///< damage: max(w_n, w_t); plastic: kappa/u_f; brittle: 0
    double elastic;     ///< energy stored in the bond, J
    double dissipated;  ///< energy released by softening, damage and breaking so far, J
    pl_vec2 point;      ///< bond point (between the discs), m
    int64_t broken_step;///< step at which it broke (-1 intact)
    double broken_time; ///< s
} pl_bond_info;

/// Copies bonds (index order) from `first` on into out[0..cap) and returns how many.
int pl_world_copy_bonds(const pl_world *w, int first, pl_bond_info *out, int cap);
/// The bonds that broke after step `since` (pl_world_step_count before the step call):
/// break events, in bond order. Returns how many were written (<= cap); with cap 0 it counts.
int pl_world_broken_bonds(const pl_world *w, int64_t since, pl_bond_info *out, int cap);

/// History of one bond held by another model (the finite-element solid's grain-edge bonds,
/// porelab/solid.h): the law's state of pl_bond_law_eval. Zero it at creation.
typedef struct pl_bond_history {
    double up_n, up_t;   ///< plastic opening and slip, m
    double kap_n, kap_t; ///< plastic: accumulated plastic increment; damage: largest |u| reached, m
    double om_n, om_t;   ///< damage 0..1
    double dissipated;   ///< released so far, J per m
} pl_bond_history;

/// What pl_bond_law_eval gives: tension n (N, > 0 pulling), shear s (N), moment m (N m), the
/// energy stored after the evaluation and released by it (J), and the break (pl_bond_state,
/// 0 while intact; forces are 0 once broken).
typedef struct pl_bond_result {
    double n, s, m, elastic, released;
    int broke;
} pl_bond_result;

/// The grains' bond law (brittle, plastic or damage, as pl_world_set_bond_law; docs/rock.md)
/// for opening un (m), slip ut (m) and rotation rot (rad), all since creation, of a bond of
/// half width hw (m, the beam criterion's R); updates h. The same kernel as the disc-disc bonds.
/// def must have passed pl_bond_def_check.
void pl_bond_law_eval(const pl_bond_def *def, pl_bond_history *h, double un, double ut, double rot, double hw,
                      pl_bond_result *out);
/// Checks a bond law (ranges of pl_bond_params; kn, rn, rt > 0; kt > 0 for the plastic and damage
/// laws) and resolves kt = -1 to kn/2. PL_OK, or PL_ERR_ARG with the reason in msg.
pl_status pl_bond_def_check(pl_bond_def *def, const char *who, char *msg, size_t len);

/* ------------------------------------------------------------------ heat and wear */

/// Thermal and wear properties of a material (seed 002 §4). Fill with pl_default_thermal_def().
typedef struct pl_thermal_def {
    double heat_capacity; ///< specific heat c, J/(kg K); > 0. Default 800 (granite).
    double conductivity;  ///< k_th, W/(m K); >= 0. Contact conductance H = k_th w / d x 1 m
                          ///< (w contact width: overlap chord, or the bond width 2 min(r_a, r_b);
                          ///< d the centre distance; the harmonic mean of the two materials' k).
                          ///< Default 0.
    double wear;          ///< Archard coefficient k, dimensionless; >= 0. Default 0 (no wear).
    double hardness;      ///< H_0 at t_ref, Pa; > 0. Default 1e9.
    double softening;     ///< beta, 1/K: H(T) = H_0 max(h_min, 1 - beta (T - t_ref)); >= 0. Default 0.
    double t_ref;         ///< reference temperature, K; default 293.15
    double h_min;         ///< smallest H(T)/H_0, in (0, 1]; default 0.1
} pl_thermal_def;

pl_thermal_def pl_default_thermal_def(void);
/// Parameter table of pl_thermal_def.
#define PL_THERMAL_PARAM_COUNT 7
extern const pl_param pl_thermal_params[PL_THERMAL_PARAM_COUNT];
/// Hardness at temperature T (K), Pa: H_0 max(h_min, 1 - beta (T - t_ref)) (seed 002 §4.2).
double pl_thermal_hardness(const pl_thermal_def *d, double T);
/// Heat q (J per m, >= 0) and wear work fn_s = F_n |v_t| dt (N m per m) that a sliding contact
/// with another model (the finite-element solid) delivers to grain `body`: its temperature rises
/// by q / (m c) and, while wear is on, its worn area by k fn_s / H(T) (the grain-grain laws,
/// docs/rock.md). Nothing happens while heat is off. PL_ERR_ARG for a bad body or value.
pl_status pl_world_body_contact_heat(pl_world *w, int body, double q, double fn_s);
/// Sets the thermal and wear properties of a material.
pl_status pl_world_set_thermal(pl_world *w, int material, const pl_thermal_def *def);

/// Switches heat on: every body starts at t_initial (K, > 0); `fraction` alpha in [0, 1] of
/// the frictional dissipation Q = |F_t v_t| of every sliding contact becomes heat, half to
/// each body of the pair; conduction through touching contacts and intact bonds,
/// C_i dT_i/dt = sum_j H_ij (T_j - T_i) (explicit; the step must satisfy dt sum_j H_ij <= C_i,
/// else the step stops with a message). Wear (Archard) needs heat on for H(T).
pl_status pl_world_enable_heat(pl_world *w, double fraction, double t_initial);
/// Sets a body's temperature, K; hold = 1 keeps it there (a reservoir: it absorbs or gives
/// what conduction asks).
pl_status pl_world_set_body_temperature(pl_world *w, int body, double t, int hold);
/// Temperature of a body, K (NaN without heat or out of range).
double pl_world_body_temperature(const pl_world *w, int body);
/// Heat a body has received (friction and conduction, J) since heat was switched on.
double pl_world_body_heat(const pl_world *w, int body);
/// Copies temperatures (K) of bodies 0..cap-1; returns the count (0 without heat).
int pl_world_copy_temperatures(const pl_world *w, double *out, int cap);

/// Archard wear: the wear volume (per unit thickness, m^3/m) of every body of a sliding
/// contact grows at dV/dt = k F_n |v_t| / H(T) with its own material's k, H_0, beta; walls
/// (segments) too. A disc whose wear reaches its area is removed after the step (remove = 1):
/// it keeps its index, leaves every contact and bond (bonds marked REMOVED) and stops moving.
pl_status pl_world_enable_wear(pl_world *w, int remove);
/// Worn volume of a body, m^3 per m of thickness (0 without wear).
double pl_world_body_wear(const pl_world *w, int body);
/// 1 when the body was removed by wear (its removal time in *time, s, when not NULL).
int pl_world_body_removed(const pl_world *w, int body, double *time);
/// Number of bodies removed (by wear or pl_world_remove_body) so far.
int pl_world_removed_count(const pl_world *w);
/// Removes a disc between steps as wear does (to carve a specimen out of a packing): it keeps
/// its index, leaves every contact and bond and stops moving; recorded like a worn grain.
pl_status pl_world_remove_body(pl_world *w, int body);

/// Number of touching contacts of a body after the last step (the contacts pl_world_copy_contacts
/// lists with a or b == body); 0 for an index out of range. Used by the specimen helpers
/// (lua/lib/porelab/rock.lua) to keep a servo wall's gain below its stability limit.
int pl_world_body_touching(const pl_world *w, int body);

#ifdef __cplusplus
}
#endif
#endif
