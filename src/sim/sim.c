/* A running simulation: scene + integrator + clock + counters + blow-up.
 * Every front end advances a sim through sw_sim_step_until, so the same
 * settings give the same states, bit for bit. A sim holds pointers into
 * itself (the system's callbacks) and must not be moved once initialised. */
#include "stepwise/sim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/stepper.h"
#include "sim/events.h"
#include "stepwise/stepwise.h"

/* Worked out on first use, behind a pointer so that const readers can. */
struct sw_sim_derived {
    int have_floor;
    double floor;         /* sw_sim_energy_floor of the system as built */
    /* The scene's drift of the state now, until the state changes: every
     * function that changes the state, the time or the system calls
     * sw_sim_state_changed, so a frame that draws without stepping pays
     * nothing for it and one that steps pays once, however many read it. */
    int have_drift;
    double drift;
    /* The energy and its error bound (0 where it is summed exactly), kept
     * the same way: a large galaxy's costs a pass of its tree. */
    int have_energy;
    double energy, energy_error;
    double energy0_error; /* the bound on energy0's error */
};

void sw_sim_state_changed(sw_sim *s) { s->derived->have_drift = s->derived->have_energy = 0; }

static double max_abs(int n, const double *v)
{
    double m = 0;
    for (int i = 0; i < n; i++)
        if (fabs(v[i]) > m)
            m = fabs(v[i]);
    return m;
}

/* A state is "runaway" once any component reaches a million times the
 * scene's size (rounded up to a power of two, so the test needs only the
 * exponent field): far past anything on screen, long before overflow. */
static void set_limits(sw_sim *s)
{
    /* an embedder's scene may have no view: the state's own extent serves */
    sw_view v = s->sys.scene->view ? s->sys.scene->view(&s->sys) : (sw_view){ 0, 0, 0, 0 };
    double span = fmax(fmax(fabs(v.xmin), fabs(v.xmax)), fmax(fabs(v.ymin), fabs(v.ymax)));
    int e;
    frexp(1e6 * (1.0 + span + max_abs(s->sys.ode->dim, s->sys.y)), &e);
    s->runaway = ldexp(1.0, e);
    s->stepper->limit_exp = (unsigned)(e + 1023);
    s->derived->have_energy = 0;
    s->energy0 = sw_sim_energy(s);
    s->derived->energy0_error = sw_sim_energy_error(s);
}

/* A fresh stepper for m on the sim's system, with the sim's tolerances. */
static int new_stepper(sw_sim *s, const sw_integrator *m, char *err, size_t errlen)
{
    s->stepper = malloc(sizeof *s->stepper);
    if (!s->stepper) {
        snprintf(err, errlen, "out of memory for a stepper");
        return SW_ENOMEM;
    }
    int rc = sw_stepper_init(s->stepper, m, s->sys.ode, err, errlen);
    if (rc != SW_OK) {
        free(s->stepper);
        s->stepper = NULL;
        return rc;
    }
    s->stepper->rtol = s->rtol;
    s->stepper->atol = s->atol;
    return SW_OK;
}

int sw_sim_init(sw_sim *s, const sw_scene *sc, const double *p, const sw_integrator *m, double dt,
                char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (!(dt >= SW_DT_MIN && dt <= SW_DT_MAX)) {
        snprintf(err, errlen, "dt = %g is outside [%g, %g]", dt, SW_DT_MIN, SW_DT_MAX);
        return SW_EINVAL;
    }
    int rc = sw_system_build(&s->sys, sc, p, err, errlen);
    if (rc != SW_OK)
        return rc;
    s->rtol = SW_RTOL_DEFAULT;
    s->atol = SW_ATOL_DEFAULT;
    s->derived = calloc(1, sizeof *s->derived);
    rc = s->derived ? new_stepper(s, m, err, errlen) : SW_ENOMEM;
    if (rc != SW_OK) {
        if (!s->derived)
            snprintf(err, errlen, "out of memory for a sim");
        free(s->derived);
        s->derived = NULL;
        sw_system_free(&s->sys);
        return rc;
    }
    s->method = m;
    s->dt = dt;
    set_limits(s);
    return SW_OK;
}

