/* What the live app measures, all of it asked of the truth module: the
 * ghost (the true state now), each sim's error, the error at the report time
 * when Δt changes (and whether its ratio can be read as an order), and the
 * stability meter. Pure C, no terminal. Invariant: nothing here steps a sim
 * on screen; measurements run on their own sims and on the truth's copy of
 * the system, so reading a number never changes what is shown. */
#include "app/app.h"
#include "app/sweep.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "measure/bench.h"
#include "stepwise/stepwise.h"

void sw_app_truth_reset(sw_app *a)
{
    if (a->have_truth)
        sw_truth_free(&a->truth);
    a->have_truth = a->have_truth_report = 0;
    a->have_spec0 = a->have_spec = 0;
    a->meter.ok = 0;
    a->meter.method = NULL;
    free(a->truth_report);
    a->truth_report = NULL;
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

/* The error of state y against truth for system sys: positions (velocity
 * 0) or velocities (1; NaN for a flow, which has none). */
static double sw_app_state_error(const sw_system *sys, const double *y, const double *truth, int velocity)
{
    const sw_ode *ode = sys->ode;
    if (ode->order != 2) /* a flow's state is positions alone */
        return velocity ? NAN : sw_truth_error(ode->dim, y, truth);
    int half = ode->dim / 2; /* y = [x | v] */
    return velocity ? sw_truth_error(half, y + half, truth + half) : sw_truth_error(half, y, truth);
}

double sw_app_error(sw_app *a, int i)
{
    const sw_sim *s = &a->sims[i];
    const double *g = s->blown || !a->have_truth || !a->truth_live ? NULL : sw_truth_at(&a->truth, s->t);
    return g ? sw_app_state_error(&s->sys, s->sys.y, g, a->err_velocity) : NAN;
}

/* The true state at the sample times to the report time (one reference
 * run, marching forward), computed once per scene, within the key-press
 * budget; the last sample is the report time's. */
static const double *truth_report(sw_app *a)
{
    if (!a->have_truth_report && a->have_truth && a->truth_cost <= a->work_key) {
        size_t dim = (size_t)a->truth.sys.ode->dim;
        sw_truth tr;
        char err[SW_ERRLEN];
        if (!a->truth_report) /* kept for the next try when this one finds no truth (fire, water) */
            a->truth_report = malloc(SW_TRUTH_SAMPLES * dim * sizeof *a->truth_report);
        if (a->truth_report && sw_truth_init(&tr, a->scene, a->p, err, sizeof err) == SW_OK) {
            int ok = 1;
            for (int j = 1; j <= SW_TRUTH_SAMPLES && ok; j++) {
                const double *y = sw_truth_at(&tr, sw_truth_sample_time(a->scene->duration, j));
                if (y)
                    memcpy(a->truth_report + (size_t)(j - 1) * dim, y, dim * sizeof *y);
                ok = y != NULL;
            }
            a->have_truth_report = ok;
            sw_truth_free(&tr);
        }
    }
    return a->have_truth_report ? a->truth_report : NULL;
}

/* The state's scale at the report time, for "the error is N% of the motion". */
static double report_scale(sw_app *a)
{
    const double *want = truth_report(a);
    size_t dim = (size_t)a->sims[0].sys.ode->dim;
    size_t npos = a->sims[0].sys.ode->order == 2 ? dim / 2 : dim; /* positions: y = [x | v] */
    double scale = 1e-300;
    for (size_t j = 0; want && j < SW_TRUTH_SAMPLES; j++)
        for (size_t k = 0; k < npos; k++)
            scale = fmax(scale, fabs(want[j * dim + k]));
    return scale;
}

double sw_app_measure(sw_app *a, const sw_integrator *m, double dt)
{
    const sw_scene *sc = a->scene;
    double T = sc->duration;
    int dim = a->sims[0].sys.ode->dim;
    if (!(dt > 0) || (T / dt) * sw_truth_step_work(&a->sims[0].sys, m) > a->work_key)
        return NAN;
    const double *want = truth_report(a);
    if (!want)
        return NAN;
    sw_sim s;
    char err[SW_ERRLEN];
    double e = NAN;
    if (sw_sim_init(&s, sc, a->p, m, dt, err, sizeof err) == SW_OK) {
        /* the run on screen's event mode: located events keep the order */
        if (sw_sim_set_events(&s, a->events, err, sizeof err) != SW_OK) {
            sw_sim_free(&s);
            return NAN;
        }
        /* the largest error over the samples (SW_TRUTH_SAMPLES): one report
         * time can be special, a whole run is not */
        int first = (m->flags & SW_ADAPTIVE) ? 1 : sw_truth_first_sample(T, dt);
        e = 0;
        for (int j = first; j <= SW_TRUTH_SAMPLES && !isnan(e); j++) {
            double t = sw_truth_sample_time(T, j);
            if (sw_sim_run_until(&s, t) != 0 || fabs(s.t - t) > 1e-9 * fmax(1.0, T)) {
                e = NAN;
                break;
            }
            double ej = sw_app_state_error(&s.sys, s.sys.y, want + (size_t)(j - 1) * (size_t)dim, 0);
            if (!(ej <= e))
                e = ej;
        }
        sw_sim_free(&s);
    }
    return e;
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
    case SW_ACT_DT_DOUBLE:
        return "measuring the error at the old and the new dt...";
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

/* The spectrum at the start (for the dt-change check), once per scene. */
static const sw_spectrum *spectrum0(sw_app *a)
{
    if (!a->have_spec0 && a->have_truth && a->meter_work)
    {
        a->have_spec0 = sw_truth_spectrum_with(a->meter_work, &a->truth.sys, 0.0, a->truth.sys.y, &a->spec0) == 0;
        a->spec_job.active = 0; /* that assembled the truth's Jacobian at the start: the job starts again */
    }
    return a->have_spec0 ? &a->spec0 : NULL;
}

/* How much the method's worst mode grows over a run to the report time at
 * dt: ρ^(T/dt); NaN when unknown (adaptive, no spectrum). */
static double run_growth(sw_app *a, const sw_integrator *m, double dt, double *rho)
{
    const sw_spectrum *sp = spectrum0(a);
    *rho = sp ? sw_truth_growth_with(a->meter_work, m, sp, dt, NULL) : NAN;
    return pow(*rho, a->scene->duration / dt);
}

/* A symplectic method's large position error is mostly phase: it keeps
 * the energy and the path's shape, and runs ahead of or behind the truth
 * along it (lesson 8). */
/* Errors below this fraction of the motion are rounding (some 1e5 units
 * in the last place, summed over thousands of steps), never an order. */
#define SW_APP_ROUNDING 1e-11

/* The message fits errors up to half the motion (larger ones get "the
 * error is N% of the motion" above): the order rule's ceiling here. */
#define SW_APP_CEILING 0.5

#define PHASE_NOTE ". Symplectic: energy and path kept, the error is phase"

void sw_app_measure_dt_change(sw_app *a, double old_dt)
{
    const sw_integrator *m = a->sims[0].method;
    double e_old = sw_app_measure(a, m, old_dt), e_new = sw_app_measure(a, m, a->dt);
    a->meas_method[0] = a->meas_method[1] = m;
    a->meas_dt[0] = old_dt;
    a->meas_err[0] = e_old;
    a->meas_dt[1] = a->dt;
    a->meas_err[1] = e_new;
    a->nmeas = 2;
    double big_dt = fmax(old_dt, a->dt);
    double big = old_dt > a->dt ? e_old : e_new, small = old_dt > a->dt ? e_new : e_old;
    double ratio = big / small, T = a->scene->duration;
    a->error_ratio = NAN;
    if (!isfinite(ratio) || !(small > 0)) {
        char why[SW_ERRLEN], truth_why[SW_ERRLEN];
        double cost = (T / fmin(old_dt, a->dt)) * sw_truth_step_work(&a->sims[0].sys, m);
        if (a->have_truth && a->truth_cost > a->work_key)
            snprintf(why, sizeof why, "no error measured: the reference to t=%.3g would cost %.2g state "
                     "evaluations, over the %.0e a key press may spend", T, a->truth_cost, a->work_key);
        else if (cost > a->work_key)
            snprintf(why, sizeof why, "no error measured: the run to t=%.3g would cost %.2g state evaluations, "
                     "over the %.0e a key press may spend", T, cost, a->work_key);
        else if (isnan(e_new) || isnan(e_old))
            snprintf(why, sizeof why, "no error to compare (%s)",
                     truth_report(a) ? "a run blew up" : sw_app_truth_why(a, truth_why, sizeof truth_why));
        else
            snprintf(why, sizeof why, "the error is zero at one step: no ratio");
        snprintf(a->message, sizeof a->message, "dt=%g: %s", a->dt, why);
        return;
    }
    /* An order can be read from the ratio only where both runs are in the
     * asymptotic range: no mode grows much over the run (else the ratio
     * measures growth), the error is small against the motion, and halving
     * once more gives the same ratio (within 0.15 in its base-2 logarithm;
     * Euler's amplitude error on an oscillator, e^(ω²ΔtT/2) - 1, is not yet
     * proportional to Δt while the exponent is near 1). */
    if (m->flags & SW_ADAPTIVE) {
        /* dt only caps the steps: the error follows rtol and atol */
        snprintf(a->message, sizeof a->message, "dt=%g, the largest step %s may take: position error %.3g m to "
                 "t=%.3g (%.3g m at dt=%g); the tolerances set the error, not dt, so no order", a->dt, m->name,
                 e_new, T, e_old, old_dt);
        return;
    }
    double rho, grow = run_growth(a, m, big_dt, &rho);
    double scale = report_scale(a);
    if (small <= SW_APP_ROUNDING * scale) {
        /* rounding, not truncation: a ratio of rounding errors is no order
         * (RK4 on a parabola, a located bounce without drag) */
        snprintf(a->message, sizeof a->message, "dt=%g: position error %.3g m to t=%.3g (%.3g m at dt=%g): "
                 "at rounding level (below %.0e of the motion), so %s is exact here and shows no order",
                 a->dt, e_new, T, e_old, old_dt, SW_APP_ROUNDING, m->name);
        return;
    }
    char head[160];
    snprintf(head, sizeof head, "dt=%g: position error %.3g m to t=%.3g (%.3g m at dt=%g), ratio %.3g",
             a->dt, e_new, T, e_old, old_dt, ratio);
    if (grow > 2) {
        snprintf(a->message, sizeof a->message, "%s: not an order - at dt=%g %s grows ×%.4g per step, "
                 "×%.2g by t=%.3g", head, big_dt, m->name, rho, grow, T);
    } else if (big >= SW_APP_CEILING * scale) {
        /* an order shows only where the error is small: say which way that is */
        snprintf(a->message, sizeof a->message, "%s: not an order - at dt=%g the error is %.0f%% of the motion%s%s",
                 head, big_dt, 100 * big / scale,
                 a->dt < old_dt ? "; halve dt again" : " (an order shows at small dt only)",
                 (m->flags & SW_SYMPLECTIC) ? PHASE_NOTE : "");
    } else {
        /* the three runs through the order rule every printed order
         * passes (sw_bench_order_rule): above round-off, falling, local
         * slopes within 0.15 + 0.03·p of each other */
        double small_dt = fmin(old_dt, a->dt), e_next = sw_app_measure(a, m, 0.5 * small_dt);
        double h[3] = { big_dt, small_dt, 0.5 * small_dt }, e[3] = { big, small, e_next };
        long steps[3];
        for (int k = 0; k < 3; k++)
            steps[k] = (long)ceil(T / h[k]);
        static sw_bench_series fit; /* large: kept off the stack; the app is single-threaded */
        double order = sw_bench_order_rule(h, e, steps, 3, scale, SW_APP_CEILING, &fit);
        if (isnan(order)) {
            snprintf(a->message, sizeof a->message, "%s: not an order yet - with dt=%g too, %s%s%s", head,
                     0.5 * small_dt, sw_bench_no_order_text(&fit),
                     a->dt < old_dt ? "; halve dt again" : " (an order shows at small dt only)",
                     (m->flags & SW_SYMPLECTIC) && big > 0.05 * scale ? PHASE_NOTE : "");
        } else {
            a->error_ratio = ratio;
            snprintf(a->message, sizeof a->message, "%s, order ~%.2f", head, order);
        }
    }
}

/* The limit with the damping of every oscillating mode taken away (λ, μ =
 * ±i|λ|): what a lesson's closed form for the undamped oscillator gives
 * (RK4's 2√2). 0 when no mode is damped or it rounds to the same 3 digits
 * as the limit shown. */
static double undamped_limit(sw_app *a, const sw_integrator *m, double limit)
{
    static sw_spectrum sp; /* large: kept off the stack; the app is single-threaded */
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
