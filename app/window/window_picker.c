/* The scene picker's list (see window_picker.h). */
#include "window_picker.h"

#include <ctype.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int is_dir(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

/* The first sentence of s (up to ". ", "? " kept, or the end), without parentheses. */
static void first_sentence(const char *s, char *out, int n)
{
    int k = 0, depth = 0;
    for (const char *p = s; *p && k < n - 1; p++) {
        if (*p == '(') { depth++; continue; }
        if (*p == ')') { if (depth > 0) depth--; continue; }
        if (depth > 0) continue;
        if (*p == ' ' && k > 0 && out[k - 1] == ' ') continue;
        out[k++] = *p;
        if ((*p == '.' || *p == '?' || *p == '!') && (p[1] == ' ' || p[1] == 0)) break;
    }
    while (k > 0 && (out[k - 1] == ' ' || out[k - 1] == ',' || out[k - 1] == ':')) k--;
    out[k] = 0;
    /* " ." and " ," left where a parenthesis was dropped */
    for (char *q = out; (q = strstr(q, " .")) != NULL;) memmove(q, q + 1, strlen(q));
    for (char *q = out; (q = strstr(q, " ,")) != NULL;) memmove(q, q + 1, strlen(q));
    for (char *q = out; (q = strstr(q, " :")) != NULL;) memmove(q, q + 1, strlen(q));
}

void pl_picker_describe(const char *path, char *out, int n)
{
    out[0] = 0;
    FILE *f = fopen(path, "r");
    if (!f) return;
    char line[512], text[2048] = "";
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "--", 2) != 0) break; /* the opening comment only */
        char *p = line + 2;
        while (*p == ' ') p++;
        p[strcspn(p, "\r\n")] = 0;
        if (strncmp(p, "Description:", 12) == 0) {
            p += 12;
            while (*p == ' ') p++;
            snprintf(out, (size_t)n, "%s", p);
            fclose(f);
            return;
        }
        if (strlen(text) + strlen(p) + 2 < sizeof text) {
            if (text[0]) strcat(text, " ");
            strcat(text, p);
        }
    }
    fclose(f);
    /* a reference before a colon ("Seed 003 (Tan 1990) §2.2.5.1, Table 2.1: one disc ...")
     * is left out */
    const char *s = text, *colon = strchr(text, ':');
    if (colon && (strncmp(text, "Seed ", 5) == 0 || strncmp(text, "seed ", 5) == 0)) s = colon + 1;
    while (*s == ' ') s++;
    first_sentence(s, out, n);
    if (out[0]) out[0] = (char)toupper((unsigned char)out[0]);
}

/* 1 when the file has a top-level return (a declarative scene). */
static int declarative(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    char line[512];
    int yes = 0;
    while (!yes && fgets(line, sizeof line, f)) yes = strncmp(line, "return", 6) == 0;
    fclose(f);
    return yes;
}

/* The classroom and soil scenes first, then the rest by name. */
static int rank(const char *name)
{
    static const char *const first[] = {"lab/", "soil/", "demo", "grains/", "fluid_quicksand", NULL};
    for (int i = 0; first[i]; i++)
        if (strncmp(name, first[i], strlen(first[i])) == 0) return i;
    return 99;
}

static int by_name(const void *a, const void *b)
{
    const char *x = ((const pl_picker_entry *)a)->name, *y = ((const pl_picker_entry *)b)->name;
    int rx = rank(x), ry = rank(y);
    return rx != ry ? rx - ry : strcmp(x, y);
}

static void scan_dir(pl_picker *pk, const char *dir, const char *rel, int depth)
{
    DIR *d = opendir(dir);
    if (!d) return;
    struct dirent *de;
    while ((de = readdir(d)) != NULL && pk->n < PL_PICKER_MAX) {
        if (de->d_name[0] == '.') continue;
        char p[PATH_MAX], r[PATH_MAX];
        if (snprintf(p, sizeof p, "%s/%s", dir, de->d_name) >= (int)sizeof p) continue;
        snprintf(r, sizeof r, "%s%s%s", rel, rel[0] ? "/" : "", de->d_name);
        if (is_dir(p)) {
            if (depth < 2) scan_dir(pk, p, r, depth + 1);
            continue;
        }
        size_t l = strlen(r);
        if (l >= sizeof pk->e[0].name + 4) continue;
        if (l < 5 || strcmp(r + l - 4, ".lua") != 0 || l - 4 >= sizeof pk->e[0].name) continue;
        if (!declarative(p)) continue;
        pl_picker_entry *e = &pk->e[pk->n++];
        snprintf(e->path, sizeof e->path, "%s", p);
        snprintf(e->name, sizeof e->name, "%.*s", (int)(l - 4), r);
        pl_picker_describe(p, e->desc, (int)sizeof e->desc);
    }
    closedir(d);
}

int pl_picker_scan(pl_picker *pk, const char *open_scene)
{
    pk->n = 0;
    pk->dir[0] = 0;
    const char *env = getenv("PORELAB_SCENES");
    if (env && env[0] && is_dir(env)) {
        snprintf(pk->dir, sizeof pk->dir, "%s", env);
    } else {
        /* the nearest folder named "scenes" above the open scene */
        char buf[PATH_MAX];
        if (open_scene && realpath(open_scene, buf)) {
            char *s;
            while ((s = strrchr(buf, '/')) != NULL && s != buf) {
                *s = 0;
                const char *base = strrchr(buf, '/');
                if (base && strcmp(base + 1, "scenes") == 0) {
                    snprintf(pk->dir, sizeof pk->dir, "%s", buf);
                    break;
                }
            }
        }
        if (!pk->dir[0] && is_dir("scenes")) snprintf(pk->dir, sizeof pk->dir, "scenes");
    }
    if (!pk->dir[0]) return 0;
    scan_dir(pk, pk->dir, "", 0);
    qsort(pk->e, (size_t)pk->n, sizeof pk->e[0], by_name);
    return pk->n;
}
