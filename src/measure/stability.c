/* Stability limits by bisection beside the theory. A probe runs the sim for
 * a fixed simulated time (so slow growth at small steps has as long to show
 * as fast growth at large ones) and feeds the energy of the motion to a
 * growth watch (sim/watch.c); unstable when the run blows up or the watch
 * sees growth. No twin runs: numerical runs part by chaos as exact ones do,
 * and at large steps faster, without the method being unstable (a plucked
 * chain under symplectic Euler). The theory comes from the truth module. */
#include "measure/stability.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim/truth.h"
#include "stepwise/stepwise.h"

#define TWO_PI 6.283185307179586

void sw_stability_config_default(sw_stability_config *c)
{
    *c = (sw_stability_config){ .periods = 100, .reports = 20, .min_steps = 400, .max_steps = 4000000,
                                .low = 0.01, .high = 1000, .rel_tol = 1e-4, .samples = 16 };
}

int sw_stability_measurable(const sw_scene *sc, const double *p, char *why, size_t whylen)
{
    sw_sim s;
    char err[SW_ERRLEN];
    if (sw_sim_init(&s, sc, p, sw_integrator_at(0), sc->dt, err, sizeof err) != SW_OK) {
        snprintf(why, whylen, "%s", err);
        return 0;
    }
    int ok = sw_watch_judges(&s, why, whylen);
    sw_sim_free(&s);
    return ok;
}

/* Largest |λ| at the start (0 when nothing oscillates or decays). */
static double start_stiffness(const sw_scene *sc, const double *p, char *err, size_t errlen, int *rc)
{
    sw_system sys;
    *rc = sw_system_build(&sys, sc, p, err, errlen);
    if (*rc != SW_OK)
        return NAN;
    sw_spectrum sp;
    double w = sw_truth_spectrum(&sys, 0.0, sys.y, &sp) == 0 ? sp.largest : 0.0;
    sw_system_free(&sys);
    return w;
}

/* Simulated time per probe: `periods` periods of the stiffest motion (report
 * times when there is none), and at least `reports` report times; with the
 * defaults, the truth module's horizon. Or the config's own horizon. */
static double probe_time(const sw_scene *sc, double stiff, const sw_stability_config *c)
{
    if (c->horizon > 0)
        return c->horizon;
    double unit = stiff > 0 && isfinite(stiff) ? TWO_PI / stiff : sc->duration;
    return fmax(c->periods * unit, c->reports * sc->duration);
}

