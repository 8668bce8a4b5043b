/* The status line of each sim as fields, each with a full and a brief form
 * and a priority, so the renderer can lay it out in any width without
 * cutting a word or a number: brief forms first, then the least important
 * fields go. */
#include "app/app.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/stepwise.h"

static sw_field *add(sw_field *f, int *n, int max, int prio)
{
    if (*n >= max)
        return NULL;
    sw_field *x = &f[(*n)++];
    x->full[0] = x->brief[0] = '\0';
    x->prio = prio;
    return x;
}

int sw_app_status_fields(sw_app *a, int i, sw_field *f, int max)
{
    const sw_sim *s = &a->sims[i];
    int n = 0;
    sw_field *x;
    if (i == 0 && (x = add(f, &n, max, 5)))
        snprintf(x->full, sizeof x->full, "%s", a->scene->name);
    if ((x = add(f, &n, max, 10)))
        snprintf(x->full, sizeof x->full, "%s", s->method->name);
    if ((x = add(f, &n, max, 9)))
        snprintf(x->full, sizeof x->full, "dt=%g", s->dt);
    if ((x = add(f, &n, max, 8))) {
        snprintf(x->full, sizeof x->full, "t=%.3f", s->t);
        snprintf(x->brief, sizeof x->brief, "t=%.4g", s->t);
    }
    if (i == 0 && a->until > 0 && (x = add(f, &n, max, 7))) {
        snprintf(x->full, sizeof x->full, "stops at t=%g (u)", a->until);
        snprintf(x->brief, sizeof x->brief, "stop t=%g", a->until);
    }
    /* an adaptive method's cost is its evaluations (what lesson 9 compares;
     * its steps are the accepted count beside them): they go before steps */
    int adaptive = (s->method->flags & SW_ADAPTIVE) != 0;
    if ((x = add(f, &n, max, adaptive ? 1 : 3))) {
        snprintf(x->full, sizeof x->full, "steps %ld", s->steps);
    }
    if (i == 0 && a->steps_per_sec > 0 && (x = add(f, &n, max, 1)))
        snprintf(x->full, sizeof x->full, "%.0f steps/s", a->steps_per_sec);
    if ((x = add(f, &n, max, adaptive ? 5 : 2))) {
        snprintf(x->full, sizeof x->full, "evals %ld", sw_sim_evals(s));
    }
    double drift = sw_sim_energy_drift(s);
    double drift_error = sw_sim_energy_drift_error(s);
    if (isfinite(drift) && drift_error > 0 && (x = add(f, &n, max, 7))) {
        /* summed approximately (a large galaxy's tree): say so, and how far off it can be */
        snprintf(x->full, sizeof x->full, "energy ≈%+.3g%% ±%.2g%%", drift, drift_error);
        snprintf(x->brief, sizeof x->brief, "E≈%+.2g%%±%.2g%%", drift, drift_error);
    } else if (isfinite(drift) && (x = add(f, &n, max, 7))) {
        snprintf(x->full, sizeof x->full, "energy %+.3g%%", drift);
        snprintf(x->brief, sizeof x->brief, "E%+.3g%%", drift);
    }
    double err = sw_app_error(a, i);
    if (s->steps == 0 && isfinite(err))
        err = 0; /* nothing integrated yet: what differs is the truth's rounding (lesson 9 read 1e-34) */
    if (isfinite(err) && (x = add(f, &n, max, 6))) {
        /* against the truth at this time; the run restarts when dt or the
         * method changes, so it is this run's error alone */
        const char *what = a->err_velocity ? "velocity error" : "position error";
        const char *unit = a->err_velocity ? "m/s" : "m";
        snprintf(x->full, sizeof x->full, "%s %.3g %s", what, err, unit);
        snprintf(x->brief, sizeof x->brief, "%s %.2g %s", a->err_velocity ? "v err" : "err", err, unit);
    }
    double inv = s->blown ? NAN : sw_sim_drift(s);
    if (isfinite(inv) && a->scene->drift_name && (x = add(f, &n, max, adaptive ? 4 : 6))) {
        /* what a page's `drift` goal reads: the scene names it */
        snprintf(x->full, sizeof x->full, "%s %.2g", a->scene->drift_name, inv);
        snprintf(x->brief, sizeof x->brief, "drift %.1g", inv);
    }
    if (adaptive && (x = add(f, &n, max, 6))) {
        long acc, rej;
        sw_sim_step_counts(s, &acc, &rej);
        snprintf(x->full, sizeof x->full, "accepted %ld rejected %ld", acc, rej);
        snprintf(x->brief, sizeof x->brief, "acc %ld rej %ld", acc, rej);
    }
    if (i == 0 && sw_system_event_count(&s->sys) > 0 && (x = add(f, &n, max, 4))) {
        snprintf(x->full, sizeof x->full, "events %s", sw_events_mode_name(s->events));
        snprintf(x->brief, sizeof x->brief, "ev %s", s->events == SW_EVENTS_LOCATE ? "loc" : "step");
    }
    if (s->blown && (x = add(f, &n, max, 10))) {
        snprintf(x->full, sizeof x->full, "BLOWN UP at step %ld", s->blow_step);
        snprintf(x->brief, sizeof x->brief, "BLOWN UP");
    }
    return n;
}

