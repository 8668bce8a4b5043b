/* The live app model: sims on screen, the clock, and what each action does.
 * Pure C: no terminal. Invariant: every sim on screen shares the scene, its
 * parameters and dt; only the method differs, so compare is a fair race. */
#include "app/app.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/stages.h"
#include "app/sweep.h"
#include "measure/bench.h"
#include "stepwise/stepwise.h"
#include "util/escape.h"

/* A compare pair that differs from the main method and suits the system,
 * in the order the method rows give (compare: 1 first): the lecture's
 * contrast (Euler against RK4) plus a symplectic method. */
static void default_compare(sw_app *a, const sw_integrator **m1, const sw_integrator **m2)
{
    const sw_integrator *main = a->sims[0].method, *picked[2] = { NULL, NULL };
    int n = 0, count = sw_integrator_count();
    char err[SW_ERRLEN];
    for (int rank = 1; rank <= count && n < 2; rank++)
        for (int i = 0; i < count && n < 2; i++) {
            const sw_integrator *m = sw_integrator_at(i);
            if (m->compare == rank && m != main &&
                sw_integrator_accepts(m, a->sims[0].sys.ode, err, sizeof err) == SW_OK)
                picked[n++] = m;
        }
    *m1 = picked[0];
    *m2 = picked[1];
}

static void free_bench(sw_app *a)
{
    sw_sweep_cancel(a->sweep);
    a->sweep = NULL;
    if (a->bench) {
        sw_bench_free(a->bench);
        free(a->bench);
    }
    a->bench = NULL;
    a->workprec = 0;
}

static void workprec_message(sw_app *a)
{
    snprintf(a->message, sizeof a->message, "%s",
             !a->workprec ? "work-precision plot closed"
             : a->sweep ? (a->workprec == 1 ? "measuring every method for the work-precision plot; it opens "
                                              "when done (w: against time)"
                                            : "measuring every method for the work-precision plot; it opens "
                                              "when done, against wall time (w closes)")
             : a->workprec == 1 ? "work-precision: error against derivative evaluations (w: against time)"
                                : "work-precision: error against wall time (w closes)");
}

/* The work-precision sweep's worker: take its report when it is done
 * (every frame; sw_app_advance calls it). */
static void sw_app_sweep_poll(sw_app *a)
{
    sw_bench_report *r;
    char why[SW_ERRLEN];
    if (!a->sweep || !sw_sweep_poll(a->sweep, &r, why, sizeof why))
        return;
    a->sweep = NULL;
    if (!r) {
        a->workprec = 0;
        snprintf(a->message, sizeof a->message, "no work-precision plot: %s", why);
        return;
    }
    a->bench = r;
    if (a->workprec)
        workprec_message(a);
}

void sw_app_sweep_wait(sw_app *a)
{
    if (a->sweep)
        sw_sweep_wait(a->sweep);
    sw_app_sweep_poll(a);
}

static void free_sims(sw_app *a)
{
    for (int i = 0; i < a->nsims; i++) {
        sw_app_history_detach(a, i);
        sw_sim_free(&a->sims[i]);
    }
    a->nsims = 0;
}

static int init_sim(sw_app *a, sw_sim *s, const sw_integrator *m, char *err, size_t errlen)
{
    int rc = sw_sim_init(s, a->scene, a->p, m, a->dt, err, errlen);
    if (rc == SW_OK && (rc = sw_sim_set_events(s, a->events, err, errlen)) != SW_OK)
        sw_sim_free(s);
    if (rc == SW_OK)
        sw_app_history_attach(a, (int)(s - a->sims));
    return rc;
}

