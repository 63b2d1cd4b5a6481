/* Bodies: creation with exact mass properties, outlines, setters and per-body queries. */
#include "core/alloc.h"
#include "dem/world_internal.h"
#include "geom/polygon.h"
#include "porelab/shapes.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

pl_body_def pl_default_body_def(void) {
    pl_body_def d;
    memset(&d, 0, sizeof d);
    d.shape = PL_SHAPE_DISC;
    d.motion = PL_MOTION_DYNAMIC;
    d.material = -1;
    d.user_id = -1;
    return d;
}

#define GROW(ptr, cap)                                                       \
    do {                                                                     \
        void *p_ = pl_realloc((ptr), (size_t)(cap) * sizeof *(ptr));         \
        if (!p_) return 0;                                                   \
        (ptr) = p_;                                                          \
    } while (0)

int pl__ensure_body_capacity(pl_world *w, int need) {
    if (need <= w->cap) return 1;
    int cap = w->cap ? w->cap : 64;
    while (cap < need) cap *= 2;
    GROW(w->pos, cap); GROW(w->vel, cap); GROW(w->force, cap);
    GROW(w->angle, cap); GROW(w->omega, cap); GROW(w->torque, cap);
    GROW(w->mass, cap); GROW(w->inv_mass, cap); GROW(w->inertia, cap); GROW(w->inv_inertia, cap);
    GROW(w->radius, cap); GROW(w->area, cap); GROW(w->shape, cap); GROW(w->motion, cap);
    GROW(w->material, cap); GROW(w->user_id, cap); GROW(w->law, cap);
    GROW(w->load, cap); GROW(w->load_moment, cap); GROW(w->x0, cap);
    GROW(w->tally, cap);
    GROW(w->vert_offset, cap); GROW(w->vert_count, cap);
    GROW(w->pos_at_build, cap); GROW(w->angle_at_build, cap);
    GROW(w->temperature, cap); GROW(w->heat, cap); GROW(w->wear, cap); GROW(w->removed_at, cap);
    GROW(w->temp_hold, cap); GROW(w->removed, cap); /* bonds.h columns */
    {
        void *p_ = pl_realloc(w->heat_step, (size_t)cap * 2 * sizeof *w->heat_step);
        if (!p_) return 0;
        w->heat_step = p_;
    }
    w->cap = cap;
    return 1;
}

static int ensure_vertex_capacity(pl_world *w, int need) {
    if (need <= w->verts_cap) return 1;
    int cap = w->verts_cap ? w->verts_cap : 256;
    while (cap < need) cap *= 2;
    GROW(w->verts_local, cap);
    GROW(w->verts_world, cap);
    w->verts_cap = cap;
    return 1;
}

void pl__update_world_vertices(pl_world *w, int i) {
    const int n = w->vert_count[i];
    if (n == 0) return;
    const double c = cos(w->angle[i]), s = sin(w->angle[i]);
    const pl_vec2 p = w->pos[i];
    const pl_vec2 *l = &w->verts_local[w->vert_offset[i]];
    pl_vec2 *o = &w->verts_world[w->vert_offset[i]];
    for (int k = 0; k < n; k++) o[k] = (pl_vec2){p.x + c * l[k].x - s * l[k].y, p.y + s * l[k].x + c * l[k].y};
}

/* Mass properties from the outline; density per unit thickness (2D). */
static void set_mass_properties(pl_world *w, int i, double density) {
    if (w->shape[i] == PL_SHAPE_SEGMENT) {
        w->area[i] = 0;
        w->mass[i] = w->inertia[i] = 0;
    } else if (w->shape[i] == PL_SHAPE_DISC) {
        const double r = w->radius[i];
        w->area[i] = M_PI * r * r;
        w->mass[i] = density * w->area[i];
        w->inertia[i] = 0.5 * w->mass[i] * r * r;
    } else {
        const pl_vec2 *l = &w->verts_local[w->vert_offset[i]];
        w->area[i] = pl_poly_signed_area(l, w->vert_count[i]);
        w->mass[i] = density * w->area[i];
        w->inertia[i] = density * pl_poly_polar_moment(l, w->vert_count[i]);
    }
    const int dyn = w->motion[i] == PL_MOTION_DYNAMIC && w->mass[i] > 0;
    w->inv_mass[i] = dyn ? 1.0 / w->mass[i] : 0;
    /* a guided (fixed-rotation) body turns as if its inertia were infinite */
    w->inv_inertia[i] = dyn && w->inertia[i] > 0 && !w->law[i].fixed_rotation ? 1.0 / w->inertia[i] : 0;
}

