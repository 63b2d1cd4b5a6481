/// Saturated soil diagnostics on top of the Darcy pore fluid (porelab/fluid.h) with pore
/// pressure from skeleton volume change (flag FLUID_CONSOLIDATION = 1, fluid bulk modulus
/// FLUID_BULK_MODULUS; docs/soil.md). Stresses are 2D: force per unit thickness per metre,
/// i.e. Pa; compression positive.
#ifndef PORELAB_SOIL_H
#define PORELAB_SOIL_H

#include "porelab/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pl_world pl_world;

/// Stress state of a rectangular region [lo, hi].
typedef struct pl_soil_region {
    double eff[4];     ///< effective stress sigma' {xx, xy, yx, yy}, Pa, compression positive: the
                       ///< contact (branch-vector) stress of the grains whose centroids lie inside
    double u;          ///< mean pore pressure over the region (area-weighted), Pa (gauge)
    double u_excess;   ///< mean excess pore pressure (pressure minus hydrostatic), Pa
    double total[4];   ///< total stress sigma = sigma' + u I, Pa, compression positive
    int bodies;        ///< grains counted for sigma'
    double overburden; ///< geostatic vertical effective stress, Pa: the submerged weight per unit
                       ///< width of the dynamic bodies whose centroids lie in the column
                       ///< lo.x..hi.x above each level, averaged over the region's height
                       ///< (buoyancy taken off where the centroid's pore pressure is positive);
                       ///< 0 unless gravity points along -y
    double area;       ///< area of the region inside the fluid mesh, m^2
} pl_soil_region;

/// Fills *out for the region [lo, hi] (m). Without a fluid model u = u_excess = 0.
pl_status pl_world_soil_region(pl_world *w, pl_vec2 lo, pl_vec2 hi, pl_soil_region *out);

/// Makes the current body positions the reference of the consolidation source (call after
/// moving bodies by hand, e.g. set_body_position, so that the jump is not read as a
/// compaction of the skeleton).
pl_status pl_world_soil_reset(pl_world *w);

/// Consolidation statistics: time spent computing the skeleton source (s) and the sum of
/// |source| over the nodes at the last fluid update (m^2/s per m).
pl_status pl_world_soil_stats(const pl_world *w, double *t_source, double *last_source_abs);

/// Copies the nodal volume source -div(v_s) of the last fluid update (weak form, m^2/s per m
/// thickness); returns the number written (0 when FLUID_CONSOLIDATION is off).
int pl_world_soil_copy_source(pl_world *w, double *out, int cap);

#ifdef __cplusplus
}
#endif
#endif