static int build(sw_app *a, const sw_integrator *m, char *err, size_t errlen)
{
    int rc = init_sim(a, &a->sims[0], m, err, errlen);
    if (rc != SW_OK)
        return rc;
    a->nsims = 1;
    sw_app_truth_reset(a);
    sw_app_watch_restart(a);
    if (a->compare) {
        for (int i = 0; i < 2; i++) {
            const sw_integrator *cm = a->compare_methods[i];
            if (!cm || sw_integrator_accepts(cm, a->sims[0].sys.ode, err, errlen) != SW_OK)
                default_compare(a, &a->compare_methods[0], &a->compare_methods[1]);
        }
        for (int i = 0; i < (a->compare_one ? 1 : 2) && a->compare_methods[i]; i++) {
            if (init_sim(a, &a->sims[a->nsims], a->compare_methods[i], err, errlen) != SW_OK)
                break;
            a->nsims++;
        }
    }
    a->t_goal = 0;
    a->nmeas = 0;
    a->error_ratio = NAN;
    for (int i = 0; i < SW_APP_SIMS; i++)
        sw_series_clear(&a->series[i]);
    if (!sw_phase_available(&a->sims[0].sys, a->phase_particle, a->phase_coord))
        sw_phase_default(&a->sims[0].sys, &a->phase_particle, &a->phase_coord);
    sw_app_phase_clear(a);
    return SW_OK;
}

int sw_app_init(sw_app *a, const sw_scene *sc, const double *p, const sw_integrator *m, double dt,
                char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    a->scene = sc;
    sw_scene_fill(sc, p, a->p);
    a->epoch++; /* a new picture */
    a->dt = dt > 0 ? dt : sw_scene_dt(sc, a->p);
    a->speed = 1.0;
    a->slowmo = 1.0;
    a->zoom = 1.0;
    a->error_ratio = NAN;
    a->work_key = SW_WORK_KEY;
    a->work_inline = SW_APP_WORK_INLINE;
    if (!m)
        m = sw_integrator_find(sc->integrator);
    int rc = build(a, m, err, errlen);
    if (rc == SW_OK)
        sw_phase_default(&a->sims[0].sys, &a->phase_particle, &a->phase_coord);
    return rc;
}

void sw_app_free(sw_app *a)
{
    sw_app_record_stop(a);
    free_bench(a);
    free_sims(a);
    sw_stages_free(&a->stages);
    a->scene = NULL;
    sw_app_truth_reset(a); /* frees it */
}

int sw_app_set_scene(sw_app *a, const sw_scene *sc, const double *p, char *err, size_t errlen)
{
    sw_app_record_stop(a); /* a trace describes one run */
    free_bench(a);         /* the sweep was for the old parameters */
    sw_app_stages_close(a);
    const sw_integrator *m = a->sims[0].method;
    const sw_scene *old_scene = a->scene;
    double old_p[SW_MAX_PARAMS], old_dt = a->dt;
    memcpy(old_p, a->p, sizeof old_p);
    free_sims(a);
    a->scene = sc;
    sw_scene_fill(sc, p, a->p);
    a->epoch++; /* a new picture */
    /* a new scene, or a run at its scene's default step, starts at the
     * default step for the new parameters (water's follows n, k and nu) */
    if (sc != old_scene || old_dt == sw_scene_dt(old_scene, old_p))
        a->dt = sw_scene_dt(sc, a->p);
    int rc = build(a, m, err, errlen);
    if (rc == SW_EINVAL)
        rc = build(a, sw_integrator_find(sc->integrator), err, errlen);
    if (rc != SW_OK) { /* put the old scene back so the app always has a sim */
        char e2[SW_ERRLEN];
        a->scene = old_scene;
        memcpy(a->p, old_p, sizeof old_p);
        a->dt = old_dt;
        build(a, m, e2, sizeof e2);
    } else if (sc != old_scene)
        sw_phase_default(&a->sims[0].sys, &a->phase_particle, &a->phase_coord);
    return rc;
}

int sw_app_set_method(sw_app *a, const sw_integrator *m)
{
    char err[SW_ERRLEN];
    sw_app_dt_cancel(a); /* it measured the method before */
    if (sw_sim_set_method(&a->sims[0], m, err, sizeof err) != SW_OK) {
        snprintf(a->message, sizeof a->message, "%s", err);
        return SW_EINVAL;
    }
    if (a->compare) /* keep the compare pair distinct from the new main method */
        for (int i = 1; i < a->nsims; i++)
            if (a->sims[i].method == m) {
                const sw_integrator *m1, *m2;
                default_compare(a, &m1, &m2);
                sw_sim_set_method(&a->sims[i], i == 1 ? m1 : m2, err, sizeof err);
                a->compare_methods[i - 1] = a->sims[i].method;
                sw_app_history_restart(a, i);
            }
    sw_app_history_restart(a, 0); /* the past was stepped by another method */
    char label[4 * 100 + 4]; /* a plugin chose it: escaped (bidirectional controls too) */
    sw_escape(m->label, 100, label, sizeof label);
    snprintf(a->message, sizeof a->message, "integrator: %s (%s)", m->name, label);
    sw_app_watch_restart(a);
    return SW_OK;
}