static void free_stepper(sw_sim *s)
{
    if (s->stepper) {
        sw_stepper_free(s->stepper);
        free(s->stepper);
    }
    s->stepper = NULL;
}

void sw_sim_free(sw_sim *s)
{
    free_stepper(s);
    sw_sim_events_free(s);
    free(s->derived);
    s->derived = NULL;
    sw_system_free(&s->sys);
}

int sw_sim_set_method(sw_sim *s, const sw_integrator *m, char *err, size_t errlen)
{
    unsigned limit_exp = s->stepper->limit_exp;
    sw_stepper *old = s->stepper;
    int rc = new_stepper(s, m, err, errlen);
    if (rc != SW_OK) {
        s->stepper = old;
        return rc;
    }
    sw_stepper_free(old);
    free(old);
    s->stepper->limit_exp = limit_exp;
    s->method = m;
    sw_sim_state_changed(s);
    return SW_OK;
}

int sw_sim_set_events(sw_sim *s, sw_events_mode mode, char *err, size_t errlen)
{
    int rc = sw_sim_events_set_mode(s, mode, err, errlen);
    sw_sim_state_changed(s); /* arming may set the scene's discrete data */
    return rc;
}

void sw_sim_set_tolerances(sw_sim *s, double rtol, double atol)
{
    s->rtol = s->stepper->rtol = rtol;
    s->atol = s->stepper->atol = atol;
    sw_sim_state_changed(s);
}

void sw_sim_step_counts(const sw_sim *s, long *accepted, long *rejected)
{
    *accepted = s->stepper->accepted;
    *rejected = s->stepper->rejected;
}

int sw_sim_set_dt(sw_sim *s, double dt, char *err, size_t errlen)
{
    if (!(dt >= SW_DT_MIN && dt <= SW_DT_MAX)) {
        snprintf(err, errlen, "dt = %g is outside [%g, %g]", dt, SW_DT_MIN, SW_DT_MAX);
        return SW_EINVAL;
    }
    s->dt = dt;
    s->stepper->h_next = 0;
    s->stepper->err_last = 0;
    sw_sim_state_changed(s);
    return SW_OK;
}

void sw_sim_set_state(sw_sim *s, const double *y)
{
    memcpy(s->sys.y, y, (size_t)s->sys.ode->dim * sizeof *y);
    sw_sim_events_arm(s);
    sw_stepper_touch(s->stepper);
    sw_sim_state_changed(s);
    s->energy0 = sw_sim_energy(s);
    s->derived->energy0_error = sw_sim_energy_error(s);
}

int sw_sim_reset(sw_sim *s, char *err, size_t errlen)
{
    int rc = sw_system_reset(&s->sys, err, errlen);
    sw_sim_state_changed(s); /* even a failed reset may have rebuilt part of the system */
    if (rc != SW_OK)
        return rc;
    free_stepper(s);
    rc = new_stepper(s, s->method, err, errlen);
    if (rc != SW_OK)
        return rc;
    s->t = 0;
    s->steps = 0;
    s->blown = 0;
    s->blow_step = 0;
    s->blow_time = 0;
    s->blow_reason[0] = '\0';
    sw_sim_events_reset(s);
    sw_sim_events_arm(s);
    set_limits(s);
    return SW_OK;
}

static void blow_up(sw_sim *s, const char *why)
{
    s->blown = 1;
    s->blow_step = s->steps;
    s->blow_time = s->t;
    snprintf(s->blow_reason, sizeof s->blow_reason, "%s", why);
}

