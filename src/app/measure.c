/* What the live app measures, all of it asked of the truth module: the
 * ghost (the true state now), each sim's error, the error at the report time
 * when Δt changes (app/dt_error.c, on a worker when it takes long:
 * app/dt_job.c), and the stability meter. Pure C, no terminal. Invariant:
 * nothing here steps a sim on screen; measurements run on their own sims
 * and on the truth's copy of the system, so reading a number never changes
 * what is shown. */
#include "app/app.h"
#include "app/dt_job.h"
#include "app/sweep.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/stepwise.h"

void sw_app_truth_reset(sw_app *a)
{
    if (a->have_truth)
        sw_truth_free(&a->truth);
    a->have_truth = 0;
    a->have_spec = 0;
    a->meter.ok = 0;
    a->meter.method = NULL;
    sw_dt_job_cancel(a->dt_job, NULL); /* it measured the old scene: its cache goes with it */
    a->dt_job = NULL;
    sw_dt_cache_free(&a->dt_cache);
    char err[SW_ERRLEN];
    a->truth_live = 0;
    sw_spectrum_job_free(&a->spec_job); /* its blocks were in the old truth's system */
    if (!a->scene) { /* the app is being freed */
        sw_truth_work_free(a->meter_work);
        a->meter_work = NULL;
        return;
    }
    if (!a->meter_work)
        a->meter_work = sw_truth_work_new();
    if (a->scene && sw_truth_init(&a->truth, a->scene, a->p, err, sizeof err) == SW_OK) {
        a->have_truth = 1;
        /* a reference run follows the run on screen only where it keeps up */
        a->truth_cost = sw_truth_reference_cost(&a->truth, a->scene->duration);
        a->truth_live = a->truth_cost / a->scene->duration <= SW_WORK_LIVE_PER_S;
    }
}

/* Why the ghost or the error is missing, for messages. */
const char *sw_app_truth_why(const sw_app *a, char *buf, size_t len)
{
    if (!a->have_truth)
        snprintf(buf, len, "no truth for this scene");
    else if (a->truth.source == SW_TRUTH_NONE)
        snprintf(buf, len, "%s", a->truth.why);
    else if (!a->truth_live)
        snprintf(buf, len, "a reference run for these parameters would cost %.2g state evaluations per "
                 "simulated second, more than the %.0e a live run may spend", a->truth_cost / a->scene->duration,
                 SW_WORK_LIVE_PER_S);
    else
        buf[0] = '\0';
    return buf;
}

const double *sw_app_ghost(sw_app *a)
{
    return a->have_truth && a->truth_live ? sw_truth_at(&a->truth, a->sims[0].t) : NULL;
}

double sw_app_error(sw_app *a, int i)
{
    const sw_sim *s = &a->sims[i];
    const double *g = s->blown || !a->have_truth || !a->truth_live ? NULL : sw_truth_at(&a->truth, s->t);
    return g ? sw_dt_state_error(s->sys.ode->dim, s->sys.ode->order, s->sys.y, g, a->err_velocity) : NAN;
}

/* What the measurement of method m from old_dt to dt reads, copied from
 * the app now (app/dt_error.h). */
static void dt_in(const sw_app *a, const sw_integrator *m, double old_dt, double dt, sw_dt_in *in)
{
    memset(in, 0, sizeof *in);
    in->sc = a->scene;
    memcpy(in->p, a->p, sizeof in->p);
    in->events = a->events;
    in->m = m;
    in->old_dt = old_dt;
    in->dt = dt;
    in->work_key = a->work_key;
    in->step_work = sw_truth_step_work(&a->sims[0].sys, m);
    in->dim = a->sims[0].sys.ode->dim;
    in->order = a->sims[0].sys.ode->order;
    in->have_truth = a->have_truth;
    in->truth_cost = a->truth_cost;
    sw_app_truth_why(a, in->truth_why, sizeof in->truth_why);
}

/* Whether the measurement goes to a worker: it may spend more than a
 * frame's share (a->work_inline) and no plugin is loaded (a plugin's host
 * answers one thread). */
static int dt_on_worker(const sw_app *a, const sw_dt_in *in)
{
    return !sw_sweep_inline() && sw_dt_change_work(in, &a->dt_cache) > a->work_inline;
}

double sw_app_measure(sw_app *a, const sw_integrator *m, double dt)
{
    sw_dt_in in;
    sw_app_dt_wait(a); /* the cache is the worker's while it runs */
    dt_in(a, m, a->dt, a->dt, &in);
    return sw_dt_error(&in, &a->dt_cache, m, dt);
}

