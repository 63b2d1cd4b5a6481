/* Particle buoyancy (seed 000 §4.2, Appendix C.2, Figs. 4-6 to 4-8), run through the coupled
 * stepping (fluid hook + grain integrator). Still water 0 <= y <= 0.5 m (pressure head 0.5 at
 * the floor, 0 at the surface), rho_f = 1000 kg/m^3, g = 9.81, Rayleigh damping.
 * References (Archimedes):
 * - an ellipse-like 24-gon (a = 0.1, b = 0.05) with rho_p / rho_f = 1/2 floats with its centroid
 *   on the water line (half submerged by symmetry): draft b within 2%; started rotated 30
 *   degrees it rights itself (long axis horizontal is stable: GM = 4 (a^2 - b^2) / (3 pi b) > 0);
 * - rho_p / rho_f = 1, started immersed, stays put (displacement < 1e-6 m);
 * - rho_p / rho_f = 2 sinks to the floor;
 * - a disc with rho_p / rho_f = 1/4 floats with the submerged segment of central angle theta,
 *   theta - sin theta = 2 pi s, draft r (1 - cos(theta / 2)), within 2%. */
#include "harness.h"
#include "porelab/fluid.h"
#include "porelab/world.h"
#include <stdlib.h>
#include <string.h>

#define PI 3.141592653589793

static pl_world *pond(double rho_p, int *mat) {
    pl_world_def wd = pl_default_world_def();
    pl_world *w = pl_world_create(&wd);
    pl_fluid_quad_def q = pl_default_fluid_quad_def();
    q.corners[0] = (pl_vec2){0, 0};
    q.corners[1] = (pl_vec2){1, 0};
    q.corners[2] = (pl_vec2){1, 0.5};
    q.corners[3] = (pl_vec2){0, 0.5};
    q.ndivx = 10;
    q.ndivy = 5;
    pl_world_add_fluid_quad(w, &q);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0}, (pl_vec2){1, 0}, 0.5);
    pl_world_add_fluid_bc(w, (pl_vec2){0, 0.5}, (pl_vec2){1, 0.5}, 0.0);
    const char *names[] = {"FLUIDS_ON", "FIRST_STEP_STATIC", "FLUID_PERM", "FLUID_DENSITY", "FLUID_SOLVE_TIMESTEPS",
                           "RAYLEIGH_FACTOR", "DT"};
    const double vals[] = {1, 1, 0, 1000, 1000, 16, 1e-4};
    for (int k = 0; k < 7; k++)
        if (pl_world_set_flag(w, names[k], vals[k]) != PL_OK) fprintf(stderr, "%s\n", pl_world_last_error(w));
    pl_material_def md = pl_default_material_def();
    md.name = "grain";
    md.density = rho_p;
    md.kn = 1e7;
    md.friction = 0.3;
    *mat = pl_world_add_material(w, &md);
    pl_body_def fl = pl_default_body_def();
    fl.shape = PL_SHAPE_SEGMENT;
    fl.motion = PL_MOTION_FIXED;
    fl.material = *mat;
    fl.a = (pl_vec2){-0.5, 0};
    fl.b = (pl_vec2){1.5, 0};
    pl_world_add_body(w, &fl);
    return w;
}

static int add_ellipse(pl_world *w, int mat, pl_vec2 c, double angle) {
    pl_vec2 v[24];
    for (int k = 0; k < 24; k++) v[k] = (pl_vec2){c.x + 0.1 * cos(2 * PI * k / 24), c.y + 0.05 * sin(2 * PI * k / 24)};
    pl_body_def bd = pl_default_body_def();
    bd.shape = PL_SHAPE_POLYGON;
    bd.material = mat;
    bd.vertices = v;
    bd.vertex_count = 24;
    bd.angle = angle;
    return pl_world_add_body(w, &bd);
}

static int run(pl_world *w, double T) {
    int n = (int)(T / 1e-4 + 0.5);
    pl_status st = pl_world_step(w, n);
    if (st != PL_OK) {
        fprintf(stderr, "step: %s\n", pl_world_last_error(w));
        return 1;
    }
    return 0;
}

static int test_half_density_floats_half_submerged(void) {
    int mat;
    pl_world *w = pond(500, &mat);
    int b = add_ellipse(w, mat, (pl_vec2){0.5, 0.7}, 0);
    ENSURE(b >= 0);
    ENSURE(run(w, 3.0) == 0);
    pl_body_info bi;
    pl_world_body_info(w, b, &bi);
    /* draft = water level - lowest point; analytic draft b = 0.05 (centroid on the water line).
       The 24-gon's lowest vertex is at b exactly (k = 18). */
    double draft = 0.5 - (bi.position.y - 0.05);
    fprintf(stderr, "  rho_p/rho_f = 1/2: centroid y = %.6f, draft %.6f m (analytic 0.05), angle %.2e rad\n",
            bi.position.y, draft, bi.angle);
    pl_validation("fluid.buoyancy_half", "buoyancy (§4.2), ρ_p/ρ_f = ½ superquadric", "half submerged: draft 0.05 m",
                  "2 %", "draft %.6f m", draft);
    ENSURE_NEAR(draft, 0.05, 0.02 * 0.05);
    pl_world_destroy(&w);
    return 0;
}

static int test_rotated_rights_itself(void) {
    int mat;
    pl_world *w = pond(500, &mat);
    int b = add_ellipse(w, mat, (pl_vec2){0.5, 0.7}, 30 * PI / 180);
    ENSURE(run(w, 4.0) == 0);
    pl_body_info bi;
    pl_world_body_info(w, b, &bi);
    double s = sin(bi.angle);
    fprintf(stderr, "  started at 30 degrees: final angle %.3f degrees (mod 180), centroid y = %.5f\n",
            fmod(bi.angle * 180 / PI, 180), bi.position.y);
    pl_validation("fluid.buoyancy_half", "", "", "", "rights itself from 30° (to %.2f°)", fmod(bi.angle * 180 / PI, 180));
    ENSURE(fabs(s) < 0.02);
    ENSURE_NEAR(bi.position.y, 0.5, 0.02 * 0.05);
    pl_world_destroy(&w);
    return 0;
}