int sw_app_set_dt(sw_app *a, double dt)
{
    char err[SW_ERRLEN];
    sw_app_dt_cancel(a); /* a new step: the next key measures again */
    for (int i = 0; i < a->nsims; i++)
        if (sw_sim_set_dt(&a->sims[i], dt, err, sizeof err) != SW_OK) {
            snprintf(a->message, sizeof a->message, "%s", err);
            return SW_EINVAL;
        }
    a->dt = dt;
    for (int i = 0; i < a->nsims; i++)
        sw_app_history_restart(a, i);
    sw_app_watch_restart(a);
    return SW_OK;
}

int sw_app_set_compare(sw_app *a, int on, const sw_integrator *m1, const sw_integrator *m2)
{
    for (int i = 1; i < a->nsims; i++) {
        sw_app_history_detach(a, i);
        sw_sim_free(&a->sims[i]);
    }
    a->nsims = 1;
    a->compare = on;
    a->compare_one = 0;
    if (!on)
        return SW_OK;
    const sw_integrator *d1, *d2;
    default_compare(a, &d1, &d2);
    a->compare_methods[0] = m1 ? m1 : d1;
    a->compare_methods[1] = m2 ? m2 : (m1 && d1 != m1 ? d1 : d2);
    char err[SW_ERRLEN];
    const sw_sim *main = &a->sims[0];
    for (int i = 0; i < 2; i++) {
        const sw_integrator *m = a->compare_methods[i];
        if (!m || sw_integrator_accepts(m, main->sys.ode, err, sizeof err) != SW_OK)
            continue;
        if (init_sim(a, &a->sims[a->nsims], m, err, sizeof err) != SW_OK)
            continue;
        a->nsims++;
    }
    /* A fair race: every method starts together from the scene's start at
     * t = 0, so each one's energy and error are measured against its own
     * start (a run joined late would carry the main run's drift). */
    sw_app_reset(a);
    return SW_OK;
}

int sw_app_compare_with(sw_app *a, const sw_integrator *const *m, int n)
{
    int rc = sw_app_set_compare(a, 1, m[0], n > 1 ? m[1] : NULL);
    a->compare_one = n == 1;
    if (a->compare_one && a->nsims == 3) { /* one method asked for: not the app's second choice */
        sw_app_history_detach(a, 2);
        sw_sim_free(&a->sims[2]);
        a->nsims = 2;
    }
    return rc;
}

void sw_app_set_ghost(sw_app *a, int on) { a->ghost = on; }

void sw_app_set_events(sw_app *a, sw_events_mode mode)
{
    char err[SW_ERRLEN];
    sw_app_dt_cancel(a); /* its runs met events the old way */
    a->events = mode;
    for (int i = 0; i < a->nsims; i++) {
        if (sw_sim_set_events(&a->sims[i], mode, err, sizeof err) != SW_OK)
            snprintf(a->message, sizeof a->message, "%s", err);
        sw_app_history_restart(a, i);
    }
}

/* A sim whose plugin failed goes on under the scene's method from t = 0;
 * the message says so (set after the reset, which may report a recording). */
static void guard_plugins(sw_app *a)
{
    char msg[sizeof a->message];
    if (!sw_app_plugins_disable_failed(a, msg, sizeof msg))
        return;
    sw_app_reset(a);
    snprintf(a->message, sizeof a->message, "%s", msg);
}

void sw_app_reset(sw_app *a)
{
    char err[SW_ERRLEN];
    if (a->record_path[0] && a->sims[0].t > 0)
        sw_app_record_stop(a);
    for (int i = 0; i < a->nsims; i++) {
        sw_sim_reset(&a->sims[i], err, sizeof err);
        sw_app_history_restart(a, i);
    }
    a->t_goal = 0;
    a->slowmo = 1.0;
    a->epoch++;
    for (int i = 0; i < SW_APP_SIMS; i++)
        sw_series_clear(&a->series[i]);
    sw_app_phase_clear(a);
    sw_app_watch_restart(a);
}