void sw_app_dt_poll(sw_app *a)
{
    sw_dt_result r;
    if (!a->dt_job || !sw_dt_job_poll(a->dt_job, &r, &a->dt_cache))
        return;
    a->dt_job = NULL;
    if (r.stopped)
        return;
    a->meas_err[0] = r.err[0];
    a->meas_err[1] = r.err[1];
    a->nmeas = 2;
    a->error_ratio = r.error_ratio;
    snprintf(a->message, sizeof a->message, "%s", r.message);
}

void sw_app_dt_wait(sw_app *a)
{
    if (a->dt_job)
        sw_dt_job_wait(a->dt_job);
    sw_app_dt_poll(a);
}

void sw_app_dt_cancel(sw_app *a)
{
    sw_dt_job_cancel(a->dt_job, &a->dt_cache);
    a->dt_job = NULL;
}

void sw_app_measure_dt_change(sw_app *a, double old_dt)
{
    const sw_integrator *m = a->sims[0].method;
    sw_dt_in in;
    char err[SW_ERRLEN];
    sw_app_dt_cancel(a);
    dt_in(a, m, old_dt, a->dt, &in);
    a->meas_method[0] = a->meas_method[1] = m;
    a->meas_dt[0] = old_dt;
    a->meas_dt[1] = a->dt;
    a->meas_err[0] = a->meas_err[1] = NAN;
    a->nmeas = 0;
    a->error_ratio = NAN;
    int worker = dt_on_worker(a, &in);
    if (!(a->dt_job = sw_dt_job_start(&in, &a->dt_cache, !worker, err, sizeof err))) {
        snprintf(a->message, sizeof a->message, "dt=%g: no error measured: %s", a->dt, err);
        return;
    }
    if (!worker) {
        sw_app_dt_poll(a); /* done already */
        return;
    }
    snprintf(a->message, sizeof a->message, "dt=%g: " SW_APP_MEASURING " to t=%.3g in the background; the "
             "figures show here when done", a->dt, old_dt, a->dt, a->scene->duration);
}

const char *sw_app_key_notice(const sw_app *a, int key, int in_lesson)
{
    const sw_control *c;
    int arg;
    if (!sw_key_lookup(key, sw_key_contexts(a->panel, in_lesson), &c, &arg))
        return NULL;
    switch (c->action) {
    case SW_ACT_WORKPREC:
        /* on a worker thread the picture runs on: nothing to announce */
        return !a->workprec && !a->bench && !a->sweep && sw_sweep_inline()
                   ? "measuring every method for the work-precision plot..." : NULL;
    case SW_ACT_DT_HALVE:
    case SW_ACT_DT_DOUBLE: {
        /* on a worker when it takes long: the picture runs on, the message says so */
        sw_dt_in in;
        dt_in(a, a->sims[0].method, a->dt, c->action == SW_ACT_DT_HALVE ? a->dt / 2 : a->dt * 2, &in);
        return dt_on_worker(a, &in) ? NULL : "measuring the error at the old and the new dt...";
    }
    case SW_ACT_UNTIL:
        return a->until > 0 ? "running to the stop time..." : NULL;
    /* the rest answer at once */
    case SW_ACT_NEXT_METHOD: case SW_ACT_PREV_METHOD: case SW_ACT_PICK_METHOD: case SW_ACT_PAUSE:
    case SW_ACT_STEP: case SW_ACT_BACK: case SW_ACT_BACK_MANY: case SW_ACT_RESET: case SW_ACT_SLOWER:
    case SW_ACT_FASTER: case SW_ACT_COMPARE: case SW_ACT_GHOST: case SW_ACT_TRAILS: case SW_ACT_GRAPH:
    case SW_ACT_ERROR_KIND: case SW_ACT_BRAILLE: case SW_ACT_PANEL: case SW_ACT_RECORD: case SW_ACT_ZOOM_OUT:
    case SW_ACT_ZOOM_IN: case SW_ACT_FOLLOW: case SW_ACT_LANES: case SW_ACT_PHASE: case SW_ACT_PHASE_COORD:
    case SW_ACT_PHASE_PREV: case SW_ACT_PHASE_NEXT: case SW_ACT_REGION: case SW_ACT_STAGES:
    case SW_ACT_STAGES_CLOSE: case SW_ACT_EVENTS: case SW_ACT_HELP: case SW_ACT_QUIT:
    SW_LESSON_CASES
    SW_PANEL_CASES
    case SW_ACT_NONE:
    case SW_ACT_COUNT:
        return NULL;
    }
    return NULL;
}

