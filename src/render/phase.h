/* The phase view: a coordinate against its velocity for the chosen
 * particle, one path per method on screen, the exact orbit as the ghost
 * (the closed form sampled over the run, or the reference run's path), on
 * a frame fixed by the true motion so that growth looks like growth. */
#ifndef SW_RENDER_PHASE_H
#define SW_RENDER_PHASE_H

#include "app/app.h"
#include "render/canvas.h"

#define SW_PHASE_EXACT 1024     /* samples of the exact orbit */

typedef struct sw_phase_view {
    /* the exact orbit over [0, cover], cached for this scene, parameters and coordinate */
    const sw_scene *scene;
    double p[SW_MAX_PARAMS];
    int particle;
    sw_phase_coord coord;
    double cover;
    double q[SW_PHASE_EXACT], v[SW_PHASE_EXACT];
    int n;
    double *state;              /* one state of the truth's system (grown as needed) */
    int state_dim;
    /* the plot's range: the true motion's box (or the run's, grown) */
    double qmin, qmax, vmin, vmax;
    int have_range;
} sw_phase_view;

void sw_phase_view_free(sw_phase_view *ph);
/* Draw the view of app a onto canvas c (sized by the caller). Returns the
 * number of sims whose path left the frame (marked at its edge). */
int sw_phase_draw(sw_phase_view *ph, sw_canvas *c, sw_app *a, int unicode);
/* The glyph run i's path is drawn with in ASCII ('.' for the main run,
 * whose present point is its own glyph), for the legend to show. */
uint32_t sw_phase_path_glyph(int i);
/* The range shown (after a draw): q from *q0 to *q1, v from *v0 to *v1. */
void sw_phase_range(const sw_phase_view *ph, const sw_app *a, double *q0, double *q1, double *v0, double *v1);

#endif
