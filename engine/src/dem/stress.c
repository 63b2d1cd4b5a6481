/* Micromechanical diagnostics: average stress in a region from contact forces and branch
 * vectors (Love-Weber: sigma_ij = (1/A) sum_c f_i l_j), and the coordination number. */
#include "dem/world_internal.h"

static int inside(pl_vec2 p, pl_vec2 lo, pl_vec2 hi) { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }

int pl_world_stress_in_region(const pl_world *w, pl_vec2 lo, pl_vec2 hi, double out[4]) {
    double s[4] = {0, 0, 0, 0};
    const double area = (hi.x - lo.x) * (hi.y - lo.y);
    for (int k = 0; k < w->pair_n; k++) {
        const pl_pair *p = &w->pairs[k];
        if (!p->touching) continue;
        const pl_vec2 t = {-p->normal.y, p->normal.x};
        /* force on b */
        const pl_vec2 F = {p->fn * p->normal.x + p->ft * t.x, p->fn * p->normal.y + p->ft * t.y};
        const int ends[2] = {p->a, p->b};
        for (int e = 0; e < 2; e++) {
            const int i = ends[e];
            if (w->motion[i] != PL_MOTION_DYNAMIC || !inside(w->pos[i], lo, hi)) continue;
            const double sign = e == 0 ? -1 : 1; /* force on a is -F */
            const pl_vec2 l = {p->point.x - w->pos[i].x, p->point.y - w->pos[i].y};
            /* compression positive: minus the tensile-positive sum */
            s[0] -= sign * F.x * l.x;
            s[1] -= sign * F.x * l.y;
            s[2] -= sign * F.y * l.x;
            s[3] -= sign * F.y * l.y;
        }
    }
    int count = 0;
    for (int i = 0; i < w->n; i++) count += w->motion[i] == PL_MOTION_DYNAMIC && inside(w->pos[i], lo, hi);
    for (int c = 0; c < 4; c++) out[c] = area > 0 ? s[c] / area : 0;
    return count;
}

double pl_world_coordination_number(const pl_world *w) {
    int ndyn = 0;
    long ends = 0;
    for (int i = 0; i < w->n; i++) ndyn += w->motion[i] == PL_MOTION_DYNAMIC;
    for (int k = 0; k < w->pair_n; k++) {
        const pl_pair *p = &w->pairs[k];
        if (!p->touching) continue;
        ends += (w->motion[p->a] == PL_MOTION_DYNAMIC) + (w->motion[p->b] == PL_MOTION_DYNAMIC);
    }
    return ndyn ? (double)ends / ndyn : 0;
}