/* One run from the scene's start, or from `start` (NULL: the scene's). */
static int probe_from(const sw_scene *sc, const double *p, const sw_integrator *m, double dt, double duration,
                      const double *start, const sw_stability_config *c, sw_stability_probe *out, char *err,
                      size_t errlen)
{
    memset(out, 0, sizeof *out);
    out->dt = dt;
    sw_sim s;
    int rc = sw_sim_init(&s, sc, p, m, dt, err, errlen);
    if (rc != SW_OK)
        return rc;
    if (start)
        sw_sim_set_state(&s, start);
    int dim = s.sys.ode->dim;
    double *y0 = malloc((size_t)dim * sizeof *y0);
    if (!y0) {
        sw_sim_free(&s);
        snprintf(err, errlen, "out of memory for a %d-long state", dim);
        return SW_ENOMEM;
    }
    memcpy(y0, s.sys.y, (size_t)dim * sizeof *y0);
    double want = ceil(duration / dt);
    long steps = !(want >= (double)c->min_steps) ? c->min_steps
                 : want > (double)c->max_steps ? c->max_steps : (long)want;
    sw_watch w;
    sw_watch_start(&w, (double)steps * dt / SW_WATCH_WINDOWS, &s);
    out->verdict = SW_PROBE_STABLE;
    int bound = s.sys.scene->energy && !sw_sim_energy_scale_is_motion(&s);
    /* an orbit whose energy reached 0 near the end is run on until the
     * watch has seen whether it stays unbound for a revolution */
    long more = w.revolution > 0 ? (long)ceil(w.revolution / dt) + 1 : 0;
    long k, taken = 0;
    for (k = 1; k <= steps || (sw_watch_pending(&w) && k <= steps + more); k++) {
        taken = k;
        if (sw_sim_step(&s)) {
            out->verdict = SW_PROBE_BLOWN;
            snprintf(out->reason, sizeof out->reason, "%s", s.blow_reason);
            break;
        }
        double v = sw_watch_measure(&s, y0);
        out->m_max = fmax(out->m_max, v);
        sw_watch_verdict wv = sw_watch_add(&w, s.t, v);
        if (wv != SW_WATCH_STEADY) {
            out->verdict = wv == SW_WATCH_BOUND ? SW_PROBE_BOUND : wv == SW_WATCH_RAISED ? SW_PROBE_RAISED
                                                                                         : SW_PROBE_TREND;
            break;
        }
        /* damped away: nothing is left to grow. Not on a bound orbit, whose
         * M = 1 + (E - E(0))/|E(0)| passes 0 where the energy doubles its
         * binding (rk4 at a coarse step, on the way to flinging the planet
         * out): that is no decay. */
        if (v < 1e-20 && !bound) {
            out->verdict = SW_PROBE_DECAYED;
            break;
        }
    }
    out->steps = taken;
    if (out->verdict == SW_PROBE_STABLE) {
        sw_watch_verdict wv = sw_watch_finish(&w);
        if (wv != SW_WATCH_STEADY)
            out->verdict = wv == SW_WATCH_BOUND ? SW_PROBE_BOUND : wv == SW_WATCH_RAISED ? SW_PROBE_RAISED
                                                                                         : SW_PROBE_TREND;
    }
    double solve, eval = sw_truth_eval_work(&s.sys, &solve);
    out->work = (double)sw_sim_evals(&s) * eval + (double)s.sys.ode->solver_iters * solve;
    free(y0);
    sw_sim_free(&s);
    return SW_OK;
}

/* The scene's start, and where it has a resting state the same motion shrunk
 * ten-thousandfold towards it, y_rest + 1e-4·(y0 - y_rest), plus a tenth of
 * that in a fixed pseudo-random pattern over every component: in that copy
 * nothing nonlinear (a spring swinging through its anchor) can cap a growing
 * mode before it shows, and no mode starts unexcited (a chain plucked in
 * one bead barely moves some of its modes). Unstable when either run is. */
typedef struct starts {
    double *small;      /* NULL: no resting state */
    double amplitude;   /* the small copy's largest distance from rest */
    double size;        /* and its largest component: what Newton's tolerance scales with */
} starts;

/* Newton's methods accept a step whose correction is below 1e-12 of the
 * state's size, or 1e-9 where no descent is left (engine/implicit.c): per
 * step, an error that large relative to the small copy's motion moves its
 * energy by twice as much; over the probe's steps, that is the most its
 * energy can wander by solving alone. Above the watch's 1e-3 the copy is
 * not measurable with this method (a shrunk motion far from the origin:
 * 1e-7 at |x| = 2), and the scene's own start decides. */
static int small_resolved(const starts *st, const sw_integrator *m, double steps)
{
    if (!(m->flags & SW_NEWTON))
        return 1;
    return 2e-9 * st->size / st->amplitude * steps <= 1e-3;
}

