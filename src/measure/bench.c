/* Work–precision sweeps: each method runs a scene to its report time at a
 * geometric sequence of step sizes (tolerances for adaptive methods); each run
 * records its error against the exact solution or a cached dop853 reference (sw_truth_reference_method),
 * its evaluations and its wall time. Invariant: every run is an sw_sim
 * advanced by sw_sim_run_until, exactly as the UI and the recorder advance
 * it; this file measures and fits (bench_plot.c renders), it never prints. */
#include "measure/bench.h"

#include "sim/truth.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/base.h"
#include "util/clock.h"

#define MAX_REPEATS 15

void sw_bench_config_default(sw_bench_config *c)
{
    *c = (sw_bench_config){ .min_points = 8, .max_points = 16, .fit_points = 4, .fine = 1e-6, .settled = 6,
                            .repeats = 3,
                            .repeat_below = 0.05, .max_work = 1e8 };
}

void sw_bench_config_quick(sw_bench_config *c)
{
    *c = (sw_bench_config){ .min_points = 6, .max_points = 8, .fit_points = 3, .repeats = 1,
                            .repeat_below = 0.0, .max_work = 1e7 };
}

static double max_abs_diff(int n, const double *a, const double *b)
{
    double m = 0;
    for (int i = 0; i < n; i++) {
        double d = fabs(a[i] - b[i]);
        if (!(d <= m)) /* NaN wins */
            m = d;
    }
    return m;
}

/* The sim's state carried to exactly time T: sw_sim_run_until may stop up to
 * 1e-9·dt short of T, so add (T - t)·f(t, y), leaving an O((T - t)²) error.
 * Uses one evaluation; callers read the counters first. */
static void state_at(sw_sim *s, double T, double *out, double *deriv)
{
    int n = s->sys.ode->dim;
    memcpy(out, s->sys.y, (size_t)n * sizeof *out);
    double gap = T - s->t;
    if (gap != 0) {
        sw_ode_eval(s->sys.ode, s->t, s->sys.y, deriv);
        for (int i = 0; i < n; i++)
            out[i] += gap * deriv[i];
    }
}

int sw_bench_measurable(const sw_scene *sc, const double *p, char *why, size_t whylen)
{
    sw_system sys;
    char err[SW_ERRLEN];
    if (sc->no_truth) { /* the truth module's word: no error that means anything here */
        snprintf(why, whylen, "%s has no error to measure: %s", sc->name, sc->no_truth);
        return 0;
    }
    if (sw_system_build(&sys, sc, p, err, sizeof err) != SW_OK) {
        snprintf(why, whylen, "%s", err);
        return 0;
    }
    int ok = 0;
    double *y = malloc((size_t)sys.ode->dim * sizeof *y);
    if (y && sc->exact && sc->exact(&sys, sc->duration, y) == 0)
        ok = 1;
    else if (sc->reference || sw_system_event_count(&sys) > 0) /* events: located in the reference */
        ok = 1;
    else
        snprintf(why, whylen, "%s has no exact solution%s and no trustworthy reference (events at "
                 "step boundaries make every run, rk45 too, only first order)", sc->name,
                 sc->exact ? " for these parameters" : "");
    free(y);
    sw_system_free(&sys);
    return ok;
}

static double sample_time(const sw_bench_report *r, int j) { return sw_truth_sample_time(r->t_report, j); }

/* One reference run to the report time at the given tolerances, the state
 * at every sample time into out (SW_BENCH_SAMPLES × dim). */
/* Another thread asked the sweep to end (stop set): err says so. */
static int stopped(const atomic_int *stop, char *err, size_t errlen)
{
    if (!stop || !atomic_load(stop))
        return 0;
    snprintf(err, errlen, "stopped");
    return 1;
}

