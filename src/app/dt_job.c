/* The Δt measurement on a worker thread (app/dt_job.h). The worker reads
 * its copied inputs, the scene (read-only) and the method table (read-only
 * once plugins are loaded: docs/architecture.md, "Threads"), and writes its
 * cache and result only; the app reads them after the worker is done. */
#include "app/dt_job.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/worker.h"

struct sw_dt_job {
    sw_dt_in in;
    sw_dt_cache cache;
    sw_dt_result result;
    sw_worker worker;     /* its stop ends the runs at their next sample time */
};

static void work(void *arg)
{
    sw_dt_job *j = arg;
    sw_dt_change(&j->in, &j->cache, &j->result);
}

sw_dt_job *sw_dt_job_start(const sw_dt_in *in, sw_dt_cache *c, int on_caller, char *err, size_t errlen)
{
    sw_dt_job *j = calloc(1, sizeof *j);
    if (!j) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    j->in = *in;
    j->in.stop = &j->worker.stop;
    j->cache = *c;
    if (sw_worker_start(&j->worker, work, j, on_caller, err, errlen) != 0) {
        free(j);
        return NULL;
    }
    memset(c, 0, sizeof *c);
    return j;
}

/* The cache back to the app (or freed), then the job. */
static void finish(sw_dt_job *j, sw_dt_cache *c)
{
    if (c)
        *c = j->cache;
    else
        sw_dt_cache_free(&j->cache);
    free(j);
}

int sw_dt_job_poll(sw_dt_job *j, sw_dt_result *out, sw_dt_cache *c)
{
    if (!sw_worker_done(&j->worker))
        return 0;
    *out = j->result;
    finish(j, c);
    return 1;
}

void sw_dt_job_wait(sw_dt_job *j) { sw_worker_wait(&j->worker); }

void sw_dt_job_cancel(sw_dt_job *j, sw_dt_cache *c)
{
    if (!j)
        return;
    sw_worker_stop(&j->worker);
    finish(j, c);
}
