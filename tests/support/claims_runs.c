/* Claims: scenes, runs and lesson pages, measured the way the texts say. */
#include "claims.h"

#include "canvas_help.h"

/* Parameters of scene `name`: its defaults, then "NAME=VALUE" assignments
 * separated by spaces (NULL or "": none). */
const sw_scene *cl_scene_p(const char *name, const char *sets, double *p)
{
    const sw_scene *sc = sw_scene_find(name);
    ck_assert_msg(sc != NULL, "no scene %s", name);
    sw_scene_defaults(sc, p);
    char buf[256], err[SW_ERRLEN];
    snprintf(buf, sizeof buf, "%s", sets ? sets : "");
    for (char *tok = strtok(buf, " "); tok; tok = strtok(NULL, " "))
        ck_assert_msg(sw_scene_set(sc, p, tok, err, sizeof err) == SW_OK, "%s", err);
    return sc;
}

double cl_param(const char *scene, const char *name)
{
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = cl_scene_p(scene, NULL, p);
    int i = sw_scene_param_index(sc, name);
    ck_assert_msg(i >= 0, "%s has no parameter %s", scene, name);
    return p[i];
}

const sw_integrator *cl_method(const char *name)
{
    const sw_integrator *m = sw_integrator_find(name);
    ck_assert_msg(m != NULL, "no integrator %s", name);
    return m;
}

void cl_sim_init(sw_sim *s, const char *scene, const char *sets, const char *m, double dt)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    const sw_scene *sc = cl_scene_p(scene, sets, p);
    ck_assert_msg(sw_sim_init(s, sc, p, cl_method(m), dt, err, sizeof err) == SW_OK, "%s", err);
}

/* Whole steps until t reaches T (as the app steps: whole steps of dt). */
void cl_steps_to(sw_sim *s, double T)
{
    while (!s->blown && s->t < T - 1e-9 * s->dt)
        sw_sim_step(s);
}

/* The energy drift in percent (sw_sim_energy_drift, as the status line
 * shows it) after whole steps to T. */
double cl_drift_at(const char *scene, const char *sets, const char *m, double dt, double T)
{
    sw_sim s;
    cl_sim_init(&s, scene, sets, m, dt);
    cl_steps_to(&s, T);
    ck_assert_msg(!s.blown, "%s on %s at dt %g blew up at t = %g", m, scene, dt, s.blow_time);
    double d = sw_sim_energy_drift(&s);
    sw_sim_free(&s);
    return d;
}

/* The same at exactly t = T (the last step cut to land there), as a page
 * with `@until T` shows it when it stops. */
double cl_drift_until(const char *scene, const char *sets, const char *m, double dt, double T)
{
    sw_sim s;
    cl_sim_init(&s, scene, sets, m, dt);
    sw_sim_run_until(&s, T);
    ck_assert_msg(!s.blown, "%s on %s at dt %g blew up at t = %g", m, scene, dt, s.blow_time);
    double d = sw_sim_energy_drift(&s);
    sw_sim_free(&s);
    return d;
}

/* The first time the drift passes `level` percent (level > 0: rises above,
 * level < 0: falls below), stepping up to T; NaN if it never does. */
double cl_time_drift_passes(const char *scene, const char *sets, const char *m, double dt, double level,
                                double T)
{
    sw_sim s;
    cl_sim_init(&s, scene, sets, m, dt);
    double when = NAN;
    while (!s.blown && s.t < T) {
        sw_sim_step(&s);
        double d = sw_sim_energy_drift(&s);
        if (level > 0 ? d > level : d < level) {
            when = s.t;
            break;
        }
    }
    sw_sim_free(&s);
    return when;
}

/* The largest |drift| over whole steps to T. */
double cl_max_abs_drift(const char *scene, const char *sets, const char *m, double dt, double T)
{
    sw_sim s;
    cl_sim_init(&s, scene, sets, m, dt);
    double worst = 0;
    while (!s.blown && s.t < T - 1e-9 * dt) {
        sw_sim_step(&s);
        worst = fmax(worst, fabs(sw_sim_energy_drift(&s)));
    }
    ck_assert(!s.blown);
    sw_sim_free(&s);
    return worst;
}

