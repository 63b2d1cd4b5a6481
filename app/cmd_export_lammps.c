/* porelab export-lammps SCENE.lua [--out DIR]: the scene's dry discs and straight walls as a
 * LAMMPS input (GRANULAR package: pair gran/hooke/history, fix wall/gran, fix enforce2d,
 * fix nve/sphere disc), for runs past one machine (docs/scaling.md, "LAMMPS").
 *
 * The contact law maps onto gran/hooke/history term by term (docs/scaling.md lists what is
 * exact and what is approximate):
 *   k_n, k_t          = porelab's k_N, k_S of the pair (N/m per metre of thickness)
 *   gamma_n           = c_N' / m*  (c_N = 2 zeta sqrt(m* k_N) from the restitution, or the
 *                       material's c_N; c_N' = c_N (sqrt(1 + q^2) - q), q = c_N dt / (4 m*),
 *                       porelab's half-step dashpot correction, neighbor.c)
 *   gamma_t           = c_S / m*
 *   xmu               = mu
 *   mass              = density x pi r^2 x 1 m (set density/disc), inertia m r^2 / 2 (nve/sphere disc)
 *   timestep          = porelab's step
 * LAMMPS has one set of these for every disc pair, so the scene's disc pairs must share their
 * parameters; m* is the mean disc mass (exact when all discs have one mass). The export writes
 * DIR/in.lammps, DIR/data.lammps and DIR/porelab-lammps.txt (time step, types, walls), which
 * `porelab import-lammps` reads beside the dumps. */
#include "cli_common.h"
#include "commands.h"
#include "run_plan.h"
#include "porelab/bonds.h"
#include "porelab/solid.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const pl_opt_spec export_specs[] = {
    {"--out", NULL, "DIR", "folder for in.lammps, data.lammps and porelab-lammps.txt (default out/<scene>-lammps/)"},
    {"--until", NULL, "T", "simulated end time of the LAMMPS run, s (default: the scene's run)"},
    {"--steps", NULL, "N", "or: number of steps"},
    {"--fps", NULL, "F", "dumps per simulated second (default: the scene's frame rate)"},
    {"--every", NULL, "N", "or: steps between dumps"},
    {"--param", NULL, "NAME=VALUE", "set a parameter the scene declares (repeatable)"},
    {"--seed", NULL, "N", "run seed feeding every random helper (default 0: the scene's own seeds)"},
    {"--trust", NULL, NULL, "lift the sandbox (only for scenes you trust)"},
    {"--traceback", NULL, NULL, "print the Lua traceback with errors"},
    {"--quiet", "-q", NULL, "print only errors"},
    {NULL, NULL, NULL, NULL}};

static const pl_command_help export_help = {
    "export-lammps", "SCENE.lua [--out DIR] [--until T | --steps N] [--every N]",
    "Writes the scene, as it stands after loading, as a LAMMPS input for the GRANULAR package:\n"
    "discs (pair gran/hooke/history), straight walls along x or y (fix wall/gran), fixed discs\n"
    "(fix freeze), gravity and global damping, with porelab's stiffness, damping, friction and\n"
    "time step. Run it with `lmp -in in.lammps` (or `mpirun -np N lmp -in in.lammps`) inside DIR;\n"
    "it dumps atoms.dump and contacts.dump, which `porelab import-lammps` reads back.\n"
    "Scenes LAMMPS cannot express (polygons, pore water or any fluid model, solids, bonds,\n"
    "moving, shaking or servo walls, slanted walls, rolling resistance, cohesion, local or\n"
    "rotational damping, discs of several contact laws) are refused with the list of features.",
    export_specs};

#define MAX_PROBLEMS 24

typedef struct problems {
    int n;
    char text[MAX_PROBLEMS][240];
} problems;

static void problem(problems *p, const char *fmt, ...)
{
    if (p->n >= MAX_PROBLEMS) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(p->text[p->n++], sizeof p->text[0], fmt, ap);
    va_end(ap);
}