int sw_sim_step_until(sw_sim *s, double t_stop)
{
    if (s->blown)
        return 1;
    sw_sim_state_changed(s); /* a step that fails may still have moved the state */
    double h = s->dt;
    if (t_stop > s->t && s->t + h > t_stop)
        h = t_stop - s->t;
    double *y = s->sys.y, t_start = s->t;
    int locate = s->events == SW_EVENTS_LOCATE && s->ev;
    int rc = locate ? sw_sim_locate_step(s, h) : sw_stepper_step(s->stepper, s->sys.ode, &s->t, y, h);
    if (rc != SW_OK) {
        /* The step did not run (a failed solve, a failed plugin): it is not
         * counted, so no trace has a row for it; the blow-up names it, at
         * the time it was stepping to. */
        blow_up(s, s->stepper->why                    ? s->stepper->why
                   : (s->method->flags & SW_PLUGIN)   ? SW_PLUGIN_REFUSED " an error"
                   : (s->method->flags & SW_ADAPTIVE) ? "step size underflow: the error control gave up"
                                                      : "the implicit solve failed");
        s->blow_step = s->steps + 1;
        s->blow_time = t_start + h;
        return 1;
    }
    s->steps++;
    const sw_scene *sc = s->sys.scene;
    int touched = sc->post_step && sc->post_step(&s->sys, s->t, y);
    if (touched)
        sw_stepper_touch(s->stepper);
    int n = s->sys.ode->dim;
    /* A step cut at an event changed the state between the method's steps:
     * the last sub-step's check does not cover it all. */
    int rescan = touched || (locate && sw_sim_events_cut(s));
    int beyond = (rescan || !s->stepper->checked) ? sw_state_beyond(y, 0, n, s->stepper->limit_exp)
                                                   : s->stepper->beyond;
    if (!beyond)
        return 0;
    for (int i = 0; i < n; i++) { /* rare: say what went wrong */
        if (!isfinite(y[i])) {
            blow_up(s, "the state became non-finite (NaN or infinity)");
            return 1;
        }
        if (fabs(y[i]) >= s->runaway) {
            blow_up(s, "the state ran away (beyond a million times the scene size)");
            return 1;
        }
    }
    return 0;
}

int sw_sim_step(sw_sim *s) { return sw_sim_step_until(s, 0.0); }

int sw_sim_run_until(sw_sim *s, double t_end)
{
    while (t_end - s->t > 1e-9 * s->dt)
        if (sw_sim_step_until(s, t_end))
            return 1;
    return s->blown;
}

long sw_sim_evals(const sw_sim *s) { return s->sys.ode->evals; }

/* Worked out once per state, as the drift (below). */
static const struct sw_sim_derived *energy_now(const sw_sim *s)
{
    struct sw_sim_derived *d = s->derived;
    if (!d->have_energy) {
        const sw_scene *sc = s->sys.scene;
        d->energy = sc->energy ? sc->energy(&s->sys, s->sys.y) : NAN;
        d->energy_error = sc->energy && sc->energy_error ? sc->energy_error(&s->sys, s->sys.y) : 0;
        d->have_energy = 1;
    }
    return d;
}

double sw_sim_energy(const sw_sim *s) { return energy_now(s)->energy; }

double sw_sim_energy_error(const sw_sim *s) { return energy_now(s)->energy_error; }

int sw_sim_resting_state(const sw_system *sys, double *out, double *energy)
{
    const sw_scene *sc = sys->scene;
    sw_sim s;
    char err[SW_ERRLEN];
    const sw_integrator *rest = NULL; /* the built-in whose row says it finds rest */
    for (int i = 0; i < sw_integrator_count() && !rest; i++)
        rest = sw_integrator_at(i)->resting ? sw_integrator_at(i) : NULL;
    if (sys->kind != SW_SYS_PARTICLES || !sc->energy || sc->post_step || !rest)
        return -1;
    if (sw_sim_init(&s, sc, sys->p, rest, SW_DT_MAX, err, sizeof err) != SW_OK)
        return -1;
    double e0 = sw_sim_energy(&s);
    int rc = -1;
    for (int k = 0; k < 12 && sw_sim_step(&s) == 0; k++)
        ;
    if (!s.blown) {
        int dim = s.sys.ode->dim, n2 = dim / 2;
        double vmax = 0, e = sw_sim_energy(&s);
        for (int i = n2; i < dim; i++)
            vmax = fmax(vmax, fabs(s.sys.y[i]));
        if (vmax < 1e-9 && e <= e0) {
            if (out)
                memcpy(out, s.sys.y, (size_t)dim * sizeof *out);
            if (energy)
                *energy = e;
            rc = 0;
        }
    }
    sw_sim_free(&s);
    return rc;
}

