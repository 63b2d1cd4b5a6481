/* porelab import-lammps DUMP --out DIR: reads the dumps of a run of `porelab export-lammps`'s
 * input (atoms.dump, contacts.dump and porelab-lammps.txt beside them) back into porelab: PNG
 * frames drawn by porelab's renderer, VTK files (--vtk) and, per dump, the contact diagnostics
 * porelab prints for its own runs (DIR/diagnostics.csv):
 *   coordination = (2 x disc-disc contacts between moving discs + contacts of moving discs with
 *                  walls or fixed discs) / moving discs            (pl_world_coordination_number)
 *   mean normal force over all contacts: disc pairs from LAMMPS' pair/local force (elastic +
 *                  damping, as porelab's fn), walls k_N x overlap (the elastic part; fix wall/gran
 *                  writes no per-contact force)
 *   mean overlap over the same contacts, m. */
#include "cli_common.h"
#include "commands.h"
#include "render/atomic_file.h"
#include "render/render.h"
#include "vtk_series.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const pl_opt_spec import_specs[] = {
    {"--out", NULL, "DIR", "output folder: frames, vtk/, diagnostics.csv (required)"},
    {"--contacts", NULL, "FILE", "local dump of the contacts (default: contacts.dump beside DUMP)"},
    {"--meta", NULL, "FILE", "the export's porelab-lammps.txt (default: beside DUMP)"},
    {"--vtk", NULL, NULL, "also write VTK files per dump (DIR/vtk/, indexed by DIR/run.pvd)"},
    {"--no-frames", NULL, NULL, "write no PNG frames (diagnostics only)"},
    {"--size", NULL, "WxH", "frame size in pixels (default 800x600)"},
    {"--quiet", "-q", NULL, "print only errors"},
    {NULL, NULL, NULL, NULL}};

static const pl_command_help import_help = {
    "import-lammps", "DUMP --out DIR [--contacts FILE] [--meta FILE] [--vtk] [--no-frames]",
    "Reads a LAMMPS custom dump (id type radius x y ...; the atoms.dump of an exported scene)\n"
    "with its contact dump and the export's porelab-lammps.txt, draws every dump with porelab's\n"
    "renderer (DIR/frame_NNNNNN.png), writes VTK with --vtk, and writes DIR/diagnostics.csv:\n"
    "contacts, coordination number, mean normal contact force and mean overlap per dump. The\n"
    "last dump's diagnostics are printed.",
    import_specs};

#define MAX_TYPES 64
#define MAX_WALLS 64

typedef struct meta {
    double dt;
    int ntypes;
    char type_name[MAX_TYPES][64];
    double density[MAX_TYPES];
    double disc_kn;
    int nwalls;
    char wall_axis[MAX_WALLS];
    double wall_pos[MAX_WALLS], wall_lo[MAX_WALLS], wall_hi[MAX_WALLS], wall_kn[MAX_WALLS];
    int wall_hi_side[MAX_WALLS];
    int *fixed; /* ids, 1-based */
    int nfixed, capfixed;
} meta;

typedef struct dumpfile {
    FILE *f;
    const char *path;
    long line;
    char buf[4096];
} dumpfile;

static char *next_line(dumpfile *d)
{
    if (!fgets(d->buf, sizeof d->buf, d->f)) return NULL;
    d->line++;
    return d->buf;
}