/* A list of up to 5 body numbers (1-based, as scenes count them) for a message. */
static void body_list(char *out, size_t n, const int *ids, int count)
{
    size_t off = 0;
    out[0] = 0;
    for (int k = 0; k < count && k < 5 && off < n; k++)
        off += (size_t)snprintf(out + off, n - off, "%s%d", k ? ", " : "", ids[k] + 1);
    if (count > 5 && off < n) snprintf(out + off, n - off, ", ...");
}

typedef struct wall {
    int body;
    int axis;  /* 0: xplane (a wall along y), 1: yplane (a wall along x) */
    double pos;
    int side;  /* 0: discs above/right of it (lo wall), 1: below/left (hi wall) */
    double lo, hi; /* extent along the wall */
    pl_pair_def pd;
    int material;
} wall;

typedef struct law {
    double kn, kt, gn, gt, mu;
    double cn, cn_corr;
} law;

/* porelab's dashpots for a pair of reduced mass mred (neighbor.c), as gran/hooke damping rates */
static law map_law(const pl_pair_def *pd, double mred, double dt)
{
    law l;
    l.kn = pd->kn;
    l.kt = pd->ks;
    l.mu = pd->friction;
    double cn = pd->cn, cs = pd->cs;
    if (pd->restitution >= 0) {
        double zeta = 0;
        if (pd->restitution < 1) {
            const double g = log(pd->restitution);
            zeta = -g / sqrt(M_PI * M_PI + g * g);
        }
        cn = 2 * zeta * sqrt(mred * pd->kn);
        cs = pd->kn > 0 ? cn * pd->ks / pd->kn : 0;
    }
    const double q = mred > 0 && dt > 0 ? cn * dt / (4 * mred) : 0;
    l.cn = cn;
    l.cn_corr = cn * (sqrt(1 + q * q) - q);
    l.gn = mred > 0 ? l.cn_corr / mred : 0;
    l.gt = mred > 0 ? cs / mred : 0;
    return l;
}

static int same_pair(const pl_pair_def *a, const pl_pair_def *b)
{
    return a->kn == b->kn && a->ks == b->ks && a->friction == b->friction && a->cohesion == b->cohesion &&
           a->cn == b->cn && a->cs == b->cs && a->restitution == b->restitution && a->rolling == b->rolling;
}

static double flag(const pl_world *w, const char *name)
{
    double v = 0;
    pl_world_get_flag(w, name, &v);
    return v;
}

