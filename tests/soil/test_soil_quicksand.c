/* Quicksand onset with pore pressure from skeleton volume change on (docs/soil.md §4).
 * A bed of discs (rho_s = 2650 kg/m^3, frictionless walls) settles in water with
 * FLUID_CONSOLIDATION 1 (grains moving into or out of the pores change the pressure; the
 * Darcy drag of a moving grain now comes out of the pressure field), then the head under the
 * bed is raised in steps. The bed is "quick" when its floor reaction vanishes; the measured
 * gradient across the bed must be within 10% of
 *     i_c = (1 - n)(G_s - 1)            (Terzaghi; e.g. Das, Principles of Geotechnical Eng.)
 * with n the bed's measured areal porosity. The ramp is slow against the bed's consolidation
 * time, so the coupling must not shift the onset; the test also checks that the excess pore
 * pressure at the floor carries the seepage: it equals rho_f g i H_bed there within 10%. */
#include "harness.h"
#include "soil_common.h"

#define BW 0.06
#define HW 0.10

static void heads(pl_world *w, double dh) {
    pl_world_clear_fluid_bcs(w);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){BW, 0}, HW + dh);
    pl_world_add_fluid_bc(w, (pl_vec2){0, HW}, (pl_vec2){BW, HW}, 0);
}

static double head_at(pl_world *w, double y) {
    double s = 0;
    int n = 0;
    for (int k = 0; k < 25; k++) {
        double h;
        pl_world_prepare(w); /* queries read only: build first */
        if (pl_world_fluid_pressure_at(w, (pl_vec2){BW * (k + 0.5) / 25, y}, NULL, &h)) { s += h; n++; }
    }
    return s / n;
}

static int test_quicksand_onset(void) {
    soil_box b = soil_make_box(BW, 72, 2e5, 0.3);
    pl_world *w = b.w;
    /* frictionless walls already (soil_make_box); water */
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){BW, 0};
    q.corners[2] = (pl_vec2){BW, HW};
    q.corners[3] = (pl_vec2){0, HW};
    q.ndivx = 6;
    q.ndivy = 10;
    pl_world_add_fluid_quad(w, &q);
    heads(w, 0);
    soil_flag(w, "FLUIDS_ON", 1);
    soil_flag(w, "FIRST_STEP_STATIC", 1);
    soil_flag(w, "FLUID_PERM", 1);
    soil_flag(w, "FLUID_PERM_LOW", 1e-3);
    soil_flag(w, "FLUID_PERM_HIGH", 1.0);
    soil_flag(w, "FLUID_STORAGE", 0);
    soil_flag(w, "RAYLEIGH_FACTOR", 30);
    soil_flag(w, "FLUID_CONSOLIDATION", 1);
    soil_flag(w, "FLUID_BULK_MODULUS", 2.2e9);
    soil_flag(w, "FLUID_SOLVE_TIMESTEPS", 2);
    if (soil_run_for(w, 1.2)) return 1;
    double top = soil_grain_top(&b);
    double n = 1 - b.solid_area / (BW * top);
    double i_c = (1 - n) * (2.65 - 1);
    double Wb = (2650 - 1000) * 9.81 * b.solid_area;
    {
        /* at rest, the floor carries the bed's submerged weight (issue 13 item 6: with the
           floor on the mesh's edge the bottom grains lost part of their buoyancy and the floor
           carried 1.2-1.3 W'; docs/fluid.md §6.1) */
        pl_body_info fl;
        pl_world_body_info(w, b.floor_body, &fl);
        fprintf(stderr, "  at rest (still water): floor reaction %.4f W' (W' = (rho_s - rho_f) g A_s = %.3f N/m)\n",
                fabs(fl.force.y) / Wb, Wb);
    }
    double prev_i = 0, prev_r = 1, il = -1, pex_ratio = 0;
    for (double f = 0.5; f <= 1.4; f += 0.02) {
        heads(w, f * i_c * top);
        if (soil_run_for(w, 0.025)) return 1;
        double i = (head_at(w, 1e-9) - head_at(w, top)) / top;
        pl_body_info fl;
        pl_world_body_info(w, b.floor_body, &fl);
        double r = fabs(fl.force.y) / Wb;
        if (r < 0.03) {
            il = prev_i + (i - prev_i) * prev_r / (prev_r - r);
            fprintf(stderr, "  floor reaction %.3f W' at i = %.4f (previous %.3f W' at %.4f): quick at i = %.4f\n", r, i,
                    prev_r, prev_i, il);
            break;
        }
        /* excess pore pressure at the floor against the seepage it carries */
        pl_soil_region rg;
        pl_world_soil_region(w, (pl_vec2){0, 0}, (pl_vec2){BW, 0.004}, &rg);
        pex_ratio = (head_at(w, 1e-9) - HW) / (i * top);
        prev_i = i;
        prev_r = r;
    }
    fprintf(stderr, "  bed n = %.4f (areal), i_c = (1 - n)(G_s - 1) = %.4f; quick at %.4f (%+.1f%%); excess head at the floor / (i H) = %.3f\n",
            n, i_c, il, 100 * (il - i_c) / i_c, pex_ratio);
    pl_validation("soil.quicksand", "quicksand onset with the coupling on", "i_c = (1 − n)(G_s − 1)",
                  "10 %; excess head at the floor / (i H) within 10 % of 1", "%+.1f %% (n = %.3f); excess head ratio %.3f",
                  100 * (il - i_c) / i_c, n, pex_ratio);
    ENSURE(il > 0);
    ENSURE_NEAR(il, i_c, 0.10 * i_c);
    ENSURE_NEAR(pex_ratio, 1.0, 0.10);
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(test_quicksand_onset);
    return pl_test_report();
}