static int test_neutral_stays(void) {
    int mat;
    pl_world *w = pond(1000, &mat);
    int b = add_ellipse(w, mat, (pl_vec2){0.43, 0.23}, 0.4);
    ENSURE(run(w, 0.5) == 0);
    pl_body_info bi;
    pl_world_body_info(w, b, &bi);
    double d = hypot(bi.position.x - 0.43, bi.position.y - 0.23);
    fprintf(stderr, "  rho_p/rho_f = 1, immersed: displacement after 0.5 s %.3e m, angle change %.3e rad\n", d,
            bi.angle - 0.4);
    pl_validation("fluid.buoyancy_neutral_dense", "ρ_p = ρ_f immersed; ρ_p = 2 ρ_f", "stays put; sinks to the floor",
                  "1e-6 m; rests on the floor (y 0.045–0.051 m)", "moves %.1e m", d);
    ENSURE(d < 1e-6);
    ENSURE(fabs(bi.angle - 0.4) < 1e-6);
    pl_world_destroy(&w);
    return 0;
}

static int test_dense_sinks(void) {
    int mat;
    pl_world *w = pond(2000, &mat);
    int b = add_ellipse(w, mat, (pl_vec2){0.5, 0.4}, 0);
    ENSURE(run(w, 2.0) == 0);
    pl_body_info bi;
    pl_world_body_info(w, b, &bi);
    fprintf(stderr, "  rho_p/rho_f = 2: centroid y = %.5f m after 2 s (resting on the floor: 0.05)\n", bi.position.y);
    pl_validation("fluid.buoyancy_neutral_dense", "", "", "", "heavy one at y = %.5f m (resting: 0.05)", bi.position.y);
    ENSURE(bi.position.y < 0.05 + 1e-3 && bi.position.y > 0.045);
    pl_world_destroy(&w);
    return 0;
}

static int test_disc_quarter_density(void) {
    int mat;
    pl_world *w = pond(250, &mat);
    const double r = 0.05;
    pl_body_def bd = pl_default_body_def();
    bd.shape = PL_SHAPE_DISC;
    bd.material = mat;
    bd.position = (pl_vec2){0.3, 0.6};
    bd.radius = r;
    int b = pl_world_add_body(w, &bd);
    ENSURE(run(w, 3.0) == 0);
    double th = 2; /* theta - sin theta = 2 pi s, s = 1/4 */
    for (int k = 0; k < 50; k++) th -= (th - sin(th) - 2 * PI * 0.25) / (1 - cos(th));
    double draft_ref = r * (1 - cos(th / 2));
    pl_body_info bi;
    pl_world_body_info(w, b, &bi);
    double draft = 0.5 - (bi.position.y - r);
    fprintf(stderr, "  disc rho_p/rho_f = 1/4: theta = %.6f, draft %.6f m (analytic %.6f, error %.2f%%)\n", th, draft,
            draft_ref, 100 * fabs(draft - draft_ref) / draft_ref);
    pl_validation("fluid.buoyancy_disc", "disc ρ_p/ρ_f = ¼", "θ − sin θ = 2π s", "2 %", "draft %.6f m vs %.6f (%.3f %%)",
                  draft, draft_ref, 100 * fabs(draft - draft_ref) / draft_ref);
    ENSURE_NEAR(draft, draft_ref, 0.02 * draft_ref);
    pl_world_destroy(&w);
    return 0;
}

/* FLUIDS_ON = 0 does no fluid work (the body falls freely); FLUID_SOLVE_TIMESTEPS = N solves
   once every N grain steps. */
static int test_flags(void) {
    int mat;
    pl_world *w = pond(500, &mat);
    pl_world_set_flag(w, "FLUIDS_ON", 0);
    pl_world_set_flag(w, "RAYLEIGH_FACTOR", 0);
    int b = add_ellipse(w, mat, (pl_vec2){0.5, 0.3}, 0);
    ENSURE(pl_world_step(w, 1000) == PL_OK);
    pl_body_info bi;
    pl_world_body_info(w, b, &bi);
    pl_fluid_stats st;
    pl_world_fluid_stats(w, &st);
    fprintf(stderr, "  FLUIDS_ON 0: velocity after 0.1 s %.6f m/s (free fall %.6f), fluid updates %ld\n", bi.velocity.y,
            -9.81 * 0.1, st.updates);
    ENSURE(st.updates == 0);
    ENSURE_NEAR(bi.velocity.y, -9.81 * 0.1, 1e-9);
    pl_world_destroy(&w);
    w = pond(500, &mat);
    pl_world_set_flag(w, "FLUID_SOLVE_TIMESTEPS", 7);
    pl_world_set_flag(w, "FIRST_STEP_STATIC", 0);
    add_ellipse(w, mat, (pl_vec2){0.5, 0.3}, 0);
    ENSURE(pl_world_step(w, 71) == PL_OK);
    pl_world_fluid_stats(w, &st);
    ENSURE(st.updates == 1 + 70 / 7);
    pl_world_destroy(&w);
    return 0;
}

int main(void) {
    RUN(test_flags);
    RUN(test_half_density_floats_half_submerged);
    RUN(test_rotated_rights_itself);
    RUN(test_neutral_stays);
    RUN(test_dense_sinks);
    RUN(test_disc_quarter_density);
    return pl_test_report();
}
