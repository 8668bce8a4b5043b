/* Stability limits by bisection. A probe runs the sim and a twin started 1e-7
 * ahead along its path for a fixed simulated time (so slow growth at small
 * steps has as long to show as fast growth at large ones), with the run cut
 * into 20 windows and M's peak taken in each. It is unstable when either sim
 * blows up, when M leaves a bound, when the twins drift apart (a growing mode
 * whose growth a nonlinear scene has capped still shows there), when the
 * window peaks climb steadily (16 rises in 19), or when the last tenth's peak
 * stands above the first tenth's by more than the first tenth varied. A
 * bounded oscillation (symplectic methods, energy errors modulated by slow
 * motion) has peaks that rise and fall at random; decay lowers them; growth,
 * however slow, raises them one window after another. M is used for the
 * trend rather than D because D also grows polynomially in stable nonlinear
 * scenes (nearby orbits drift in phase). */
#include "lab/stability.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/base.h"

#define TWO_PI 6.283185307179586

void sw_stability_config_default(sw_stability_config *c)
{
    *c = (sw_stability_config){ .periods = 100, .reports = 10, .min_steps = 400, .max_steps = 4000000,
                                .bound = 1e4, .twin_bound = 1e8, .rises = 16, .jump = 1.0, .low = 0.01,
                                .high = 1000, .rel_tol = 1e-4 };
}

int sw_stability_applicable(const sw_scene *sc, char *why, size_t whylen)
{
    if (sc->post_step) {
        snprintf(why, whylen, "%s changes its state at step boundaries (contact, births), so "
                 "nearby runs split at every step size and no limit can be measured; try spring, "
                 "stiff-spring, chain, orbit, vortex or projectile", sc->name);
        return 0;
    }
    if (sc->energy || sc->omega_max)
        return 1;
    snprintf(why, whylen, "%s defines no energy and no stiffest frequency, so growth cannot be "
             "told from the flow itself; try spring, stiff-spring, chain, orbit, vortex or "
             "projectile", sc->name);
    return 0;
}

/* M: the energy when the scene has one, else ½|y|² (for a flow: points
 * circling keep it constant, points spiralling out raise it). */
static double measure(const sw_sim *s)
{
    if (s->sys.scene->energy)
        return sw_sim_energy(s);
    double m = 0;
    for (int i = 0; i < s->sys.ode->dim; i++)
        m += s->sys.y[i] * s->sys.y[i];
    return 0.5 * m;
}

/* Simulated time per probe: `periods` periods of the stiffest motion (report
 * times when ω is unknown), and at least `reports` report times, so that each
 * tenth of the run also spans the scene's slow motion and sees the same
 * peaks of a bounded energy oscillation. */
static double probe_time(const sw_scene *sc, double omega, const sw_stability_config *c)
{
    double unit = omega > 0 && isfinite(omega) ? TWO_PI / omega : sc->duration;
    return fmax(c->periods * unit, c->reports * sc->duration);
}

static double scene_omega(const sw_scene *sc, const double *p, char *err, size_t errlen, int *rc)
{
    sw_system sys;
    *rc = sw_system_build(&sys, sc, p, err, errlen);
    if (*rc != SW_OK)
        return NAN;
    double w = sc->omega_max ? sc->omega_max(&sys) : NAN;
    sw_system_free(&sys);
    return w;
}

/* Squared distance between the twins' states. */
static double twin_distance(const sw_sim *a, const sw_sim *b)
{
    double d = 0;
    for (int i = 0; i < a->sys.ode->dim; i++) {
        double e = a->sys.y[i] - b->sys.y[i];
        d += e * e;
    }
    return d;
}

