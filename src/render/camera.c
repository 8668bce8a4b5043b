/* The camera: a view that follows the particles, growing in jumps (never
 * shrinking) so the picture does not swim, and ignoring a blow-up. */
#include "render/camera.h"

#include <math.h>

int sw_view_follow(sw_view *v, const double *xy, int n, double margin)
{
    double sx = v->xmax - v->xmin, sy = v->ymax - v->ymin;
    if (!(sx > 0 && sy > 0 && isfinite(sx) && isfinite(sy)))
        return 0;
    if (!(margin >= 0.0))
        margin = 0.0;
    if (margin > 10.0)
        margin = 10.0;
    double cx = v->xmin + sx / 2.0, cy = v->ymin + sy / 2.0;
    double lox = INFINITY, hix = -INFINITY, loy = INFINITY, hiy = -INFINITY;
    for (int i = 0; i < n; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        /* also false for NaN and ±inf; x - cx may overflow to inf, which fails too */
        if (!(fabs(x - cx) <= 1000.0 * sx && fabs(y - cy) <= 1000.0 * sy))
            continue;
        lox = fmin(lox, x);
        hix = fmax(hix, x);
        loy = fmin(loy, y);
        hiy = fmax(hiy, y);
    }
    int changed = 0;
    if (lox < v->xmin)
        v->xmin = lox - margin * sx, changed = 1;
    if (hix > v->xmax)
        v->xmax = hix + margin * sx, changed = 1;
    if (loy < v->ymin)
        v->ymin = loy - margin * sy, changed = 1;
    if (hiy > v->ymax)
        v->ymax = hiy + margin * sy, changed = 1;
    return changed;
}