static FILE *open_out(const char *dir, const char *name, char *path, size_t n)
{
    snprintf(path, n, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    if (!f) fprintf(stderr, "porelab export-lammps: cannot write %s\n", path);
    return f;
}

int pl_cmd_export_lammps(int argc, char **argv)
{
    pl_opts o;
    int rc = pl_opts_parse(&o, &export_help, argc, argv, 1);
    if (rc >= 0) return rc;
    if (pl_cli_require_scene(&o) != 0) return PL_EXIT_USAGE;
    char out_dir[PATH_MAX];
    if (pl_opts_has(&o, "--out"))
        snprintf(out_dir, sizeof out_dir, "%s", pl_opts_get(&o, "--out"));
    else {
        pl_cli_default_out(o.positional[0], out_dir, sizeof out_dir);
        strncat(out_dir, "-lammps", sizeof out_dir - strlen(out_dir) - 1);
    }
    if (pl_path_mkdirs(out_dir) != 0) {
        fprintf(stderr, "porelab export-lammps: cannot create the folder %s\n", out_dir);
        return PL_EXIT_FAIL;
    }
    pl_scene *s = pl_cli_load_scene(&o, out_dir);
    if (!s) return PL_EXIT_FAIL;
    pl_world *w = pl_scene_world(s);
    const char *scene = o.positional[0];
    rc = PL_EXIT_FAIL;
    int *polys = NULL, *moving = NULL, *discs = NULL;
    wall *walls = NULL;
    if (!w) {
        fprintf(stderr, "porelab export-lammps: %s creates no world, so there is nothing to export\n", scene);
        goto done;
    }
    pl_run_plan plan;
    if ((rc = pl_run_plan_make(&o, s, w, &plan)) != 0) goto done;
    rc = PL_EXIT_FAIL;
    const double dt = plan.dt;
    const int n = pl_world_body_count(w);
    polys = calloc((size_t)n + 1, sizeof *polys);
    moving = calloc((size_t)n + 1, sizeof *moving);
    discs = calloc((size_t)n + 1, sizeof *discs);
    walls = calloc((size_t)n + 1, sizeof *walls);
    if (!polys || !moving || !discs || !walls) {
        fprintf(stderr, "porelab export-lammps: out of memory for %d bodies\n", n);
        goto done;
    }
    problems pr = {0};
    int np = 0, nm = 0, nd = 0, nw = 0, nfixed = 0;
    double rmin = INFINITY, rmax = 0, msum = 0, mmin = INFINITY, mmax = 0;
    int ndyn = 0;
    for (int i = 0; i < n; i++) {
        pl_body_info b;
        if (pl_world_body_info(w, i, &b) != PL_OK) continue;
        if (b.shape == PL_SHAPE_POLYGON) polys[np++] = i;
        if (b.motion == PL_MOTION_PRESCRIBED) moving[nm++] = i;
        if (b.shape == PL_SHAPE_DISC) {
            discs[nd++] = i;
            rmin = fmin(rmin, b.radius);
            rmax = fmax(rmax, b.radius);
            if (b.motion == PL_MOTION_DYNAMIC) {
                ndyn++;
                msum += b.mass;
                mmin = fmin(mmin, b.mass);
                mmax = fmax(mmax, b.mass);
            } else if (b.motion == PL_MOTION_FIXED) {
                nfixed++;
            }
        }
        if (b.shape == PL_SHAPE_SEGMENT) {
            pl_vec2 v[2];
            pl_world_body_vertices(w, i, v, 2);
            wall *wl = &walls[nw];
            wl->body = i;
            wl->material = b.material;
            const double len = hypot(v[1].x - v[0].x, v[1].y - v[0].y);
            if (fabs(v[1].y - v[0].y) <= 1e-12 * len) {
                wl->axis = 1;
                wl->pos = 0.5 * (v[0].y + v[1].y);
                wl->lo = fmin(v[0].x, v[1].x);
                wl->hi = fmax(v[0].x, v[1].x);
            } else if (fabs(v[1].x - v[0].x) <= 1e-12 * len) {
                wl->axis = 0;
                wl->pos = 0.5 * (v[0].x + v[1].x);
                wl->lo = fmin(v[0].y, v[1].y);
                wl->hi = fmax(v[0].y, v[1].y);
            } else {
                problem(&pr, "wall %d (from (%g, %g) to (%g, %g) m) is slanted: fix wall/gran takes planes along x or y only",
                        i + 1, v[0].x, v[0].y, v[1].x, v[1].y);
                continue;
            }
            nw++;
        }
    }
    char ids[128];
    if (np) {
        body_list(ids, sizeof ids, polys, np);
        problem(&pr, "%d polygon%s (bod%s %s): gran/hooke/history has spheres (discs) only", np, np > 1 ? "s" : "",
                np > 1 ? "ies" : "y", ids);
    }
    if (nm) {
        body_list(ids, sizeof ids, moving, nm);
        problem(&pr, "%d moving bod%s (%s: prescribed velocity, shaking table, servo or hinged wall): the export "
                "writes fixed walls only", nm, nm > 1 ? "ies" : "y", ids);
    }
    for (int k = 0; k < pl_world_model_count(w); k++)
        problem(&pr, "the model '%s' (%s): LAMMPS' GRANULAR package has no pore water, fluid or solid model",
                pl_world_model_name(w, k), pl_world_model_label(w, k));
    if (pl_world_model_count(w) == 0 && pl_world_has_solid(w))
        problem(&pr, "finite-element solids: LAMMPS' GRANULAR package has none");
    if (pl_world_bond_total(w) > 0)
        problem(&pr, "%d bond%s between grains: gran/hooke/history has no bonded contacts", pl_world_bond_total(w),
                pl_world_bond_total(w) > 1 ? "s" : "");
    if (flag(w, "GLOBAL_DAMPING_ROT") > 0)
        problem(&pr, "rotational global damping GLOBAL_DAMPING_ROT = %g N m s: no fix of the GRANULAR package damps "
                "rotation alone", flag(w, "GLOBAL_DAMPING_ROT"));
    if (flag(w, "LOCAL_DAMPING") > 0)
        problem(&pr, "local (non-viscous) damping LOCAL_DAMPING = %g: not in this LAMMPS", flag(w, "LOCAL_DAMPING"));
    if (ndyn == 0) problem(&pr, "no moving discs: there is nothing for LAMMPS to run");

    /* the disc pairs' contact law: one set for all of them */
    int dmat[64], ndm = 0, too_many = 0;
    for (int k = 0; k < nd; k++) {
        pl_body_info b;
        pl_world_body_info(w, discs[k], &b);
        int seen = 0;
        for (int j = 0; j < ndm; j++) seen |= dmat[j] == b.material;
        if (!seen) {
            if (ndm < 64) dmat[ndm++] = b.material;
            else too_many = 1;
        }
    }
    if (too_many) problem(&pr, "discs of more than 64 materials");
    pl_pair_def disc_pair = pl_default_pair_def();
    if (ndm > 0) pl_world_pair_params(w, dmat[0], dmat[0], &disc_pair);
    for (int a = 0; a < ndm; a++)
        for (int b = a; b < ndm; b++) {
            pl_pair_def pd;
            pl_world_pair_params(w, dmat[a], dmat[b], &pd);
            if (!same_pair(&pd, &disc_pair)) {
                pl_material_def ma = pl_world_material(w, dmat[a]), mb = pl_world_material(w, dmat[b]);
                problem(&pr, "discs of %d materials with different contact laws ('%s' on '%s' differs from '%s' on "
                        "'%s'): gran/hooke/history has one law for every disc pair", ndm, ma.name, mb.name,
                        pl_world_material(w, dmat[0]).name, pl_world_material(w, dmat[0]).name);
                a = b = ndm; /* once is enough */
            }
        }
    if (ndm > 0 && disc_pair.rolling > 0)
        problem(&pr, "rolling resistance %g between discs: gran/hooke/history has none", disc_pair.rolling);
    if (ndm > 0 && disc_pair.cohesion > 0)
        problem(&pr, "cohesion %g N between discs: gran/hooke/history has none", disc_pair.cohesion);
    int nmixed = 0, nboth = 0, *mixed = moving, *both = polys; /* reused: their lists are in pr already */
    for (int k = 0; k < nw && ndm > 0; k++) {
        wall *wl = &walls[k];
        pl_world_pair_params(w, dmat[0], wl->material, &wl->pd);
        for (int j = 1; j < ndm; j++) {
            pl_pair_def pd;
            pl_world_pair_params(w, dmat[j], wl->material, &pd);
            if (!same_pair(&pd, &wl->pd)) {
                mixed[nmixed++] = wl->body;
                break;
            }
        }
        if (wl->pd.rolling > 0)
            problem(&pr, "rolling resistance %g on wall %d: fix wall/gran has none", wl->pd.rolling, wl->body + 1);
        if (wl->pd.cohesion > 0)
            problem(&pr, "cohesion %g N on wall %d: fix wall/gran has none", wl->pd.cohesion, wl->body + 1);
        /* the side the discs are on: a LAMMPS plane pushes one way */
        int above = 0, below = 0;
        for (int j = 0; j < nd; j++) {
            pl_body_info b;
            pl_world_body_info(w, discs[j], &b);
            const double c = wl->axis ? b.position.y : b.position.x;
            if (c > wl->pos) above++;
            else below++;
        }
        if (above && below) both[nboth++] = wl->body;
        wl->side = above ? 0 : 1;
    }
    if (nmixed) {
        body_list(ids, sizeof ids, mixed, nmixed);
        problem(&pr, "%d wall%s (%s) touch%s discs of materials with different contact laws (fix wall/gran has one "
                "law per wall)", nmixed, nmixed > 1 ? "s" : "", ids, nmixed > 1 ? "" : "es");
    }
    if (nboth) {
        body_list(ids, sizeof ids, both, nboth);
        problem(&pr, "%d wall%s (%s) ha%s discs on both sides: a LAMMPS wall plane pushes one way", nboth,
                nboth > 1 ? "s" : "", ids, nboth > 1 ? "ve" : "s");
    }
    if (pr.n) {
        fprintf(stderr, "porelab export-lammps: %s: LAMMPS (GRANULAR: gran/hooke/history, wall/gran) cannot express "
                        "%d feature%s this scene uses:\n", scene, pr.n, pr.n > 1 ? "s" : "");
        for (int k = 0; k < pr.n; k++) fprintf(stderr, "  - %s\n", pr.text[k]);
        fprintf(stderr, "nothing was written; run the scene with `porelab run` instead\n");
        goto done;
    }

    /* ---------------------------------------------------------------- writing */
    const double mbar = msum / ndyn;
    const law dl = map_law(&disc_pair, 0.5 * mbar, dt);
    const int exact_mass = mmax <= mmin * (1 + 1e-12);
    pl_vec2 lo, hi;
    pl_world_bounds(w, &lo, &hi);
    const double ext = fmax(hi.x - lo.x, hi.y - lo.y);
    const double margin = 0.05 * ext + 2 * rmax;
    const double skin = 0.2 * rmin;
    const pl_vec2 g = {flag(w, "GRAVITY_X"), flag(w, "GRAVITY_Y")};
    const double gmag = hypot(g.x, g.y);
    const double damp_c = flag(w, "GLOBAL_DAMPING"), damp_a = flag(w, "RAYLEIGH_FACTOR");
    long long every = plan.every > 0 ? plan.every : pl_run_plan_frame_step(&plan, 1);
    if (every < 1) every = 1;
    char path[PATH_MAX + 64];

    FILE *f = open_out(out_dir, "data.lammps", path, sizeof path);
    if (!f) goto done;
    fprintf(f, "LAMMPS data file written by porelab export-lammps from %s\n\n", scene);
    fprintf(f, "%d atoms\n%d atom types\n\n", nd, ndm);
    fprintf(f, "%.17g %.17g xlo xhi\n%.17g %.17g ylo yhi\n-0.5 0.5 zlo zhi\n\n", lo.x - margin, hi.x + margin,
            lo.y - margin, hi.y + margin + 0.5 * ext);
    fprintf(f, "Atoms # sphere\n\n");
    int any_v = 0;
    for (int k = 0; k < nd; k++) {
        pl_body_info b;
        pl_world_body_info(w, discs[k], &b);
        int type = 1;
        for (int j = 0; j < ndm; j++)
            if (dmat[j] == b.material) type = j + 1;
        /* the density column is replaced by set density/disc in in.lammps (2D mass) */
        fprintf(f, "%d %d %.17g %.17g %.17g %.17g 0\n", k + 1, type, 2 * b.radius,
                pl_world_material(w, b.material).density, b.position.x, b.position.y);
        any_v |= b.velocity.x != 0 || b.velocity.y != 0 || b.omega != 0;
    }
    if (any_v) {
        fprintf(f, "\nVelocities\n\n");
        for (int k = 0; k < nd; k++) {
            pl_body_info b;
            pl_world_body_info(w, discs[k], &b);
            fprintf(f, "%d %.17g %.17g 0 0 0 %.17g\n", k + 1, b.velocity.x, b.velocity.y, b.omega);
        }
    }
    if (fclose(f) != 0) goto done;

    f = open_out(out_dir, "in.lammps", path, sizeof path);
    if (!f) goto done;
    fprintf(f, "# LAMMPS input written by porelab export-lammps from %s (porelab %s)\n", scene, PL_VERSION_STRING);
    fprintf(f, "# %d discs (%d fixed), %d walls; porelab's step %.9g s, %lld steps (%s), a dump every %lld steps\n",
            nd, nfixed, nw, dt, plan.total_steps, plan.length_from, every);
    fprintf(f, "# Contact law (porelab -> gran/hooke/history): kn = k_N, kt = k_S, xmu = mu, gamma_n = c_N'/m*,\n"
               "# gamma_t = c_S/m* with m* = %s (mean disc mass %.6g kg%s).\n",
            "m/2 for two discs, m for a disc on a wall", mbar,
            exact_mass ? ", every disc has it: exact" : "; masses differ, so the damping is approximate");
    fprintf(f, "# Approximate (docs/scaling.md): LAMMPS' Coulomb limit uses the total normal force (porelab the\n"
               "# elastic part); porelab's dashpot onset/release corrections are not in LAMMPS; walls are\n"
               "# infinite planes; velocity Verlet instead of porelab's central differences.\n\n");
    fprintf(f, "units si\ndimension 2\nboundary f fm p\natom_style sphere\nnewton off\ncomm_modify vel yes\n\n");
    fprintf(f, "read_data data.lammps\n");
    for (int j = 0; j < ndm; j++)
        fprintf(f, "set type %d density/disc %.17g\n", j + 1, pl_world_material(w, dmat[j]).density);
    fprintf(f, "\nneighbor %.17g bin\nneigh_modify delay 0 every 1 check yes\n", skin);
    fprintf(f, "pair_style gran/hooke/history %.17g %.17g %.17g %.17g %.17g 1\npair_coeff * *\n", dl.kn, dl.kt, dl.gn,
            dl.gt, dl.mu);
    fprintf(f, "timestep %.17g\n\n", dt);
    if (nfixed) {
        int first = 1, col = 0;
        for (int k = 0; k < nd; k++) {
            pl_body_info b;
            pl_world_body_info(w, discs[k], &b);
            if (b.motion != PL_MOTION_FIXED) continue;
            if (first || col == 16) {
                fprintf(f, "%sgroup frozen id", first ? "" : "\n");
                first = 0;
                col = 0;
            }
            fprintf(f, " %d", k + 1);
            col++;
        }
        fprintf(f, "\ngroup mobile subtract all frozen\nfix freeze frozen freeze\n");
    } else {
        fprintf(f, "group mobile union all\n");
    }
    fprintf(f, "fix move mobile nve/sphere disc\nfix plane all enforce2d\n");
    if (gmag > 0) fprintf(f, "fix gravity mobile gravity %.17g vector %.17g %.17g 0\n", gmag, g.x / gmag, g.y / gmag);
    if (damp_c > 0 || damp_a > 0)
        fprintf(f, "# global damping C + alpha m (alpha with the mean mass%s)\nfix damping mobile viscous %.17g\n",
                exact_mass ? ": exact" : ": approximate", damp_c + damp_a * mbar);
    for (int k = 0; k < nw; k++) {
        const wall *wl = &walls[k];
        const law l = map_law(&wl->pd, mbar, dt);
        char where[96];
        if (wl->side == 0) snprintf(where, sizeof where, "%.17g NULL", wl->pos);
        else snprintf(where, sizeof where, "NULL %.17g", wl->pos);
        fprintf(f, "fix wall%d all wall/gran hooke/history %.17g %.17g %.17g %.17g %.17g 1 %s %s  # porelab body %d\n",
                k + 1, l.kn, l.kt, l.gn, l.gt, l.mu, wl->axis ? "yplane" : "xplane", where, wl->body + 1);
    }
    fprintf(f, "\ncompute contact all pair/local force cutoff radius\n"
               "compute pairs all property/local patom1 patom2 cutoff radius\n");
    fprintf(f, "dump atoms all custom %lld atoms.dump id type radius mass x y vx vy omegaz fx fy\n"
               "dump_modify atoms sort id format float %%.17g\n", every);
    fprintf(f, "dump contacts all local %lld contacts.dump c_pairs[1] c_pairs[2] c_contact\n"
               "dump_modify contacts format float %%.17g\n", every);
    fprintf(f, "thermo %lld\nthermo_style custom step time atoms ke\nthermo_modify norm no\n\n", every);
    fprintf(f, "run %lld\n", plan.total_steps);
    if (plan.total_steps % every != 0) /* the last state too, when the dump interval does not end on it */
        fprintf(f, "dump_modify atoms every 1\ndump_modify contacts every 1\nrun 0 post no\n");
    if (fclose(f) != 0) goto done;

    f = open_out(out_dir, "porelab-lammps.txt", path, sizeof path);
    if (!f) goto done;
    fprintf(f, "# porelab export-lammps: what import-lammps needs beside the dumps (SI units)\n");
    fprintf(f, "scene %s\ndt %.17g\nsteps %lld\nevery %lld\n", scene, dt, plan.total_steps, every);
    fprintf(f, "disc_kn %.17g\n", dl.kn);
    for (int j = 0; j < ndm; j++) {
        const pl_material_def m = pl_world_material(w, dmat[j]);
        fprintf(f, "type %d %s %.17g\n", j + 1, m.name, m.density);
    }
    for (int k = 0; k < nd; k++) {
        pl_body_info b;
        pl_world_body_info(w, discs[k], &b);
        if (b.motion == PL_MOTION_FIXED) fprintf(f, "fixed %d\n", k + 1);
    }
    for (int k = 0; k < nw; k++) {
        const wall *wl = &walls[k];
        fprintf(f, "wall %c %.17g %s %.17g %.17g %.17g %s\n", wl->axis ? 'y' : 'x', wl->pos, wl->side ? "hi" : "lo",
                wl->lo, wl->hi, wl->pd.kn, pl_world_material(w, wl->material).name);
    }
    if (fclose(f) != 0) goto done;

    if (!pl_opts_has(&o, "--quiet")) {
        printf("porelab export-lammps: wrote %s/in.lammps and data.lammps: %d discs (%d fixed), %d walls, "
               "dt = %.6g s, %lld steps\n", out_dir, nd, nfixed, nw, dt, plan.total_steps);
        printf("  kn %.6g N/m, kt %.6g N/m, gamma_n %.6g 1/s, gamma_t %.6g 1/s, mu %.6g (m* from the mean disc mass "
               "%.6g kg: %s)\n", dl.kn, dl.kt, dl.gn, dl.gt, dl.mu, mbar, exact_mass ? "exact" : "approximate");
        if (pl_scene_push_result_field(s, "on_frame") != 0 /* LUA_TNIL */)
            printf("  note: the scene's on_frame hook is Lua: LAMMPS runs without it\n");
        lua_pop(pl_scene_lua(s), 1);
        printf("  run it: cd %s && lmp -in in.lammps   (or mpirun -np N lmp -in in.lammps)\n", out_dir);
    }
    rc = PL_EXIT_OK;
done:
    free(polys);
    free(moving);
    free(discs);
    free(walls);
    pl_scene_destroy(&s);
    return rc;
}
