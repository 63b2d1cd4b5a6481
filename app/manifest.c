/* DIR/manifest.json: writer (atomic) and a small reader (manifest.h). */
#include "manifest.h"
#include "porelab/core.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef PL_BUILD_TYPE
#define PL_BUILD_TYPE "unknown"
#endif
#ifndef PL_ASSERTS
#define PL_ASSERTS 0
#endif

#define FNV_OFFSET 0xcbf29ce484222325ull

const char *pl_manifest_build(void)
{
    static char buf[160];
    if (!buf[0])
        snprintf(buf, sizeof buf, "%s, %s %s, gmsh %d, asserts %d, -ffp-contract=off", PL_BUILD_TYPE,
#if defined(__clang__)
                 "clang",
#elif defined(__GNUC__)
                 "GCC",
#else
                 "cc",
#endif
                 __VERSION__, PL_HAVE_GMSH, PL_ASSERTS);
    return buf;
}

int pl_file_hash(const char *path, uint64_t *hash, long long *bytes)
{
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    uint64_t h = FNV_OFFSET;
    long long n = 0;
    unsigned char buf[65536];
    size_t k;
    while ((k = fread(buf, 1, sizeof buf, f)) > 0) {
        h = pl_hash_bytes(h, buf, k);
        n += (long long)k;
    }
    int bad = ferror(f);
    fclose(f);
    if (bad) return -1;
    *hash = h;
    if (bytes) *bytes = n;
    return 0;
}

static int cmp_over(const void *a, const void *b) { return strcmp(*(const char *const *)a, *(const char *const *)b); }

int pl_manifest_prepare(pl_manifest *m, const char *scene_path, char *err, size_t errlen)
{
    if (!realpath(scene_path, m->scene_path)) snprintf(m->scene_path, sizeof m->scene_path, "%s", scene_path);
    if (pl_file_hash(scene_path, &m->scene_hash, &m->scene_bytes) != 0) {
        snprintf(err, errlen, "cannot read scene '%s': %s", scene_path, strerror(errno));
        return -1;
    }
    char line[PL_MANIFEST_MAX_OVER][96];
    const char *sorted[PL_MANIFEST_MAX_OVER];
    for (int i = 0; i < m->nover; i++) {
        snprintf(line[i], sizeof line[i], "%s=%.17g", m->over_name[i], m->over_value[i]);
        sorted[i] = line[i];
    }
    qsort(sorted, (size_t)m->nover, sizeof *sorted, cmp_over);
    uint64_t h = pl_hash_bytes(FNV_OFFSET, &m->scene_hash, sizeof m->scene_hash);
    for (int i = 0; i < m->nover; i++) h = pl_hash_bytes(h, sorted[i], strlen(sorted[i]) + 1);
    char tail[512];
    snprintf(tail, sizeof tail, "seed=%lld until=%s steps=%s porelab=%s build=%s", m->seed, m->until ? m->until : "-",
             m->steps ? m->steps : "-", PL_VERSION_STRING, pl_manifest_build());
    m->inputs = pl_hash_bytes(h, tail, strlen(tail));
    return 0;
}

/* ------------------------------------------------------------------ writer */

static void put_str(FILE *f, const char *s)
{
    fputc('"', f);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\') fprintf(f, "\\%c", *p);
        else if (*p == '\n') fputs("\\n", f);
        else if (*p == '\t') fputs("\\t", f);
        else if (*p < 0x20 || *p == 0x7f) fprintf(f, "\\u%04x", *p);
        else fputc(*p, f);
    }
    fputc('"', f);
}

/* the shortest of %.15g / %.17g that reads back as the same double */
static void put_num(FILE *f, double v)
{
    if (!isfinite(v)) {
        fputs("null", f);
        return;
    }
    char b[40];
    snprintf(b, sizeof b, "%.15g", v);
    if (strtod(b, NULL) != v) snprintf(b, sizeof b, "%.17g", v);
    fputs(b, f);
}