static void starts_init(starts *st, const sw_scene *sc, const double *p)
{
    st->small = NULL;
    st->amplitude = st->size = 0;
    sw_system sys;
    char err[SW_ERRLEN];
    if (sw_system_build(&sys, sc, p, err, sizeof err) != SW_OK)
        return;
    int dim = sys.ode->dim;
    double *rest = malloc((size_t)2 * dim * sizeof *rest);
    if (rest && sw_sim_resting_state(&sys, rest, NULL) == 0) {
        st->small = rest + dim;
        double span = 0;
        for (int i = 0; i < dim; i++)
            span = fmax(span, fabs(sys.y[i] - rest[i]));
        unsigned long long z = 0x9E3779B97F4A7C15ull;
        for (int i = 0; i < dim; i++) {
            z = z * 6364136223846793005ull + 1442695040888963407ull; /* Knuth's LCG */
            double noise = (double)(z >> 11) * (1.0 / 9007199254740992.0) * 2.0 - 1.0;
            st->small[i] = rest[i] + SW_STABILITY_SHRINK * (sys.y[i] - rest[i]) + 1e-5 * span * noise;
            st->size = fmax(st->size, fabs(st->small[i]));
        }
        st->amplitude = SW_STABILITY_SHRINK * span;
        memmove(rest, st->small, (size_t)dim * sizeof *rest);
        st->small = rest;
    } else {
        free(rest);
    }
    sw_system_free(&sys);
}

static int probe(const sw_scene *sc, const double *p, const sw_integrator *m, double dt, double duration,
                 const starts *st, const sw_stability_config *c, sw_stability_probe *out, char *err,
                 size_t errlen)
{
    int rc = probe_from(sc, p, m, dt, duration, NULL, c, out, err, errlen);
    if (rc != SW_OK || !st || !st->small || (out->verdict != SW_PROBE_STABLE && out->verdict != SW_PROBE_DECAYED))
        return rc;
    if (!small_resolved(st, m, (double)out->steps))
        return rc;
    sw_stability_probe small;
    rc = probe_from(sc, p, m, dt, duration, st->small, c, &small, err, errlen);
    if (rc == SW_OK && small.verdict != SW_PROBE_STABLE && small.verdict != SW_PROBE_DECAYED) {
        small.steps += out->steps;
        small.work += out->work;
        *out = small;
        out->small = 1;
    } else {
        out->steps += small.steps;
        out->work += small.work;
    }
    return rc;
}

int sw_stability_probe_run(const sw_scene *sc, const double *p, const sw_integrator *m, double dt,
                           const sw_stability_config *c, sw_stability_probe *out, char *err,
                           size_t errlen)
{
    int rc;
    double w = start_stiffness(sc, p, err, errlen, &rc);
    if (rc != SW_OK)
        return rc;
    starts st;
    starts_init(&st, sc, p);
    rc = probe(sc, p, m, dt, probe_time(sc, w, c), &st, c, out, err, errlen);
    free(st.small);
    return rc;
}

const char *sw_stability_verdict_text(int verdict)
{
    switch (verdict) {
    case SW_PROBE_BLOWN: return "blew up";
    case SW_PROBE_BOUND: return "energy x1000";
    case SW_PROBE_RAISED: return "energy raised";
    case SW_PROBE_TREND: return "energy grew";
    case SW_PROBE_DECAYED: return "decayed";
    default: return "stable";
    }
}

/* One method's share: the reference run's cost `ref` (the same for every
 * method) plus the probes'. */
static double method_cost(const sw_scene *sc, sw_truth *tr, const sw_integrator *m, double w, double duration,
                          double ref, const sw_stability_config *c)
{
    double cost = ref, step = sw_truth_step_work(&tr->sys, m);
    double lo = w > 0 && isfinite(w) ? c->low / w : c->low * sc->dt;
    double near = w > 0 && isfinite(w) ? 1.0 / w : sc->dt;
    double steps_lo = fmin((double)c->max_steps, duration / fmax(lo, SW_DT_MIN));
    double steps_near = fmin((double)c->max_steps, duration / near);
    cost += 2 * step * (steps_lo + 25 * steps_near);
    return cost;
}