static int reference_run(sw_bench_report *r, double rtol, double atol, double *out, double *deriv,
                         char *err, size_t errlen)
{
    const sw_integrator *m = sw_truth_reference_method();
    double dt = fmax(SW_DT_MIN, fmin(fmin(r->t_report, 8.0 * r->scene->dt), SW_DT_MAX));
    sw_sim s;
    int rc = sw_sim_init(&s, r->scene, r->p, m, dt, err, errlen);
    if (rc != SW_OK)
        return rc;
    sw_sim_set_tolerances(&s, rtol, atol);
    /* events located: only then do tight runs converge through them */
    if ((rc = sw_sim_set_events(&s, SW_EVENTS_LOCATE, err, errlen)) != SW_OK) {
        sw_sim_free(&s);
        return rc;
    }
    for (int j = 1; j <= SW_BENCH_SAMPLES && rc == SW_OK; j++) {
        double t = sample_time(r, j);
        if (stopped(r->stop, err, errlen)) {
            rc = SW_EINVAL;
        } else if (sw_sim_run_until(&s, t)) {
            snprintf(err, errlen, "%s: the %s reference run (rtol %g) failed at t = %g: %s",
                     r->scene->name, m->name, rtol, s.blow_time, s.blow_reason);
            rc = SW_EDIVERGED;
        } else {
            state_at(&s, t, out + (size_t)(j - 1) * (size_t)r->dim, deriv);
        }
    }
    if (rc == SW_OK)
        r->ref_evals += sw_sim_evals(&s);
    sw_sim_free(&s);
    return rc;
}

/* sw_bench_init, ending early (SW_EINVAL, "stopped") when another thread
 * sets stop. */
static int sw_bench_init_stoppable(sw_bench_report *r, const sw_scene *sc, const double *p, const atomic_int *stop,
                                   char *err, size_t errlen);

int sw_bench_init(sw_bench_report *r, const sw_scene *sc, const double *p, char *err, size_t errlen)
{
    return sw_bench_init_stoppable(r, sc, p, NULL, err, errlen);
}

static int sw_bench_init_stoppable(sw_bench_report *r, const sw_scene *sc, const double *p, const atomic_int *stop,
                                   char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    r->stop = stop;
    r->scene = sc;
    sw_scene_fill(sc, p, r->p);
    r->t_report = sc->duration;
    r->omega = NAN;
    sw_system sys;
    int rc = sw_system_build(&sys, sc, r->p, err, errlen);
    if (rc != SW_OK)
        return rc;
    r->dim = sys.ode->dim;
    if (sw_truth_spectrum(&sys, 0.0, sys.y, &r->spectrum) == 0 && r->spectrum.largest > 0)
        r->omega = r->spectrum.largest;
    else
        r->spectrum.n = 0;
    size_t all = (size_t)SW_BENCH_SAMPLES * (size_t)r->dim;
    r->samples = malloc(all * sizeof *r->samples);
    double *work = malloc((all + (size_t)r->dim) * sizeof *work);
    if (!r->samples || !work) {
        sw_system_free(&sys);
        free(work);
        sw_bench_free(r);
        snprintf(err, errlen, "out of memory for a %d-long reference state", r->dim);
        return SW_ENOMEM;
    }
    int exact = sc->exact != NULL;
    for (int j = 1; j <= SW_BENCH_SAMPLES && exact; j++)
        exact = sc->exact(&sys, sample_time(r, j), r->samples + (size_t)(j - 1) * (size_t)r->dim) == 0;
    if (exact) {
        r->source = SW_BENCH_EXACT;
    } else if (sc->reference || sw_system_event_count(&sys) > 0) {
        /* The reference, and a 10x looser run whose distance from it bounds
         * the reference's own error from above (an embedded
         * method's global error scales roughly with the tolerance); both within the budget. */
        r->source = SW_BENCH_REFERENCE;
        sw_truth tr;
        double cost = INFINITY;
        if (sw_truth_init(&tr, sc, r->p, err, errlen) == SW_OK) {
            cost = 2.2 * sw_truth_reference_cost(&tr, r->t_report);
            sw_truth_free(&tr);
        }
        if (!(cost <= SW_WORK_REPORT)) {
            snprintf(err, errlen, "%s: the reference runs to t = %g would cost about %.2g state evaluations, over "
                     "the budget of %.0e; use fewer particles", sc->name, r->t_report, cost, SW_WORK_REPORT);
            rc = SW_EINVAL;
        } else {
            rc = reference_run(r, SW_TRUTH_RTOL, SW_TRUTH_ATOL, r->samples, work, err, errlen);
        }
        if (rc == SW_OK)
            rc = reference_run(r, 10 * SW_TRUTH_RTOL, 10 * SW_TRUTH_ATOL, work + r->dim, work, err, errlen);
        if (rc == SW_OK)
            r->ref_error = max_abs_diff((int)all, r->samples, work + r->dim);
    } else {
        sw_bench_measurable(sc, r->p, err, errlen);
        rc = SW_EINVAL;
    }
    sw_system_free(&sys);
    free(work);
    if (rc != SW_OK) {
        sw_bench_free(r);
        return rc;
    }
    r->truth = r->samples + (all - (size_t)r->dim);
    r->scale = 1.0;
    for (size_t i = 0; i < all; i++)
        r->scale = fmax(r->scale, fabs(r->samples[i]));
    return SW_OK;
}

