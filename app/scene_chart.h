/* porelab.chart{...} for scenes: XY charts of recorded series (PLplot, render/charts.h). */
#ifndef PL_APP_SCENE_CHART_H
#define PL_APP_SCENE_CHART_H
#include "scene.h"

/* Adds porelab.chart to the scene's Lua state; call after pl_scene_create, before
   pl_scene_load. */
void pl_scene_register_chart(pl_scene *s);

#endif
