/* The stage view's model (see stages.h). Invariant: what is shown is the
 * main run's next step as sim/stages.c recorded it from the run's state
 * now; the run stays paused while the view is open. */
#include "app/stages.h"

#include <stdio.h>
#include <string.h>

#include "stepwise/stepwise.h"

/* Largest state the true path is worked out for (vortex n = 10000: 0.007 s;
 * n = 200000: 0.41 s, measured with -O2 on this machine). */
#define SW_STAGES_TRUE_DIM 20000

const sw_stage_script *sw_stage_script_of(const sw_integrator *m)
{
    return m ? m->lecture : NULL;
}

/* What the message line says about the stage shown. */
static void say(sw_app *a)
{
    const sw_stage_script *sc = sw_stage_script_of(a->sims[0].method);
    if (!sc) {
        snprintf(a->message, sizeof a->message, "%s (Esc closes)", a->stages_why);
        return;
    }
    const sw_stage_view *v = &sc->views[a->stage_shown - 1];
    snprintf(a->message, sizeof a->message, "%s  [%d of %d: k %s, Esc closes]", v->caption, a->stage_shown,
             sc->nviews, a->stage_shown < sc->nviews ? "next" : "closes");
}

void sw_app_stages_close(sw_app *a)
{
    a->stages_open = 0;
    a->stage_shown = 0;
}

int sw_app_stages_apply(sw_app *a, sw_action act)
{
    if (act == SW_ACT_STAGES_CLOSE) {
        if (!a->stages_open)
            return 0;
        sw_app_stages_close(a);
        snprintf(a->message, sizeof a->message, "stage view closed");
        return 1;
    }
    const sw_stage_script *sc = sw_stage_script_of(a->sims[0].method);
    if (!a->stages_open) {
        if (!sw_app_stages(a)) { /* one line: why not, and nothing opens */
            snprintf(a->message, sizeof a->message, "%s", a->stages_why);
            return 0;
        }
        a->stages_open = 1;
        a->stage_shown = 1;
        a->paused = 1;
        sw_app_set_view(a, SW_VIEW_SCENE); /* the stages are drawn on the scene */
    } else if (!sc || a->stage_shown >= sc->nviews) {
        sw_app_stages_close(a);
        snprintf(a->message, sizeof a->message, "stage view closed (k opens it on the next step)");
        return 1;
    } else
        a->stage_shown++;
    say(a);
    return 1;
}

const sw_stages *sw_app_stages(sw_app *a)
{
    const sw_sim *s = &a->sims[0];
    sw_stages *r = &a->stages;
    /* the same step as recorded: the method, t, dt and the state all unchanged */
    if (r->method == s->method && r->t0 == s->t && r->h == s->dt && r->dim == s->sys.ode->dim &&
        memcmp(r->y0, s->sys.y, (size_t)r->dim * sizeof *r->y0) == 0)
        return r;
    if (sw_stages_record(r, s, a->stages_why, sizeof a->stages_why) != SW_OK)
        return NULL;
    a->stages_why[0] = '\0';
    /* where the step should land: the true path over it (a reference run of
     * the whole system: left out past SW_STAGES_TRUE_DIM, where it would
     * take a good part of a second on every step) */
    if (a->have_truth && r->dim <= SW_STAGES_TRUE_DIM)
        sw_stages_true_path(r, s);
    if (a->stage_shown > 0) { /* the script may be shorter under a new method */
        const sw_stage_script *sc = sw_stage_script_of(s->method);
        if (sc && a->stage_shown > sc->nviews)
            a->stage_shown = sc->nviews;
    }
    return r;
}
