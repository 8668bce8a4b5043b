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

/* Each drawn method's update in the lecture's EulerStep style: the
 * statements of one step, y the state, f its derivative. */
static const sw_stage_script scripts[] = {
    { "euler", { "k1 = f(t, y)", "y = y + h*k1", "t = t + h" },
      { { 0, 0, SW_STAGE_SLOPE, "k1", "k1: the slope where the step starts" },
        { 1, 0, SW_STAGE_SUM, "y1", "y1: Euler follows k1 for the whole step" } }, 2 },
    { "midpoint", { "k1 = f(t, y)", "k2 = f(t + h/2, y + h/2*k1)", "y = y + h*k2", "t = t + h" },
      { { 0, 0, SW_STAGE_SLOPE, "k1", "k1: the slope at the start" },
        { 1, 1, SW_STAGE_SLOPE, "k2", "k2: the slope half a step along k1" },
        { 2, 0, SW_STAGE_SUM, "y1", "y1: the whole step on the middle's slope k2" } }, 3 },
    { "heun", { "k1 = f(t, y)", "k2 = f(t + h, y + h*k1)", "y = y + h/2*(k1 + k2)", "t = t + h" },
      { { 0, 0, SW_STAGE_SLOPE, "k1", "k1: the predictor's slope, at the start" },
        { 1, 1, SW_STAGE_SLOPE, "k2", "k2: the corrector's slope, at the end of an Euler step" },
        { 2, 0, SW_STAGE_SUM, "y1", "y1: the step on the average of k1 and k2" } }, 3 },
    { "rk4", { "k1 = f(t, y)", "k2 = f(t + h/2, y + h/2*k1)", "k3 = f(t + h/2, y + h/2*k2)",
               "k4 = f(t + h, y + h*k3)", "y = y + h/6*(k1+2*k2+2*k3+k4)", "t = t + h" },
      { { 0, 0, SW_STAGE_SLOPE, "k1", "k1: the slope at the start" },
        { 1, 1, SW_STAGE_SLOPE, "k2", "k2: the slope half a step along k1" },
        { 2, 2, SW_STAGE_SLOPE, "k3", "k3: the slope half a step along k2" },
        { 3, 3, SW_STAGE_SLOPE, "k4", "k4: the slope a whole step along k3" },
        { 4, 0, SW_STAGE_SUM, "y1", "y1: the weighted sum, weights 1 2 2 1 over 6" } }, 5 },
    { "symplectic-euler", { "a = a(x, v)", "v = v + h*a", "x = x + h*v", "t = t + h" },
      { { 1, 0, SW_STAGE_KICK, "v1", "kick: v changes by h*a, taken at the old x (dim: before)" },
        { 2, 0, SW_STAGE_DRIFT, "x1", "drift: x moves a step with the new v" } }, 2 },
    { "verlet", { "v = v + h/2*a   (a: last step's)", "x = x + h*v", "a = a(x, v)", "v = v + h/2*a", "t = t + h" },
      { { 0, 0, SW_STAGE_KICK, "v'", "half kick: v changes by h/2*a (dim: v before)" },
        { 1, 0, SW_STAGE_DRIFT, "x1", "drift: x moves a whole step with the half-kicked v" },
        { 3, 1, SW_STAGE_KICK_END, "v1", "a at the new x, then the second half kick" } }, 3 },
};

const sw_stage_script *sw_stage_script_of(const sw_integrator *m)
{
    char why[SW_ERRLEN];
    if (!m || !sw_stages_supported(m, why, sizeof why))
        return NULL;
    for (size_t i = 0; i < sizeof scripts / sizeof scripts[0]; i++)
        if (strcmp(scripts[i].method, m->name) == 0)
            return &scripts[i];
    return NULL;
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
