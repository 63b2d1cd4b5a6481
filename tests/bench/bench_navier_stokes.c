/* Benchmark of the resolved Navier–Stokes solver (not a test): error against CPU time for the
 * three elements (P2 + bubble / P1, P2/P1, MINI) on several gmsh meshes of
 *   - the lid-driven cavity at Re = 100 (error: largest deviation of the centreline extremes
 *     u_min, v_min, v_max from the finest P2 + bubble run of the same benchmark), and
 *   - the DFG 2D-1 cylinder (error: |c_D - 5.57953523384| / 5.5795, reference of John 2004),
 * the cost split of each stationary solve (assembly, UMFPACK analysis, factorisation, solve,
 * fill of L + U), and the cost per coupled step of the model with a moving grain (remesh,
 * interpolation, assembly, factorisation, solve, forces).
 *     bench_navier_stokes [OUT_DIR]     CSV to OUT_DIR/bench_navier_stokes.csv; with the app's
 *                                       charts OUT_DIR/ns_cavity_error_cpu.png, ns_dfg_error_cpu.png
 *     bench_navier_stokes --moving      only the cost per coupled step of the settling disc
 *     bench_navier_stokes --plates K L  lambda of a fixed circle between plates (k = K, ends at +-L)
 *     bench_navier_stokes --cavity-p2 H only the Taylor-Hood P2/P1 cavity at Re = 100 on a uniform
 *                                       mesh of size H, one line "FF ..." for run_freefem_ns.sh */
#include "navier_stokes/ns_cases.h"
#include "porelab/navier_stokes.h"
#include "porelab/world.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if BENCH_CHART
#include "bench/bench_chart.h"
#endif

#define NMESH 4
static const char *names[3] = {"P2+bubble/P1", "P2/P1", "MINI"};

/* one series per element: CPU time per stationary solve against the error */
static void chart(const char *dir, const char *file, const char *ylab, const char *title, double C[3][NMESH],
                  double E[3][NMESH], int nm) {
#if BENCH_CHART
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    const double *const x[3] = {C[0], C[1], C[2]}, *const y[3] = {E[0], E[1], E[2]};
    const int n[3] = {nm, nm, nm};
    bench_error_cpu_chart(path, title, "CPU time per stationary solve (s)", ylab, 1, 3, names, x, y, n);
#else
    (void)dir, (void)file, (void)ylab, (void)title, (void)C, (void)E, (void)nm;
#endif
}

