/* The camera: a view that follows the particles, growing in jumps (never
 * shrinking) so the picture does not swim, and ignoring a blow-up. */
#include "render/camera.h"

#include <math.h>
#include <stdio.h>

#include "render/canvas.h"

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

sw_view sw_view_zoom(sw_view v, double zoom)
{
    double cx = (v.xmin + v.xmax) / 2, cy = (v.ymin + v.ymax) / 2;
    double hx = (v.xmax - v.xmin) / 2 * zoom, hy = (v.ymax - v.ymin) / 2 * zoom;
    return (sw_view){ cx - hx, cx + hx, cy - hy, cy + hy };
}

/* Where the ray from the canvas centre to (x, y) leaves the cell grid:
 * the edge cell and the side (0 left, 1 right, 2 bottom, 3 top). */
static int edge_cell(const sw_canvas *c, double x, double y, int *col, int *row)
{
    /* in cell units from the centre, rows growing downwards */
    double u = (x - c->cx) / c->scale, w = -(y - c->cy) / (2 * c->scale);
    double hu = c->cols / 2.0 - 0.5, hw = c->rows / 2.0 - 0.5;
    double f = fmin(fabs(u) > 0 ? hu / fabs(u) : INFINITY, fabs(w) > 0 ? hw / fabs(w) : INFINITY);
    int side = hu / fmax(fabs(u), 1e-300) <= hw / fmax(fabs(w), 1e-300) ? (u < 0 ? 0 : 1) : (w > 0 ? 2 : 3);
    *col = (int)floor(c->cols / 2.0 + u * f);
    *row = (int)floor(c->rows / 2.0 + w * f);
    *col = *col < 0 ? 0 : *col >= c->cols ? c->cols - 1 : *col;
    *row = *row < 0 ? 0 : *row >= c->rows ? c->rows - 1 : *row;
    return side;
}

int sw_canvas_offscreen(sw_canvas *c, const double *xy, int n, const unsigned char *keep, int style, int label)
{
    static const uint32_t arrow[4] = { '<', '>', 'v', '^' };
    sw_view vis = sw_canvas_visible(c);
    double far[4] = { -1, -1, -1, -1 };
    int far_col[4] = { 0 }, far_row[4] = { 0 }, out = 0;
    for (int i = 0; i < n; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        if ((keep && !keep[i]) || !isfinite(x) || !isfinite(y))
            continue;
        if (x >= vis.xmin && x < vis.xmax && y > vis.ymin && y <= vis.ymax)
            continue;
        int col, row, side = edge_cell(c, x, y, &col, &row);
        sw_canvas_put(c, col, row, arrow[side], style);
        out++;
        double d = hypot(x - c->cx, y - c->cy);
        if (d > far[side]) {
            far[side] = d;
            far_col[side] = col;
            far_row[side] = row;
        }
    }
    for (int side = 0; label && side < 4; side++) {
        if (far[side] < 0)
            continue;
        char text[24];
        int len = snprintf(text, sizeof text, "%.3g", far[side]);
        /* beside the arrow, inwards: right of a left arrow, left of a right
         * one, beside (and inside) a bottom or top arrow */
        int col = side == 0 ? far_col[side] + 1 : side == 1 ? far_col[side] - len : far_col[side] + 1;
        if (col + len > c->cols)
            col = far_col[side] - len;
        if (col < 0)
            col = 0;
        sw_canvas_text(c, col, far_row[side], text, style);
    }
    return out;
}
