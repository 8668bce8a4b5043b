/* The scenes of `stepwise bench` on worker threads (cli/bench_jobs.h). A
 * worker writes only its own scene's report, status and message, then
 * marks it done under the lock; the caller reads them after that. */
#include "cli/bench_jobs.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/stepwise.h"

#define MAX_WORKERS 16

struct sw_bench_jobs {
    const sw_bench_task *task;
    sw_bench_report *report;
    int n, nthreads;
    atomic_int next;              /* the next scene a worker takes */
    pthread_mutex_t lock;
    pthread_cond_t changed;
    unsigned char *done;          /* per scene, under lock */
    int *rc;
    char (*err)[SW_ERRLEN];
    pthread_t thread[MAX_WORKERS];
};

static void measure(sw_bench_jobs *j, int i)
{
    const sw_bench_task *t = &j->task[i];
    sw_bench_report *r = &j->report[i];
    int rc = sw_bench_init(r, t->scene, t->p, j->err[i], sizeof j->err[i]);
    if (rc == SW_OK) {
        r->events = t->events;
        rc = sw_bench_sweep_all(r, t->methods, t->nmethods, t->cfg, j->err[i], sizeof j->err[i]);
        if (rc != SW_OK)
            sw_bench_free(r);
    }
    j->rc[i] = rc;
}

static void *work(void *arg)
{
    sw_bench_jobs *j = arg;
    for (int i; (i = atomic_fetch_add(&j->next, 1)) < j->n;) {
        measure(j, i);
        pthread_mutex_lock(&j->lock);
        j->done[i] = 1;
        pthread_cond_broadcast(&j->changed);
        pthread_mutex_unlock(&j->lock);
    }
    return NULL;
}

sw_bench_jobs *sw_bench_jobs_start(const sw_bench_task *task, sw_bench_report *report, int n, int workers,
                                   char *err, size_t errlen)
{
    sw_bench_jobs *j = calloc(1, sizeof *j);
    if (j) {
        j->done = calloc((size_t)n, 1);
        j->rc = calloc((size_t)n, sizeof *j->rc);
        j->err = calloc((size_t)n, sizeof *j->err);
    }
    if (!j || !j->done || !j->rc || !j->err) {
        if (j) {
            free(j->done);
            free(j->rc);
            free(j->err);
        }
        free(j);
        snprintf(err, errlen, "out of memory for %d scenes' sweeps", n);
        return NULL;
    }
    j->task = task;
    j->report = report;
    j->n = n;
    atomic_init(&j->next, 0);
    pthread_mutex_init(&j->lock, NULL);
    pthread_cond_init(&j->changed, NULL);
    workers = workers < 0 ? 0 : workers > n ? n : workers > MAX_WORKERS ? MAX_WORKERS : workers;
    for (int k = 0; k < workers; k++) {
        int rc = pthread_create(&j->thread[k], NULL, work, j);
        if (rc != 0) {
            if (k > 0)
                break; /* fewer workers: the ones running take every scene */
            snprintf(err, errlen, "cannot start a thread for the sweeps: %s", strerror(rc));
            free(j->done);
            free(j->rc);
            free(j->err);
            free(j);
            return NULL;
        }
        j->nthreads++;
    }
    return j;
}

static void await(sw_bench_jobs *j, int i)
{
    pthread_mutex_lock(&j->lock);
    while (!j->done[i])
        pthread_cond_wait(&j->changed, &j->lock);
    pthread_mutex_unlock(&j->lock);
}

int sw_bench_jobs_wait(sw_bench_jobs *j, int i, char *err, size_t errlen)
{
    if (j->nthreads == 0) /* no workers: measured here, in order */
        measure(j, i);
    else
        await(j, i);
    if (j->rc[i] != SW_OK)
        snprintf(err, errlen, "%s", j->err[i]);
    return j->rc[i];
}

void sw_bench_jobs_free(sw_bench_jobs *j)
{
    if (!j)
        return;
    for (int k = 0; k < j->nthreads; k++)
        pthread_join(j->thread[k], NULL);
    pthread_mutex_destroy(&j->lock);
    pthread_cond_destroy(&j->changed);
    free(j->done);
    free(j->rc);
    free(j->err);
    free(j);
}