static int read_meta(const char *path, meta *m)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "porelab import-lammps: cannot read %s (%s): give --meta, the porelab-lammps.txt that "
                        "export-lammps wrote beside in.lammps\n", path, strerror(errno));
        return -1;
    }
    char line[1024];
    long ln = 0;
    while (fgets(line, sizeof line, f)) {
        ln++;
        char key[32];
        if (line[0] == '#' || sscanf(line, "%31s", key) != 1) continue;
        int ok = 1;
        if (!strcmp(key, "dt")) ok = sscanf(line, "%*s %lf", &m->dt) == 1 && m->dt > 0;
        else if (!strcmp(key, "disc_kn")) ok = sscanf(line, "%*s %lf", &m->disc_kn) == 1;
        else if (!strcmp(key, "type")) {
            int t;
            char name[64];
            double rho;
            ok = sscanf(line, "%*s %d %63s %lf", &t, name, &rho) == 3 && t >= 1 && t <= MAX_TYPES && rho > 0;
            if (ok) {
                snprintf(m->type_name[t - 1], sizeof m->type_name[0], "%s", name);
                m->density[t - 1] = rho;
                if (t > m->ntypes) m->ntypes = t;
            }
        } else if (!strcmp(key, "fixed")) {
            int id;
            ok = sscanf(line, "%*s %d", &id) == 1 && id >= 1;
            if (ok && m->nfixed == m->capfixed) {
                m->capfixed = m->capfixed ? 2 * m->capfixed : 64;
                int *p = realloc(m->fixed, (size_t)m->capfixed * sizeof *p);
                if (!p) ok = 0;
                else m->fixed = p;
            }
            if (ok) m->fixed[m->nfixed++] = id;
        } else if (!strcmp(key, "wall")) {
            const int k = m->nwalls;
            char axis[4], side[4];
            ok = k < MAX_WALLS && sscanf(line, "%*s %3s %lf %3s %lf %lf %lf", axis, &m->wall_pos[k], side,
                                         &m->wall_lo[k], &m->wall_hi[k], &m->wall_kn[k]) == 6 &&
                 (axis[0] == 'x' || axis[0] == 'y') && (!strcmp(side, "lo") || !strcmp(side, "hi"));
            if (ok) {
                m->wall_axis[k] = axis[0];
                m->wall_hi_side[k] = !strcmp(side, "hi");
                m->nwalls++;
            }
        }
        if (!ok) {
            fprintf(stderr, "porelab import-lammps: %s:%ld: cannot read the '%s' line: %s", path, ln, key, line);
            fclose(f);
            return -1;
        }
    }
    fclose(f);
    if (!(m->dt > 0) || m->ntypes == 0) {
        fprintf(stderr, "porelab import-lammps: %s: no 'dt' or no 'type' line (is it export-lammps' "
                        "porelab-lammps.txt?)\n", path);
        return -1;
    }
    return 0;
}

typedef struct atoms {
    long long step;
    int n, cap;
    int *id, *type;
    double *r, *x, *y;
} atoms;