/* A key changed dt or the method mid-run: the run starts again at t = 0,
 * so what is on screen (err, energy, the picture) is this dt's and this
 * method's alone, never an error carried over from the steps before.
 * The one rule for the run's state: only space runs it; every restart
 * (this, r, a parameter) leaves it paused, so "then press space" always
 * starts it, and the meter line says PAUSED. */
static void restart_run(sw_app *a)
{
    a->paused = 1;
    if (!(a->sims[0].t > 0))
        return;
    sw_app_reset(a);
    /* first, so that a long message cut at the screen's third line keeps it */
    static const char lead[] = "restarted at t = 0, paused; ";
    char said[sizeof a->message];
    size_t keep = strlen(a->message), room = sizeof a->message - sizeof lead;
    keep = keep < room ? keep : room;
    memcpy(said, a->message, keep);
    memcpy(a->message, lead, sizeof lead - 1);
    memcpy(a->message + sizeof lead - 1, said, keep);
    a->message[sizeof lead - 1 + keep] = '\0';
    if (!keep)
        a->message[sizeof lead - 3] = '\0'; /* nothing after it: no "; " */
}

static int method_index(const sw_integrator *m)
{
    for (int i = 0; i < sw_integrator_count(); i++)
        if (sw_integrator_at(i) == m)
            return i;
    return 0;
}

/* Next (dir = +1) or previous method that this system accepts. */
static void cycle_method(sw_app *a, int dir)
{
    int n = sw_integrator_count(), i = method_index(a->sims[0].method);
    char err[SW_ERRLEN];
    for (int k = 1; k <= n; k++) {
        const sw_integrator *m = sw_integrator_at(((i + dir * k) % n + n) % n);
        if (sw_integrator_accepts(m, a->sims[0].sys.ode, err, sizeof err) == SW_OK) {
            sw_app_set_method(a, m);
            return;
        }
    }
}

/* Step a parameter: by ×2 over ranges spanning decades (a range from 0 counts
 * when it reaches 1000; from 0 the first step is 1/1000 of the range), else
 * by 1/20 of the range. */
/* The next value of the 1-2-5 ladder (…, 0.5, 1, 2, 5, 10, 20, …) above v
 * (dir > 0) or below it (dir < 0), v > 0: every round value a lesson sets
 * (c = 0.5, 10, 200, 5000) is on it, and from any value off it (a page's
 * own setting) a press lands on it. */
static double ladder_step(double v, int dir)
{
    static const double mant[3] = { 1, 2, 5 };
    double e = floor(log10(v)), best = dir > 0 ? INFINITY : 0;
    for (int k = -1; k <= 1; k++)
        for (int j = 0; j < 3; j++) {
            double c = mant[j] * pow(10, e + k);
            if (dir > 0 && c > v * (1 + 1e-9) && c < best)
                best = c;
            if (dir < 0 && c < v * (1 - 1e-9) && c > best)
                best = c;
        }
    return best;
}

static void change_param(sw_app *a, int dir)
{
    const sw_param *pd = &a->scene->params[a->param_sel];
    double v = a->p[a->param_sel], nv, span = pd->max - pd->min;
    int decades = pd->min > 0 ? pd->max / pd->min >= 100 : pd->min == 0 && pd->max >= 1000;
    /* with a floor of 0: the ladder down to a millionth of the range, then 0 */
    double floor0 = ladder_step(span * 1e-6 * 0.999, 1);
    if (decades && pd->min == 0 && (v == 0 || (dir < 0 && v <= floor0)))
        nv = dir > 0 ? (pd->integer ? 1 : floor0) : 0;
    else if (decades)
        nv = ladder_step(v, dir);
    else if (pd->integer)
        nv = v + dir;
    else
        nv = v + dir * span / 20;
    if (pd->integer)
        nv = round(nv);
    nv = fmin(pd->max, fmax(pd->min, nv));
    if (nv == v) {
        snprintf(a->message, sizeof a->message, "%s stays in [%g, %g]", pd->name, pd->min, pd->max);
        return;
    }
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    memcpy(p, a->p, sizeof p);
    p[a->param_sel] = nv;
    a->paused = 1; /* a restart, as every other (restart_run) */
    if (sw_app_set_scene(a, a->scene, p, err, sizeof err) != SW_OK)
        snprintf(a->message, sizeof a->message, "%s", err);
    else
        snprintf(a->message, sizeof a->message, "%s = %g %s (restarted, paused: space runs)", pd->name, nv, pd->unit);
}