int pl_manifest_write(const pl_manifest *m, const char *dir, char *err, size_t errlen)
{
    char path[4200], tmp[4300];
    snprintf(path, sizeof path, "%s/manifest.json", dir);
    snprintf(tmp, sizeof tmp, "%s/.manifest.json.%ld.tmp", dir, (long)getpid());
    FILE *f = fopen(tmp, "w");
    if (!f) {
        snprintf(err, errlen, "cannot write %s: %s", tmp, strerror(errno));
        return -1;
    }
    fprintf(f, "{\n  \"format\": \"%s\",\n  \"scene\": {\"path\": ", PL_MANIFEST_FORMAT);
    put_str(f, m->scene_path);
    fprintf(f, ", \"hash\": \"fnv1a64:%016llx\", \"bytes\": %lld},\n", (unsigned long long)m->scene_hash,
            m->scene_bytes);
    fprintf(f, "  \"inputs\": \"%016llx\",\n  \"out_dir\": ", (unsigned long long)m->inputs);
    put_str(f, m->out_dir);
    fprintf(f, ",\n  \"seed\": %lld,\n  \"params\": {", m->seed);
    for (int i = 0; i < m->nparams; i++) {
        const pl_scene_param *p = &m->params[i];
        fprintf(f, "%s\n    ", i ? "," : "");
        put_str(f, p->name);
        fputs(": {\"value\": ", f);
        put_num(f, p->value);
        fputs(", \"unit\": ", f);
        put_str(f, p->unit);
        fputs(", \"min\": ", f);
        put_num(f, p->min);
        fputs(", \"max\": ", f);
        put_num(f, p->max);
        fprintf(f, ", \"given\": %s}", m->overridden[i] ? "true" : "false");
    }
    /* overrides the scene never saw (the run failed before declaring them) */
    fprintf(f, "%s},\n  \"given\": {", m->nparams ? "\n  " : "");
    for (int i = 0; i < m->nover; i++) {
        fprintf(f, "%s", i ? ", " : "");
        put_str(f, m->over_name[i]);
        fputs(": ", f);
        put_num(f, m->over_value[i]);
    }
    fprintf(f, "},\n  \"run_length\": {\"until\": ");
    if (m->until) put_str(f, m->until); else fputs("null", f);
    fputs(", \"steps\": ", f);
    if (m->steps) put_str(f, m->steps); else fputs("null", f);
    fprintf(f, "},\n  \"porelab\": {\"version\": \"%s\", \"build\": ", PL_VERSION_STRING);
    put_str(f, pl_manifest_build());
    fprintf(f, "},\n  \"started_utc\": \"%s\",\n", m->started_utc);
    if (m->has_state)
        fprintf(f, "  \"state_hash\": \"%016llx\",\n  \"steps\": %lld,\n  \"t_end\": ", (unsigned long long)m->state_hash,
                m->step_count);
    else
        fputs("  \"state_hash\": null,\n  \"steps\": null,\n  \"t_end\": ", f);
    put_num(f, m->has_state ? m->t_end : NAN);
    fputs(",\n  \"wall_s\": ", f);
    put_num(f, m->wall_s);
    fputs(",\n  \"cpu_s\": ", f);
    put_num(f, m->cpu_s);
    fprintf(f, ",\n  \"exit_status\": %d,\n  \"error\": ", m->exit_status);
    put_str(f, m->error);
    fputs(",\n  \"results\": {", f);
    for (int i = 0; i < m->nresults; i++) {
        const pl_scene_result *r = &m->results[i];
        fprintf(f, "%s\n    ", i ? "," : "");
        put_str(f, r->name);
        fputs(": {\"value\": ", f);
        if (r->kind == 0) put_num(f, r->value);
        else if (r->kind == 1) fputs(r->value != 0 ? "true" : "false", f);
        else put_str(f, r->text);
        fputs(", \"unit\": ", f);
        put_str(f, r->unit);
        fputc('}', f);
    }
    fprintf(f, "%s}\n}\n", m->nresults ? "\n  " : "");
    int bad = ferror(f);
    if (fflush(f) != 0 || fsync(fileno(f)) != 0) bad = 1;
    if (fclose(f) != 0) bad = 1;
    if (bad || rename(tmp, path) != 0) {
        snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
        remove(tmp);
        return -1;
    }
    return 0;
}

int pl_manifest_done(const char *dir, uint64_t inputs)
{
    char path[4200], err[256];
    snprintf(path, sizeof path, "%s/manifest.json", dir);
    pl_json_doc d = {0};
    if (pl_json_read(path, &d, err, sizeof err) != 0) return 0;
    const pl_json_item *in = pl_json_get(&d, "inputs"), *st = pl_json_get(&d, "exit_status");
    char want[32];
    snprintf(want, sizeof want, "%016llx", (unsigned long long)inputs);
    int done = in && in->type == 3 && strcmp(in->str, want) == 0 && st && st->type == 2 && st->num == 0;
    pl_json_free(&d);
    return done;
}

/* ------------------------------------------------------------------ reader */

typedef struct jp {
    const char *s, *p;
    pl_json_doc *doc;
    char err[256];
} jp;

static void ws(jp *j)
{
    while (*j->p && isspace((unsigned char)*j->p)) j->p++;
}

static int fail(jp *j, const char *what)
{
    if (!j->err[0]) snprintf(j->err, sizeof j->err, "%s at byte %ld", what, (long)(j->p - j->s));
    return -1;
}

