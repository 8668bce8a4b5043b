/* Step traces, what writer and reader share: the run rule (how long a run
 * lasts, which steps it records) and the columns of a system's rows. */
#include "trace/trace.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "plugin/plugin.h"
#include "stepwise/base.h"

/* ---- the run rule --------------------------------------------------------- */

int sw_trace_spec_check(const sw_trace_spec *spec, double dt, char *err, size_t errlen)
{
    if (spec->steps < 0 || spec->steps > SW_TRACE_MAX_STEPS) {
        snprintf(err, errlen, "steps = %ld is not allowed: a run takes 1 to %ld steps",
                 spec->steps, SW_TRACE_MAX_STEPS);
        return SW_EINVAL;
    }
    if (spec->steps == 0) {
        if (!(isfinite(spec->until) && spec->until > 0)) {
            snprintf(err, errlen, "until = %g is not allowed: it must be a positive finite time",
                     spec->until);
            return SW_EINVAL;
        }
        /* ceil(until/dt) steps, and one more when rounding in t leaves the
         * run short of until: refused at once, not after 10^7 steps. */
        if (!(dt > 0) || ceil(spec->until / dt * (1 - 1e-12)) + 1 > (double)SW_TRACE_MAX_STEPS) {
            snprintf(err, errlen, "until = %g with dt = %g needs %.3g steps (and one more when "
                     "rounding leaves t short of until); a run takes at most %ld (raise dt or "
                     "shorten the run)", spec->until, dt, ceil(spec->until / dt), SW_TRACE_MAX_STEPS);
            return SW_EINVAL;
        }
    }
    if (spec->every < 1 || spec->every > SW_TRACE_MAX_STEPS) {
        snprintf(err, errlen, "every = %ld is not allowed: it takes a whole number in [1, %ld]",
                 spec->every, SW_TRACE_MAX_STEPS);
        return SW_EINVAL;
    }
    return SW_OK;
}

int sw_trace_done(const sw_sim *s, const sw_trace_spec *spec)
{
    if (s->blown)
        return 1;
    if (spec->steps > 0)
        return s->steps >= spec->steps;
    /* The same test as sw_sim_run_until: within a billionth of a step is there. */
    return !(spec->until - s->t > 1e-9 * s->dt);
}

int sw_trace_due(const sw_sim *s, const sw_trace_spec *spec)
{
    return s->steps == 0 || s->steps % spec->every == 0 || sw_trace_done(s, spec);
}

int sw_trace_step(sw_sim *s, const sw_trace_spec *spec, char *err, size_t errlen)
{
    if (s->steps >= SW_TRACE_MAX_STEPS) {
        snprintf(err, errlen, "the run needs more than %ld steps (at t = %g of %g); raise dt or "
                 "shorten the run", SW_TRACE_MAX_STEPS, s->t, spec->until);
        return SW_EINVAL;
    }
    if (sw_sim_step_until(s, spec->steps > 0 ? 0.0 : spec->until))
        sw_plugin_failed(s); /* a plugin that crashed, looped, ...: say so, not "diverged" */
    return SW_OK;
}

/* ---- columns -------------------------------------------------------------- */

/* Values per particle: position, plus velocity for second-order systems. */
int sw_trace_per_particle(const sw_system *sys) { return sys->ode->order == 2 ? 4 : 2; }

int sw_trace_ncols(const sw_system *sys)
{
    return 2 + sw_trace_per_particle(sys) * sys->n + (sys->scene->energy ? 1 : 0);
}

void sw_trace_colname(const sw_system *sys, int c, char *buf, size_t len)
{
    static const char *const kinds[] = { "x", "y", "vx", "vy" };
    int pp = sw_trace_per_particle(sys);
    if (c == 0)
        snprintf(buf, len, "step");
    else if (c == 1)
        snprintf(buf, len, "t");
    else if (c - 2 < pp * sys->n)
        snprintf(buf, len, "%s%d", kinds[(c - 2) % pp], (c - 2) / pp);
    else
        snprintf(buf, len, "energy");
}

int sw_trace_colindex(const sw_system *sys, const char *name)
{
    static const char *const kinds[] = { "x", "y", "vx", "vy" };
    int pp = sw_trace_per_particle(sys);
    if (strcmp(name, "step") == 0)
        return 0;
    if (strcmp(name, "t") == 0)
        return 1;
    if (strcmp(name, "energy") == 0)
        return sys->scene->energy ? 2 + pp * sys->n : -1;
    for (int k = pp - 1; k >= 0; k--) {
        size_t len = strlen(kinds[k]);
        const char *digits = name + len;
        if (strncmp(name, kinds[k], len) != 0 || !*digits || strlen(digits) > 9 ||
            (digits[0] == '0' && digits[1]))
            continue;
        long i = 0;
        for (const char *d = digits; *d; d++) {
            if (*d < '0' || *d > '9')
                return -1;
            i = 10 * i + (*d - '0');
        }
        return i < sys->n ? 2 + pp * (int)i + k : -1;
    }
    return -1;
}

void sw_trace_row_values(const sw_sim *s, double *row)
{
    const sw_system *sys = &s->sys;
    int n = sys->n, pp = sw_trace_per_particle(sys);
    const double *y = sys->y;
    row[0] = (double)s->steps;
    row[1] = s->t;
    /* The state is [x(2n) | v(2n)]; the trace groups each particle's values. */
    for (int i = 0; i < n; i++) {
        double *out = row + 2 + pp * i;
        out[0] = y[2 * i];
        out[1] = y[2 * i + 1];
        if (pp == 4) {
            out[2] = y[2 * n + 2 * i];
            out[3] = y[2 * n + 2 * i + 1];
        }
    }
    if (sys->scene->energy)
        row[2 + pp * n] = sw_sim_energy(s);
}