int sw_app_apply(sw_app *a, sw_action act, int arg)
{
    const sw_control *control = sw_control_of(act);
    if (control && (a->locked & control->lock)) {
        snprintf(a->message, sizeof a->message, "'%s' is locked on this page", sw_action_name(act));
        return 0;
    }
    switch (act) {
    case SW_ACT_NEXT_METHOD:
    case SW_ACT_PREV_METHOD: {
        const sw_integrator *before = a->sims[0].method;
        cycle_method(a, act == SW_ACT_NEXT_METHOD ? 1 : -1);
        if (a->sims[0].method != before)
            restart_run(a);
        return a->sims[0].method != before;
    }
    case SW_ACT_PICK_METHOD: {
        const sw_integrator *m = sw_integrator_at(arg - 1);
        if (!m) {
            snprintf(a->message, sizeof a->message, "there is no integrator %d (there are %d)", arg,
                     sw_integrator_count());
            return 0;
        }
        if (sw_app_set_method(a, m) != SW_OK)
            return 0;
        restart_run(a);
        return 1;
    }
    case SW_ACT_DT_DOUBLE:
    case SW_ACT_DT_HALVE: {
        double old = a->dt, dt = act == SW_ACT_DT_DOUBLE ? old * 2 : old / 2;
        if (!(dt >= SW_DT_MIN && dt <= SW_DT_MAX)) {
            snprintf(a->message, sizeof a->message, "dt stays in [%g, %g]", SW_DT_MIN, SW_DT_MAX);
            return 0;
        }
        if (sw_app_set_dt(a, dt) != SW_OK)
            return 0;
        sw_app_measure_dt_change(a, old);
        restart_run(a);
        return 1;
    }
    case SW_ACT_ERROR_KIND:
        a->err_velocity = !a->err_velocity;
        snprintf(a->message, sizeof a->message, "err is now the largest %s",
                 a->err_velocity ? "velocity error, in m/s (m: positions again)"
                                 : "position error, in metres (m: velocities)");
        return 1;
    case SW_ACT_PAUSE:
        a->paused = !a->paused;
        if (!a->paused)
            sw_app_stages_close(a); /* the stage view shows a paused run */
        snprintf(a->message, sizeof a->message, "%s", a->paused ? "paused" : "running");
        return 1;
    case SW_ACT_STEP: {
        double stop = sw_app_stop_ahead(a); /* the main run's, before it steps */
        a->paused = 1;
        for (int i = 0; i < a->nsims; i++)
            sw_app_step_sim(a, i, stop);
        a->t_goal = a->sims[0].t;
        sw_app_watch_feed(a);
        guard_plugins(a);
        sw_app_phase_push(a);
        return 1;
    }
    case SW_ACT_UNTIL:
        return sw_app_run_to_stop(a);
    case SW_ACT_BACK:
    case SW_ACT_BACK_MANY:
        return sw_app_step_back(a, act == SW_ACT_BACK ? 1 : SW_APP_BACK_MANY);
    case SW_ACT_RESET:
        sw_app_reset(a);
        a->paused = 1;
        snprintf(a->message, sizeof a->message, "reset to t = 0, paused (space runs)");
        return 1;
    case SW_ACT_SLOWER:
    case SW_ACT_FASTER: {
        double s = act == SW_ACT_FASTER ? a->speed * 2 : a->speed / 2;
        a->speed = fmin(SW_APP_SPEED_MAX, fmax(SW_APP_SPEED_MIN, s));
        snprintf(a->message, sizeof a->message, "speed x%g", a->speed);
        return 1;
    }
    case SW_ACT_COMPARE:
        sw_app_set_compare(a, !a->compare, NULL, NULL);
        a->paused = 1; /* a restart of every run, as restart_run's */
        if (a->compare && a->nsims > 1)
            snprintf(a->message, sizeof a->message, "compare %s, %s%s%s from t = 0, paused (l: side by side; &: "
                     "one cell)",
                     a->sims[0].method->name, a->sims[1].method->name, a->nsims > 2 ? " and " : "",
                     a->nsims > 2 ? a->sims[2].method->name : "");
        else
            snprintf(a->message, sizeof a->message, "compare off");
        return 1;
    case SW_ACT_GHOST: {
        sw_app_set_ghost(a, !a->ghost);
        char why[SW_ERRLEN];
        if (a->ghost && *sw_app_truth_why(a, why, sizeof why))
            snprintf(a->message, sizeof a->message, "no ghost: %s", why);
        else if (!a->ghost)
            snprintf(a->message, sizeof a->message, "ghost off");
        else if (a->truth.source == SW_TRUTH_EXACT)
            snprintf(a->message, sizeof a->message, "ghost on: the exact solution, drawn ' (&: ghost and run in one cell)");
        else
            snprintf(a->message, sizeof a->message, "ghost on: a tight reference run (%s), drawn '", a->truth.why);
        return 1;
    }
    case SW_ACT_EVENTS: {
        sw_app_set_events(a, a->events == SW_EVENTS_LOCATE ? SW_EVENTS_STEP : SW_EVENTS_LOCATE);
        if (sw_system_event_count(&a->sims[0].sys) == 0)
            snprintf(a->message, sizeof a->message, "events %s (this scene has none: its forces are smooth)",
                     a->events == SW_EVENTS_LOCATE ? "located" : "stepped over");
        else if (a->events == SW_EVENTS_LOCATE)
            snprintf(a->message, sizeof a->message,
                     "events located: a step that crosses one is cut there (order kept)");
        else
            snprintf(a->message, sizeof a->message,
                     "events stepped over: met at step ends (first order)");
        return 1;
    }
    case SW_ACT_TRAILS:
        a->trails = !a->trails;
        snprintf(a->message, sizeof a->message, "trails %s", a->trails ? "on" : "off");
        return 1;
    case SW_ACT_GRAPH:
        a->graph = !a->graph;
        snprintf(a->message, sizeof a->message, "graph %s", a->graph ? "on" : "off");
        return 1;
    case SW_ACT_BRAILLE:
        a->braille = !a->braille;
        snprintf(a->message, sizeof a->message, "%s", a->braille ? "Braille dots" : "one character per point");
        return 1;
    case SW_ACT_PANEL:
        a->panel = !a->panel;
        return 1;
    case SW_ACT_PANEL_CLOSE:
        a->panel = 0;
        return 1;
    case SW_ACT_PANEL_UP:
    case SW_ACT_PANEL_DOWN: {
        int n = a->scene->nparams;
        a->param_sel = (a->param_sel + (act == SW_ACT_PANEL_UP ? n - 1 : 1)) % n;
        return 1;
    }
    case SW_ACT_PANEL_DEC:
    case SW_ACT_PANEL_INC:
        change_param(a, act == SW_ACT_PANEL_INC ? 1 : -1);
        return 1;
    case SW_ACT_RECORD:
        if (a->record_path[0])
            sw_app_record_stop(a);
        else {
            sw_app_reset(a); /* a trace starts at t = 0 */
            sw_app_record_begin(a, NULL);
        }
        return 1;
    case SW_ACT_WORKPREC: {
        /* off -> against evaluations -> against wall time -> off; the sweep
         * runs once per scene, on a worker thread (app/sweep.c): the
         * picture runs on and the plot opens when it is done. */
        char why[SW_ERRLEN];
        a->workprec = (a->workprec + 1) % 3;
        if (a->workprec && !a->bench && !a->sweep) {
            if (!sw_bench_measurable(a->scene, a->p, why, sizeof why) ||
                /* the truth's cost as the app measured it: no pilot run on the key */
                !sw_bench_quick_affordable(a->scene, a->p, a->have_truth ? a->truth_cost : NAN, 4 * a->work_key,
                                           why, sizeof why) ||
                !(a->sweep = sw_sweep_start(a->scene, a->p, 4 * a->work_key, why, sizeof why))) {
                a->workprec = 0;
                snprintf(a->message, sizeof a->message, "no work-precision plot: %s", why);
                return 0;
            }
            sw_app_sweep_poll(a); /* done already when it ran on this thread */
            if (!a->workprec)
                return 0;
        }
        workprec_message(a);
        return 1;
    }
    case SW_ACT_STAGES:
    case SW_ACT_STAGES_CLOSE:
        return sw_app_stages_apply(a, act);
    case SW_ACT_HELP:
        a->help++; /* the next page; the composer closes it after the last */
        return 1;
    case SW_ACT_QUIT:
        a->quit = 1;
        return 1;
    case SW_ACT_ZOOM_OUT:
    case SW_ACT_ZOOM_IN:
        return sw_app_zoom(a, act == SW_ACT_ZOOM_OUT);
    case SW_ACT_FOLLOW:
        return sw_app_toggle_follow(a);
    case SW_ACT_LANES:
        return sw_app_toggle_lanes(a);
    case SW_ACT_PHASE:
        return sw_app_toggle_phase(a);
    case SW_ACT_PHASE_COORD:
    case SW_ACT_PHASE_PREV:
    case SW_ACT_PHASE_NEXT:
        return sw_app_phase_next(a, act == SW_ACT_PHASE_COORD ? 1 : act == SW_ACT_PHASE_NEXT ? 2 : -2);
    case SW_ACT_REGION:
        return sw_app_toggle_region(a);
    SW_LESSON_CASES /* the lesson runner's (runner.c) */
    case SW_ACT_NONE:
    case SW_ACT_COUNT:
        return 0;
    }
    return 0;
}

