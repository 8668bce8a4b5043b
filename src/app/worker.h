/* One job on a thread of its own beside the picture's (app/sweep.c's
 * work-precision sweep, app/dt_job.c's Δt measurement): started, polled
 * each frame, waited for, or asked to stop and joined. The job's function
 * touches only what it was handed; the caller reads its results only
 * after sw_worker_done answers 1. */
#ifndef SW_APP_WORKER_H
#define SW_APP_WORKER_H

#include <pthread.h>
#include <stdatomic.h>
#include <stddef.h>

typedef struct sw_worker {
    void (*fn)(void *arg);
    void *arg;
    atomic_int stop;      /* the caller asks the job to end early (the job reads it) */
    atomic_int done;      /* fn has returned */
    int threaded;         /* 0: it ran on the caller's thread */
    pthread_t thread;
} sw_worker;

/* Run fn(arg) on a new thread, or at once on this one when on_caller is
 * set. 0, or -1 with err filled when no thread could start. */
int sw_worker_start(sw_worker *w, void (*fn)(void *arg), void *arg, int on_caller, char *err, size_t errlen);
/* 1 when fn has returned (the thread joined), else 0. */
int sw_worker_done(sw_worker *w);
/* Wait for fn to return. */
void sw_worker_wait(sw_worker *w);
/* Ask the job to stop (w->stop) and wait for it. */
void sw_worker_stop(sw_worker *w);

#endif
