/* Navier–Stokes validation on fixed gmsh meshes against published values (seed 004 §6):
 *   - lid-driven cavity, Re = 100: centreline velocities against Ghia, Ghia & Shin (1982);
 *   - Schäfer & Turek (1996) DFG benchmark 2D-1 (Re = 20): c_D, c_L, Delta p in the bands;
 *   - cylinder between plates in the Stokes limit: Faxén's series for a translating cylinder,
 *     Richou et al. (2004) lambda at k = 0.125 (Poiseuille), Tan (1990) T/(mu U) = 24.20 at
 *     k = 0.2, the seed's dodecagon corner-on / side-on.
 * `test_ns_validation` runs the fast meshes; `test_ns_validation long` (ctest label long) adds
 * the mesh sequences and all three elements. */
#include "harness.h"
#include "navier_stokes/ns_cases.h"
#include <stdlib.h>
#include <string.h>

static char msg[512];
static int long_run = 0;

/* Ghia et al. (1982) Tables I-II, Re = 100: every interior point within 1 % of the lid speed. */
static int test_cavity_ghia(void) {
    const double hs[3] = {0.08, 0.04, 0.02}, hc[3] = {0.004, 0.002, 0.001};
    const int nmesh = long_run ? 3 : 1, first = long_run ? 0 : 1;
    for (int kind = 0; kind < (long_run ? 3 : 1); kind++)
        for (int i = first; i < first + nmesh && i < 3; i++) {
            ns_cavity_result r;
            ENSURE(ns_case_cavity(kind, hs[i], hc[i], 100, &r, msg, sizeof msg) == 0);
            printf("cavity Re=100 %-13s h=%.3f (corners %.3f): %6d unknowns, max |u-u_Ghia| %.4f, max |v-v_Ghia| "
                   "%.4f; u_min %.5f v_min %.5f v_max %.5f; Newton %d; CPU %.2f s (factor %.2f, solve %.2f), fill "
                   "%.1f\n",
                   ns_elem_name(kind), hs[i], hc[i], r.nunk, r.err_u, r.err_v, r.u_min, r.v_min, r.v_max,
                   r.st.newton_iters, r.t_total, r.st.t_numeric, r.st.t_solve, r.st.nnz_lu / r.st.nnz_matrix);
            if (i == 1) {
                pl_validation("fluid.ns_cavity", "Navier-Stokes: lid-driven cavity Re=100, centreline velocities",
                              "Ghia, Ghia & Shin 1982, Tables I-II (30 points)", "< 1 % of lid speed",
                              "%s h=%.2f: max dev. u %.2f %%, v %.2f %%", ns_elem_name(kind), hs[i], 100 * r.err_u,
                              100 * r.err_v);
                if (kind != NS_EL_MINI) {
                    ENSURE(r.err_u < 0.01);
                    ENSURE(r.err_v < 0.01);
                }
            }
        }
    return 0;
}

/* Schäfer & Turek (1996), 2D-1: c_D in [5.57, 5.59], c_L in [0.0104, 0.0110], Delta p in
   [0.1172, 0.1176] (reference 5.57953523384, 0.010618948146, 0.11752016697, John 2004). */