void sw_app_status(sw_app *a, int i, char *buf, size_t len)
{
    sw_field f[SW_STATUS_FIELDS];
    int n = sw_app_status_fields(a, i, f, SW_STATUS_FIELDS);
    size_t used = 0;
    if (len)
        buf[0] = '\0';
    if (i != 0 && len)
        used = (size_t)snprintf(buf, len, "  vs");
    for (int k = 0; k < n && used < len; k++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", used ? "  " : "", f[k].full);
}

const char *sw_app_growth_text(double rho, int grows, int slow, char *num, size_t len)
{
    /* grows = slow = 0: the word from rho alone (the fastest mode's factor) */
    int beyond = !grows && !slow && rho > 1 + SW_TRUTH_NEUTRAL;
    const char *word = grows || beyond ? "grows" : slow > 0 ? "grows slowly" : slow < 0 ? "decays slowly"
                     : rho < 1 - SW_TRUTH_NEUTRAL ? "decays" : "neutral";
    int above = grows || beyond || slow > 0, below = !above && rho < 1 - SW_TRUTH_NEUTRAL;
    /* the word is decided from rho; the digits follow it, so the number
     * printed is never 1.000000 beside "grows" or "decays" */
    for (int digits = 6; digits <= 15; digits++) {
        snprintf(num, len, "×%.*f", digits, rho);
        double shown = strtod(num + strlen("×"), NULL);
        if ((above && shown > 1) || (below && shown < 1) || (!above && !below && shown == 1) || !isfinite(rho))
            break;
    }
    return word;
}

int sw_app_meter_fields(sw_app *a, sw_field *f, int max, int *warn)
{
    sw_app_meter m;
    int n = 0;
    sw_field *x;
    *warn = 0;
    if (!sw_app_stability(a, &m)) {
        if ((a->sims[0].method->flags & SW_ADAPTIVE) && (x = add(f, &n, max, 8))) {
            snprintf(x->full, sizeof x->full, "%s chooses its own steps: no fixed-step limit", a->sims[0].method->name);
            snprintf(x->brief, sizeof x->brief, "adaptive steps");
        } else if (!(a->sims[0].method->flags & SW_ADAPTIVE) && sw_app_meter_pending(a) && (x = add(f, &n, max, 8))) {
            snprintf(x->full, sizeof x->full, "stability: finding the stiffest mode");
            snprintf(x->brief, sizeof x->brief, "finding the stiffest mode");
        } else if (sw_app_meter_out_of_reach(a) && (x = add(f, &n, max, 8))) {
            snprintf(x->full, sizeof x->full, "stability: not measured: every pair of bodies is coupled, %.2g "
                     "pairs, too many to take its spectrum live", (double)sw_app_meter_out_of_reach(a));
            snprintf(x->brief, sizeof x->brief, "stability: not measured (%.2g pairs)",
                     (double)sw_app_meter_out_of_reach(a));
        }
        return n;
    }
    /* stiffness·dt is |λ|·Δt, the stiffest mode's rate times the step: a
     * pure number, never a second time step */
    int bounded = !m.unbounded && m.limit > 0;
    if ((x = add(f, &n, max, 7))) {
        if (bounded) {
            snprintf(x->full, sizeof x->full, "stiffness·dt %.3g of limit %.3g", m.stiff * a->dt, m.stiff * m.limit);
        } else
            snprintf(x->full, sizeof x->full, "stiffness·dt %.3g, %s", m.stiff * a->dt,
                     m.unbounded ? "stable at any dt" : "no stable dt");
    }
    if (bounded && m.limit_undamped > 0 && (x = add(f, &n, max, 3))) {
        snprintf(x->full, sizeof x->full, "(limit with this damping; %.3g undamped)", m.stiff * m.limit_undamped);
        snprintf(x->brief, sizeof x->brief, "(%.3g undamped)", m.stiff * m.limit_undamped);
    }
    if (bounded && (x = add(f, &n, max, 2))) {
        int fill = (int)fmin(10.0, fmax(0.0, floor(10.0 * a->dt / m.limit + 1e-9)));
        x->full[0] = '[';
        for (int i = 0; i < 10; i++)
            x->full[i + 1] = i < fill ? '#' : '.';
        x->full[11] = ']';
        x->full[12] = '\0';
    }
    if ((x = add(f, &n, max, 9))) {
        char num[40];
        const char *word = sw_app_growth_text(m.growth, m.grows, m.slow, num, sizeof num);
        snprintf(x->full, sizeof x->full, "growth %s per step: %s", num, m.grows ? "GROWS" : word);
        snprintf(x->brief, sizeof x->brief, "growth %s/step %s", num, m.grows ? "GROWS" : word);
    }
    /* ρ is the largest over the modes: where it is not the fastest mode's,
     * name its mode and give the fastest one's own factor (issue 38) */
    if (m.growth_lambda < m.stiff * (1 - 1e-9) && isfinite(m.fast_growth) && (x = add(f, &n, max, 5))) {
        char fast[40];
        sw_app_growth_text(m.fast_growth, 0, 0, fast, sizeof fast);
        snprintf(x->full, sizeof x->full, "(of the mode |λ| %.3g; the fastest, |λ| %.3g: %s)", m.growth_lambda, m.stiff,
                 fast);
        snprintf(x->brief, sizeof x->brief, "(fastest %s)", fast);
    }
    int run_grows = a->watch.verdict != SW_WATCH_STEADY;
    if (run_grows && !m.grows && (x = add(f, &n, max, 6))) {
        snprintf(x->full, sizeof x->full, "but the run's energy grows: nonlinear");
        snprintf(x->brief, sizeof x->brief, "but the run grows");
    }
    *warn = m.grows || run_grows || (bounded && a->dt > 0.9 * m.limit);
    return n;
}