/* The limit with the damping of every oscillating mode taken away (λ, μ =
 * ±i|λ|): what a lesson's closed form for the undamped oscillator gives
 * (RK4's 2√2). 0 when no mode is damped or it rounds to the same 3 digits
 * as the limit shown. */
static double undamped_limit(sw_app *a, const sw_integrator *m, double limit)
{
    static sw_spectrum sp; /* large: kept off the stack; the meter runs on the picture's thread alone */
    sp = a->spec;
    int damped = 0;
    for (int k = 0; k < sp.n; k++) {
        sw_mode *md = &sp.mode[k];
        if (md->im == 0 || md->re == 0)
            continue;
        double w = hypot(md->re, md->im); /* |λ| kept: the same stiffness, no damping */
        md->pre = 0; /* μ is λ's conjugate */
        md->pim = md->im > 0 ? -w : w;
        md->re = 0;
        md->im = md->im > 0 ? w : -w;
        damped = 1;
    }
    if (!damped || !(limit > 0))
        return 0;
    int unbounded;
    double u = sw_truth_limit_with(a->meter_work, m, &sp, SW_DT_MAX, &unbounded);
    char shown[32], und[32];
    snprintf(shown, sizeof shown, "%.3g", a->spec.largest * limit);
    snprintf(und, sizeof und, "%.3g", sp.largest * u);
    return unbounded || !(u > 0) || strcmp(shown, und) == 0 ? 0 : u;
}

int sw_app_stability(sw_app *a, sw_app_meter *out)
{
    const sw_sim *s = &a->sims[0];
    sw_app_meter *m = &a->meter;
    if (!a->have_truth || !a->meter_work || (s->method->flags & SW_ADAPTIVE) || s->blown) {
        m->ok = 0;
        *out = *m;
        return 0;
    }
    sw_app_meter_refresh(a);
    if (m->method != s->method || m->dt != a->dt) {
        memset(m, 0, sizeof *m);
        m->method = s->method;
        m->dt = a->dt;
        m->t = a->spec_t;
        if (a->have_spec) {
            m->stiff = a->spec.largest;
            m->complete = a->spec.complete;
            m->growing = a->spec.growing;
            int worst = -1;
            m->growth = sw_truth_growth_with(a->meter_work, s->method, &a->spec, a->dt, &worst);
            m->growth_lambda = worst >= 0 ? hypot(a->spec.mode[worst].re, a->spec.mode[worst].im) : NAN;
            /* the stiffest mode alone (modes are kept stiffest first) */
            sw_spectrum fast = a->spec;
            fast.n = fast.n > 0 ? 1 : 0;
            m->fast_growth = fast.n ? sw_truth_growth_with(a->meter_work, s->method, &fast, a->dt, NULL) : NAN;
            m->horizon = sw_truth_horizon(a->scene, a->spec.largest);
            m->grows = sw_truth_growth_visible(m->growth, a->dt, m->horizon) || isnan(m->growth);
            /* a change too small to see over the horizon (under 1%): "slowly" */
            int faint = !((m->horizon / a->dt) * log(m->growth) < log(0.99));
            m->slow = m->grows ? 0 : m->growth > 1 + SW_TRUTH_NEUTRAL ? 1
                    : m->growth < 1 - SW_TRUTH_NEUTRAL && faint ? -1 : 0;
            m->limit = sw_truth_limit_with(a->meter_work, s->method, &a->spec, SW_DT_MAX, &m->unbounded);
            m->limit_undamped = undamped_limit(a, s->method, m->limit);
            m->ok = isfinite(m->growth);
        }
    }
    *out = *m;
    return m->ok;
}

void sw_app_watch_restart(sw_app *a)
{
    const sw_sim *s = &a->sims[0];
    sw_watch_start(&a->watch, a->scene->duration, s);
    a->watch.t0 = s->t;
    char why[SW_ERRLEN];
    a->watch_m0 = a->have_truth && sw_watch_judges(s, why, sizeof why) ? sw_watch_measure(s, a->truth.sys.y) : NAN;
}

void sw_app_watch_feed(sw_app *a)
{
    const sw_sim *s = &a->sims[0];
    if (!(a->watch_m0 > 0) || s->blown)
        return;
    sw_watch_add(&a->watch, s->t, sw_watch_measure(s, a->truth.sys.y) / a->watch_m0);
}
