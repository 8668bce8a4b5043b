/* The work-precision sweep on a worker thread (app/sweep.h). The worker
 * touches only its own job: a report, the scene (read-only), a copy of the
 * parameters and the method table (read-only once plugins are loaded; see
 * docs/architecture.md, "Threads"). */
#include "app/sweep.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/worker.h"
#include "stepwise/stepwise.h"

struct sw_sweep {
    const sw_scene *sc;
    double p[SW_MAX_PARAMS];
    double budget;
    sw_worker worker;     /* its stop ends the sweep early; done: rc, report and why written */
    int rc;
    sw_bench_report *report;
    char why[SW_ERRLEN];
};

static void work(void *arg)
{
    sw_sweep *s = arg;
    s->report = malloc(sizeof *s->report);
    if (!s->report) {
        s->rc = SW_ENOMEM;
        snprintf(s->why, sizeof s->why, "out of memory");
    } else {
        s->rc = sw_bench_scene_quick(s->report, s->sc, s->p, s->budget, &s->worker.stop, s->why, sizeof s->why);
        if (s->rc != SW_OK) {
            free(s->report);
            s->report = NULL;
        }
    }
}

/* A plugin steps through its host's one channel, which the main thread
 * uses too. */
int sw_sweep_inline(void)
{
    for (int i = 0; i < sw_integrator_count(); i++)
        if (sw_integrator_at(i)->flags & SW_PLUGIN)
            return 1;
    return 0;
}

sw_sweep *sw_sweep_start(const sw_scene *sc, const double *p, double budget, char *err, size_t errlen)
{
    sw_sweep *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    s->sc = sc;
    sw_scene_fill(sc, p, s->p); /* NULL: the defaults */
    s->budget = budget;
    if (sw_worker_start(&s->worker, work, s, sw_sweep_inline(), err, errlen) != 0) {
        free(s);
        return NULL;
    }
    return s;
}

int sw_sweep_poll(sw_sweep *s, sw_bench_report **report, char *why, size_t whylen)
{
    if (!sw_worker_done(&s->worker))
        return 0;
    *report = s->report;
    snprintf(why, whylen, "%s", s->rc == SW_OK ? "" : s->why);
    free(s);
    return 1;
}

void sw_sweep_wait(sw_sweep *s) { sw_worker_wait(&s->worker); }

void sw_sweep_cancel(sw_sweep *s)
{
    if (!s)
        return;
    sw_worker_stop(&s->worker);
    if (s->report) {
        sw_bench_free(s->report);
        free(s->report);
    }
    free(s);
}