/* The time a run blows up (NaN: not by T). */
double cl_blow_time(const char *scene, const char *sets, const char *m, double dt, double T)
{
    sw_sim s;
    cl_sim_init(&s, scene, sets, m, dt);
    cl_steps_to(&s, T);
    double when = s.blown ? s.blow_time : NAN;
    sw_sim_free(&s);
    return when;
}

/* The spectrum of a scene's linearisation at its start. */
sw_spectrum cl_spectrum0(const char *scene, const char *sets)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    const sw_scene *sc = cl_scene_p(scene, sets, p);
    sw_system sys;
    ck_assert_msg(sw_system_build(&sys, sc, p, err, sizeof err) == SW_OK, "%s", err);
    sw_spectrum sp;
    ck_assert_int_eq(sw_truth_spectrum(&sys, 0.0, sys.y, &sp), 0);
    sw_system_free(&sys);
    return sp;
}

/* Growth per step ρ of method m at dt on the scene's worst mode at its start. */
double cl_growth0(const char *scene, const char *sets, const char *m, double dt)
{
    sw_spectrum sp = cl_spectrum0(scene, sets);
    return sw_truth_growth_all(cl_method(m), &sp, dt, NULL);
}

/* The largest stable step in theory at the scene's start. */
double cl_limit0(const char *scene, const char *sets, const char *m)
{
    sw_spectrum sp = cl_spectrum0(scene, sets);
    int unbounded;
    return sw_truth_limit(cl_method(m), &sp, SW_DT_MAX, &unbounded);
}

/* Theory and measurement of the stability lab (what `stepwise stability`
 * prints). */
sw_stability_result cl_stability(const char *scene, const char *sets, const char *m)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    const sw_scene *sc = cl_scene_p(scene, sets, p);
    sw_stability_config c;
    sw_stability_config_default(&c);
    sw_stability_result r;
    ck_assert_msg(sw_stability_find(sc, p, cl_method(m), &c, &r, err, sizeof err) == SW_OK, "%s", err);
    return r;
}

/* A lesson page as the student meets it: the runner opens the page of
 * lesson file `file` by its title, with the page's (and earlier pages')
 * settings applied. */
void cl_lesson_page(sw_runner *r, sw_app *a, const char *file, const char *title)
{
    ct_open_page(r, a, file, title);
    a->paused = 0;
}

void cl_page_free(sw_runner *r, sw_app *a)
{
    sw_app_free(a);
    sw_runner_free(r);
}

/* Press a key as the student would (locks ignored: the claim is about what
 * the key shows, not whether the page allows it). */
void cl_act(sw_app *a, sw_action action, int arg)
{
    unsigned locked = a->locked;
    a->locked = 0;
    sw_app_apply(a, action, arg);
    sw_app_dt_wait(a); /* a Δt key's figures, where they were measured on a worker */
    a->locked = locked;
}

/* The page's set-up under integrator (NULL: the page's), after k presses of '-'. */
static void page_halved(sw_runner *r, sw_app *a, const char *file, const char *title, const char *integrator, int k)
{
    cl_lesson_page(r, a, file, title);
    if (integrator)
        ck_assert_int_eq(sw_app_set_method(a, cl_method(integrator)), SW_OK);
    for (int i = 0; i < k; i++)
        cl_act(a, SW_ACT_DT_HALVE, 0);
}

/* The error ratio the status line shows after k presses of '-' from the
 * page's set-up (NaN when the app shows no order). */
double cl_page_ratio(const char *file, const char *title, const char *integrator, int k)
{
    sw_runner r;
    sw_app a;
    page_halved(&r, &a, file, title, integrator, k);
    double ratio = a.error_ratio;
    cl_page_free(&r, &a);
    return ratio;
}

/* The ratio the status line prints after k presses of '-', read as an
 * order or not: the errors at the larger and the smaller Δt. */
double cl_page_shown_ratio(const char *file, const char *title, const char *integrator, int k)
{
    sw_runner r;
    sw_app a;
    page_halved(&r, &a, file, title, integrator, k);
    double ratio = a.nmeas == 2 ? a.meas_err[0] / a.meas_err[1] : NAN;
    cl_page_free(&r, &a);
    return ratio;
}