static int finite2(pl_vec2 v) { return isfinite(v.x) && isfinite(v.y); }

/* Clears a body's motion law for a new one, keeping its guided rotation. */
static void reset_law(pl_world *w, int i) {
    const int fixed_rotation = w->law[i].fixed_rotation;
    const pl_vec2 guide = w->law[i].guide;
    memset(&w->law[i], 0, sizeof w->law[i]);
    w->law[i].fixed_rotation = fixed_rotation;
    w->law[i].guide = guide;
}

/* Sets the linear guide (unit direction, or {0, 0}) and projects the velocity onto it. */
static pl_status set_guide(pl_world *w, int i, pl_vec2 d) {
    if (!finite2(d)) return pl__error(w, PL_ERR_ARG, "guide: the direction must be finite");
    const double l = sqrt(d.x * d.x + d.y * d.y);
    if (l == 0) {
        w->law[i].guide = (pl_vec2){0, 0};
        return PL_OK;
    }
    const pl_vec2 u = {d.x / l, d.y / l};
    w->law[i].guide = u;
    w->law[i].fixed_rotation = 1;
    const double s = w->vel[i].x * u.x + w->vel[i].y * u.y;
    w->vel[i] = (pl_vec2){s * u.x, s * u.y};
    w->omega[i] = 0;
    return PL_OK;
}

