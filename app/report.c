#include "report.h"
#include "wrap_csv.h"

#include <math.h>
#include <signal.h>
#include <string.h>
#include <time.h>

#define LABEL "  %-15s"

static double flag_value(const pl_world *w, const char *name)
{
    double v = 0;
    return pl_world_get_flag(w, name, &v) == PL_OK ? v : 0;
}

void pl_report_bodies(FILE *f, const pl_world *w)
{
    int shape[3] = {0, 0, 0}, motion[3] = {0, 0, 0};
    int n = pl_world_body_count(w);
    for (int i = 0; i < n; i++) {
        pl_body_info b;
        if (pl_world_body_info(w, i, &b) != PL_OK) continue;
        if ((unsigned)b.shape < 3) shape[b.shape]++;
        if ((unsigned)b.motion < 3) motion[b.motion]++;
    }
    fprintf(f, LABEL "%d (%d discs, %d polygons, %d walls; %d dynamic, %d fixed, "
                     "%d prescribed)\n",
            "bodies", n, shape[PL_SHAPE_DISC], shape[PL_SHAPE_POLYGON],
            shape[PL_SHAPE_SEGMENT], motion[PL_MOTION_DYNAMIC], motion[PL_MOTION_FIXED],
            motion[PL_MOTION_PRESCRIBED]);
}

void pl_report_materials(FILE *f, const pl_world *w)
{
    int n = pl_world_material_count(w);
    fprintf(f, LABEL "%d\n", "materials", n);
    for (int i = 0; i < n; i++) {
        pl_material_def m = pl_world_material(w, i);
        fprintf(f, "    %-12s density %g kg/m^3; ", m.name, m.density);
        if (m.kn > 0)
            fprintf(f, "kn %g N/m; ", m.kn);
        else
            fprintf(f, "kn from young %g Pa (Tan 1990 eq. 2.36, overlap %g R); ", m.young,
                    m.young_overlap);
        if (m.ks >= 0)
            fprintf(f, "ks %g N/m; ", m.ks);
        else
            fprintf(f, "ks = 2/3 kn; ");
        fprintf(f, "friction %g; cohesion %g N; ", m.friction, m.cohesion);
        if (m.restitution >= 0)
            fprintf(f, "damping from restitution e = %g\n", m.restitution);
        else if (m.cs >= 0)
            fprintf(f, "cn %g N s/m, cs %g N s/m\n", m.cn, m.cs);
        else
            fprintf(f, "cn %g N s/m, cs = cn ks/kn\n", m.cn);
    }
}

void pl_report_contact_law(FILE *f, const pl_world *w)
{
    int polygons = 0, n = pl_world_body_count(w);
    for (int i = 0; i < n && !polygons; i++) {
        pl_body_info b;
        polygons = pl_world_body_info(w, i, &b) == PL_OK && b.shape == PL_SHAPE_POLYGON;
    }
    fprintf(f, LABEL "Cundall-Strack for discs and walls: linear normal spring, incremental "
                     "shear spring\n" LABEL "with the Coulomb limit, normal and shear dashpots "
                     "(Tan 1990 §2.2.4)\n",
            "contact law", "");
    if (polygons)
        fprintf(f, LABEL "polygons: area-based normal force F = Y A / l_char (Mueller et al. 2020 §3)\n",
                "");
}

void pl_report_damping(FILE *f, const pl_world *w)
{
    fprintf(f, LABEL "global C = %g N s/m, C* = %g N m s (Tan 1990 eqs. 2.21-2.22); "
                     "Rayleigh alpha = %g 1/s (Klosek 1997 eq. 2.5); local %g\n",
            "damping", flag_value(w, "GLOBAL_DAMPING"), flag_value(w, "GLOBAL_DAMPING_ROT"),
            flag_value(w, "RAYLEIGH_FACTOR"), flag_value(w, "LOCAL_DAMPING"));
    fprintf(f, LABEL "(%g, %g) m/s^2\n", "gravity", flag_value(w, "GRAVITY_X"),
            flag_value(w, "GRAVITY_Y"));
}

void pl_report_time_step(FILE *f, pl_world *w)
{
    pl_dt_report r = pl_world_dt_report(w);
    fprintf(f, LABEL "dt = %.6g s ", "time step", r.dt);
    if (r.fixed)
        fprintf(f, "(fixed by the scene; %.3g of the critical step)\n",
                r.dt_critical > 0 ? r.dt / r.dt_critical : 0);
    else if (r.capped)
        fprintf(f, "(automatic, capped by MAX_DT_CR = %g s)\n", flag_value(w, "MAX_DT_CR"));
    else
        fprintf(f, "(automatic: %g x the critical step)\n", flag_value(w, "DT_SAFETY"));
    if (r.limiting_body >= 0)
        fprintf(f, LABEL "%.6g s = 2 sqrt(m/k), limited by body #%d (%s)\n", "critical step",
                r.dt_critical, r.limiting_body + 1, r.limit_kind ? r.limit_kind : "?");
    else
        fprintf(f, LABEL "%.6g s (no dynamic body limits it)\n", "critical step",
                r.dt_critical);
}