/* The adaptive methods are left out: they have no limit to find. */
static double cost_sum(const sw_scene *sc, const double *p, const sw_integrator *const *methods, int n,
                       const sw_stability_config *c, double *each)
{
    for (int i = 0; each && i < n; i++)
        each[i] = 0;
    char err[SW_ERRLEN];
    int rc;
    double w = start_stiffness(sc, p, err, sizeof err, &rc);
    if (rc != SW_OK)
        return 0;
    double duration = probe_time(sc, w, c), total = 0;
    sw_truth tr;
    if (sw_truth_init(&tr, sc, p, err, sizeof err) != SW_OK)
        return 0;
    double ref = sw_truth_reference_cost(&tr, duration);
    for (int i = 0; i < n; i++)
        if (!(methods[i]->flags & SW_ADAPTIVE)) {
            double one = method_cost(sc, &tr, methods[i], w, duration, ref, c);
            total += one;
            if (each)
                each[i] = one;
        }
    sw_truth_free(&tr);
    return total;
}

double sw_stability_cost_sum(const sw_scene *sc, const double *p, const sw_integrator *const *methods, int n,
                             const sw_stability_config *c, double *each)
{
    return cost_sum(sc, p, methods, n, c, each);
}

static int stable(int verdict) { return verdict == SW_PROBE_STABLE || verdict == SW_PROBE_DECAYED; }

/* Theory against measurement, and why they differ where they do. */
static void compare(const sw_scene *sc, const double *p, const sw_integrator *m, const sw_stability_config *c,
                    sw_stability_result *r)
{
    double measured = r->kind == SW_STAB_NONE ? 0 : r->dt, theory = r->theory_unbounded ? INFINITY : r->theory;
    int meas_unb = r->kind == SW_STAB_UNBOUNDED;
    if ((meas_unb && r->theory_unbounded) || (theory == 0 && measured == 0) ||
        (theory > 0 && isfinite(theory) && fabs(measured / theory - 1) <= SW_STABILITY_AGREE)) {
        r->agree = 1;
        return;
    }
    if (isnan(r->theory) || (r->fail.verdict == SW_PROBE_BLOWN && strncmp(r->fail.reason, "the plugin", 10) == 0)) {
        snprintf(r->why, sizeof r->why, "%s failed, not the scene: %.200s", m->name,
                 r->fail.reason[0] ? r->fail.reason : "its step fails on the theory's test systems");
        return;
    }
    if (measured < theory) {
        snprintf(r->why, sizeof r->why, "%s fails below the linear limit: the step is too coarse for the "
                 "nonlinear motion (%s at dt = %.4g)%s", m->name, sw_stability_verdict_text(r->fail.verdict),
                 r->fail.dt, r->theory_unbounded ? "; every linearisation is stable, the nonlinear "
                 "energy is not" : "");
        return;
    }
    /* measured above theory, even over the longer probes: the growth the
     * theory predicts is too slow to show, lies in a mode the motion barely
     * excites, or the nonlinear motion leaves the linearisation that grows */
    sw_truth_along al;
    char err[SW_ERRLEN];
    if (sw_truth_along_run(sc, p, m, r->horizon, c->samples, SW_DT_MAX, measured, &al, err, sizeof err) != 0)
        al.growth = NAN;
    double rho = al.growth, total = al.growth_total;
    char per_step[48];
    if (rho - 1 < 1e-3)
        snprintf(per_step, sizeof per_step, "1 + %.2g", rho - 1);
    else
        snprintf(per_step, sizeof per_step, "%.4g", rho);
    int n = snprintf(r->why, sizeof r->why, "held for %.3g s at dt = %.4g; linearised along the run, %s "
                     "grows at most x%s per step (t = %.3g), x%.3g in all",
                     r->horizon, measured, m->name, per_step, al.t_growth, total);
    if (n < 0 || (size_t)n >= sizeof r->why)
        return;
    if (!(total >= 2))
        snprintf(r->why + n, sizeof r->why - (size_t)n, ": too slow to tell from the motion");
    else
        snprintf(r->why + n, sizeof r->why - (size_t)n, ": a mode (|L| = %.3g) the motion barely excites, or growth "
                 "the nonlinear motion does not keep up", al.growth_lambda);
}