int pl_world_add_body(pl_world *w, const pl_body_def *d) {
    if (!d) return pl__error(w, PL_ERR_ARG, "body: no definition");
    if (d->material < 0 || d->material >= w->material_count)
        return pl__error(w, PL_ERR_ARG, "body: material index must be in 0..%d (got %d)%s", w->material_count - 1,
                         d->material, w->material_count == 0 ? "; add a material first" : "");
    if (d->motion < PL_MOTION_DYNAMIC || d->motion > PL_MOTION_PRESCRIBED)
        return pl__error(w, PL_ERR_ARG, "body: unknown motion type %d", (int)d->motion);
    if (!finite2(d->position) || !finite2(d->velocity) || !isfinite(d->angle) || !isfinite(d->omega) ||
        !finite2(d->guide))
        return pl__error(w, PL_ERR_ARG, "body: position, velocity, angle and omega must be finite numbers");
    int nv = 0;
    pl_vec2 verts[PL_MAX_POLY_VERTICES];
    pl_vec2 centre = d->position;
    double radius = 0;
    switch (d->shape) {
    case PL_SHAPE_DISC:
        if (!(d->radius > 0) || !isfinite(d->radius))
            return pl__error(w, PL_ERR_ARG, "disc: radius must be > 0 (got %g)", d->radius);
        radius = d->radius;
        break;
    case PL_SHAPE_POLYGON:
        if (!d->vertices || d->vertex_count < 3 || d->vertex_count > PL_MAX_POLY_VERTICES)
            return pl__error(w, PL_ERR_ARG, "polygon: vertex count must be in 3..%d (got %d)", PL_MAX_POLY_VERTICES,
                             d->vertex_count);
        {
            char msg[512];
            if (pl_polygon_check(d->vertices, d->vertex_count, msg, sizeof msg) != PL_OK)
                return pl__error(w, PL_ERR_ARG, "%s", msg); /* "polygon: ..." */
        }
        nv = d->vertex_count;
        centre = pl_poly_centroid(d->vertices, nv);
        for (int k = 0; k < nv; k++) {
            verts[k] = (pl_vec2){d->vertices[k].x - centre.x, d->vertices[k].y - centre.y};
            radius = fmax(radius, hypot(verts[k].x, verts[k].y));
        }
        break;
    case PL_SHAPE_SEGMENT:
        if (!finite2(d->a) || !finite2(d->b)) return pl__error(w, PL_ERR_ARG, "wall: end points must be finite");
        if (d->a.x == d->b.x && d->a.y == d->b.y)
            return pl__error(w, PL_ERR_ARG, "wall: end points must differ (got (%g, %g) twice)", d->a.x, d->a.y);
        if (d->motion == PL_MOTION_DYNAMIC)
            return pl__error(w, PL_ERR_ARG, "wall: a wall segment cannot be dynamic (use fixed or prescribed)");
        nv = 2;
        centre = (pl_vec2){0.5 * (d->a.x + d->b.x), 0.5 * (d->a.y + d->b.y)};
        verts[0] = (pl_vec2){d->a.x - centre.x, d->a.y - centre.y};
        verts[1] = (pl_vec2){d->b.x - centre.x, d->b.y - centre.y};
        radius = hypot(verts[0].x, verts[0].y);
        break;
    default:
        return pl__error(w, PL_ERR_ARG, "body: unknown shape %d", (int)d->shape);
    }
    if (!pl__ensure_body_capacity(w, w->n + 1) || (nv && !ensure_vertex_capacity(w, w->verts_n + nv)))
        return pl__error(w, PL_ERR_NOMEM, "body: out of memory");
    const int i = w->n;
    w->shape[i] = (uint8_t)d->shape;
    w->motion[i] = (uint8_t)d->motion;
    w->material[i] = d->material;
    w->user_id[i] = d->user_id;
    w->pos[i] = centre;
    w->x0[i] = centre;
    w->angle[i] = 0;
    w->vel[i] = d->motion == PL_MOTION_FIXED ? (pl_vec2){0, 0} : d->velocity;
    w->omega[i] = d->motion == PL_MOTION_FIXED ? 0 : d->omega;
    w->force[i] = (pl_vec2){0, 0};
    w->torque[i] = 0;
    memset(&w->tally[i], 0, sizeof w->tally[i]);
    w->radius[i] = radius;
    w->load[i] = (pl_vec2){0, 0};
    w->load_moment[i] = 0;
    w->temperature[i] = w->heat_on ? w->heat_t0 : 0;
    w->heat[i] = w->wear[i] = 0;
    w->removed_at[i] = -1;
    w->temp_hold[i] = w->removed[i] = 0;
    memset(&w->law[i], 0, sizeof w->law[i]);
    w->law[i].law = PL_LAW_CONSTANT;
    w->law[i].velocity = w->vel[i];
    w->law[i].omega = w->omega[i];
    w->law[i].fixed_rotation = d->fixed_rotation != 0;
    if (d->fixed_rotation) w->omega[i] = 0;
    set_guide(w, i, d->guide); /* finite: checked above */
    w->vert_offset[i] = w->verts_n;
    w->vert_count[i] = nv;
    for (int k = 0; k < nv; k++) w->verts_local[w->verts_n + k] = verts[k];
    w->verts_n += nv;
    w->n++;
    set_mass_properties(w, i, w->materials[d->material].def.density);
    if (d->angle != 0) {
        if (d->shape == PL_SHAPE_SEGMENT) {
            /* segments are given in world coordinates: rotate the local outline itself */
            w->angle[i] = 0;
        } else {
            w->angle[i] = d->angle;
        }
    }
    pl__update_world_vertices(w, i);
    w->need_rebuild = 1;
    w->classify_dirty = 1;
    if (w->def.dt <= 0) w->dt = 0; /* the automatic step may change */
    w->energy_initialised = 0;
    return i;
}

int pl_world_body_count(const pl_world *w) { return w->n; }

static int bad_body(const pl_world *w, int i) { return i < 0 || i >= w->n; }

