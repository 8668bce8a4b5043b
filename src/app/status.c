/* The status line of each sim as fields, each with a full and a brief form
 * and a priority, so the renderer can lay it out in any width without
 * cutting a word or a number: brief forms first, then the least important
 * fields go. */
#include "app/app.h"

#include <math.h>
#include <stdio.h>
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
    if ((x = add(f, &n, max, 3))) {
        snprintf(x->full, sizeof x->full, "steps %ld", s->steps);
    }
    if (i == 0 && a->steps_per_sec > 0 && (x = add(f, &n, max, 1)))
        snprintf(x->full, sizeof x->full, "%.0f steps/s", a->steps_per_sec);
    if ((x = add(f, &n, max, 2))) {
        snprintf(x->full, sizeof x->full, "evals %ld", sw_sim_evals(s));
    }
    double drift = sw_sim_energy_drift(s);
    if (isfinite(drift) && (x = add(f, &n, max, 7))) {
        snprintf(x->full, sizeof x->full, "energy %+.3g%%", drift);
        snprintf(x->brief, sizeof x->brief, "E%+.3g%%", drift);
    }
    double err = sw_app_error(a, i);
    if (isfinite(err) && (x = add(f, &n, max, 6))) {
        snprintf(x->full, sizeof x->full, "error %.2e", err);
        snprintf(x->brief, sizeof x->brief, "err %.1e", err);
    }
    if ((s->method->flags & SW_ADAPTIVE) && (x = add(f, &n, max, 4))) {
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
