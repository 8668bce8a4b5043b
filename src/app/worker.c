/* One job on a thread beside the picture's (app/worker.h). Invariant: the
 * thread is joined exactly once, by whichever of done, wait or stop first
 * sees it finished. */
#include "app/worker.h"

#include <stdio.h>
#include <string.h>

static void *run(void *arg)
{
    sw_worker *w = arg;
    w->fn(w->arg);
    atomic_store(&w->done, 1);
    return NULL;
}

int sw_worker_start(sw_worker *w, void (*fn)(void *arg), void *arg, int on_caller, char *err, size_t errlen)
{
    w->fn = fn;
    w->arg = arg;
    w->threaded = 0;
    atomic_init(&w->stop, 0);
    atomic_init(&w->done, 0);
    if (on_caller) {
        run(w);
        return 0;
    }
    int rc = pthread_create(&w->thread, NULL, run, w);
    if (rc != 0) {
        snprintf(err, errlen, "cannot start a worker thread: %s", strerror(rc));
        return -1;
    }
    w->threaded = 1;
    return 0;
}

void sw_worker_wait(sw_worker *w)
{
    if (w->threaded) {
        pthread_join(w->thread, NULL);
        w->threaded = 0;
    }
}

int sw_worker_done(sw_worker *w)
{
    if (!atomic_load(&w->done))
        return 0;
    sw_worker_wait(w);
    return 1;
}

void sw_worker_stop(sw_worker *w)
{
    atomic_store(&w->stop, 1);
    sw_worker_wait(w);
}