/* Reads the next frame of a custom atom dump; returns 1, 0 at the end, -1 on error. */
static int read_atoms(dumpfile *d, atoms *a)
{
    char *l = next_line(d);
    if (!l) return 0;
    long long n = 0;
    if (strncmp(l, "ITEM: TIMESTEP", 14) != 0 || !next_line(d) || sscanf(d->buf, "%lld", &a->step) != 1) goto bad;
    if (!next_line(d) || strncmp(d->buf, "ITEM: NUMBER OF ATOMS", 21) != 0 || !next_line(d) ||
        sscanf(d->buf, "%lld", &n) != 1 || n < 0 || n > 100000000)
        goto bad;
    if (!next_line(d) || strncmp(d->buf, "ITEM: BOX BOUNDS", 16) != 0) goto bad;
    for (int k = 0; k < 3; k++)
        if (!next_line(d)) goto bad;
    if (!next_line(d) || strncmp(d->buf, "ITEM: ATOMS", 11) != 0) goto bad;
    int col_id = -1, col_type = -1, col_r = -1, col_x = -1, col_y = -1, ncol = 0;
    for (char *tok = strtok(d->buf + 11, " \t\r\n"); tok; tok = strtok(NULL, " \t\r\n"), ncol++) {
        if (!strcmp(tok, "id")) col_id = ncol;
        else if (!strcmp(tok, "type")) col_type = ncol;
        else if (!strcmp(tok, "radius")) col_r = ncol;
        else if (!strcmp(tok, "x")) col_x = ncol;
        else if (!strcmp(tok, "y")) col_y = ncol;
    }
    if (col_id < 0 || col_type < 0 || col_r < 0 || col_x < 0 || col_y < 0) {
        fprintf(stderr, "porelab import-lammps: %s:%ld: the dump needs the columns id type radius x y "
                        "(dump custom ... id type radius x y)\n", d->path, d->line);
        return -1;
    }
    if (n > a->cap) {
        a->cap = (int)n;
        a->id = realloc(a->id, (size_t)n * sizeof *a->id);
        a->type = realloc(a->type, (size_t)n * sizeof *a->type);
        a->r = realloc(a->r, (size_t)n * sizeof *a->r);
        a->x = realloc(a->x, (size_t)n * sizeof *a->x);
        a->y = realloc(a->y, (size_t)n * sizeof *a->y);
        if (!a->id || !a->type || !a->r || !a->x || !a->y) {
            fprintf(stderr, "porelab import-lammps: out of memory for %lld atoms\n", n);
            return -1;
        }
    }
    a->n = (int)n;
    for (int i = 0; i < a->n; i++) {
        if (!next_line(d)) goto bad;
        char *p = d->buf;
        for (int c = 0; c < ncol; c++) {
            char *e;
            const double v = strtod(p, &e);
            if (e == p || !isfinite(v)) goto bad;
            p = e;
            if (c == col_id) a->id[i] = (int)v;
            else if (c == col_type) a->type[i] = (int)v;
            else if (c == col_r) a->r[i] = v;
            else if (c == col_x) a->x[i] = v;
            else if (c == col_y) a->y[i] = v;
        }
        if (a->id[i] != i + 1) {
            fprintf(stderr, "porelab import-lammps: %s:%ld: atom ids must run 1..N in order (dump_modify sort id); "
                            "got %d at row %d\n", d->path, d->line, a->id[i], i + 1);
            return -1;
        }
    }
    return 1;
bad:
    fprintf(stderr, "porelab import-lammps: %s:%ld: not a LAMMPS custom atom dump here: %s", d->path, d->line,
            d->buf);
    return -1;
}

typedef struct pairs {
    long long step;
    int n, cap;
    int *a, *b;
    double *f;
} pairs;

static int read_pairs(dumpfile *d, pairs *p)
{
    char *l = next_line(d);
    if (!l) return 0;
    long long n = 0;
    if (strncmp(l, "ITEM: TIMESTEP", 14) != 0 || !next_line(d) || sscanf(d->buf, "%lld", &p->step) != 1) goto bad;
    if (!next_line(d) || strncmp(d->buf, "ITEM: NUMBER OF ENTRIES", 23) != 0 || !next_line(d) ||
        sscanf(d->buf, "%lld", &n) != 1 || n < 0 || n > 1000000000)
        goto bad;
    if (!next_line(d) || strncmp(d->buf, "ITEM: BOX BOUNDS", 16) != 0) goto bad;
    for (int k = 0; k < 3; k++)
        if (!next_line(d)) goto bad;
    if (!next_line(d) || strncmp(d->buf, "ITEM: ENTRIES", 13) != 0) goto bad;
    if (n > p->cap) {
        p->cap = (int)n;
        p->a = realloc(p->a, (size_t)n * sizeof *p->a);
        p->b = realloc(p->b, (size_t)n * sizeof *p->b);
        p->f = realloc(p->f, (size_t)n * sizeof *p->f);
        if (!p->a || !p->b || !p->f) {
            fprintf(stderr, "porelab import-lammps: out of memory for %lld contacts\n", n);
            return -1;
        }
    }
    p->n = (int)n;
    for (int i = 0; i < p->n; i++) {
        double a, b, f;
        if (!next_line(d) || sscanf(d->buf, "%lf %lf %lf", &a, &b, &f) != 3 || !isfinite(f)) goto bad;
        p->a[i] = (int)fmin(a, b);
        p->b[i] = (int)fmax(a, b);
        p->f[i] = f;
    }
    return 1;
bad:
    fprintf(stderr, "porelab import-lammps: %s:%ld: not a LAMMPS local dump of 'patom1 patom2 force' here: %s",
            d->path, d->line, d->buf);
    return -1;
}

