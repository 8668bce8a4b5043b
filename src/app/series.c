/* The graph's time series and the per-frame samples the clock adds: each
 * sim's energy drift (or error) against time, bounded by halving the
 * resolution when full, and cut back when the student steps back. */
#include "app/app.h"

#include <math.h>

#include "stepwise/stepwise.h"

void sw_series_clear(sw_series *s)
{
    s->len = 0;
    s->stride = 1;
    s->skip = 0;
}

/* Keep at most SW_APP_GRAPH samples: when full, drop every other one and
 * keep only every stride-th new sample from then on. */
static void series_push(sw_series *s, double t, double v)
{
    if (s->skip > 0) {
        s->skip--;
        return;
    }
    if (s->len == SW_APP_GRAPH) {
        for (int i = 0; i < SW_APP_GRAPH / 2; i++) {
            s->t[i] = s->t[2 * i];
            s->v[i] = s->v[2 * i];
        }
        s->len = SW_APP_GRAPH / 2;
        s->stride *= 2;
    }
    s->t[s->len] = t;
    s->v[s->len] = v;
    s->len++;
    s->skip = s->stride - 1;
}

void sw_series_cut(sw_series *s, double t)
{
    while (s->len > 0 && s->t[s->len - 1] > t)
        s->len--;
    s->skip = 0;
}

static double graph_value(sw_app *a, int i)
{
    double e = sw_sim_energy_drift(&a->sims[i]);
    return isfinite(e) ? e : sw_app_error(a, i);
}

void sw_app_sample(sw_app *a)
{
    for (int i = 0; i < a->nsims; i++)
        series_push(&a->series[i], a->sims[i].t, a->graph ? graph_value(a, i) : sw_sim_energy_drift(&a->sims[i]));
    sw_app_phase_push(a);
}