int sw_app_key(sw_app *a, int key, int in_lesson)
{
    const sw_control *c;
    int arg;
    if (!sw_key_lookup(key, sw_key_contexts(a->panel, in_lesson), &c, &arg))
        return 0;
    a->message[0] = '\0'; /* a message stays until the next key */
    int changed = sw_app_apply(a, c->action, arg);
    if (a->record_path[0] && (a->sims[0].method != a->record_method || a->dt != a->record_dt))
        sw_app_record_stop(a); /* a trace describes one method at one dt */
    return changed;
}

void sw_app_advance(sw_app *a, double wall, long max_steps)
{
    sw_app_sweep_poll(a);
    sw_app_dt_poll(a);
    if (a->paused || !(wall > 0))
        return;
    double want = wall * a->speed;
    a->t_goal += want;
    /* a stop time ahead caps the goal, and every run lands on it exactly */
    double stop = sw_app_stop_ahead(a);
    int to_stop = stop > 0 && a->t_goal >= stop;
    if (to_stop)
        a->t_goal = stop;
    int behind = 0;
    for (int i = 0; i < a->nsims; i++) {
        sw_sim *s = &a->sims[i];
        long n = 0;
        /* Fixed steps land within half a step of the goal (rounding in t
         * never buys an extra step); adaptive steps go just past it. */
        double slack = (s->method->flags & SW_ADAPTIVE) ? 0.0 : to_stop ? 1e-9 * s->dt : 0.5 * s->dt;
        while (!s->blown && s->t + slack < a->t_goal && n < max_steps) {
            sw_app_step_sim(a, i, stop);
            if (i == 0)
                sw_app_watch_feed(a); /* every step: the energy's peaks are per step */
            n++;
        }
        if (!s->blown && s->t + slack < a->t_goal)
            behind = 1;
    }
    if (behind) {
        /* drop the backlog: slow motion, not a spiral of death; the race
         * goes on from the slowest run still going, so all stay level */
        double slowest = a->sims[0].t;
        for (int i = 1; i < a->nsims; i++)
            if (!a->sims[i].blown && a->sims[i].t < slowest)
                slowest = a->sims[i].t;
        double got = slowest - (a->t_goal - want);
        a->slowmo = got > 0 ? want / got : INFINITY;
        a->t_goal = slowest;
    } else {
        a->slowmo = 1.0;
    }
    sw_app_sample(a);
    guard_plugins(a);
    if (stop > 0) /* reached on the way, or by capping the goal */
        sw_app_stop_reached(a, stop);
}

