/* Growth of the energy of the motion, judged window by window. A bounded
 * oscillation (a symplectic method's energy error, a slow swing modulating
 * it, chaos) has window peaks that rise and fall at random and comes back
 * down to its start; decay lowers the peaks; growth, however slow, raises
 * them window after window, and growth a nonlinearity caps early (a spring
 * flung through its anchor) leaves the energy raised for good.
 * Invariant: the watch never steps anything; it only reads samples. */
#include "sim/watch.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "engine/central.h"
#include "engine/ode_fast.h"
#include "util/num.h"


double sw_watch_measure(const sw_sim *s, const double *y0)
{
    if (s->sys.scene->energy) /* (E - E0)/scale + 1: with a floor, (E - floor)/(E0 - floor) */
        return 1.0 + (sw_sim_energy(s) - s->energy0) / sw_sim_energy_scale(s);
    if (s->sys.kind != SW_SYS_FLOW || !y0)
        return NAN;
    double num = 0, den = 0;
    for (int i = 0; i < s->sys.ode->dim; i++) {
        num += s->sys.y[i] * s->sys.y[i];
        den += y0[i] * y0[i];
    }
    return den > 0 ? num / den : NAN;
}

int sw_watch_judges(const sw_sim *s, char *why, size_t whylen)
{
    const sw_scene *sc = s->sys.scene;
    if (sc->post_step) {
        snprintf(why, whylen, "%s changes its state at step boundaries (contact, births), so "
                 "nearby runs split at every step size and no limit can be measured", sc->name);
        return 0;
    }
    if (sc->kind == SW_SYS_FLOW && !sc->energy) {
        if (sc->exact)
            return 1;
        snprintf(why, whylen, "%s defines no energy and no closed form, so growth cannot be told "
                 "from the flow itself", sc->name);
        return 0;
    }
    if (sw_sim_energy_scale_is_motion(s) || s->energy0 < 0)
        return 1;
    snprintf(why, whylen, "%s's energy has no floor and no well to be bound in (it falls forever), "
             "so growth cannot be told from the energy", sc->name);
    return 0;
}

static int bound_state(const sw_sim *s)
{
    return s->sys.scene->energy && !sw_sim_energy_scale_is_motion(s) && s->energy0 < 0;
}

double sw_watch_raised_level(const sw_sim *s)
{
    return bound_state(s) ? 2.0 : (s->method->flags & SW_SYMPLECTIC) ? 30.0 : 3.0;
}

void sw_watch_init(sw_watch *w, double window, double raised)
{
    memset(w, 0, sizeof *w);
    w->window = window;
    w->raised = raised;
    w->rebound = raised;
    w->low_mean = INFINITY;
    w->t0 = 0;
    w->cur_max = -INFINITY;
    w->cur_min = INFINITY;
    w->first_max = -INFINITY;
    w->first_min = INFINITY;
    w->first_mean = NAN;
    w->last = NAN;
    w->unbound_since = NAN;
}

int sw_watch_pending(const sw_watch *w) { return w->verdict == SW_WATCH_STEADY && !isnan(w->unbound_since); }

/* How far a window's sampled peak of M can lie below the oscillation's
 * true peak, from the samples alone: an oscillation M = c + A·cos(θ)
 * sampled every φ of phase moves at most A·φ between samples, and its
 * sampled peak misses the true one by up to A·(1 - cos(φ/2)) ≈ A·φ²/8 =
 * step_max²/(8·A), A half the first window's range. Peaks that creep up
 * by less than this (as the sampling phase drifts towards the crest) are
 * no growth. 0 before two windows. */
static double sw_watch_sampling_floor(const sw_watch *w)
{
    double amplitude = (w->first_max - w->first_min) / 2;
    if (w->windows < 1 || !(amplitude > 0))
        return 0;
    return w->step_max * w->step_max / (8 * amplitude);
}

/* One revolution of a single body about a fixed centre from its energy at
 * the start, T = 2π·μ/(−2ε)^(3/2) with ε = E/m; 0 when the system is not
 * that or is not bound. */
static double revolution(const sw_sim *s)
{
    sw_central1 c;
    if (!sw_ode_central1(s->sys.ode, &c) || !(c.mu > 0) || !(c.mass > 0))
        return 0;
    double eps = s->energy0 / c.mass;
    return eps < 0 ? 2 * SW_PI * c.mu / pow(-2 * eps, 1.5) : 0;
}

void sw_watch_start(sw_watch *w, double window, const sw_sim *s)
{
    sw_watch_init(w, window, sw_watch_raised_level(s));
    if (bound_state(s)) {
        w->rebound = 0;
        w->escape = 2.0;
        w->revolution = revolution(s);
    } else
        w->relative = (s->method->flags & SW_SYMPLECTIC) != 0;
}