/* x rounded down to SW_STABILITY_DIGITS significant digits: the limit as
 * it is reported, never above the step found stable. */
static double round_down(double x)
{
    double scale = pow(10.0, SW_STABILITY_DIGITS - 1 - floor(log10(x)));
    double r = floor(x * scale) / scale;
    return r <= x ? r : nextafter(r, 0.0);
}

/* The search: probes at a horizon, bracketing and bisection. */
typedef struct search {
    const sw_scene *sc;
    const double *p;
    const sw_integrator *m;
    const sw_stability_config *c;
    starts st;
    sw_stability_result *out;
    char *err;
    size_t errlen;
    double lo_bound, hi_bound;
} search;

static int run(search *q, double dt, double horizon, sw_stability_probe *pr)
{
    int rc = probe(q->sc, q->p, q->m, dt, horizon, &q->st, q->c, pr, q->err, q->errlen);
    if (rc == SW_OK) {
        q->out->probes++;
        q->out->steps += pr->steps;
        q->out->work += pr->work;
    }
    return rc;
}

/* Bisect geometrically between a stable and an unstable step (the limit is
 * a ratio, so halve its logarithm). */
static int bisect(search *q, double horizon, double *ok, double *bad)
{
    sw_stability_probe pr;
    while (*bad / *ok - 1.0 > q->c->rel_tol) {
        double mid = sqrt(*ok * *bad);
        int rc = run(q, mid, horizon, &pr);
        if (rc != SW_OK)
            return rc;
        if (stable(pr.verdict)) {
            *ok = mid;
        } else {
            *bad = mid;
            q->out->fail = pr;
        }
    }
    return SW_OK;
}

/* From the scene's own step, doubling until a probe fails; sets the kind. */
static int bracket_up(search *q, double horizon, double *ok, double *bad)
{
    sw_stability_probe pr;
    int rc = run(q, q->lo_bound, horizon, &pr);
    if (rc != SW_OK)
        return rc;
    if (!stable(pr.verdict)) {
        q->out->kind = SW_STAB_NONE;
        q->out->fail = pr;
        *ok = q->lo_bound;
        return SW_OK;
    }
    *ok = q->lo_bound;
    double dt = fmin(fmax(q->sc->dt, q->lo_bound), q->hi_bound);
    for (;;) {
        if (dt > *ok) {
            if ((rc = run(q, dt, horizon, &pr)) != SW_OK)
                return rc;
            if (!stable(pr.verdict)) {
                *bad = dt;
                q->out->fail = pr;
                q->out->kind = SW_STAB_LIMIT;
                return SW_OK;
            }
            *ok = dt;
        }
        if (*ok >= q->hi_bound) {
            q->out->kind = SW_STAB_UNBOUNDED;
            return SW_OK;
        }
        dt = fmin(2.0 * *ok, q->hi_bound);
    }
}

/* Where the measurement lies above the theory, the theory's growth may only
 * be slow: probe the found step again for SW_STABILITY_LONGER times as long,
 * twice, and where the longer run grows, search again below it (halving
 * down to a stable step, then bisecting) at that horizon. A run that blows
 * up after the probe's time is not stable. */
static int confirm(search *q, double *horizon, double *ok, double *bad)
{
    sw_stability_result *out = q->out;
    double theory = out->theory_unbounded ? INFINITY : out->theory;
    for (int round = 0; round < 2; round++) {
        if (out->kind == SW_STAB_NONE || !(*ok > (1 + SW_STABILITY_AGREE) * theory))
            return SW_OK;
        double longer = SW_STABILITY_LONGER * *horizon;
        sw_stability_probe pr;
        int rc = run(q, *ok, longer, &pr);
        if (rc != SW_OK)
            return rc;
        *horizon = longer;
        if (stable(pr.verdict))
            continue;
        out->fail = pr;
        *bad = *ok;
        out->kind = SW_STAB_LIMIT;
        for (;;) { /* down to a step that holds over the longer run */
            double dt = fmax(*bad / 2, q->lo_bound);
            if ((rc = run(q, dt, longer, &pr)) != SW_OK)
                return rc;
            if (stable(pr.verdict)) {
                *ok = dt;
                break;
            }
            *bad = dt;
            out->fail = pr;
            if (dt <= q->lo_bound) {
                out->kind = SW_STAB_NONE;
                *ok = dt;
                return SW_OK;
            }
        }
        if ((rc = bisect(q, longer, ok, bad)) != SW_OK)
            return rc;
    }
    return SW_OK;
}