typedef struct diag {
    int moving, contacts, wall_contacts;
    double coordination, mean_fn, mean_overlap;
} diag;

static int cmp_pair(const void *x, const void *y, const pairs *p);
static const pairs *sort_pairs;
static int cmp_idx(const void *x, const void *y) { return cmp_pair(x, y, sort_pairs); }
static int cmp_pair(const void *x, const void *y, const pairs *p)
{
    const int i = *(const int *)x, j = *(const int *)y;
    if (p->a[i] != p->a[j]) return p->a[i] < p->a[j] ? -1 : 1;
    if (p->b[i] != p->b[j]) return p->b[i] < p->b[j] ? -1 : 1;
    return 0;
}

/* The diagnostics of one dump (definitions at the top of the file). fixed[i] = 1 for fixed discs. */
static int diagnose(const atoms *a, const pairs *p, const unsigned char *fixed, const meta *m, diag *out)
{
    memset(out, 0, sizeof *out);
    for (int i = 0; i < a->n; i++) out->moving += !fixed[i];
    int *idx = malloc((size_t)(p->n ? p->n : 1) * sizeof *idx);
    if (!idx) return -1;
    for (int k = 0; k < p->n; k++) idx[k] = k;
    sort_pairs = p;
    qsort(idx, (size_t)p->n, sizeof *idx, cmp_idx); /* with MPI, a pair across ranks may come twice */
    double fsum = 0, osum = 0, zsum = 0;
    for (int q = 0; q < p->n; q++) {
        const int k = idx[q];
        if (q > 0 && p->a[k] == p->a[idx[q - 1]] && p->b[k] == p->b[idx[q - 1]]) continue;
        const int i = p->a[k] - 1, j = p->b[k] - 1;
        if (i < 0 || j >= a->n || i == j) continue;
        const double ov = a->r[i] + a->r[j] - hypot(a->x[j] - a->x[i], a->y[j] - a->y[i]);
        if (!(ov > 0)) continue;
        out->contacts++;
        fsum += p->f[k];
        osum += ov;
        zsum += !fixed[i] + !fixed[j];
    }
    free(idx);
    for (int i = 0; i < a->n; i++) {
        if (fixed[i]) continue;
        for (int k = 0; k < m->nwalls; k++) {
            const double c = m->wall_axis[k] == 'y' ? a->y[i] : a->x[i];
            const double dist = m->wall_hi_side[k] ? m->wall_pos[k] - c : c - m->wall_pos[k];
            const double ov = a->r[i] - dist;
            if (!(ov > 0)) continue;
            out->contacts++;
            out->wall_contacts++;
            fsum += m->wall_kn[k] * ov;
            osum += ov;
            zsum += 1;
        }
    }
    out->coordination = out->moving ? zsum / out->moving : 0;
    out->mean_fn = out->contacts ? fsum / out->contacts : 0;
    out->mean_overlap = out->contacts ? osum / out->contacts : 0;
    return 0;
}

static void sibling(const char *file, const char *name, char *out, size_t n)
{
    const char *slash = strrchr(file, '/');
    if (!slash) snprintf(out, n, "%s", name);
    else snprintf(out, n, "%.*s/%s", (int)(slash - file), file, name);
}