/* The energy of the resting state reached from the start; NaN when none. */
static double resting_energy(const sw_system *sys)
{
    double e;
    return sw_sim_resting_state(sys, NULL, &e) == 0 ? e : NAN;
}

static double system_energy_floor(const sw_system *sys)
{
    const sw_scene *sc = sys->scene;
    if (!sc->energy)
        return NAN;
    double floor = sc->energy_floor ? sc->energy_floor(sys) : NAN;
    if (!isnan(floor) || sys->kind != SW_SYS_PARTICLES)
        return floor;
    double cx, cy, mu;
    if (sw_particles_spring_count(&sys->particles) == 0 || sw_particles_central(&sys->particles, &cx, &cy, &mu))
        return NAN; /* free flight or an orbit: the potential has no bottom */
    return resting_energy(sys);
}

/* The floor depends on the parameters only: worked out once. */
double sw_sim_energy_floor(const sw_sim *s)
{
    struct sw_sim_derived *d = s->derived;
    if (!d->have_floor) {
        d->floor = isfinite(s->energy0) ? system_energy_floor(&s->sys) : NAN;
        d->have_floor = 1;
    }
    return d->floor;
}

int sw_sim_energy_scale_is_motion(const sw_sim *s)
{
    return s->energy0 - sw_sim_energy_floor(s) > 1e-12 * fabs(s->energy0);
}

double sw_sim_energy_scale(const sw_sim *s)
{
    if (sw_sim_energy_scale_is_motion(s))
        return s->energy0 - sw_sim_energy_floor(s);
    return fabs(s->energy0) > 0 ? fabs(s->energy0) : NAN;
}

double sw_sim_energy_drift(const sw_sim *s)
{
    double scale = sw_sim_energy_scale(s);
    return 100.0 * (sw_sim_energy(s) - s->energy0) / scale;
}

double sw_sim_energy_drift_error(const sw_sim *s)
{
    double bound = sw_sim_energy_error(s) + s->derived->energy0_error;
    return bound > 0 ? 100.0 * bound / fabs(sw_sim_energy_scale(s)) : 0;
}

double sw_sim_exact_error(const sw_sim *s, double *scratch)
{
    const sw_scene *sc = s->sys.scene;
    if (!sc->exact || sc->exact(&s->sys, s->t, scratch) != 0)
        return NAN;
    double m = 0;
    for (int i = 0; i < s->sys.ode->dim; i++) {
        double d = fabs(s->sys.y[i] - scratch[i]);
        if (!(d <= m))
            m = d;
    }
    return m;
}

/* Worked out once per state: an O(n) pass that the status line and a
 * page's goals ask for on every frame. */
double sw_sim_drift(const sw_sim *s)
{
    struct sw_sim_derived *d = s->derived;
    if (!d->have_drift) {
        const sw_scene *sc = s->sys.scene;
        d->drift = sc->drift ? sc->drift(&s->sys, s->sys.y) : NAN;
        d->have_drift = 1;
    }
    return d->drift;
}

int sw_sim_alive(const sw_sim *s, int i)
{
    const sw_scene *sc = s->sys.scene;
    return sc->alive ? sc->alive(&s->sys, s->t, s->sys.y, i) : 1;
}

int sw_sim_refused(const char *reason)
{
    return strncmp(reason, SW_PLUGIN_REFUSED, strlen(SW_PLUGIN_REFUSED)) == 0;
}
