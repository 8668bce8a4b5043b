/* The stage view: one step of the main run drawn stage by stage on the
 * picture (each stage's point and its slope as an arrow h·k long), zoomed
 * on the step, with the method's update formula beside it, the current
 * line lit. */
#ifndef SW_RENDER_STAGES_H
#define SW_RENDER_STAGES_H

#include "render/screen.h"

/* Draw the stage view of a (a->stages_open) in the rectangle given, on
 * f's main canvas. Returns the number of stage arrows drawn (slopes,
 * kicks and the step itself), 0 when the method's stages are not drawn
 * (the rectangle then says why in one line). */
int sw_draw_stages(sw_frame *f, sw_app *a, sw_screen *scr, int row0, int col0, int rows, int cols);

#endif