/* The error the app measures at the report time for the page's scene. */
double cl_page_error(const char *file, const char *title, const char *m, double dt)
{
    sw_runner r;
    sw_app a;
    cl_lesson_page(&r, &a, file, title);
    double e = sw_app_measure(&a, cl_method(m), dt);
    cl_page_free(&r, &a);
    return e;
}

/* The digit key that picks a method, from the controls' key table; NaN: none. */
/* The method key picks in play, from the controls' table, and its place
 * (1-based); NULL when the key picks none. */
static const sw_integrator *picked(int key, int *place)
{
    const sw_control *control;
    int arg;
    if (!sw_key_lookup(key, SW_CTX_PLAY, &control, &arg) || control->action != SW_ACT_PICK_METHOD)
        return NULL;
    *place = arg;
    return sw_integrator_at(arg - 1);
}

double cl_key_of(const char *name)
{
    for (int d = 0; d <= 9; d++) {
        int place;
        const sw_integrator *m = picked('0' + d, &place);
        if (m && strcmp(m->name, name) == 0)
            return d;
    }
    return NAN;
}

double cl_key_picks(int key, int place, const char *name)
{
    int at;
    const sw_integrator *m = picked(key, &at);
    return m && at == place && strcmp(m->name, name) == 0;
}

/* Δt after k presses of + (double) or - (halve) from the page's set-up. */
double cl_page_dt_after(const char *file, const char *title, sw_action action, int k)
{
    sw_runner r;
    sw_app a;
    cl_lesson_page(&r, &a, file, title);
    for (int i = 0; i < k; i++)
        cl_act(&a, action, 0);
    double dt = a.dt;
    cl_page_free(&r, &a);
    return dt;
}

/* Derivative evaluations per step of m on a scene, measured over n steps
 * after the first. */
double cl_evals_per_step(const char *scene, const char *sets, const char *m, double dt, int n)
{
    sw_sim s;
    cl_sim_init(&s, scene, sets, m, dt);
    sw_sim_step(&s); /* a first step may evaluate what later steps reuse */
    long e1 = sw_sim_evals(&s);
    for (int i = 0; i < n; i++)
        sw_sim_step(&s);
    double r = (double)(sw_sim_evals(&s) - e1) / (double)n;
    sw_sim_free(&s);
    return r;
}

/* Order measured by halving dt: log2 of the error ratio at the report time
 * against the truth module. */
double cl_order_by_halving(const char *scene, const char *sets, const char *m, double dt)
{
    double p[SW_MAX_PARAMS], err2[2];
    const sw_scene *sc = cl_scene_p(scene, sets, p);
    double T = sc->duration;
    double *truth = malloc(4096 * sizeof *truth);
    ck_assert_int_eq(sw_truth_state(sc, p, T, truth), 0);
    for (int i = 0; i < 2; i++) {
        sw_sim s;
        cl_sim_init(&s, scene, sets, m, dt / (1 << i));
        ck_assert_int_eq(sw_sim_run_until(&s, T), 0);
        err2[i] = sw_truth_error(s.sys.ode->dim, s.sys.y, truth);
        sw_sim_free(&s);
    }
    free(truth);
    return log2(err2[0] / err2[1]);
}

/* Radius of vortex particle i over its start after whole steps to T. */
double cl_vortex_radius_growth(const char *m, double dt, double T)
{
    sw_sim s;
    cl_sim_init(&s, "vortex", NULL, m, dt);
    double r0 = hypot(s.sys.y[0], s.sys.y[1]);
    cl_steps_to(&s, T);
    double r = hypot(s.sys.y[0], s.sys.y[1]);
    sw_sim_free(&s);
    return r / r0;
}

long cl_steps_for(const char *scene, const char *sets, const char *m, double dt, double T)
{
    sw_sim s;
    cl_sim_init(&s, scene, sets, m, dt);
    ck_assert_int_eq(sw_sim_run_until(&s, T), 0);
    long n = s.steps;
    sw_sim_free(&s);
    return n;
}
