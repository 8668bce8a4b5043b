/* A small difference made visible at any size: where a run and the ghost
 * (or two runs) fall in one cell, and how far apart they are. */
#ifndef SW_RENDER_GAP_H
#define SW_RENDER_GAP_H

#include "render/canvas.h"
#include "stepwise/scene.h"

/* The glyph of a cell where two runs (or a run and the ghost) are both. */
#define SW_GLYPH_BOTH '&'
/* Systems with more particles than this get no cell-sharing marks (a
 * dense cloud, where every cell is shared), and more than SW_GAP_LABEL_MAX
 * no gap label. The lessons' clouds (200 points) get them: "the computed
 * dots sit on the ghost" must be seen, not read. */
#define SW_GAP_MARK_MAX 1000
#define SW_GAP_LABEL_MAX 16

/* After both were drawn: each particle of sys whose positions in y (the
 * run) and other (the ghost or another run, the same layout) fall in one
 * cell of c gets SW_GLYPH_BOTH in style. With label (e.g. "ghost") the
 * particle furthest from its counterpart gets the distance with its unit
 * beside its marker ("ghost 0.44 m"), on blank cells right, left, above or
 * below it, in the longest form that fits ("gap to ghost 0.44 m", "ghost
 * 0.44 m", "0.44 m"), unless they are exactly together (t = 0). Returns
 * the distance labelled (NaN: none). */
double sw_canvas_draw_gap(sw_canvas *c, const sw_system *sys, const double *y, const double *other, double t,
                          const char *label, int style);

#endif
