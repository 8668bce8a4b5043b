/* The camera: the part of the world the scene pane shows. */
#ifndef SW_RENDER_CAMERA_H
#define SW_RENDER_CAMERA_H

#include "stepwise/scene.h"

/* Grow *v so it contains every point (xy[2i], xy[2i+1]), i < n: a side moves
 * only when a point lies beyond it, and then past the farthest such point by
 * margin × the view's span on that axis (margin in [0, 10]), so a particle
 * leaving slowly moves the view in jumps rather than every frame. The view
 * never shrinks. Non-finite points, and points farther than 1000 spans from
 * the view's centre (a blow-up, which the sim reports), are ignored. Returns
 * 1 when v changed, else 0. */
int sw_view_follow(sw_view *v, const double *xy, int n, double margin);

#endif
