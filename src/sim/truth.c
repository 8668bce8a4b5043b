/* The true state, the error norm, the energy of the motion, and which
 * methods a scene takes: the half of the truth module that is about one
 * run. (Linear stability is in truth_stability.c.) Invariant: the true
 * state comes from the scene's closed form only where the scene says it
 * holds for these parameters; everywhere else from one reference run at
 * SW_TRUTH_RTOL / SW_TRUTH_ATOL. */
#include "sim/truth.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/particles_solve.h"
#include "stepwise/stepwise.h"

const sw_integrator *sw_truth_reference_method(void)
{
    for (int i = 0; i < sw_integrator_count(); i++)
        if (sw_integrator_at(i)->reference)
            return sw_integrator_at(i); /* a built-in's row says so (integrators.c) */
    return NULL;
}

sw_truth_source sw_truth_source_of(const sw_system *sys, char *why, size_t whylen)
{
    const sw_scene *sc = sys->scene;
    const char *fails = sc->exact && sc->exact_fails ? sc->exact_fails(sys) : NULL;
    if (sc->exact && !fails) {
        if (why && whylen)
            why[0] = '\0';
        return SW_TRUTH_EXACT;
    }
    /* A scene with events is run with them located: then tight runs converge. */
    int located = sw_system_event_count(sys) > 0;
    if (sc->no_truth) {
        if (why)
            snprintf(why, whylen, "%s", sc->no_truth);
        return SW_TRUTH_NONE;
    }
    if (sc->reference || located) {
        if (why)
            snprintf(why, whylen, "%s%s%s", fails ? fails : "no closed form",
                     fails ? ": measured against a tight reference run" : "",
                     fails && located ? " with its events located" : "");
        return SW_TRUTH_REFERENCE;
    }
    if (why)
        snprintf(why, whylen, "%s, and events at step boundaries make every run first order, "
                 "so no run is a trustworthy reference", fails ? fails : "no closed form");
    return SW_TRUTH_NONE;
}

int sw_truth_init(sw_truth *tr, const sw_scene *sc, const double *p, char *err, size_t errlen)
{
    memset(tr, 0, sizeof *tr);
    tr->t = NAN;
    int rc = sw_system_build(&tr->sys, sc, p, err, errlen);
    if (rc != SW_OK)
        return rc;
    tr->source = sw_truth_source_of(&tr->sys, tr->why, sizeof tr->why);
    tr->frame = sc->dt;
    tr->y = malloc((size_t)tr->sys.ode->dim * sizeof *tr->y);
    if (!tr->y) {
        sw_system_free(&tr->sys);
        snprintf(err, errlen, "out of memory for a %d-long state", tr->sys.ode->dim);
        return SW_ENOMEM;
    }
    return SW_OK;
}

void sw_truth_free(sw_truth *tr)
{
    if (tr->have_ref)
        sw_sim_free(&tr->ref);
    tr->have_ref = 0;
    free(tr->y);
    tr->y = NULL;
    if (tr->sys.ode)
        sw_system_free(&tr->sys);
}

/* (Re)start the reference run at t = 0. */
static int start_reference(sw_truth *tr)
{
    char err[SW_ERRLEN];
    if (tr->have_ref)
        sw_sim_free(&tr->ref);
    tr->have_ref = 0;
    const sw_scene *sc = tr->sys.scene;
    if (sw_sim_init(&tr->ref, sc, tr->sys.p, sw_truth_reference_method(), tr->frame, err, sizeof err) != SW_OK)
        return -1;
    sw_sim_set_tolerances(&tr->ref, SW_TRUTH_RTOL, SW_TRUTH_ATOL);
    if (sw_sim_set_events(&tr->ref, SW_EVENTS_LOCATE, err, sizeof err) != SW_OK) {
        sw_sim_free(&tr->ref);
        return -1;
    }
    tr->have_ref = 1;
    return 0;
}

double sw_truth_eval_work(const sw_system *sys, double *solve)
{
    if (sys->kind == SW_SYS_PARTICLES)
        return sw_particles_work(&sys->particles, solve);
    return *solve = sys->ode->dim;
}

double sw_truth_step_work(const sw_system *sys, const sw_integrator *m)
{
    double solve, eval = sw_truth_eval_work(sys, &solve);
    double evals = m->evals > 0 ? m->evals : 1;
    if (!(m->flags & SW_IMPLICIT))
        return evals * eval;
    return 4 * evals * eval + 3 * fmax(0, solve - eval);
}

double sw_truth_reference_cost(sw_truth *tr, double t_end)
{
    if (tr->source != SW_TRUTH_REFERENCE)
        return 0;
    sw_sim pilot;
    char err[SW_ERRLEN];
    const sw_scene *sc = tr->sys.scene;
    const sw_integrator *ref = sw_truth_reference_method();
    double step = ref ? sw_truth_step_work(&tr->sys, ref) : INFINITY;
    if (20 * step > SW_TRUTH_PILOT_MAX) /* the pilot alone would be out of reach (a galaxy of 1e5 stars): */
        return t_end / sc->dt * step;  /* at the scene's step, which a tight run does not exceed much */
    if (sw_sim_init(&pilot, sc, tr->sys.p, sw_truth_reference_method(), sc->dt, err, sizeof err) != SW_OK)
        return INFINITY;
    sw_sim_set_tolerances(&pilot, SW_TRUTH_RTOL, SW_TRUTH_ATOL);
    if (sw_sim_set_events(&pilot, SW_EVENTS_LOCATE, err, sizeof err) != SW_OK) {
        sw_sim_free(&pilot);
        return INFINITY;
    }
    int k;
    for (k = 0; k < 20 && pilot.t < t_end; k++)
        if (sw_sim_step_until(&pilot, t_end))
            break;
    double cost = INFINITY;
    if (!pilot.blown && pilot.t > 0) {
        double per_time = (double)sw_sim_evals(&pilot) / pilot.t;
        double solve;
        cost = per_time * t_end * sw_truth_eval_work(&pilot.sys, &solve);
    }
    sw_sim_free(&pilot);
    return cost;
}