#define CHECK_BODY(w, i, what)                                                                  \
    if (bad_body(w, i))                                                                         \
    return pl__error(w, PL_ERR_ARG, "%s: body index must be in 0..%d (got %d)", what, \
                     (w)->n - 1, i)

pl_status pl_world_body_info(const pl_world *w, int i, pl_body_info *o) {
    CHECK_BODY(w, i, "body_info");
    o->shape = (pl_shape_type)w->shape[i];
    o->motion = (pl_motion_type)w->motion[i];
    o->material = w->material[i];
    o->user_id = w->user_id[i];
    o->position = w->pos[i];
    o->angle = w->angle[i];
    o->velocity = w->vel[i];
    o->omega = w->omega[i];
    o->mass = w->mass[i];
    o->inertia = w->inertia[i];
    o->radius = w->radius[i];
    o->area = w->area[i];
    o->vertex_count = w->vert_count[i];
    o->force = w->force[i];
    o->torque = w->torque[i];
    return PL_OK;
}

int pl_world_body_vertices(const pl_world *w, int i, pl_vec2 *out, int cap) {
    if (bad_body(w, i)) return 0;
    const int n = w->vert_count[i];
    for (int k = 0; k < n && k < cap; k++) out[k] = w->verts_world[w->vert_offset[i] + k];
    return n < cap ? n : cap;
}

int pl_world_copy_positions(const pl_world *w, pl_vec2 *out, int cap) {
    const int n = w->n < cap ? w->n : cap;
    memcpy(out, w->pos, (size_t)n * sizeof *out);
    return n;
}

int pl_world_copy_velocities(const pl_world *w, pl_vec2 *out, int cap) {
    const int n = w->n < cap ? w->n : cap;
    memcpy(out, w->vel, (size_t)n * sizeof *out);
    return n;
}

pl_status pl_world_set_body_position(pl_world *w, int i, pl_vec2 p, double angle) {
    CHECK_BODY(w, i, "set_position");
    if (!finite2(p) || !isfinite(angle)) return pl__error(w, PL_ERR_ARG, "set_position: values must be finite");
    w->pos[i] = p;
    w->x0[i] = p;
    w->angle[i] = angle;
    pl__update_world_vertices(w, i);
    w->need_rebuild = 1;
    w->classify_dirty = 1;
    w->energy_initialised = 0;
    return PL_OK;
}

pl_status pl_world_set_body_velocity(pl_world *w, int i, pl_vec2 v, double omega) {
    CHECK_BODY(w, i, "set_velocity");
    if (!finite2(v) || !isfinite(omega)) return pl__error(w, PL_ERR_ARG, "set_velocity: values must be finite");
    if (w->motion[i] == PL_MOTION_FIXED) return pl__error(w, PL_ERR_STATE, "set_velocity: body %d is fixed", i);
    w->vel[i] = v;
    w->omega[i] = omega;
    if (w->motion[i] == PL_MOTION_PRESCRIBED && w->law[i].law == PL_LAW_CONSTANT) {
        w->law[i].velocity = v;
        w->law[i].omega = omega;
    }
    w->energy_initialised = 0;
    return PL_OK;
}

pl_status pl_world_prescribe_velocity(pl_world *w, int i, pl_vec2 v, double omega) {
    CHECK_BODY(w, i, "prescribe_velocity");
    if (!finite2(v) || !isfinite(omega)) return pl__error(w, PL_ERR_ARG, "prescribe_velocity: values must be finite");
    w->motion[i] = PL_MOTION_PRESCRIBED;
    reset_law(w, i);
    w->law[i].law = PL_LAW_CONSTANT;
    w->law[i].velocity = v;
    w->law[i].omega = omega;
    w->vel[i] = v;
    w->omega[i] = omega;
    w->inv_mass[i] = w->inv_inertia[i] = 0;
    if (w->def.dt <= 0) w->dt = 0;
    return PL_OK;
}

