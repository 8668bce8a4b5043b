/* The lesson pane drawn into its cells: titles fixed at the top, the
 * text scrolled, what the page asks (goals, question) kept at its foot. */
#ifndef SW_RENDER_SIDE_H
#define SW_RENDER_SIDE_H

#include "render/screen.h"

/* Draws `side` into rows row..row+height-1, columns col..col+width-1;
 * updates *side->scroll (clamped) and *side->step (what a press moves). */
void sw_side_draw(const sw_side *side, sw_screen *scr, int row, int col, int height, int width);

#endif
