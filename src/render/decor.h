/* What a scene's text says is there but its particles do not show: a flow's
 * direction as a faint field of arrows, the river's rock, the projectile's
 * ground. Drawn under the particles. */
#ifndef SW_RENDER_DECOR_H
#define SW_RENDER_DECOR_H

#include "render/canvas.h"
#include "stepwise/scene.h"

/* The scene's fixed features (the rock, the ground) and, for a flow, its
 * field at time t as arrows every few cells (unicode: arrows in 8
 * directions, else '<' '>' '^' 'v'), faint, left out where the flow is
 * slower than a twentieth of its fastest (the whirls' centres). */
void sw_canvas_draw_decor(sw_canvas *c, const sw_system *sys, double t, int unicode);

#endif