/* The engine's VTK files go whole into the --out folder the user named (temporary, rename). */
static int write_file(void *ctx, const char *path, int append, const void *data, size_t len, char *msg, size_t n)
{
    (void)ctx;
    if (append) {
        FILE *f = fopen(path, "ab");
        const int ok = f && fwrite(data, 1, len, f) == len;
        if ((f && fclose(f) != 0) || !ok) {
            snprintf(msg, n, "cannot append to %s: %s", path, strerror(errno));
            return -1;
        }
        return 0;
    }
    pl_atomic_file a;
    if (pl_atomic_file_begin(&a, path, msg, n) != 0) return -1;
    FILE *f = fopen(a.tmp_path, "wb");
    int ok = f && fwrite(data, 1, len, f) == len;
    if (f && fclose(f) != 0) ok = 0;
    if (!ok) snprintf(msg, n, "cannot write %s: %s", path, strerror(errno));
    return pl_atomic_file_end(&a, ok, msg, n);
}

/* A world holding the discs (fixed ones fixed) and the walls, for the renderer and VTK. */
static pl_world *build_world(const atoms *a, const meta *m, const unsigned char *fixed)
{
    pl_world_def wd = pl_default_world_def();
    wd.gravity = (pl_vec2){0, 0};
    pl_world *w = pl_world_create(&wd);
    if (!w) return NULL;
    static const pl_file_writer writer = {write_file, NULL};
    pl_world_set_file_writer(w, &writer);
    for (int t = 0; t < m->ntypes; t++) {
        pl_material_def md = pl_default_material_def();
        char name[80];
        snprintf(name, sizeof name, "%s", m->type_name[t][0] ? m->type_name[t] : "type");
        if (pl_world_find_material(w, name) >= 0) snprintf(name, sizeof name, "type%d", t + 1);
        md.name = name;
        md.density = m->density[t] > 0 ? m->density[t] : 1;
        md.kn = m->disc_kn > 0 ? m->disc_kn : 1;
        if (pl_world_add_material(w, &md) < 0) goto fail;
    }
    pl_material_def wm = pl_default_material_def();
    wm.name = "lammps wall";
    wm.kn = m->disc_kn > 0 ? m->disc_kn : 1;
    const int wall_mat = pl_world_add_material(w, &wm);
    if (wall_mat < 0) goto fail;
    for (int i = 0; i < a->n; i++) {
        pl_body_def b = pl_default_body_def();
        b.shape = PL_SHAPE_DISC;
        b.motion = fixed[i] ? PL_MOTION_FIXED : PL_MOTION_DYNAMIC;
        b.material = a->type[i] >= 1 && a->type[i] <= m->ntypes ? a->type[i] - 1 : 0;
        b.position = (pl_vec2){a->x[i], a->y[i]};
        b.radius = a->r[i];
        if (pl_world_add_body(w, &b) < 0) goto fail;
    }
    for (int k = 0; k < m->nwalls; k++) {
        pl_body_def b = pl_default_body_def();
        b.shape = PL_SHAPE_SEGMENT;
        b.motion = PL_MOTION_FIXED;
        b.material = wall_mat;
        if (m->wall_axis[k] == 'y') {
            b.a = (pl_vec2){m->wall_lo[k], m->wall_pos[k]};
            b.b = (pl_vec2){m->wall_hi[k], m->wall_pos[k]};
        } else {
            b.a = (pl_vec2){m->wall_pos[k], m->wall_lo[k]};
            b.b = (pl_vec2){m->wall_pos[k], m->wall_hi[k]};
        }
        if (pl_world_add_body(w, &b) < 0) goto fail;
    }
    return w;
fail:
    fprintf(stderr, "porelab import-lammps: cannot rebuild the discs for drawing: %s\n", pl_world_last_error(w));
    pl_world_destroy(&w);
    return NULL;
}