static int test_dfg(void) {
    const double hn[2] = {0.005, 0.0025}, hf[2] = {0.03, 0.02};
    for (int kind = 0; kind < (long_run ? 3 : 1); kind++)
        for (int i = 0; i < (long_run ? 2 : 1); i++) {
            ns_dfg_result r;
            ENSURE(ns_case_dfg(kind, hn[i], hf[i], 128, &r, msg, sizeof msg) == 0);
            printf("DFG 2D-1 %-13s h=%.4f/%.3f: %6d unknowns, c_D %.5f c_L %.5f dp %.5f (line integral: c_D %.5f "
                   "c_L %.5f); flux in/mid/out %.6f %.6f %.6f; ||div u|| %.2e; CPU %.2f s\n",
                   ns_elem_name(kind), hn[i], hf[i], r.nunk, r.cd, r.cl, r.dp, r.cd_line, r.cl_line, r.flux_in,
                   r.flux_mid, r.flux_out, r.div_l2, r.t_total);
            if (i == 0)
                pl_validation("fluid.ns_dfg", "Navier-Stokes: DFG 2D-1 cylinder in a channel, Re=20",
                              "Schaefer & Turek 1996: c_D 5.57-5.59, c_L 0.0104-0.0110, dp 0.1172-0.1176",
                              "inside the bands", "%s: c_D %.4f, c_L %.5f, dp %.5f", ns_elem_name(kind), r.cd, r.cl,
                              r.dp);
            if (kind == NS_EL_MINI) continue;
            ENSURE(r.cd >= 5.57 && r.cd <= 5.59);
            ENSURE(r.cl >= 0.0104 && r.cl <= 0.0110);
            ENSURE(r.dp >= 0.1172 && r.dp <= 0.1176);
            /* mass: the inflow 2/3 U_max H = 0.082 leaves through every cut */
            ENSURE_REL(r.flux_mid, 0.082, 1e-4);
            ENSURE_REL(r.flux_out, 0.082, 1e-4);
        }
    return 0;
}