static int add(jp *j, const char *path, int type, double num, const char *str)
{
    pl_json_doc *d = j->doc;
    if (d->n == d->cap) {
        int cap = d->cap ? 2 * d->cap : 64;
        pl_json_item *it = realloc(d->items, (size_t)cap * sizeof *it);
        if (!it) return fail(j, "out of memory");
        d->items = it;
        d->cap = cap;
    }
    pl_json_item *it = &d->items[d->n++];
    snprintf(it->path, sizeof it->path, "%s", path);
    it->type = type;
    it->num = num;
    snprintf(it->str, sizeof it->str, "%s", str ? str : "");
    return 0;
}

static int parse_string(jp *j, char *out, size_t n)
{
    if (*j->p != '"') return fail(j, "expected a string");
    j->p++;
    size_t k = 0;
    while (*j->p && *j->p != '"') {
        char c = *j->p++;
        if (c == '\\') {
            c = *j->p++;
            if (c == 'n') c = '\n';
            else if (c == 't') c = '\t';
            else if (c == 'u') {
                unsigned v = 0;
                for (int i = 0; i < 4; i++) {
                    if (!isxdigit((unsigned char)*j->p)) return fail(j, "bad \\u escape");
                    char h = *j->p++;
                    v = v * 16 + (unsigned)(isdigit((unsigned char)h) ? h - '0' : (tolower(h) - 'a' + 10));
                }
                c = v < 0x80 ? (char)v : '?';
            } else if (c == '\0') {
                return fail(j, "unterminated string");
            }
        }
        if (k + 1 < n) out[k++] = c;
    }
    if (*j->p != '"') return fail(j, "unterminated string");
    j->p++;
    out[k] = '\0';
    return 0;
}

static int parse_value(jp *j, const char *path, int depth)
{
    if (depth > 32) return fail(j, "nesting too deep");
    ws(j);
    char sub[160], key[128];
    if (*j->p == '{' || *j->p == '[') {
        int obj = *j->p == '{';
        j->p++;
        ws(j);
        if (*j->p == (obj ? '}' : ']')) {
            j->p++;
            return 0;
        }
        for (int i = 0;; i++) {
            ws(j);
            if (obj) {
                if (parse_string(j, key, sizeof key) != 0) return -1;
                ws(j);
                if (*j->p != ':') return fail(j, "expected ':'");
                j->p++;
            } else {
                snprintf(key, sizeof key, "%d", i);
            }
            snprintf(sub, sizeof sub, "%s%s%s", path, path[0] ? "." : "", key);
            if (parse_value(j, sub, depth + 1) != 0) return -1;
            ws(j);
            if (*j->p == ',') {
                j->p++;
                continue;
            }
            if (*j->p == (obj ? '}' : ']')) {
                j->p++;
                return 0;
            }
            return fail(j, obj ? "expected ',' or '}'" : "expected ',' or ']'");
        }
    }
    if (*j->p == '"') {
        char str[512];
        if (parse_string(j, str, sizeof str) != 0) return -1;
        return add(j, path, 3, 0, str);
    }
    if (strncmp(j->p, "true", 4) == 0) return j->p += 4, add(j, path, 1, 1, NULL);
    if (strncmp(j->p, "false", 5) == 0) return j->p += 5, add(j, path, 1, 0, NULL);
    if (strncmp(j->p, "null", 4) == 0) return j->p += 4, add(j, path, 0, NAN, NULL);
    char *end;
    double v = strtod(j->p, &end);
    if (end == j->p) return fail(j, "expected a value");
    j->p = end;
    return add(j, path, 2, v, NULL);
}

int pl_json_read(const char *path, pl_json_doc *doc, char *err, size_t errlen)
{
    memset(doc, 0, sizeof *doc);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap + 1);
    size_t k;
    while (buf && (k = fread(buf + n, 1, cap - n, f)) > 0) {
        n += k;
        if (n == cap) {
            char *nb = cap < (64u << 20) ? realloc(buf, 2 * cap + 1) : NULL;
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
    }
    fclose(f);
    if (!buf) {
        snprintf(err, errlen, "%s: too large or out of memory", path);
        return -1;
    }
    buf[n] = '\0';
    jp j = {buf, buf, doc, ""};
    int rc = parse_value(&j, "", 0);
    if (rc == 0) {
        ws(&j);
        if (*j.p) rc = fail(&j, "text after the document");
    }
    if (rc != 0) {
        snprintf(err, errlen, "%s: not a valid manifest (%s)", path, j.err);
        pl_json_free(doc);
    }
    free(buf);
    return rc;
}

const pl_json_item *pl_json_get(const pl_json_doc *doc, const char *path)
{
    for (int i = 0; i < doc->n; i++)
        if (strcmp(doc->items[i].path, path) == 0) return &doc->items[i];
    return NULL;
}

void pl_json_free(pl_json_doc *doc)
{
    free(doc->items);
    memset(doc, 0, sizeof *doc);
}