int pl_cmd_import_lammps(int argc, char **argv)
{
    pl_opts o;
    int rc = pl_opts_parse(&o, &import_help, argc, argv, 1);
    if (rc >= 0) return rc;
    if (o.npositional != 1 || !pl_opts_has(&o, "--out")) {
        fprintf(stderr, "porelab import-lammps: give one dump file and --out DIR (porelab import-lammps --help)\n");
        return PL_EXIT_USAGE;
    }
    const char *dump = o.positional[0], *out_dir = pl_opts_get(&o, "--out");
    int width = 800, height = 600;
    if (pl_opts_has(&o, "--size") && pl_opts_size(&o, "--size", &width, &height) != 0) return PL_EXIT_USAGE;
    char meta_path[PATH_MAX], contacts_path[PATH_MAX];
    if (pl_opts_has(&o, "--meta")) snprintf(meta_path, sizeof meta_path, "%s", pl_opts_get(&o, "--meta"));
    else sibling(dump, "porelab-lammps.txt", meta_path, sizeof meta_path);
    if (pl_opts_has(&o, "--contacts")) snprintf(contacts_path, sizeof contacts_path, "%s", pl_opts_get(&o, "--contacts"));
    else sibling(dump, "contacts.dump", contacts_path, sizeof contacts_path);
    const int quiet = pl_opts_has(&o, "--quiet"), frames = !pl_opts_has(&o, "--no-frames");

    meta m;
    memset(&m, 0, sizeof m);
    atoms a;
    memset(&a, 0, sizeof a);
    pairs p;
    memset(&p, 0, sizeof p);
    dumpfile da = {0}, dc = {0};
    unsigned char *fixed = NULL;
    pl_world *w = NULL;
    pl_frame_writer *fw = NULL;
    pl_vtk_series *vtk = NULL;
    FILE *csv = NULL;
    char err[1024];
    rc = PL_EXIT_FAIL;
    if (read_meta(meta_path, &m) != 0) goto done;
    da.path = dump;
    dc.path = contacts_path;
    if (!(da.f = fopen(dump, "r"))) {
        fprintf(stderr, "porelab import-lammps: cannot read %s (%s)\n", dump, strerror(errno));
        goto done;
    }
    if (!(dc.f = fopen(contacts_path, "r"))) {
        fprintf(stderr, "porelab import-lammps: cannot read the contact dump %s (%s): give --contacts\n",
                contacts_path, strerror(errno));
        goto done;
    }
    if (pl_path_mkdirs(out_dir) != 0) {
        fprintf(stderr, "porelab import-lammps: cannot create the folder %s\n", out_dir);
        goto done;
    }
    char csv_path[PATH_MAX + 32];
    snprintf(csv_path, sizeof csv_path, "%s/diagnostics.csv", out_dir);
    if (!(csv = fopen(csv_path, "w"))) {
        fprintf(stderr, "porelab import-lammps: cannot write %s\n", csv_path);
        goto done;
    }
    fprintf(csv, "# porelab %s import-lammps %s (contacts %s, dt %.9g s)\n", PL_VERSION_STRING, dump, contacts_path,
            m.dt);
    fprintf(csv, "# units: step 1, t s, discs 1, contacts 1, wall_contacts 1, coordination 1, mean_fn N, "
                 "mean_overlap m\n");
    fprintf(csv, "step,t,discs,contacts,wall_contacts,coordination,mean_fn,mean_overlap\n");
    pl_render_options ropt = pl_default_render_options();
    ropt.width = width;
    ropt.height = height;
    ropt.layers = PL_LAYER_BODIES | PL_LAYER_TIME | PL_LAYER_TITLE | PL_LAYER_SCALEBAR;
    diag dg = {0};
    long long last_step = -1;
    int nframes = 0;
    for (;;) {
        int ra = read_atoms(&da, &a);
        if (ra < 0) goto done;
        if (ra == 0) break;
        int rp;
        do rp = read_pairs(&dc, &p);
        while (rp == 1 && p.step < a.step);
        if (rp < 0) goto done;
        if (rp == 0 || p.step != a.step) {
            fprintf(stderr, "porelab import-lammps: %s has no contacts for step %lld of %s\n", contacts_path, a.step,
                    dump);
            goto done;
        }
        if (!w) {
            fixed = calloc((size_t)a.n + 1, 1);
            if (!fixed) goto done;
            for (int k = 0; k < m.nfixed; k++)
                if (m.fixed[k] <= a.n) fixed[m.fixed[k] - 1] = 1;
            if (!(w = build_world(&a, &m, fixed))) goto done;
            if (frames && !(fw = pl_frame_writer_open(out_dir, NULL, 30, err, sizeof err))) {
                fprintf(stderr, "porelab import-lammps: %s\n", err);
                goto done;
            }
            if (pl_opts_has(&o, "--vtk") && !(vtk = pl_vtk_series_open(out_dir, err, sizeof err))) {
                fprintf(stderr, "porelab import-lammps: %s\n", err);
                goto done;
            }
        } else if (a.n != pl_world_body_count(w) - m.nwalls) {
            fprintf(stderr, "porelab import-lammps: %s: step %lld has %d atoms, the first dump had %d (atoms lost?)\n",
                    dump, a.step, a.n, pl_world_body_count(w) - m.nwalls);
            goto done;
        }
        if (diagnose(&a, &p, fixed, &m, &dg) != 0) goto done;
        const double t = (double)a.step * m.dt;
        fprintf(csv, "%lld,%.9g,%d,%d,%d,%.9g,%.9g,%.9g\n", a.step, t, a.n, dg.contacts, dg.wall_contacts,
                dg.coordination, dg.mean_fn, dg.mean_overlap);
        for (int i = 0; i < a.n; i++) pl_world_set_body_position(w, i, (pl_vec2){a.x[i], a.y[i]}, 0);
        ropt.time_offset = t;
        snprintf(ropt.title, sizeof ropt.title, "LAMMPS run read back: %d discs, coordination %.2f", a.n,
                 dg.coordination);
        if (fw && pl_frame_writer_add(fw, w, &ropt, err, sizeof err) != 0) {
            fprintf(stderr, "porelab import-lammps: %s\n", err);
            goto done;
        }
        if (vtk && pl_vtk_series_add(vtk, w, err, sizeof err) != 0) {
            fprintf(stderr, "porelab import-lammps: %s\n", err);
            goto done;
        }
        last_step = a.step;
        nframes++;
    }
    if (nframes == 0) {
        fprintf(stderr, "porelab import-lammps: %s holds no dump\n", dump);
        goto done;
    }
    if (fw && pl_frame_writer_close(&fw, err, sizeof err) != 0) {
        fprintf(stderr, "porelab import-lammps: %s\n", err);
        goto done;
    }
    if (fclose(csv) != 0) {
        csv = NULL;
        fprintf(stderr, "porelab import-lammps: cannot write %s\n", csv_path);
        goto done;
    }
    csv = NULL;
    if (!quiet) {
        printf("porelab import-lammps: %d dumps read; wrote %s%s%s\n", nframes, csv_path,
               frames ? " and the frames" : "", vtk ? " and vtk/" : "");
        printf("last dump: step %lld, t = %.6g s: %d discs (%d moving), %d contacts (%d with walls), "
               "coordination %.4f, mean normal contact force %.6g N, mean overlap %.6g m\n",
               last_step, (double)last_step * m.dt, a.n, dg.moving, dg.contacts, dg.wall_contacts, dg.coordination,
               dg.mean_fn, dg.mean_overlap);
    }
    rc = PL_EXIT_OK;
done:
    if (fw) pl_frame_writer_close(&fw, err, sizeof err);
    if (vtk) pl_vtk_series_close(&vtk);
    if (csv) fclose(csv);
    if (da.f) fclose(da.f);
    if (dc.f) fclose(dc.f);
    pl_world_destroy(&w);
    free(fixed);
    free(m.fixed);
    free(a.id);
    free(a.type);
    free(a.r);
    free(a.x);
    free(a.y);
    free(p.a);
    free(p.b);
    free(p.f);
    return rc;
}