/* Stokes limit between plates y = +-b. */
static int test_plates(void) {
    const double h = long_run ? 0.05 : 0.15, hf = long_run ? 1.0 : 3.0;
    ns_plates_result r;
    /* Faxén (Happel & Brenner 1965): a cylinder translating midway between plates,
       F/(mu U) = 4 pi / (ln(1/k) - 0.9157 + 1.7244 k^2 - 1.7302 k^4), k = r/b. Built as the same
       flow seen from the cylinder: walls and ends moving at -U. */
    {
        const double k = 0.125, rp = 1.0, b = rp / k;
        double xy[2 * 128];
        ns_ngon(128, 0, 0, rp, NS_PI, xy);
        const int32_t off[2] = {0, 128};
        ns_domain d = {-25, -b, 25, b, h, hf, 0.5, 4 * b, 1, off, xy, 0};
        ns_mesh m;
        ENSURE(ns_mesh_domain(&d, &m, msg, sizeof msg) == 0);
        ns_system s;
        ENSURE(ns_system_init(&s, &m, NS_EL_P2B, 5) == 0);
        s.nu = 1;
        ns_case_ctx c = {3, 0, 0, 0, 0, -1.0};
        const uint8_t tk[6] = {0, 1, 1, 1, 1, 1};
        ns_system_set_bc(&s, tk, ns_case_bc, &c);
        /* the hole is tag 5: zero velocity there */
        for (int j = 0; j < s.nvel; j++)
            if (s.node_tag[j] == NS_TAG_HOLE0) s.gu[j] = s.gv[j] = 0;
        ENSURE(ns_case_solve(&s, 0, msg, sizeof msg) == 0);
        double fx, fy;
        ns_system_force_react(&s, 0, NS_TAG_HOLE0, 1, 0, 0, &fx, &fy, NULL);
        const double fax = 4 * NS_PI / (log(1 / k) - 0.9157 + 1.7244 * k * k - 1.7302 * pow(k, 4));
        printf("translating cylinder k=0.125 (128-gon): F/(mu U) = %.4f, Faxen %.4f\n", -fx, fax);
        pl_validation("fluid.ns_faxen", "Navier-Stokes, Stokes limit: cylinder translating between plates, k=0.125",
                      "Faxen series (Happel & Brenner 1965): 10.558", "0.2 %", "%.4f (%.2f %%)", -fx,
                      100 * (-fx / fax - 1));
        ENSURE_REL(-fx, fax, 0.002);
        ns_system_free(&s);
    }
    /* Tan (1990) eq. 4.110: half width 5R, mean velocity U = 2/3 U0, T/(mu U) = 24.20
       (Takaisi 24.23, Bezine & Bonneau 24.15, Harrison 24.55). */
    ENSURE(ns_case_plates(NS_EL_P2B, 128, 1.0, NS_PI, 5.0, 25.0, h, hf, &r, msg, sizeof msg) == 0);
    const double tan = 1.5 * r.lam_react;
    printf("cylinder in Poiseuille flow k=0.2: F/(mu U0) = %.4f, T/(mu U_mean) = %.3f (line integral %.3f), "
           "lift %.1e; Tan 24.20\n",
           r.lam_react, tan, 1.5 * r.lam_line, r.fy);
    pl_validation("fluid.ns_tan", "Navier-Stokes, Stokes limit: fixed cylinder in Poiseuille flow, k=0.2",
                  "Tan 1990 eq. 4.110: T/(mu U_mean) = 24.20 (boundary elements)", "1 %", "%.3f (%.2f %%)", tan,
                  100 * (tan / 24.20 - 1));
    ENSURE_REL(tan, 24.20, 0.01);
    ENSURE(fabs(r.fy) < 1e-4 * r.lam_react);
    /* Richou et al. (2004): lambda = F / (mu U0) at k = r/b = 0.125, U0 the centreline velocity */
    ENSURE(ns_case_plates(NS_EL_P2B, 128, 1.0, NS_PI, 8.0, 25.0, h, hf, &r, msg, sizeof msg) == 0);
    printf("cylinder in Poiseuille flow k=0.125: lambda = F/(mu U0) = %.4f (line integral %.4f); Richou 10.65\n",
           r.lam_react, r.lam_line);
    pl_validation("fluid.ns_richou", "Navier-Stokes, Stokes limit: wall correction lambda = F/(mu U0), k=0.125",
                  "Richou et al. 2004 (Mueller et al. 2020 Table 2): 10.65", "2 %", "circle (128-gon): %.3f (%.2f %%)",
                  r.lam_react, 100 * (r.lam_react / 10.65 - 1));
    ENSURE_REL(r.lam_react, 10.65, 0.02);
    /* the seed's dodecagon (r_max = 15 mm scaled to 1): b = r_ref / k for r_max, r_min, r_equi */
    const double rmax = 1.0, rmin = cos(NS_PI / 12), requi = sqrt(3.0 / NS_PI);
    const double rref[3] = {rmax, rmin, requi};
    const char *rname[3] = {"r_max", "r_min", "r_equi"};
    for (int o = 0; o < 2; o++)
        for (int k = long_run ? 0 : 2; k < 3; k++) { /* r_max and r_min with "long" */
            /* corner on: a vertex faces the inflow (angle pi); side on: rotated by pi/12 */
            const double rot = NS_PI + (o ? NS_PI / 12 : 0);
            ENSURE(ns_case_plates(NS_EL_P2B, 12, rmax, rot, rref[k] / 0.125, 25.0 * rmax, h, hf, &r, msg,
                                  sizeof msg) == 0);
            printf("dodecagon %-9s k = %s/b = 0.125: lambda = %.5f (%+.1f %% vs 10.65)\n", o ? "side-on" : "corner-on",
                   rname[k], r.lam_react, 100 * (r.lam_react / 10.65 - 1));
            if (k == 2)
                pl_validation("fluid.ns_dodecagon", "Navier-Stokes: dodecagon between plates, k = r_equi/b = 0.125",
                              "Richou et al. 2004 circle 10.65; Mueller et al. 2020 Table 2", "4 %", "%s %.3f (%+.1f %%)",
                              o ? "side-on" : "corner-on", r.lam_react, 100 * (r.lam_react / 10.65 - 1));
            if (k == 2) ENSURE_REL(r.lam_react, 10.65, 0.04);
        }
    return 0;
}

int main(int argc, char **argv) {
    if (!ns_have_gmsh()) {
        printf("no gmsh in this build: the meshing tests are skipped\n");
        return 0;
    }
    /* argument: "long" (everything on the mesh sequences), or one of cavity, dfg, plates (the fast
       meshes; ctest runs the three as separate tests) */
    long_run = argc > 1 && strcmp(argv[1], "long") == 0;
    const char *only = argc > 1 && !long_run ? argv[1] : NULL;
    if (!only || !strcmp(only, "cavity")) RUN(test_cavity_ghia);
    if (!only || !strcmp(only, "dfg")) RUN(test_dfg);
    if (!only || !strcmp(only, "plates")) RUN(test_plates);
    return pl_test_report();
}