static int probe(const sw_scene *sc, const double *p, const sw_integrator *m, double dt,
                 double duration, const sw_stability_config *c, sw_stability_probe *out, char *err,
                 size_t errlen)
{
    memset(out, 0, sizeof *out);
    out->dt = dt;
    sw_sim s, twin;
    int rc = sw_sim_init(&s, sc, p, m, dt, err, errlen);
    if (rc != SW_OK)
        return rc;
    rc = sw_sim_init(&twin, sc, p, m, dt, err, errlen);
    if (rc != SW_OK) {
        sw_sim_free(&s);
        return rc;
    }
    /* The twin starts 1e-7 (relative) ahead along the motion, y0 + ε·f(y0):
     * the same path a moment later. The exact flow keeps such a shift
     * bounded (no shear, no transverse physics); a growing numerical mode
     * pulls the twins apart. At an equilibrium, a fixed pattern instead. */
    int dim = s.sys.ode->dim;
    double size = 1.0, fnorm = 0;
    double *f = malloc((size_t)dim * sizeof *f);
    if (!f) {
        sw_sim_free(&twin);
        sw_sim_free(&s);
        snprintf(err, errlen, "out of memory for a %d-long state", dim);
        return SW_ENOMEM;
    }
    sw_ode_eval(twin.sys.ode, 0.0, twin.sys.y, f);
    for (int i = 0; i < dim; i++) {
        size = fmax(size, fabs(s.sys.y[i]));
        fnorm = fmax(fnorm, fabs(f[i]));
    }
    for (int i = 0; i < dim; i++)
        twin.sys.y[i] += 1e-7 * size * (fnorm > 0 && isfinite(fnorm) ? f[i] / fnorm
                                        : (i % 2 ? -1.0 : 1.0) * (1.0 + 0.5 * (i % 3)));
    free(f);
    double d0 = twin_distance(&s, &twin);
    /* Steps for the fixed simulated time, clipped before converting. */
    double want = ceil(duration / dt);
    long steps = !(want >= (double)c->min_steps) ? c->min_steps
                 : want > (double)c->max_steps ? c->max_steps : (long)want;
    /* The run in SW_STAB_WINDOWS equal windows; the peak of M in each. */
    double peak[SW_STAB_WINDOWS], first_min = INFINITY;
    double m0 = measure(&s), scale = fabs(m0) > 0 ? fabs(m0) : 1.0;
    for (int w = 0; w < SW_STAB_WINDOWS; w++)
        peak[w] = -INFINITY;
    peak[0] = first_min = m0;
    out->m0 = m0;
    out->verdict = SW_PROBE_STABLE;
    long k;
    for (k = 1; k <= steps; k++) {
        if (sw_sim_step(&s) | sw_sim_step(&twin)) {
            out->verdict = SW_PROBE_BLOWN;
            snprintf(out->reason, sizeof out->reason, "%s", s.blown ? s.blow_reason : twin.blow_reason);
            break;
        }
        double v = measure(&s), d = twin_distance(&s, &twin);
        if (!(v - m0 <= (c->bound - 1.0) * scale)) { /* NaN fails too */
            out->verdict = SW_PROBE_BOUND;
            break;
        }
        if (!(d <= c->twin_bound * d0)) {
            out->verdict = SW_PROBE_TWIN;
            break;
        }
        /* Damped a millionfold and more in amplitude: nothing is left to
         * grow, and running on would only feed the solvers numbers near
         * underflow. */
        if (d < 1e-24 * d0) {
            out->verdict = SW_PROBE_DECAYED;
            break;
        }
        int w = (int)((k - 1) * SW_STAB_WINDOWS / steps);
        peak[w] = fmax(peak[w], v);
        if (w < 2)
            first_min = fmin(first_min, v);
    }
    out->steps = k > steps ? steps : k;
    const int last = SW_STAB_WINDOWS - 1;
    out->first_max = fmax(peak[0], peak[1]);
    out->first_range = out->first_max - first_min;
    out->last_max = fmax(peak[last - 1], peak[last]);
    for (int w = 1; w < SW_STAB_WINDOWS; w++)
        out->rises += peak[w] > peak[w - 1];
    if (out->verdict == SW_PROBE_STABLE) {
        /* Steady growth: the window peaks climb nearly every time. */
        if (out->rises >= c->rises && peak[last] - peak[0] > 1e-12 * scale)
            out->verdict = SW_PROBE_TREND;
        /* Growth a nonlinearity capped early: the last tenth's peak stands
         * above the first tenth's by more than the first tenth varied. */
        if (out->last_max - out->first_max > c->jump * out->first_range + 1e-9 * scale)
            out->verdict = SW_PROBE_TREND;
    }
    sw_sim_free(&twin);
    sw_sim_free(&s);
    return SW_OK;
}

