/* Scene drawing onto a canvas: what a built system looks like. */
#ifndef SW_RENDER_DRAW_H
#define SW_RENDER_DRAW_H

#include <stdint.h>

#include "render/canvas.h"
#include "stepwise/scene.h"

/* Draw a built system at state y (the sim's y, or the exact state for the
 * ghost) and time t: walls (floor/ceiling '=', sides '|', style WALL), the
 * central body 'O' (WALL), springs, anchors '#' (WALL), then the particles
 * alive at t (sys->scene->alive, NULL: all) with glyph (0: 'o') and style.
 * Springs use slope glyphs and style SPRING when style is SW_STYLE_MAIN,
 * else '.' and the caller's style. Many points (n > cols·rows/4) are drawn
 * as a density pass in ASCII mode (the main glyph only: a ghost or a
 * compared run keeps its glyph) and as dots in Braille mode; flow scenes
 * in Braille mode are always dots; otherwise each particle is a marker. */
void sw_canvas_draw_system(sw_canvas *c, const sw_system *sys, const double *y, double t,
                           uint32_t glyph, int style);

#endif
