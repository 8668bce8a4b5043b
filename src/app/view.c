/* What the picture shows and how: the scene, the phase view or the
 * stability region; the camera (fixed on the scene's natural view, zoomed,
 * or following); compare overlaid or in lanes; and the phase paths the
 * phase view draws. Pure C, no drawing: render/ reads these fields. */
#include "app/app.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "stepwise/stepwise.h"

#define ZOOM_MIN (1.0 / 64)
#define ZOOM_MAX 4096.0

void sw_app_phase_clear(sw_app *a)
{
    for (int i = 0; i <= SW_APP_SIMS; i++)
        a->phase[i].head = a->phase[i].count = 0;
}

static void hist_push(sw_phase_hist *h, double t, double q, double v)
{
    h->t[h->head] = t;
    h->q[h->head] = q;
    h->v[h->head] = v;
    h->head = (h->head + 1) % SW_PHASE_HIST;
    if (h->count < SW_PHASE_HIST)
        h->count++;
}

void sw_app_phase_push(sw_app *a)
{
    double q, v;
    const sw_system *sys0 = &a->sims[0].sys;
    if (!sw_phase_available(sys0, a->phase_particle, a->phase_coord))
        sw_phase_default(sys0, &a->phase_particle, &a->phase_coord);
    for (int i = 0; i < a->nsims; i++) {
        const sw_sim *s = &a->sims[i];
        /* a blown-up run's path ends where it was last finite */
        if (!s->blown && sw_phase_point(&s->sys, s->sys.y, a->phase_particle, a->phase_coord, &q, &v))
            hist_push(&a->phase[i], s->t, q, v);
    }
    /* A reference truth is followed along the main run's time only while
     * the phase view shows it (a closed form is drawn whole by render/). */
    if (a->view == SW_VIEW_PHASE && a->have_truth && a->truth.source == SW_TRUTH_REFERENCE) {
        const double *g = sw_app_ghost(a);
        if (g && sw_phase_point(&a->truth.sys, g, a->phase_particle, a->phase_coord, &q, &v))
            hist_push(&a->phase[SW_APP_SIMS], a->sims[0].t, q, v);
    }
}

void sw_app_set_view(sw_app *a, sw_app_view v)
{
    if (v == SW_VIEW_PHASE && a->view != SW_VIEW_PHASE)
        sw_app_phase_clear(a); /* the reference path starts now, with the others */
    if (v != a->view)
        a->view_gen++;
    a->view = v;
}

/* "stretch of particle 1 against its rate" */
static void phase_message(sw_app *a, const char *head)
{
    const char *q, *qu, *v, *vu;
    sw_phase_names(a->phase_coord, &q, &qu, &v, &vu);
    snprintf(a->message, sizeof a->message, "%s%s (%s) of particle %d against %s (%s); V, < and > choose", head,
             q, qu, a->phase_particle + 1, v, vu);
}

int sw_app_zoom(sw_app *a, int out)
{
    double z = out ? a->zoom * 2 : a->zoom / 2;
    if (z < ZOOM_MIN || z > ZOOM_MAX) {
        snprintf(a->message, sizeof a->message, "zoom stays between x%g and x%g", ZOOM_MIN, ZOOM_MAX);
        return 1;
    }
    a->zoom = z;
    snprintf(a->message, sizeof a->message, "view x%g the %s (z out, Z in)", z,
             a->view == SW_VIEW_SCENE ? "scene's" : "natural size");
    return 1;
}

int sw_app_toggle_follow(sw_app *a)
{
    a->follow = !a->follow;
    snprintf(a->message, sizeof a->message, "%s", a->follow ? "camera follows the particles (f: fixed)"
                                                            : "camera fixed on the scene (f: follow)");
    return 1;
}

int sw_app_toggle_lanes(sw_app *a)
{
    a->lanes = !a->lanes;
    snprintf(a->message, sizeof a->message, "%s%s", a->lanes ? "compare side by side" : "compare overlaid",
             a->compare ? "" : " (press c to compare)");
    return 1;
}

int sw_app_toggle_phase(sw_app *a)
{
    const sw_system *sys = &a->sims[0].sys;
    sw_app_set_view(a, a->view == SW_VIEW_PHASE ? SW_VIEW_SCENE : SW_VIEW_PHASE);
    if (a->view == SW_VIEW_PHASE) {
        if (!sw_phase_available(sys, a->phase_particle, a->phase_coord))
            sw_phase_default(sys, &a->phase_particle, &a->phase_coord);
        phase_message(a, "phase view: ");
    } else
        snprintf(a->message, sizeof a->message, "scene view");
    return 1;
}

int sw_app_phase_next(sw_app *a, int how)
{
    sw_phase_cycle(&a->sims[0].sys, &a->phase_particle, &a->phase_coord, how);
    sw_app_phase_clear(a);
    phase_message(a, "");
    return 1;
}

int sw_app_toggle_region(sw_app *a)
{
    sw_app_set_view(a, a->view == SW_VIEW_REGION ? SW_VIEW_SCENE : SW_VIEW_REGION);
    if (a->view == SW_VIEW_REGION)
        snprintf(a->message, sizeof a->message, "stability region of %s: +/- move the marks (dt x eigenvalues)",
                 a->sims[0].method->name);
    else
        snprintf(a->message, sizeof a->message, "scene view");
    return 1;
}