int sw_stability_probe_run(const sw_scene *sc, const double *p, const sw_integrator *m, double dt,
                           const sw_stability_config *c, sw_stability_probe *out, char *err,
                           size_t errlen)
{
    int rc;
    double w = scene_omega(sc, p, err, errlen, &rc);
    if (rc != SW_OK)
        return rc;
    return probe(sc, p, m, dt, probe_time(sc, w, c), c, out, err, errlen);
}

int sw_stability_find(const sw_scene *sc, const double *p, const sw_integrator *m,
                      const sw_stability_config *c, sw_stability_result *out, char *err,
                      size_t errlen)
{
    memset(out, 0, sizeof *out);
    out->method = m;
    out->theory = m->stability;
    out->dt_unstable = NAN;
    if (m->flags & SW_ADAPTIVE) {
        snprintf(err, errlen, "%s chooses its own steps (dt is only its largest step), so it has "
                 "no step-size limit to find", m->name);
        return SW_EINVAL;
    }
    if (!sw_stability_applicable(sc, err, errlen))
        return SW_EINVAL;
    int rc;
    double w = scene_omega(sc, p, err, errlen, &rc);
    if (rc != SW_OK)
        return rc;
    sw_system sys;
    rc = sw_system_build(&sys, sc, p, err, errlen);
    if (rc != SW_OK)
        return rc;
    rc = sw_integrator_accepts(m, sys.ode, err, errlen);
    sw_system_free(&sys);
    if (rc != SW_OK)
        return rc;
    out->omega = w;
    double duration = probe_time(sc, w, c), lo_bound, hi_bound;
    if (w > 0 && isfinite(w)) {
        lo_bound = c->low / w;
        hi_bound = c->high / w;
    } else {
        lo_bound = c->low * sc->dt;
        hi_bound = c->high * sc->dt;
    }
    lo_bound = fmax(lo_bound, SW_DT_MIN);
    hi_bound = fmax(lo_bound, fmin(hi_bound, SW_DT_MAX));

    sw_stability_probe pr;
#define PROBE(dt_)                                                              \
    do {                                                                        \
        rc = probe(sc, p, m, (dt_), duration, c, &pr, err, errlen);             \
        if (rc != SW_OK)                                                        \
            return rc;                                                          \
        out->probes++;                                                          \
        out->steps += pr.steps;                                                 \
    } while (0)

    PROBE(lo_bound);
    if (pr.verdict != SW_PROBE_STABLE && pr.verdict != SW_PROBE_DECAYED) {
        out->kind = SW_STAB_NONE;
        out->dt = lo_bound;
        out->fail = pr;
        return SW_OK;
    }
    /* Bracket: from the scene's own step, doubling until a probe fails. */
    double stable = lo_bound, unstable = NAN;
    double dt = fmin(fmax(sc->dt, lo_bound), hi_bound);
    while (!(unstable > 0)) {
        if (dt > stable) {
            PROBE(dt);
            if (pr.verdict == SW_PROBE_STABLE || pr.verdict == SW_PROBE_DECAYED)
                stable = dt;
            else {
                unstable = dt;
                out->fail = pr;
                break;
            }
        }
        if (stable >= hi_bound) {
            out->kind = SW_STAB_UNBOUNDED;
            out->dt = stable;
            return SW_OK;
        }
        dt = fmin(2.0 * stable, hi_bound);
    }
    /* Bisect geometrically: the limit is a ratio, so halve its logarithm. */
    while (unstable / stable - 1.0 > c->rel_tol) {
        double mid = sqrt(stable * unstable);
        PROBE(mid);
        if (pr.verdict == SW_PROBE_STABLE || pr.verdict == SW_PROBE_DECAYED)
            stable = mid;
        else {
            unstable = mid;
            out->fail = pr;
        }
    }
#undef PROBE
    out->kind = SW_STAB_LIMIT;
    out->dt = stable;
    out->dt_unstable = unstable;
    return SW_OK;
}