/* The reported limit is run as reported: the step found stable, rounded
 * down to the digits shown, from the scene's own start over the horizon;
 * where that grows (it should not), lower it until a run does not. */
static int verify(search *q, double horizon, double *ok)
{
    double dt = round_down(*ok);
    for (int tries = 0; tries < 8; tries++) {
        sw_stability_probe pr;
        int rc = run(q, dt, horizon, &pr);
        if (rc != SW_OK)
            return rc;
        if (stable(pr.verdict)) {
            *ok = dt;
            return SW_OK;
        }
        dt = round_down(dt * (1 - 2 * q->c->rel_tol));
    }
    *ok = dt;
    return SW_OK;
}

int sw_stability_find(const sw_scene *sc, const double *p, const sw_integrator *m,
                      const sw_stability_config *c, sw_stability_result *out, char *err,
                      size_t errlen)
{
    memset(out, 0, sizeof *out);
    out->method = m;
    out->dt_unstable = NAN;
    if (m->flags & SW_ADAPTIVE) {
        snprintf(err, errlen, "%s chooses its own steps (dt is only its largest step), so it has "
                 "no step-size limit to find", m->name);
        return SW_EINVAL;
    }
    if (!sw_truth_method_applies(sc, m, err, errlen))
        return SW_EINVAL;
    int rc;
    double w = start_stiffness(sc, p, err, errlen, &rc);
    if (rc != SW_OK)
        return rc;
    double horizon = probe_time(sc, w, c);
    sw_truth_along al;
    if (sw_truth_along_run(sc, p, m, horizon, c->samples, SW_DT_MAX, 0, &al, err, errlen) != 0)
        return SW_EINVAL;
    out->theory = al.limit;
    out->theory_unbounded = al.unbounded;
    out->stiff = al.stiffest;
    out->horizon = horizon;
    out->work = al.ref_work;
    if (!sw_stability_measurable(sc, p, out->why, sizeof out->why))
        return SW_OK; /* theory only */
    out->measured = 1;
    search q = { .sc = sc, .p = p, .m = m, .c = c, .out = out, .err = err, .errlen = errlen };
    starts_init(&q.st, sc, p);
    if (w > 0 && isfinite(w)) {
        q.lo_bound = c->low / w;
        q.hi_bound = c->high / w;
    } else {
        q.lo_bound = c->low * sc->dt;
        q.hi_bound = c->high * sc->dt;
    }
    q.lo_bound = fmax(q.lo_bound, SW_DT_MIN);
    q.hi_bound = fmax(q.lo_bound, fmin(q.hi_bound, SW_DT_MAX));
    double ok = q.lo_bound, bad = NAN;
    rc = bracket_up(&q, horizon, &ok, &bad);
    if (rc == SW_OK && out->kind == SW_STAB_LIMIT)
        rc = bisect(&q, horizon, &ok, &bad);
    if (rc == SW_OK)
        rc = confirm(&q, &horizon, &ok, &bad);
    if (rc == SW_OK && out->kind == SW_STAB_LIMIT)
        rc = verify(&q, horizon, &ok);
    free(q.st.small);
    if (rc != SW_OK)
        return rc;
    out->dt = ok;
    out->dt_unstable = out->kind == SW_STAB_LIMIT ? bad : NAN;
    out->horizon = horizon;
    compare(sc, p, m, c, out);
    return SW_OK;
}