pl_status pl_world_set_body_motion(pl_world *w, int i, pl_motion_type m) {
    CHECK_BODY(w, i, "set_motion");
    if (m < PL_MOTION_DYNAMIC || m > PL_MOTION_PRESCRIBED)
        return pl__error(w, PL_ERR_ARG, "set_motion: unknown motion type %d", (int)m);
    if (m == PL_MOTION_DYNAMIC && w->shape[i] == PL_SHAPE_SEGMENT)
        return pl__error(w, PL_ERR_ARG, "set_motion: a wall segment cannot be dynamic");
    w->motion[i] = (uint8_t)m;
    if (m == PL_MOTION_FIXED) {
        w->vel[i] = (pl_vec2){0, 0};
        w->omega[i] = 0;
    }
    if (m == PL_MOTION_PRESCRIBED) {
        reset_law(w, i);
        w->law[i].law = PL_LAW_CONSTANT;
        w->law[i].velocity = w->vel[i];
        w->law[i].omega = w->omega[i];
    }
    set_mass_properties(w, i, w->materials[w->material[i]].def.density);
    w->need_rebuild = 1;
    w->classify_dirty = 1;
    if (w->def.dt <= 0) w->dt = 0;
    w->energy_initialised = 0;
    return PL_OK;
}

pl_status pl_world_set_body_fixed_rotation(pl_world *w, int i, int on) {
    CHECK_BODY(w, i, "set_fixed_rotation");
    w->law[i].fixed_rotation = on != 0;
    if (on) w->omega[i] = 0;
    set_mass_properties(w, i, w->materials[w->material[i]].def.density);
    if (w->def.dt <= 0) w->dt = 0; /* its rotational limit no longer counts */
    w->energy_initialised = 0;
    return PL_OK;
}

pl_status pl_world_set_body_guide(pl_world *w, int i, pl_vec2 dir) {
    CHECK_BODY(w, i, "set_guide");
    const pl_status st = set_guide(w, i, dir);
    if (st != PL_OK) return st;
    set_mass_properties(w, i, w->materials[w->material[i]].def.density);
    if (w->def.dt <= 0) w->dt = 0;
    w->energy_initialised = 0;
    return PL_OK;
}

pl_status pl_world_set_body_load(pl_world *w, int i, pl_vec2 f, double m) {
    CHECK_BODY(w, i, "set_load");
    if (!finite2(f) || !isfinite(m)) return pl__error(w, PL_ERR_ARG, "set_load: values must be finite");
    w->load[i] = f;
    w->load_moment[i] = m;
    if (f.x != 0 || f.y != 0 || m != 0) w->any_load = 1;
    return PL_OK;
}

pl_status pl_world_set_body_density(pl_world *w, int i, double density) {
    CHECK_BODY(w, i, "set_density");
    if (!(density > 0) || !isfinite(density))
        return pl__error(w, PL_ERR_ARG, "set_density: density must be > 0 (got %g)", density);
    set_mass_properties(w, i, density);
    if (w->def.dt <= 0) w->dt = 0;
    w->energy_initialised = 0;
    w->need_rebuild = 1; /* pair dashpots depend on the masses */
    return PL_OK;
}

pl_status pl_world_set_sinusoid(pl_world *w, int i, pl_vec2 amp, double freq, double t0, double t1) {
    CHECK_BODY(w, i, "set_sinusoid");
    if (!finite2(amp) || !(freq > 0) || !isfinite(freq))
        return pl__error(w, PL_ERR_ARG, "sinusoid: amplitude must be finite and frequency > 0 Hz (got %g)", freq);
    if (!(t1 >= t0)) return pl__error(w, PL_ERR_ARG, "sinusoid: stop time %g must be >= start time %g", t1, t0);
    w->motion[i] = PL_MOTION_PRESCRIBED;
    set_mass_properties(w, i, w->materials[w->material[i]].def.density);
    reset_law(w, i);
    w->law[i].law = PL_LAW_SINUSOID;
    w->law[i].amplitude = amp;
    w->law[i].frequency = freq;
    w->law[i].t_start = t0;
    w->law[i].t_stop = t1;
    w->x0[i] = w->pos[i];
    w->need_rebuild = 1;
    w->classify_dirty = 1;
    if (w->def.dt <= 0) w->dt = 0;
    return PL_OK;
}

