/* The scene picture's legend: one line under it saying what each glyph
 * drawn means (the runs, a crowd's ramp, the ghost, anchors, springs,
 * walls, trails, the flow's arrows, marks past the edge), read from the
 * canvas itself, so it names only what is on screen. */
#ifndef SW_RENDER_LEGEND_H
#define SW_RENDER_LEGEND_H

#include "app/app.h"
#include "render/canvas.h"

/* The legend of the ncs canvases cs (the scene of app a drawn on them:
 * one, or a lane per run, whose titles name the runs) as fields, each with its priority, into f (room
 * for max); returns how many. */
int sw_scene_legend(const sw_canvas *const *cs, int ncs, const sw_app *a, sw_field *f, int max);

#endif
