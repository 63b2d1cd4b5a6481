/* Servo-controlled bodies (seed 003 eqs. 5.11-5.12) with two extras used by the simple-shear
 * box of scenes/soil/simple_shear.lua:
 *  - a drive velocity across the servo direction, so that one body can hold a normal force and
 *    shear the sample at the same time (the top wall of seed 003 Fig. 5.19);
 *  - the pore fluid's force on the body counted in the measured force, so that the servo holds
 *    the total (contact + water) force: the top wall of an undrained sample under a constant
 *    total vertical load. The world asks the models for this wall's load too and leaves it in
 *    the external-force column (it is not integrated: the wall's motion is prescribed). */
#include "dem/world_internal.h"
#include <math.h>

pl_status pl_world_set_servo_drive(pl_world *w, int i, pl_vec2 drive, int with_fluid) {
    if (i < 0 || i >= w->n) return pl__error(w, PL_ERR_ARG, "servo_drive: body index must be in 0..%d (got %d)", w->n - 1, i);
    if (w->motion[i] != PL_MOTION_PRESCRIBED || w->law[i].law != PL_LAW_SERVO)
        return pl__error(w, PL_ERR_STATE, "servo_drive: body %d is not a servo (call servo first)", i);
    if (!isfinite(drive.x) || !isfinite(drive.y)) return pl__error(w, PL_ERR_ARG, "servo_drive: drive velocity must be finite");
    pl_motion *m = &w->law[i];
    /* keep only the part across the servo direction: along it the servo decides */
    const double along = drive.x * m->servo_dir.x + drive.y * m->servo_dir.y;
    m->servo_drive = (pl_vec2){drive.x - along * m->servo_dir.x, drive.y - along * m->servo_dir.y};
    m->servo_fluid = with_fluid != 0;
    return PL_OK;
}

pl_vec2 pl__servo_velocity(pl_world *w, int i) {
    const pl_motion *m = &w->law[i];
    double fc = -(w->force[i].x * m->servo_dir.x + w->force[i].y * m->servo_dir.y);
    if (m->servo_fluid && w->ext_force && i < w->ext_cap) {
        /* the attached models' load on this wall, from the external-force column the world
           filled before the motion laws (world/models.c) */
        const pl_vec2 F = w->ext_force[i];
        fc -= F.x * m->servo_dir.x + F.y * m->servo_dir.y;
    }
    const double err = (m->servo_target - fc) / m->servo_target;
    double v = m->servo_gain * err;
    if (fabs(v) > m->servo_vmax) v = m->servo_vmax * ((v > 0) - (v < 0));
    return (pl_vec2){v * m->servo_dir.x + m->servo_drive.x, v * m->servo_dir.y + m->servo_drive.y};
}