void sw_bench_free(sw_bench_report *r)
{
    free(r->samples);
    r->samples = NULL;
    r->truth = NULL;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Run method m at (dt, rtol) `repeats` times; the first run gives the error
 * and counters (every run is identical: the sim is deterministic), the median
 * of all runs the time. *work gets evals × an evaluation's work plus
 * solver iterations × a solve's (sw_truth_eval_work). */
static int run_point(const sw_bench_report *r, const sw_integrator *m, double dt, double rtol,
                     const sw_bench_config *c, sw_bench_point *pt, double *work, double *scratch,
                     char *err, size_t errlen)
{
    double times[MAX_REPEATS];
    int repeats = c->repeats < 1 ? 1 : c->repeats > MAX_REPEATS ? MAX_REPEATS : c->repeats;
    int nrep = 0;
    memset(pt, 0, sizeof *pt);
    pt->dt = dt;
    pt->rtol = rtol;
    for (int rep = 0; rep < repeats; rep++) {
        sw_sim s;
        int rc = sw_sim_init(&s, r->scene, r->p, m, dt, err, errlen);
        if (rc != SW_OK)
            return rc;
        if (rtol > 0)
            sw_sim_set_tolerances(&s, rtol, 1e-3 * rtol);
        else if (m->flags & SW_ADAPTIVE) /* its formula on fixed steps dt */
            sw_sim_set_tolerances(&s, SW_TOL_NONE, SW_TOL_NONE);
        rc = sw_sim_set_events(&s, r->events, err, errlen);
        if (rc != SW_OK) {
            sw_sim_free(&s);
            return rc;
        }
        /* to each sample time in turn (the step before it shortened to
         * meet it), the error there; the clock runs only while stepping. A
         * fixed step coarser than half the samples' spacing is measured at
         * the report time alone (sw_truth_first_sample). */
        int first = rtol > 0 ? 1 : sw_truth_first_sample(r->t_report, dt);
        double seconds = 0, error = 0;
        long evals = 0;
        for (int j = first; j <= SW_BENCH_SAMPLES && !s.blown; j++) {
            if (stopped(c->stop, err, errlen)) {
                sw_sim_free(&s);
                return SW_EINVAL;
            }
            double t = sample_time(r, j), t0 = sw_clock_now();
            sw_sim_run_until(&s, t);
            seconds += sw_clock_now() - t0;
            if (rep > 0 || s.blown)
                continue;
            evals = sw_sim_evals(&s);
            double e;
            if (r->source == SW_BENCH_EXACT) {
                e = sw_sim_exact_error(&s, scratch);
            } else {
                state_at(&s, t, scratch, scratch + r->dim);
                e = max_abs_diff(r->dim, scratch, r->samples + (size_t)(j - 1) * (size_t)r->dim);
            }
            if (!(e <= error)) /* NaN wins */
                error = e;
        }
        times[nrep++] = seconds;
        if (rep == 0) {
            pt->evals = s.blown ? sw_sim_evals(&s) : evals; /* state_at's evaluation not counted */
            pt->solves = s.sys.ode->solves;
            pt->steps = s.steps;
            pt->blown = s.blown;
            pt->blow_time = s.blow_time;
            double solve, eval = sw_truth_eval_work(&s.sys, &solve);
            *work = (double)pt->evals * eval + (double)s.sys.ode->solver_iters * solve;
            pt->error = s.blown ? NAN : error;
        }
        sw_sim_free(&s);
        if (times[0] >= c->repeat_below)
            break;
    }
    qsort(times, (size_t)nrep, sizeof times[0], cmp_double);
    pt->seconds = nrep % 2 ? times[nrep / 2] : 0.5 * (times[nrep / 2 - 1] + times[nrep / 2]);
    pt->repeats = nrep;
    pt->h = rtol > 0 ? r->t_report / (double)(pt->steps > 0 ? pt->steps : 1) : dt;
    /* Round-off grows at most about linearly with the steps taken; a
     * reference carries its own error besides. */
    pt->floor = sw_bench_roundoff(r->scale, pt->steps) + r->ref_error;
    return SW_OK;
}

/* The first step of the sweep: eight default steps, or twice the method's
 * limit in theory on the scene's spectrum at the start, so the sweep shows
 * the method failing as well as converging; at most half the report time. */
static double sweep_top(const sw_bench_report *r, const sw_integrator *m)
{
    double top = 8.0 * r->scene->dt;
    int unbounded;
    double limit = r->spectrum.n > 0 ? sw_truth_limit(m, &r->spectrum, SW_DT_MAX, &unbounded) : NAN;
    if (limit > 0 && isfinite(limit) && !unbounded)
        top = fmax(top, 2.0 * limit);
    top = fmin(top, 0.5 * r->t_report);
    return fmax(SW_DT_MIN, fmin(top, SW_DT_MAX));
}

/* Three points down where no finer one falls below SW_BENCH_STALL of the
 * first (find_plateau's test, on the last three): a plateau. */
static int stalled(const sw_bench_point *pts, int k)
{
    return k >= 2 && !pts[k - 2].blown && !pts[k - 1].blown && !pts[k].blown &&
           !(pts[k - 1].error < SW_BENCH_STALL * pts[k - 2].error) &&
           !(pts[k].error < SW_BENCH_STALL * pts[k - 2].error);
}

/* One sweep of method m into pts (*npts points): the tolerance 1e-2,
 * 1e-3, ... (controlled, adaptive methods only), or fixed steps down by a
 * factor 2^(1/q) a point, q = ceil(p/4) for an adaptive method (so that a
 * step cuts the error by about 2^4 at most and a high order still has
 * points between 1e-2 and round-off; every q-th step an exact halving), 2
 * otherwise. Fixed steps start at sweep_top, or for an adaptive method at
 * its coarsest controlled run's mean step when that is larger (where its
 * error is near the tolerance 1e-2: sweep_top's 8 dt is already at 1e-9
 * for dop853 on the orbit). A fixed sweep ends as the order fit allows
 * (se's order points are pts); a controlled one at its floor, its
 * plateau, or min_points and an error two decades under fine (the
 * cheapest-run table's 1e-8). */
static int sweep(sw_bench_report *r, const sw_integrator *m, const sw_bench_config *c, int controlled,
                 sw_bench_series *se, sw_bench_point *pts, int *npts, double *scratch, char *err, size_t errlen)
{
    int adaptive = (m->flags & SW_ADAPTIVE) != 0, rc = SW_OK;
    int maxp = c->max_points < 1 ? 1 : c->max_points > SW_BENCH_MAX_POINTS ? SW_BENCH_MAX_POINTS : c->max_points;
    /* Controlled runs choose their own steps: allow up to half the report time. */
    double top = controlled ? fmax(SW_DT_MIN, fmin(0.5 * r->t_report, SW_DT_MAX)) : sweep_top(r, m);
    for (int j = 0; !controlled && adaptive && j < se->npoints; j++)
        if (!se->points[j].blown && se->points[j].h > top)
            top = fmin(se->points[j].h, fmax(SW_DT_MIN, fmin(0.5 * r->t_report, SW_DT_MAX)));
    int q = adaptive ? (m->order + 3) / 4 : 1;
    if (q < 1)
        q = 1;
    /* An adaptive method's fixed steps divide the samples' spacing T/16
     * exactly (m steps to each): every step is dt, none cut short to land
     * on a sample time. A cut step's share of the error changes from one
     * dt to the next without pattern (its length is the spacing modulo
     * dt), about dt/spacing of the error: enough to scatter a high order's
     * local slopes (dop853 read 6.99 on the orbit). */
    double spacing = r->t_report / SW_BENCH_SAMPLES;
    long mk = (long)fmax(1.0, ceil(spacing / top - 1e-9));
    int fixed_adaptive = !controlled && adaptive, coarse = 0;
    /* Before the first run, guess its work from the nominal evaluations. */
    double est = ceil(r->t_report / top) * (m->evals > 0 ? m->evals : 1) * r->dim;
    int stop = SW_BENCH_STOP_MAX;
    *npts = 0;
    for (int k = 0, runs = 0; k < maxp && runs < 4 * SW_BENCH_MAX_POINTS; k++, runs++) {
        double dt = controlled ? top : fixed_adaptive ? spacing / (double)mk : ldexp(top, -k);
        double rtol = controlled ? 1e-2 * pow(10.0, -k) : 0.0;
        if (dt < SW_DT_MIN) {
            stop = SW_BENCH_STOP_DT_MIN;
            break;
        }
        if (est > c->max_work) {
            stop = SW_BENCH_STOP_BUDGET;
            break;
        }
        sw_bench_point *pt = &pts[k];
        double work = 0;
        rc = run_point(r, m, dt, rtol, c, pt, &work, scratch, err, errlen);
        if (rc != SW_OK)
            break;
        *npts = k + 1;
        /* Next run: a fixed step dt·2^(-1/q) takes 2^(1/q) times the steps; a
         * 10x tighter tolerance costs DP5 about 10^(1/5) = 1.6x as many
         * steps (2x to be safe). A run that blew up stopped early: scale
         * its per-step cost. */
        double per_step = work / (double)(pt->steps > 0 ? pt->steps : 1);
        double steps_next = controlled ? 2.0 * (double)pt->steps : ceil(r->t_report * exp2(1.0 / q) / dt);
        est = per_step * steps_next;
        if (!pt->blown && pt->error <= pt->floor) {
            stop = SW_BENCH_STOP_FLOOR;
            break;
        }
        if (fixed_adaptive) {
            /* Too coarse to fit (blown, or 1e-2 of the state or more):
             * halve, and let the next run take this one's place when the
             * one before was too coarse as well; in range: the next by
             * 2^(1/q) (at least one step more to each spacing). So the
             * sweep's points lie where an order can be read, on an orbit
             * whose pericentre wants 1e4 fixed steps too. */
            int was_coarse = coarse;
            coarse = pt->blown || !(pt->error < SW_BENCH_CEILING * r->scale);
            long next = lround((double)mk * exp2(1.0 / q));
            mk = coarse ? 2 * mk : next > mk ? next : mk + 1;
            est = per_step * (double)SW_BENCH_SAMPLES * (double)mk; /* T/dt steps */
            if (coarse && was_coarse && k > 0) {
                pts[k - 1] = *pt;
                *npts = k;
                k--;
                continue;
            }
        }
        if (controlled) {
            if (k + 1 >= c->min_points && (stalled(pts, k) || pt->error <= 1e-2 * c->fine * r->scale)) {
                stop = stalled(pts, k) ? SW_BENCH_STOP_FLOOR : SW_BENCH_STOP_ENOUGH;
                break;
            }
            continue;
        }
        /* three points on a plateau down where only round-off is left:
         * finer steps only cost */
        sw_bench_fit(r, se);
        if (k + 1 >= c->min_points && se->plateau >= 0 && se->plateau <= k - 2 &&
            se->floor <= SW_BENCH_ROUNDOFF * (pts[se->plateau].floor - r->ref_error)) {
            stop = SW_BENCH_STOP_FLOOR;
            break;
        }
        if (k + 1 >= c->min_points && !fixed_adaptive) { /* fixed_adaptive: on to round-off, the finest window */
            int small = pt->error <= c->fine * r->scale || (c->settled > 0 && se->nfit >= c->settled);
            if (se->nfit >= c->fit_points && se->asymptotic && small) {
                stop = SW_BENCH_STOP_ENOUGH;
                break;
            }
        }
    }
    if (!controlled)
        se->stop = stop;
    return rc;
}

int sw_bench_sweep(sw_bench_report *r, const sw_integrator *m, const sw_bench_config *c, char *err,
                   size_t errlen)
{
    if (r->nseries == SW_BENCH_MAX_METHODS) {
        snprintf(err, errlen, "at most %d methods per report", SW_BENCH_MAX_METHODS);
        return SW_EINVAL;
    }
    sw_system sys;
    int rc = sw_system_build(&sys, r->scene, r->p, err, errlen);
    if (rc != SW_OK)
        return rc;
    rc = sw_integrator_accepts(m, sys.ode, err, errlen);
    sw_system_free(&sys);
    if (rc != SW_OK)
        return rc;
    double *scratch = malloc((size_t)2 * r->dim * sizeof *scratch);
    if (!scratch) {
        snprintf(err, errlen, "out of memory for a %d-long state", r->dim);
        return SW_ENOMEM;
    }
    sw_bench_series *se = &r->series[r->nseries];
    memset(se, 0, sizeof *se);
    se->method = m;
    /* an adaptive method's controlled runs (the ones its users make), then
     * its formula on fixed steps for the order */
    if (m->flags & SW_ADAPTIVE) {
        rc = sweep(r, m, c, 1, se, se->points, &se->npoints, scratch, err, errlen);
        if (rc == SW_OK && !c->no_fixed)
            rc = sweep(r, m, c, 0, se, se->fixed, &se->nfixed, scratch, err, errlen);
    } else {
        rc = sweep(r, m, c, 0, se, se->points, &se->npoints, scratch, err, errlen);
    }
    free(scratch);
    if (rc != SW_OK)
        return rc;
    sw_bench_fit(r, se);
    r->nseries++;
    return SW_OK;
}

int sw_bench_sweep_all(sw_bench_report *r, const sw_integrator *const *methods, int nmethods,
                       const sw_bench_config *c, char *err, size_t errlen)
{
    int count = methods ? nmethods : sw_integrator_count();
    sw_system sys;
    int rc = sw_system_build(&sys, r->scene, r->p, err, errlen);
    if (rc != SW_OK)
        return rc;
    for (int i = 0; i < count && rc == SW_OK; i++) {
        const sw_integrator *m = methods ? methods[i] : sw_integrator_at(i);
        char why[SW_ERRLEN];
        if (sw_integrator_accepts(m, sys.ode, why, sizeof why) != SW_OK)
            continue;
        rc = sw_bench_sweep(r, m, c, err, errlen);
    }
    sw_system_free(&sys);
    return rc;
}

/* The quick config for a budget: up front, the two reference runs and, per
 * method, a sweep whose runs double in cost to max_work (under 2·max_work
 * each). Three quarters of the budget go to the sweeps: with the UI's
 * 4·SW_WORK_KEY that is the quick config's own max_work. */
/* The UI's plot shows no order: its adaptive methods sweep their
 * controlled runs only, one sweep a method. */
static void quick_config(sw_bench_config *c, double budget)
{
    sw_bench_config_quick(c);
    c->no_fixed = 1;
    c->max_work = fmin(c->max_work, 0.75 * budget / (2.0 * sw_integrator_count()));
}

int sw_bench_quick_affordable(const sw_scene *sc, const double *p, double ref_cost, double budget, char *err,
                              size_t errlen)
{
    sw_bench_config c;
    quick_config(&c, budget);
    if (isnan(ref_cost)) {
        sw_truth tr;
        if (sw_truth_init(&tr, sc, p, err, errlen) != SW_OK)
            return 0;
        ref_cost = sw_truth_reference_cost(&tr, sc->duration);
        sw_truth_free(&tr);
    }
    double cost = 2.2 * ref_cost + 2.0 * c.max_work * sw_integrator_count();
    if (!(cost <= budget)) {
        snprintf(err, errlen, "the sweep would cost about %.2g state evaluations, over the %.0e the plot may "
                 "spend (fewer particles, or stepwise bench in a shell)", cost, budget);
        return 0;
    }
    return 1;
}

int sw_bench_scene_quick(sw_bench_report *r, const sw_scene *sc, const double *p, double budget,
                         const atomic_int *stop, char *err, size_t errlen)
{
    if (!sw_bench_quick_affordable(sc, p, NAN, budget, err, errlen))
        return SW_EINVAL;
    sw_bench_config c;
    quick_config(&c, budget);
    c.stop = stop;
    int rc = sw_bench_init_stoppable(r, sc, p, stop, err, errlen);
    if (rc != SW_OK)
        return rc;
    rc = sw_bench_sweep_all(r, NULL, 0, &c, err, errlen);
    if (rc != SW_OK)
        sw_bench_free(r);
    return rc;
}

int sw_bench_cheapest(const sw_bench_report *r, double level, int by_evals, int *point)
{
    int best = -1;
    double best_cost = INFINITY;
    for (int i = 0; i < r->nseries; i++)
        for (int j = 0; j < r->series[i].npoints; j++) {
            const sw_bench_point *pt = &r->series[i].points[j];
            if (pt->blown || !(pt->error <= level))
                continue;
            double cost = by_evals ? (double)pt->evals : pt->seconds;
            if (cost < best_cost) {
                best_cost = cost;
                best = i;
                *point = j;
            }
        }
    return best;
}

char sw_bench_marker(const sw_integrator *m)
{
    for (int i = 0; i < sw_integrator_count(); i++)
        if (sw_integrator_at(i) == m)
            return i < 9 ? (char)('1' + i) : i < 9 + 26 ? (char)('a' + i - 9) : '?';
    return '?';
}
