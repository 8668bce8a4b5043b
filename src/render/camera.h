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

/* v with its spans times zoom about its centre (zoom > 0). */
sw_view sw_view_zoom(sw_view v, double zoom);

struct sw_canvas;
/* Points (xy[2i], xy[2i+1], i < n; keep NULL or keep[i] != 0) that lie
 * outside what the canvas shows are marked at its edge, where the ray from
 * the centre leaves: '<', '>', '^' or 'v' in style. Beside the farthest on
 * each side goes its distance from the centre in world units, when label
 * is set. Non-finite points are skipped (a blow-up is reported elsewhere).
 * Returns how many points were outside. */
int sw_canvas_offscreen(struct sw_canvas *c, const double *xy, int n, const unsigned char *keep, int style,
                        int label);

#endif