/* Run the reference to t, as sw_sim_run_until does, but stop once it
 * spends SW_TRUTH_CRAWL times the evaluations its first steps predicted
 * (plus SW_TRUTH_CRAWL_SLACK). 0, or 1 (blown or crawling: why says which). */
static int reference_until(sw_truth *tr, double t)
{
    sw_sim *s = &tr->ref;
    while (t - s->t > 1e-9 * s->dt) {
        if (sw_sim_step_until(s, t))
            return 1;
        long evals = sw_sim_evals(s);
        if (tr->max_evals > 0 && evals > tr->max_evals) {
            snprintf(tr->why, sizeof tr->why, "a reference run to t = %.4g would cost more than the budget "
                     "allows (%ld evaluations by t = %.4g)", t, evals, s->t);
            return 1;
        }
        if (tr->ref_rate == 0 && (s->steps >= 20 || s->t >= t) && s->t > 0)
            tr->ref_rate = (double)evals / s->t;
        if (tr->ref_rate > 0 && (double)evals > SW_TRUTH_CRAWL * tr->ref_rate * t + SW_TRUTH_CRAWL_SLACK) {
            snprintf(tr->why, sizeof tr->why, "the reference run crawls (%ld evaluations by t = %.4g, %.0f times "
                     "what its first steps predicted: contacts every step, as with balls at rest on a floor)",
                     evals, s->t, (double)evals / (tr->ref_rate * t));
            return 1;
        }
    }
    return s->blown;
}

const double *sw_truth_at(sw_truth *tr, double t)
{
    if (tr->t == t)
        return tr->y;
    int dim = tr->sys.ode->dim;
    if (tr->source == SW_TRUTH_EXACT) {
        if (tr->sys.scene->exact(&tr->sys, t, tr->y) != 0)
            return NULL;
    } else if (tr->source == SW_TRUTH_REFERENCE && !tr->failed) {
        if ((!tr->have_ref || tr->ref.t > t) && start_reference(tr) != 0) {
            tr->failed = 1;
            return NULL;
        }
        if (reference_until(tr, t) != 0) {
            tr->failed = 1;
            return NULL;
        }
        memcpy(tr->y, tr->ref.sys.y, (size_t)dim * sizeof *tr->y);
    } else {
        return NULL;
    }
    tr->t = t;
    return tr->y;
}

int sw_truth_state(const sw_scene *sc, const double *p, double t, double *out)
{
    sw_truth tr;
    char err[SW_ERRLEN];
    if (sw_truth_init(&tr, sc, p, err, sizeof err) != SW_OK)
        return -1;
    const double *y = sw_truth_at(&tr, t);
    if (y)
        memcpy(out, y, (size_t)tr.sys.ode->dim * sizeof *out);
    sw_truth_free(&tr);
    return y ? 0 : -1;
}

double sw_truth_sample_time(double T, int j)
{
    return j >= SW_TRUTH_SAMPLES ? T : T * j / SW_TRUTH_SAMPLES;
}

int sw_truth_first_sample(double T, double dt)
{
    return dt <= 0.5 * T / SW_TRUTH_SAMPLES ? 1 : SW_TRUTH_SAMPLES;
}

double sw_truth_error(int dim, const double *y, const double *truth)
{
    /* the largest by running maxima, any NaN by a flag: no branch per
     * component, four independent chains in registers (a frame asks this
     * of 2e5 components per run shown); a maximum is the same in any order */
    double m0 = 0, m1 = 0, m2 = 0, m3 = 0;
    int nan = 0, i = 0;
    for (; i + 4 <= dim; i += 4) {
        double d0 = fabs(y[i] - truth[i]), d1 = fabs(y[i + 1] - truth[i + 1]);
        double d2 = fabs(y[i + 2] - truth[i + 2]), d3 = fabs(y[i + 3] - truth[i + 3]);
        m0 = d0 > m0 ? d0 : m0;
        m1 = d1 > m1 ? d1 : m1;
        m2 = d2 > m2 ? d2 : m2;
        m3 = d3 > m3 ? d3 : m3;
        nan |= (d0 != d0) | (d1 != d1) | (d2 != d2) | (d3 != d3);
    }
    for (; i < dim; i++) {
        double d = fabs(y[i] - truth[i]);
        m0 = d > m0 ? d : m0;
        nan |= d != d;
    }
    double a = m0 > m1 ? m0 : m1, b = m2 > m3 ? m2 : m3;
    return nan ? NAN : a > b ? a : b;
}

int sw_truth_method_applies(const sw_scene *sc, const sw_integrator *m, char *why, size_t whylen)
{
    if ((m->flags & SW_NEEDS_SECOND_ORDER) && sc->kind == SW_SYS_FLOW) {
        snprintf(why, whylen, "'%s' updates velocities and positions separately and needs a system "
                 "with masses; %s is a flow field with positions only", m->name, sc->name);
        return 0;
    }
    return 1;
}