static void close_window(sw_watch *w)
{
    if (w->windows == 0) {
        w->first_max = w->cur_max;
        w->first_min = w->cur_min;
        w->first_mean = w->cur_sum / (double)w->cur_n;
    }
    if (w->kept == SW_WATCH_WINDOWS) {
        memmove(w->peak, w->peak + 1, (SW_WATCH_WINDOWS - 1) * sizeof w->peak[0]);
        memmove(w->mean, w->mean + 1, (SW_WATCH_WINDOWS - 1) * sizeof w->mean[0]);
        w->kept--;
    }
    w->peak[w->kept] = w->cur_max;
    w->mean[w->kept] = w->cur_sum / (double)w->cur_n;
    w->kept++;
    w->windows++;
    w->cur_max = -INFINITY;
    w->cur_min = INFINITY;
    w->cur_sum = 0;
    w->cur_n = 0;
}

static sw_watch_verdict judge(const sw_watch *w)
{
    int k = w->kept;
    if (k == 0 || w->windows < 2)
        return SW_WATCH_STEADY;
    /* energy raised and kept: the latest window averages past the raised
     * level (nothing in these scenes adds energy); for a symplectic method,
     * past that many times what its first window averaged, its bounded
     * swing included (sw_watch_raised_level) */
    double level = w->relative && w->first_mean > 1 ? w->raised * w->first_mean : w->raised;
    if (w->mean[k - 1] > level)
        return SW_WATCH_RAISED;
    /* energy that sank and came back: the latest window's mean a rebound
     * factor above the lowest before it */
    if (w->rebound > 0 && w->mean[k - 1] > 1e-4 && w->mean[k - 1] > w->rebound * w->low_mean)
        return SW_WATCH_RAISED;
    /* steady climb: 16 rises in 19 window-to-window changes */
    if (k >= SW_WATCH_WINDOWS - 1) {
        int rises = 0;
        for (int i = k - (SW_WATCH_WINDOWS - 1) + 1; i < k; i++)
            rises += w->peak[i] > w->peak[i - 1];
        double climb = w->peak[k - 1] - w->peak[0];
        if (rises >= 16 && climb > 1e-9 && climb > 2 * sw_watch_sampling_floor(w))
            return SW_WATCH_TREND;
    }
    /* the latest peak above the first by more than the first window varied */
    double range = w->first_max - w->first_min;
    if (w->peak[k - 1] - w->first_max > range + 1e-3)
        return SW_WATCH_TREND;
    return SW_WATCH_STEADY;
}

sw_watch_verdict sw_watch_add(sw_watch *w, double t, double m)
{
    if (w->verdict != SW_WATCH_STEADY)
        return w->verdict;
    if (!(m <= 1e3)) { /* NaN too */
        w->verdict = SW_WATCH_BOUND;
        return w->verdict;
    }
    /* a bound orbit at E >= 0 for a whole revolution has escaped: a
     * planet whose energy touches 0 at a pericentre pass and comes back is
     * still bound */
    if (w->escape > 0 && m >= w->escape) {
        if (isnan(w->unbound_since))
            w->unbound_since = t;
        if (t - w->unbound_since >= w->revolution) {
            w->verdict = SW_WATCH_RAISED;
            return w->verdict;
        }
    } else {
        w->unbound_since = NAN;
    }
    w->max_seen = fmax(w->max_seen, m);
    while (t - w->t0 >= w->window && w->window > 0) {
        if (w->cur_max > -INFINITY) {
            close_window(w);
            w->verdict = judge(w);
            w->low_mean = fmin(w->low_mean, w->mean[w->kept - 1]);
            if (w->verdict != SW_WATCH_STEADY)
                return w->verdict;
        }
        w->t0 += w->window;
        if (t - w->t0 > 1e3 * w->window)
            w->t0 = t; /* a long gap: start the next window here */
    }
    if (w->last == w->last)
        w->step_max = fmax(w->step_max, fabs(m - w->last));
    w->last = m;
    w->cur_max = fmax(w->cur_max, m);
    w->cur_min = fmin(w->cur_min, m);
    w->cur_sum += m;
    w->cur_n++;
    return w->verdict;
}

sw_watch_verdict sw_watch_finish(sw_watch *w)
{
    if (w->verdict == SW_WATCH_STEADY && w->cur_max > -INFINITY) {
        close_window(w);
        w->verdict = judge(w);
    }
    return w->verdict;
}

const char *sw_watch_text(sw_watch_verdict v)
{
    switch (v) {
    case SW_WATCH_BOUND: return "energy x1000";
    case SW_WATCH_RAISED: return "energy raised";
    case SW_WATCH_TREND: return "energy grew";
    default: return "steady";
    }
}