pl_status pl_world_set_sinusoid_ramp(pl_world *w, int i, double ramp) {
    CHECK_BODY(w, i, "set_sinusoid_ramp");
    if (w->motion[i] != PL_MOTION_PRESCRIBED || w->law[i].law != PL_LAW_SINUSOID)
        return pl__error(w, PL_ERR_STATE, "sinusoid ramp: body %d has no sinusoidal motion (set_sinusoid first)", i);
    const double span = w->law[i].t_stop - w->law[i].t_start;
    if (!(ramp >= 0) || !isfinite(ramp) || (isfinite(span) && ramp > 0.5 * span))
        return pl__error(w, PL_ERR_ARG, "sinusoid ramp: must be 0 .. half the shaking time (%g s) (got %g s)",
                         0.5 * span, ramp);
    w->law[i].ramp = ramp;
    return PL_OK;
}

pl_status pl_world_set_servo(pl_world *w, int i, pl_vec2 dir, double target, double gain, double vmax) {
    CHECK_BODY(w, i, "set_servo");
    const double l = hypot(dir.x, dir.y);
    if (!(l > 0) || !isfinite(l)) return pl__error(w, PL_ERR_ARG, "servo: direction must be a non-zero vector");
    if (!(target > 0)) return pl__error(w, PL_ERR_ARG, "servo: target force must be > 0 N (got %g)", target);
    if (!(gain > 0) || !(vmax > 0))
        return pl__error(w, PL_ERR_ARG, "servo: gain and vmax must be > 0 m/s (got %g, %g)", gain, vmax);
    w->motion[i] = PL_MOTION_PRESCRIBED;
    set_mass_properties(w, i, w->materials[w->material[i]].def.density);
    reset_law(w, i);
    w->law[i].law = PL_LAW_SERVO;
    w->law[i].servo_dir = (pl_vec2){dir.x / l, dir.y / l};
    w->law[i].servo_target = target;
    w->law[i].servo_gain = gain;
    w->law[i].servo_vmax = vmax;
    w->need_rebuild = 1;
    w->classify_dirty = 1;
    if (w->def.dt <= 0) w->dt = 0;
    return PL_OK;
}

pl_status pl_world_set_hinge(pl_world *w, int i, pl_vec2 pivot, int follow, double height) {
    CHECK_BODY(w, i, "set_hinge");
    if (bad_body(w, follow) || follow == i)
        return pl__error(w, PL_ERR_ARG, "hinge: the followed body must be another body in 0..%d (got %d)", w->n - 1,
                         follow);
    if (!finite2(pivot)) return pl__error(w, PL_ERR_ARG, "hinge: pivot must be finite");
    if (!(height > 0) || !isfinite(height))
        return pl__error(w, PL_ERR_ARG, "hinge: height must be > 0 m (got %g)", height);
    if (w->motion[follow] == PL_MOTION_DYNAMIC)
        return pl__error(w, PL_ERR_ARG, "hinge: the followed body %d must be prescribed (give it a motion law)", follow);
    w->motion[i] = PL_MOTION_PRESCRIBED;
    set_mass_properties(w, i, w->materials[w->material[i]].def.density);
    reset_law(w, i);
    w->law[i].law = PL_LAW_HINGE;
    w->law[i].pivot = pivot;
    w->law[i].rel0 = (pl_vec2){w->pos[i].x - pivot.x, w->pos[i].y - pivot.y};
    w->law[i].angle0 = w->angle[i];
    w->law[i].follow = follow;
    w->law[i].follow_x0 = w->pos[follow].x;
    w->law[i].height = height;
    w->need_rebuild = 1;
    w->classify_dirty = 1;
    if (w->def.dt <= 0) w->dt = 0;
    return PL_OK;
}