static double cpu_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void pl_report_models(FILE *f, pl_world *w, int trial_steps)
{
    const int n = pl_world_model_count(w);
    if (n == 0) fprintf(f, LABEL "none: dry grains (no fluid model attached)\n", "fluid model");
    for (int k = 0; k < n; k++) {
        const char *name = pl_world_model_name(w, k);
        fprintf(f, LABEL "%s: %s", k ? "" : "fluid model", name, pl_world_model_label(w, k));
        if (strcmp(name, "darcy") == 0) {
            if (flag_value(w, "FLUIDS_ON") != 0)
                fprintf(f, "; on, density %g kg/m^3, solved every %g steps", flag_value(w, "FLUID_DENSITY"),
                        flag_value(w, "FLUID_SOLVE_TIMESTEPS"));
            else
                fprintf(f, "; off (FLUIDS_ON = 0): no fluid work");
        }
        fprintf(f, "\n");
    }
    if (trial_steps <= 0 || pl_world_body_count(w) == 0) return;
    /* a trial: step from a snapshot, measure, restore (the scene's state is left as it was) */
    pl_snapshot *snap = pl_world_snapshot(w);
    if (!snap) return;
    double before[16] = {0};
    for (int k = 0; k < n && k < 16; k++) before[k] = pl_world_model_cost(w, k, NULL);
    const double t0 = cpu_seconds();
    int steps = 0;
    pl_status st = PL_OK;
    while (steps < trial_steps && st == PL_OK) {
        st = pl_world_step(w, 1);
        steps++;
        if (cpu_seconds() - t0 > 2.0) break; /* a slow scene: a few steps tell enough */
    }
    const double total = cpu_seconds() - t0;
    double models = 0;
    char parts[512] = "";
    size_t off = 0;
    for (int k = 0; k < n && k < 16; k++) {
        const double c = pl_world_model_cost(w, k, NULL) - before[k];
        models += c;
        off += (size_t)snprintf(parts + off, off < sizeof parts ? sizeof parts - off : 0, ", %s %.3g ms",
                                pl_world_model_name(w, k), 1e3 * c / steps);
    }
    if (st != PL_OK)
        fprintf(f, LABEL "trial stopped after %d steps: %s\n", "cost per step", steps, pl_world_last_error(w));
    else
        fprintf(f, LABEL "%.3g ms CPU (grains %.3g ms%s; measured over %d steps)\n", "cost per step",
                1e3 * total / steps, 1e3 * (total - models) / steps, parts, steps);
    pl_world_restore(w, snap);
    pl_snapshot_destroy(&snap);
}

void pl_report_flags(FILE *f, pl_scene *s)
{
    int any = 0;
    for (int i = 0; i < pl_flag_count(); i++) {
        double v;
        if (!pl_scene_flag_was_set(s, pl_flag_at(i)->name, &v)) continue;
        fprintf(f, LABEL "%s = %g %s\n", any ? "" : "flags set", pl_flag_at(i)->name, v,
                pl_flag_at(i)->unit);
        any = 1;
    }
    if (!any) fprintf(f, LABEL "none set by the scene (porelab flags lists them)\n", "flags");
}

void pl_report_energy(FILE *f, const pl_world *w)
{
    pl_energy e = pl_world_energy(w);
    fprintf(f, LABEL "kinetic %.6g J, gravitational %.6g J, elastic %.6g J\n", "energy",
            e.kinetic, e.gravitational, e.elastic);
    fprintf(f, LABEL "dissipated %.6g J by damping, %.6g J by friction; external work "
                     "%.6g J\n",
            "", e.damped, e.friction, e.external);
    if (e.fracture != 0) fprintf(f, LABEL "released %.6g J by bond fracture and damage\n", "", e.fracture);
    double moved = fabs(e.kinetic) + fabs(e.elastic) + fabs(e.damped) + fabs(e.friction) +
                   fabs(e.fracture) + fabs(e.external);
    if (moved > 0)
        fprintf(f, LABEL "%.3g J (%.3g%% of the energy exchanged)\n", "balance error",
                e.balance, 100 * fabs(e.balance) / moved);
    else
        fprintf(f, LABEL "%.3g J\n", "balance error", e.balance);
}

static int csv_result(FILE *f, int rc, const char *err)
{
    if (rc != 0) fprintf(f, "porelab: %s\n", err);
    return rc;
}

int pl_report_flush_csv(FILE *f, pl_scene *s)
{
    char err[5000];
    return csv_result(f, pl_lua_csv_flush_all(pl_scene_lua(s), err, sizeof err), err);
}

int pl_report_close_csv(FILE *f, pl_scene *s)
{
    char err[5000];
    return csv_result(f, pl_lua_csv_close_all(pl_scene_lua(s), err, sizeof err), err);
}

void pl_report_ignore_file_size_signal(void)
{
    signal(SIGXFSZ, SIG_IGN);
}