static void moving_grain_cost(FILE *csv) {
    pl_world_def wd = pl_default_world_def();
    wd.dt = 2e-3;
    pl_world *w = pl_world_create(&wd);
    pl_material_def md = pl_default_material_def();
    md.name = "grain";
    md.density = 2500;
    md.kn = 1e5;
    pl_world_add_material(w, &md);
    pl_body_def b = pl_default_body_def();
    b.shape = PL_SHAPE_DISC;
    b.material = 0;
    b.radius = 0.01;
    b.position = (pl_vec2){0, 0.25};
    pl_world_add_body(w, &b);
    pl_navier_stokes_def d = pl_default_navier_stokes_def();
    d.x_min = -0.08;
    d.x_max = 0.08;
    d.y_max = 0.4;
    d.viscosity = 50;
    d.core_fraction = 1.0;
    d.h_near = 0.002;
    d.h_far = 0.02;
    d.grade_distance = 0.04;
    d.disc_sides = 64;
    d.force_relaxation = 0.3; /* below the coupling limit (rotation: beta (1 + 4.3) < 2) */
    if (pl_world_attach_navier_stokes(w, &d) != PL_OK) {
        printf("%s\n", pl_world_last_error(w));
        pl_world_destroy(&w);
        return;
    }
    const int n = 20;
    if (pl_world_step(w, n) != PL_OK) printf("%s\n", pl_world_last_error(w));
    pl_ns_stats s;
    pl_world_navier_stokes_stats(w, &s);
    const double per = 1.0 / (double)s.fluid_steps;
    printf("\nmoving disc (settling): %d vertices, %d unknowns, %ld gmsh meshes and %ld relocations in %ld fluid "
           "steps, %.1f Newton iterations per step\n",
           s.vertices, s.unknowns, s.remeshes, s.relocations, s.fluid_steps, (double)s.newton_iters * per);
    printf("  CPU per coupled step: remesh %.4f s, relocation %.4f s, interpolation %.4f s, projection %.4f s, "
           "assembly %.4f s, factorisation %.4f s, solve %.4f s, forces %.5f s, coupling check %.4f s; fill (L+U)/A "
           "%.1f\n",
           s.t_mesh * per, s.t_relocate * per, s.t_interp * per, s.t_project * per, s.t_assembly * per,
           s.t_factor * per, s.t_solve * per, s.t_forces * per, s.t_stability * per, s.nnz_lu / s.nnz_matrix);
    if (csv)
        fprintf(csv, "moving_disc,P2+bubble/P1,%d,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e\n", s.unknowns, s.t_mesh * per,
                s.t_interp * per, s.t_assembly * per, s.t_factor * per, s.t_solve * per, s.t_forces * per);
    pl_world_destroy(&w);
}

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";
    char path[512], msg[512];
    if (argc > 3 && !strcmp(argv[1], "--plates")) {
        /* lambda = F / (mu U0) of a fixed circle (128-gon, r = 1) midway between walls at y = +-b,
           k = 1/b, with Poiseuille profiles prescribed at x = +-L */
        const double k = atof(argv[2]), L = atof(argv[3]);
        const double hn = argc > 4 ? atof(argv[4]) : 0.05, hf = argc > 5 ? atof(argv[5]) : 0.5;
        ns_plates_result r;
        if (!(k > 0.01 && k < 0.9 && L > 2 / k) ||
            ns_case_plates(NS_EL_P2B, 128, 1.0, NS_PI, 1.0 / k, L, hn, hf, &r, msg, sizeof msg)) {
            printf("bench_navier_stokes --plates K L [h_near h_far]: K in (0.01, 0.9), L > 2/K; %s\n", msg);
            return 1;
        }
        printf("plates k=%.4f L=%.1f h=%.3f/%.3f: %d unknowns, lambda = F/(mu U0) = %.5f (reaction), %.5f (line "
               "integral), T/(mu U_mean) = %.4f\n",
               k, L, hn, hf, r.nunk, r.lam_react, r.lam_line, 1.5 * r.lam_react);
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "--moving")) {
        moving_grain_cost(NULL);
        return 0;
    }
    if (argc > 2 && !strcmp(argv[1], "--cavity-p2")) {
        const double h = atof(argv[2]);
        ns_cavity_result r;
        if (!(h > 0.004 && h < 0.5) || ns_case_cavity(NS_EL_P2, h, h, 100, &r, msg, sizeof msg)) {
            printf("bench_navier_stokes --cavity-p2 H: H in (0.004, 0.5) m; %s\n", msg);
            return 1;
        }
        printf("FF triangles %d unknowns %d factorisations %ld assemble %.4f factor+solve %.4f analysis %.4f "
               "umin %.6f vmin %.6f vmax %.6f\n",
               r.nt, r.nunk, r.st.n_numeric, r.st.t_assemble, r.st.t_numeric + r.st.t_solve, r.st.t_symbolic,
               r.u_min, r.v_min, r.v_max);
        return 0;
    }
    snprintf(path, sizeof path, "%s/bench_navier_stokes.csv", dir);
    FILE *csv = fopen(path, "w");
    if (csv) fprintf(csv, "case,element,h,unknowns,error,cpu,assembly,factor,solve,fill\n");
    /* cavity: reference = finest P2 + bubble run */
    const double ch[NMESH] = {0.16, 0.08, 0.04, 0.025}, cc[NMESH] = {0.008, 0.004, 0.002, 0.0012};
    ns_cavity_result ref;
    if (ns_case_cavity(NS_EL_P2B, 0.015, 0.0007, 100, &ref, msg, sizeof msg)) {
        printf("%s\n", msg);
        return 1;
    }
    printf("cavity reference (P2+bubble, h = 0.015, corners 0.0007, %d unknowns): u_min %.6f v_min %.6f v_max %.6f\n",
           ref.nunk, ref.u_min, ref.v_min, ref.v_max);
    double C[3][NMESH], E[3][NMESH];
    for (int e = 0; e < 3; e++)
        for (int k = 0; k < NMESH; k++) {
            ns_cavity_result r;
            if (ns_case_cavity(e, ch[k], cc[k], 100, &r, msg, sizeof msg)) {
                printf("%s\n", msg);
                return 1;
            }
            const double err = fmax(fabs(r.u_min - ref.u_min), fmax(fabs(r.v_min - ref.v_min), fabs(r.v_max - ref.v_max)));
            E[e][k] = err;
            C[e][k] = r.t_total;
            const double fill = r.st.nnz_lu / r.st.nnz_matrix;
            printf("cavity %-13s h=%.3f %6d unknowns: error %.2e, CPU %.2f s (assembly %.2f, analysis %.2f, factor "
                   "%.2f, solve %.2f; %d Newton), fill %.1f, Ghia max dev %.4f/%.4f\n",
                   names[e], ch[k], r.nunk, err, r.t_total, r.st.t_assemble, r.st.t_symbolic, r.st.t_numeric,
                   r.st.t_solve, r.st.newton_iters, fill, r.err_u, r.err_v);
            if (csv)
                fprintf(csv, "cavity,%s,%g,%d,%.6e,%.6e,%.6e,%.6e,%.6e,%.3f\n", names[e], ch[k], r.nunk, err, r.t_total,
                        r.st.t_assemble, r.st.t_symbolic + r.st.t_numeric, r.st.t_solve, fill);
        }
    chart(dir, "ns_cavity_error_cpu.png", "largest error of u#dmin#u, v#dmin#u, v#dmax#u (m/s)",
          "Lid-driven cavity, Re = 100: error against CPU time", C, E, NMESH);
    const double hn[NMESH] = {0.01, 0.005, 0.0035, 0.0025}, hf[NMESH] = {0.04, 0.03, 0.025, 0.02};
    for (int e = 0; e < 3; e++)
        for (int k = 0; k < NMESH; k++) {
            ns_dfg_result r;
            if (ns_case_dfg(e, hn[k], hf[k], 128, &r, msg, sizeof msg)) {
                printf("%s\n", msg);
                return 1;
            }
            const double err = fabs(r.cd - 5.57953523384) / 5.57953523384;
            E[e][k] = err;
            C[e][k] = r.t_total;
            const double fill = r.st.nnz_lu / r.st.nnz_matrix;
            printf("DFG    %-13s h=%.4f %6d unknowns: c_D %.5f (rel. error %.2e), c_L %.5f, dp %.5f, CPU %.2f s "
                   "(assembly %.2f, analysis %.2f, factor %.2f, solve %.2f), fill %.1f\n",
                   names[e], hn[k], r.nunk, r.cd, err, r.cl, r.dp, r.t_total, r.st.t_assemble, r.st.t_symbolic,
                   r.st.t_numeric, r.st.t_solve, fill);
            if (csv)
                fprintf(csv, "dfg,%s,%g,%d,%.6e,%.6e,%.6e,%.6e,%.6e,%.3f\n", names[e], hn[k], r.nunk, err, r.t_total,
                        r.st.t_assemble, r.st.t_symbolic + r.st.t_numeric, r.st.t_solve, fill);
        }
    chart(dir, "ns_dfg_error_cpu.png", "relative error of the drag coefficient c#dD#u",
          "DFG 2D-1 cylinder, Re = 20: drag error against CPU time", C, E, NMESH);
    moving_grain_cost(csv);
    if (csv) fclose(csv);
    return 0;
}
