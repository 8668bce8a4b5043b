/* The stability-region view: where the current method's growth per step on
 * a mode z = Δt·λ is at most one, shaded in the complex plane (Braille dots
 * where the terminal shows them), with the scene's own eigenvalues times Δt
 * marked, so +/- move the marks in and out of the region live. Computed
 * from the method's one-step map through the truth module: plugins get
 * their own region, nothing is sketched. */
#ifndef SW_RENDER_REGION_H
#define SW_RENDER_REGION_H

#include "app/app.h"
#include "render/canvas.h"
#include "sim/truth.h"

/* The shaded grid, cached until the method, the system's order, the size,
 * the mode or the zoom change (a redraw then steps nothing). */
typedef struct sw_region {
    const sw_integrator *method;
    int order, cols, rows, dots;
    double half;               /* the scale shaded for: units of Δt·λ per column */
    double extent;             /* the region's reach for this method and order (0: unbounded) */
    const sw_integrator *extent_method;
    int extent_order;
    unsigned char *stable;     /* per grid point (cells, then dots): 1 stable */
    size_t cap;
    int next;                  /* grid points shaded so far (cells, then cells refined to dots) */
    double progress;           /* the fraction shaded (1: all) */
    sw_truth_work *work;       /* the region's own workspace (the meter keeps its) */
    /* the marks' growths, for this method, dt and spectrum */
    const sw_integrator *marks_method;
    double marks_dt, marks_t;
    int marks_n;
    double marks_rho[SW_TRUTH_MODES];
    /* each mark's edge on its ray (|Δt·λ| where the ray leaves the region,
     * 0: unstable at once, inf: never), asked again when the method or
     * the spectrum change, not Δt (the ray's direction does not) */
    const sw_integrator *edge_method;
    double edge_t;
    int edge_n;
    double edge[2 * SW_TRUTH_MODES];
    /* what the draw leaves for the lines under the picture: the real axis's
     * tick labels, column by column (never over the shading), and the
     * worst mark against its edge on its ray (sw_region_gauge) */
    char ticks[256];
    char gauge[256];
    double ratio;              /* the worst mark's |Δt·λ| over its edge's (NaN: no mark) */
    int ratio_grows;
    double beyond;             /* the farthest mark past the view's edge, |Δt·λ| (0: none) */
    /* the scale, fixed while the view is open on a page: chosen when the
     * view opens, a page is entered or the method changes, not when Δt does */
    double fit;                /* units of Δt·λ per column at zoom 1 */
    double fit_half;           /* the half span it was chosen for (the scale said) */
    unsigned fit_gen;          /* the app's view_gen it was chosen for */
    const sw_integrator *fit_method;
    int fit_order, fit_cols, fit_rows, fit_valid;
} sw_region;

/* How far past its edge on its ray the view chosen for a page holds a
 * mark: a doubling of Δt from inside puts it at most twice as far, and
 * the view (1.25 × this) keeps a row's margin beyond that. */
#define SW_REGION_PAST 1.8

/* The half span the view shows (zoom 1) for a region reaching reach (its
 * default half span) with marks as far as largest = max |Δt·λ| from the
 * origin (or SW_REGION_PAST times their edges on their rays, when
 * farther): the whole region and
 * the marks when the marks are as large as half of it (max(reach, 1.25 ×
 * largest)), else 1.25 × largest, so that the marks fill the view and each
 * halving of Δt moves them visibly (at least reach / 1000; reach when no
 * mark). The view chosen stays for the page, whatever Δt does: a mark
 * that leaves it is an arrow at the edge, and z zooms out. */
double sw_region_scale(double reach, double largest);

/* Seconds a draw may spend shading a plugin's region (each new mode is a
 * fresh sandboxed child, about 10 ms; its grid is two cells wide): it fills
 * in over several seconds while the rest of the screen stays live. */
#define SW_REGION_BUDGET 0.1

/* The edge line's glyph where the region is drawn in characters (Braille
 * draws it as a solid line of dots round a half-toned inside). */
#define SW_REGION_EDGE '#'
/* How many columns a mark may be drawn from its own cell to stay on its
 * side of the edge line (render/region.c, mark_col). */
#define SW_REGION_NUDGE 2

void sw_region_free(sw_region *r);
/* How far the ray from the origin through (ux, uy) stays in method m's
 * region for a system of this order: the largest r with growth <= 1 before
 * the first unstable point (to 1e-9 relative); 0 when unstable at once,
 * INFINITY when stable out to 100 (an implicit method). */
double sw_region_edge_on_ray(sw_truth_work *w, const sw_integrator *m, int order, double ux, double uy);
/* The line under the picture, width columns: "in ::::|--X-- out 5×edge", a
 * mark against its ray's edge on a log scale, the edge in the middle and
 * each halving of the ratio (of Δt) a fixed notch; X when the mark grows,
 * '*' when not; the ratio said at the end ("always out" for an edge at
 * 0, "always in" for an edge never reached: ratio inf or 0). */
void sw_region_gauge(char *out, size_t len, int width, double ratio, int grows);
/* The growth per step of method m at z = x + iy on a mode of a system of
 * this order (x'' = 2x·q' - |z|²q for order 2: roots z and its conjugate),
 * through workspace w; NaN when the step fails. */
double sw_region_growth(sw_truth_work *w, const sw_integrator *m, int order, double x, double y);
/* Draw the view for app a on canvas c (sized by the caller; Braille mode
 * when the canvas is): shading, axes, the marks. *worst gets the largest
 * growth over the marks (NaN: none), *outside how many marks lie outside
 * the shaded region, *shown how many marks were drawn. 0, or -1 with why
 * filled when there is nothing to draw (an adaptive method, no spectrum).
 * r->progress says how much of the region is shaded yet. */
int sw_region_draw(sw_region *r, sw_canvas *c, sw_app *a, double *worst, int *outside, int *shown, char *why,
                   size_t whylen);

#endif
